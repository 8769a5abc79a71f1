#include "vtkSilhouetteLineVisibility.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "LineVisibility.h"
#include "vtkSilhouetteFilterSupport.h"

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkSilhouetteLineVisibility);

namespace
{

vtkIdType FieldValue(vtkIdType value, const char* name, vtkFieldData* fields)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fields->AddArray(array);
  return value;
}

} // namespace

vtkSilhouetteLineVisibility::vtkSilhouetteLineVisibility()
{
  this->SetNumberOfInputPorts(2);
  // Visibility does not depend on the viewport's size.
  this->ViewportDependent = false;
}

vtkSilhouetteLineVisibility::~vtkSilhouetteLineVisibility() = default;

void vtkSilhouetteLineVisibility::SetSurfaceConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkSilhouetteLineVisibility::SetSurfaceData(vtkDataObject* surface)
{
  this->SetInputData(1, surface);
}

int vtkSilhouetteLineVisibility::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkSilhouetteLineVisibility::RequestViewData(vtkInformation*,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector,
  const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* lines = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!lines || !output)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }
  if (!(this->Tolerance >= 0.0))
  {
    vtkErrorMacro("Tolerance must be 0 (automatic) or positive, not " << this->Tolerance << ".");
    return 0;
  }
  if (!(this->EdgeTolerance >= 0.0))
  {
    vtkErrorMacro(
      "EdgeTolerance must be 0 (automatic) or positive, not " << this->EdgeTolerance << ".");
    return 0;
  }
  if (lines->GetNumberOfVerts() + lines->GetNumberOfPolys() + lines->GetNumberOfStrips() > 0)
  {
    vtkWarningMacro("Only line cells are split; the input's vertex, polygon and strip cells are "
                    "left out.");
  }

  // The surface as triangles; without one, nothing hides anything.
  vtkSilhouetteFilterSupport::Triangles triangles;
  if (surface && surface->GetNumberOfCells() > 0)
  {
    const std::string readError = vtkSilhouetteFilterSupport::ReadTriangles(surface, triangles);
    if (!readError.empty())
    {
      vtkErrorMacro(<< "Surface: " << readError);
      return 0;
    }
  }
  silsmooth::LineVisibilityParameters parameters =
    silsmooth::LineVisibilityParameters::forMesh(triangles.Points, triangles.Cells);
  if (this->Tolerance > 0.0)
  {
    parameters.Tolerance = this->Tolerance;
  }
  silsmooth::LineVisibilityParameters edgeParameters = parameters;
  edgeParameters.Tolerance =
    this->EdgeTolerance > 0.0 ? this->EdgeTolerance : 10.0 * parameters.Precision;
  // The stubs a tolerance leaves where an occluder meets the line.
  edgeParameters.MinimumPieceLength = 10.0 * edgeParameters.Tolerance;
  vtkDataArray* kinds = lines->GetCellData()->GetArray("LineKind");
  if (kinds && kinds->GetNumberOfComponents() != 1)
  {
    kinds = nullptr;
  }
  const auto isSurfaceEdge = [kinds](vtkIdType cell) {
    if (!kinds)
    {
      return false;
    }
    const double kind = kinds->GetComponent(cell, 0);
    return kind == vtkSilhouetteFilterSupport::CreaseLine ||
      kind == vtkSilhouetteFilterSupport::BorderLine;
  };
  const silsmooth::OcclusionMesh occluder(
    std::move(triangles.Points), std::move(triangles.Cells), triangles.Normals);

  vtkPointData* inPD = lines->GetPointData();
  vtkCellData* inCD = lines->GetCellData();
  vtkPointData* outPD = output->GetPointData();
  vtkCellData* outCD = output->GetCellData();
  const vtkIdType lineCount = lines->GetNumberOfLines();
  const vtkIdType firstLineId = lines->GetNumberOfVerts(); // cells: verts, then lines
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  outPD->InterpolateAllocate(inPD, lines->GetNumberOfPoints());
  outCD->CopyAllocate(inCD, lineCount);
  vtkNew<vtkUnsignedCharArray> pointVisible;
  pointVisible->SetName("Visible");
  vtkNew<vtkUnsignedCharArray> cellVisible;
  cellVisible->SetName("Visible");
  vtkNew<vtkIdTypeArray> original;
  original->SetName("OriginalCellId");
  vtkIdType visiblePieces = 0;
  vtkIdType hiddenPieces = 0;

  std::vector<glm::dvec3> polyline;
  std::vector<vtkIdType> polylineIds;
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  vtkIdType line = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++line)
  {
    if (line % 256 == 0)
    {
      this->UpdateProgress(static_cast<double>(line) / static_cast<double>(lineCount));
      if (this->GetAbortExecute())
      {
        break;
      }
    }
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n < 2)
    {
      continue;
    }
    polyline.resize(static_cast<std::size_t>(n));
    polylineIds.assign(ids, ids + n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      lines->GetPoint(ids[i], x);
      polyline[static_cast<std::size_t>(i)] = glm::dvec3(x[0], x[1], x[2]);
    }
    const std::vector<silsmooth::LinePiece> pieces = silsmooth::splitByVisibility(occluder,
      view.Geometry, polyline, isSurfaceEdge(firstLineId + line) ? edgeParameters : parameters);
    for (const silsmooth::LinePiece& piece : pieces)
    {
      if (!piece.Visible && !this->PassHiddenLines)
      {
        ++hiddenPieces;
        continue;
      }
      ++(piece.Visible ? visiblePieces : hiddenPieces);
      cells->InsertNextCell(static_cast<vtkIdType>(piece.Points.size()));
      for (std::size_t k = 0; k < piece.Points.size(); ++k)
      {
        const glm::dvec3& p = piece.Points[k];
        const vtkIdType id = points->InsertNextPoint(p.x, p.y, p.z);
        cells->InsertCellPoint(id);
        // Vertex i keeps its data; a change point interpolates its segment's.
        const double along = piece.Along[k];
        const vtkIdType i0 = std::min(static_cast<vtkIdType>(along), n - 1);
        const double fraction = along - static_cast<double>(i0);
        if (fraction > 0.0 && i0 + 1 < n)
        {
          outPD->InterpolateEdge(inPD, id, polylineIds[static_cast<std::size_t>(i0)],
            polylineIds[static_cast<std::size_t>(i0 + 1)], fraction);
        }
        else
        {
          outPD->CopyData(inPD, polylineIds[static_cast<std::size_t>(i0)], id);
        }
        pointVisible->InsertNextValue(piece.Visible ? 1 : 0);
      }
      const vtkIdType cell = cells->GetNumberOfCells() - 1;
      outCD->CopyData(inCD, firstLineId + line, cell);
      cellVisible->InsertNextValue(piece.Visible ? 1 : 0);
      original->InsertNextValue(firstLineId + line);
    }
  }
  this->UpdateProgress(1.0);

  output->SetPoints(points);
  output->SetLines(cells);
  outPD->AddArray(pointVisible);
  outCD->AddArray(cellVisible);
  outCD->AddArray(original);
  FieldValue(visiblePieces, "VisiblePieceCount", output->GetFieldData());
  FieldValue(hiddenPieces, "HiddenPieceCount", output->GetFieldData());
  return 1;
}

void vtkSilhouetteLineVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << (this->Tolerance > 0 ? "" : " (automatic)")
     << "\n";
  os << indent << "EdgeTolerance: " << this->EdgeTolerance
     << (this->EdgeTolerance > 0 ? "" : " (automatic)") << "\n";
  os << indent << "PassHiddenLines: " << (this->PassHiddenLines ? "On" : "Off") << "\n";
}
