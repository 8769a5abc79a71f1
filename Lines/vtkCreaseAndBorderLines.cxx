#include "vtkCreaseAndBorderLines.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "SurfaceEdgeLines.h"
#include "vtkSilhouetteFilterSupport.h"

#include <unordered_map>

vtkStandardNewMacro(vtkCreaseAndBorderLines);

namespace support = vtkSilhouetteFilterSupport;

vtkCreaseAndBorderLines::vtkCreaseAndBorderLines() = default;
vtkCreaseAndBorderLines::~vtkCreaseAndBorderLines() = default;

vtkSilhouetteCheckedSetterMacro(vtkCreaseAndBorderLines, NormalJumpAngle, double, 0.0, 180.0);
vtkSilhouetteCheckedSetterMacro(vtkCreaseAndBorderLines, FeatureAngle, double, 0.0, 180.0);
vtkSilhouetteCheckedSetterMacro(
  vtkCreaseAndBorderLines, WeldTolerance, double, 0.0, VTK_DOUBLE_MAX);

int vtkCreaseAndBorderLines::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  std::optional<vtkSilhouetteFilterSupport::Surface> surface =
    vtkSilhouetteFilterSupport::ReadSurface(this, inputVector, outputVector);
  if (!surface)
  {
    return 0;
  }
  auto& [input, output, triangles] = *surface;
  if (!support::ReportProgress(this, 0.2))
  {
    return 1; // aborted: the output stays empty
  }

  silsmooth::SurfaceEdgeLineParameters parameters;
  parameters.Creases = this->Creases != 0;
  parameters.Borders = this->Borders != 0;
  parameters.NormalJumpDegrees = this->NormalJumpAngle;
  parameters.CreaseAngleDegrees = this->FeatureAngle;
  parameters.WeldTolerance = this->WeldTolerance;
  const std::vector<silsmooth::SurfaceEdgeLine> lines =
    silsmooth::surfaceEdgeLines(triangles.Points, triangles.Cells, triangles.Normals, parameters);
  if (!support::ReportProgress(this, 0.8))
  {
    return 1;
  }

  // The points the lines use, in order of first use, with their data.
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(inPD);
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_FLOAT);
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> kinds;
  kinds->SetName("LineKind");
  std::unordered_map<silsmooth::Id, vtkIdType> compact;
  vtkIdType creaseLines = 0;
  vtkIdType borderLines = 0;
  for (const silsmooth::SurfaceEdgeLine& line : lines)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(line.Points.size()));
    for (const silsmooth::Id id : line.Points)
    {
      const auto inserted = compact.emplace(id, points->GetNumberOfPoints());
      if (inserted.second)
      {
        const glm::dvec3& p = triangles.Points[static_cast<std::size_t>(id)];
        points->InsertNextPoint(p.x, p.y, p.z);
        outPD->CopyData(inPD, static_cast<vtkIdType>(id), inserted.first->second);
      }
      cells->InsertCellPoint(inserted.first->second);
    }
    const bool crease = line.Kind == silsmooth::LineKind::Crease;
    ++(crease ? creaseLines : borderLines);
    kinds->InsertNextValue(crease ? support::CreaseLine : support::BorderLine);
  }
  output->SetPoints(points);
  output->SetLines(cells);
  output->GetCellData()->AddArray(kinds);
  for (const auto& [name, count] : { std::make_pair("CreaseLineCount", creaseLines),
         std::make_pair("BorderLineCount", borderLines) })
  {
    vtkNew<vtkIdTypeArray> array;
    array->SetName(name);
    array->InsertNextValue(count);
    output->GetFieldData()->AddArray(array);
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCreaseAndBorderLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Creases: " << (this->Creases ? "On" : "Off") << "\n";
  os << indent << "Borders: " << (this->Borders ? "On" : "Off") << "\n";
  os << indent << "NormalJumpAngle: " << this->NormalJumpAngle << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "WeldTolerance: " << this->WeldTolerance << "\n";
}
