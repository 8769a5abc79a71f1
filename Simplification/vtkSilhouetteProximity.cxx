#include "vtkSilhouetteProximity.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include "SilhouetteProximity.h"
#include "vtkSilhouetteFilterSupport.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkSilhouetteProximity);

vtkSilhouetteProximity::vtkSilhouetteProximity()
{
  // A renderer without its camera yet fails too: a missing camera is an error.
  this->WaitForRenderer = false;
}

vtkSilhouetteProximity::~vtkSilhouetteProximity() = default;

int vtkSilhouetteProximity::RequestViewData(vtkInformation*, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, const vtkSilhouetteFilterSupport::View& view)
{
  std::optional<vtkSilhouetteFilterSupport::Surface> surface =
    vtkSilhouetteFilterSupport::ReadSurface(this, inputVector, outputVector);
  if (!surface)
  {
    return 0;
  }
  auto& [input, output, mesh] = *surface;
  if (!vtkSilhouetteFilterSupport::ReportProgress(this, 0.3))
  {
    return 1; // aborted: the output stays empty
  }
  const silsmooth::ProximityGrid grid =
    silsmooth::silhouetteProximity(mesh.Points, mesh.Cells, view.Geometry, this->Resolution);
  if (!vtkSilhouetteFilterSupport::ReportProgress(this, 0.7))
  {
    return 1;
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();

  output->ShallowCopy(input);
  vtkNew<vtkDoubleArray> pointDistance;
  pointDistance->SetName("SilhouetteDistance");
  pointDistance->SetNumberOfTuples(numPoints);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    pointDistance->SetValue(i, grid.PointDistance[static_cast<std::size_t>(i)]);
  }
  output->GetPointData()->AddArray(pointDistance);

  const vtkIdType numCells = input->GetNumberOfCells();
  vtkNew<vtkDoubleArray> cellDistance;
  cellDistance->SetName("SilhouetteDistance");
  cellDistance->SetNumberOfTuples(numCells);
  cellDistance->Fill(-1.0);
  // A polygon's or strip's label: the least over its triangles, -1 if any is -1.
  std::vector<char> seen(static_cast<std::size_t>(numCells), 0);
  for (std::size_t t = 0; t < mesh.Cells.size(); ++t)
  {
    const vtkIdType c = mesh.CellIds[t];
    const double d = grid.TriangleDistance[t];
    const double old = cellDistance->GetValue(c);
    if (!seen[static_cast<std::size_t>(c)])
    {
      cellDistance->SetValue(c, d);
      seen[static_cast<std::size_t>(c)] = 1;
    }
    else if (old >= 0.0)
    {
      cellDistance->SetValue(c, d < 0.0 ? -1.0 : std::min(old, d));
    }
  }
  output->GetCellData()->AddArray(cellDistance);

  vtkNew<vtkIntArray> gridSize;
  gridSize->SetName("ProximityGridSize");
  gridSize->SetNumberOfComponents(2);
  gridSize->InsertNextTuple2(grid.Width, grid.Height);
  output->GetFieldData()->AddArray(gridSize);
  vtkNew<vtkDoubleArray> cellSize;
  cellSize->SetName("ProximityCellSize");
  cellSize->InsertNextValue(grid.CellSize);
  output->GetFieldData()->AddArray(cellSize);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkSilhouetteProximity::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
}
