#include "vtkStylizedStrokeFilter.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "StrokeStylizer.h"
#include "vtkSilhouetteFilterSupport.h"

#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkStylizedStrokeFilter);

vtkSilhouetteCheckedSetterMacro(vtkStylizedStrokeFilter, Amplitude, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkStylizedStrokeFilter, Wavelength, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkStylizedStrokeFilter, Spacing, double, 0.0, VTK_DOUBLE_MAX);

vtkStylizedStrokeFilter::vtkStylizedStrokeFilter()
{
  this->ViewportDependent = false; // offsets are in model units, not pixels
}

vtkStylizedStrokeFilter::~vtkStylizedStrokeFilter() = default;

namespace
{

// The error for lines naming missing points, or for points with NaN or
// infinite coordinates; "" when there is none.
std::string LinesError(vtkPolyData* input)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (vtkCellArray* lines = input->GetLines())
  {
    auto it = vtk::TakeSmartPointer(lines->NewIterator());
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(count, ids);
      for (vtkIdType k = 0; k < count; ++k)
      {
        if (ids[k] < 0 || ids[k] >= numberOfPoints)
        {
          return "Input cells refer to points that do not exist.";
        }
      }
    }
  }
  vtkIdType nonFinite = 0;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    nonFinite += std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) ? 0 : 1;
  }
  return nonFinite == 0
    ? ""
    : "Input has " + std::to_string(nonFinite) + " points with NaN or infinite coordinates.";
}

} // namespace

int vtkStylizedStrokeFilter::RequestViewData(vtkInformation*, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, const vtkSilhouetteFilterSupport::View& modelView)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> offsets;
  offsets->SetName("BrushOffset");
  offsets->SetNumberOfComponents(2);
  vtkNew<vtkDoubleArray> arcLengths;
  arcLengths->SetName("StrokeArcLength");
  vtkNew<vtkIdTypeArray> strokeIds;
  strokeIds->SetName("StrokeId");

  vtkPoints* inPoints = input->GetPoints();
  vtkCellArray* inLines = input->GetLines();
  // What the module's other filters refuse, refused here too: a NaN point
  // went through to the output (a user's trial), a bad id was skipped.
  if (const std::string error = LinesError(input); !error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if ((!inLines || inLines->GetNumberOfCells() == 0) && input->GetNumberOfCells() > 0)
  {
    vtkWarningMacro("The input has no line cells to draw strokes along (its "
      << input->GetNumberOfCells()
      << " cells are vertices, polygons or strips): give it lines, such as "
         "vtkSilhouetteSmoothingFilter's second output or vtkSilhouetteLineVisibility's.");
  }
  if (inPoints && inLines && inLines->GetNumberOfCells() > 0)
  {
    double bounds[6];
    input->GetBounds(bounds);
    const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));

    silsmooth::StrokeParameters parameters;
    parameters.brush = static_cast<silsmooth::Brush>(this->Brush);
    parameters.amplitude = this->Amplitude * diagonal;
    parameters.wavelength = this->Wavelength * diagonal;
    parameters.spacing = this->Spacing * diagonal;
    parameters.seed = this->Seed;

    // The line of sight in the data's model coordinates.
    silsmooth::StrokeView view;
    view.parallel = modelView.Geometry.Parallel;
    view.eye = modelView.Geometry.Eye;
    view.direction = -modelView.Geometry.TowardViewer;

    const vtkIdType numberOfPoints = inPoints->GetNumberOfPoints();
    vtkIdType strokeIndex = 0;
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    const vtkIdType total = inLines->GetNumberOfCells();
    auto iterator = vtk::TakeSmartPointer(inLines->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
         iterator->GoToNextCell(), ++strokeIndex)
    {
      if (strokeIndex % 256 == 0)
      {
        if (!vtkSilhouetteFilterSupport::ReportProgress(
              this, static_cast<double>(strokeIndex) / total))
        {
          break;
        }
      }
      iterator->GetCurrentCell(count, ids);
      std::vector<glm::dvec3> stroke;
      stroke.reserve(count);
      for (vtkIdType k = 0; k < count; ++k)
      {
        double p[3];
        inPoints->GetPoint(ids[k], p);
        stroke.emplace_back(p[0], p[1], p[2]);
      }
      if (stroke.size() < 2)
      {
        continue;
      }
      const silsmooth::StylizedStroke result =
        silsmooth::stylizeStroke(stroke, view, parameters, static_cast<std::uint64_t>(strokeIndex));
      lines->InsertNextCell(static_cast<vtkIdType>(result.points.size()));
      for (std::size_t i = 0; i < result.points.size(); ++i)
      {
        const glm::dvec3& q = result.points[i];
        lines->InsertCellPoint(points->InsertNextPoint(q.x, q.y, q.z));
        offsets->InsertNextTuple2(result.tangentOffset[i], result.normalOffset[i]);
        arcLengths->InsertNextValue(result.arcLength[i]);
      }
      strokeIds->InsertNextValue(strokeIndex);
    }
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(offsets);
  output->GetPointData()->AddArray(arcLengths);
  output->GetCellData()->AddArray(strokeIds);
  return 1;
}

void vtkStylizedStrokeFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Brush: " << silsmooth::brushName(static_cast<silsmooth::Brush>(this->Brush))
     << "\n";
  os << indent << "Amplitude: " << this->Amplitude << "\n";
  os << indent << "Wavelength: " << this->Wavelength << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
