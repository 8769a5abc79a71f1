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

#include "PathJoining.h"
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

// A stroke's points, and the index among the line cells of its first line.
struct Stroke
{
  std::vector<glm::dvec3> Points;
  vtkIdType FirstLine = 0;
};

// Each line cell of two points or more, a stroke.
std::vector<Stroke> LineCells(vtkPoints* points, vtkCellArray* lines)
{
  std::vector<Stroke> strokes;
  vtkIdType index = 0;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  auto iterator = vtk::TakeSmartPointer(lines->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
       iterator->GoToNextCell(), ++index)
  {
    iterator->GetCurrentCell(count, ids);
    if (count < 2)
    {
      continue;
    }
    Stroke stroke;
    stroke.FirstLine = index;
    stroke.Points.reserve(static_cast<std::size_t>(count));
    for (vtkIdType k = 0; k < count; ++k)
    {
      double p[3];
      points->GetPoint(ids[k], p);
      stroke.Points.emplace_back(p[0], p[1], p[2]);
    }
    strokes.push_back(std::move(stroke));
  }
  return strokes;
}

// The lines joined end to end (Lines/Core/PathJoining.h) where their ends
// meet to within a hundred-thousandth of the diagonal (a hundredth of a
// pixel on a drawing 1,000 px across: ends the line visibility filter
// placed a hair apart, 1e-5 of the diagonal on the Wuson, are joined); a
// chain that comes back to its start ends exactly on its first point, so
// the stylizer closes it.
std::vector<Stroke> JoinedStrokes(std::vector<Stroke> lines, double diagonal)
{
  const double tolerance = 1e-5 * diagonal;
  std::vector<std::vector<glm::dvec3>> points;
  points.reserve(lines.size());
  for (Stroke& line : lines)
  {
    points.push_back(std::move(line.Points));
  }
  std::vector<Stroke> strokes;
  for (const std::vector<silsmooth::JoinedLine>& path : silsmooth::joinedPaths(points, tolerance))
  {
    Stroke stroke;
    stroke.FirstLine = lines[path.front().Line].FirstLine;
    for (const silsmooth::JoinedLine& piece : path)
    {
      const std::vector<glm::dvec3>& next = points[piece.Line];
      // The joint once: the point the stroke so far ends on.
      const std::size_t skip = stroke.Points.empty() ? 0 : 1;
      if (piece.Reversed)
      {
        stroke.Points.insert(stroke.Points.end(), next.rbegin() + skip, next.rend());
      }
      else
      {
        stroke.Points.insert(stroke.Points.end(), next.begin() + skip, next.end());
      }
    }
    if (path.size() > 1 && glm::length(stroke.Points.back() - stroke.Points.front()) <= tolerance)
    {
      stroke.Points.back() = stroke.Points.front();
    }
    strokes.push_back(std::move(stroke));
  }
  return strokes;
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

    const std::vector<Stroke> strokes = this->JoinLines
      ? JoinedStrokes(LineCells(inPoints, inLines), diagonal)
      : LineCells(inPoints, inLines);
    for (std::size_t s = 0; s < strokes.size(); ++s)
    {
      if (s % 256 == 0)
      {
        if (!vtkSilhouetteFilterSupport::ReportProgress(
              this, static_cast<double>(s) / static_cast<double>(strokes.size())))
        {
          break;
        }
      }
      const Stroke& stroke = strokes[s];
      const silsmooth::StylizedStroke result = silsmooth::stylizeStroke(
        stroke.Points, view, parameters, static_cast<std::uint64_t>(stroke.FirstLine));
      lines->InsertNextCell(static_cast<vtkIdType>(result.points.size()));
      for (std::size_t i = 0; i < result.points.size(); ++i)
      {
        const glm::dvec3& q = result.points[i];
        lines->InsertCellPoint(points->InsertNextPoint(q.x, q.y, q.z));
        offsets->InsertNextTuple2(result.tangentOffset[i], result.normalOffset[i]);
        arcLengths->InsertNextValue(result.arcLength[i]);
      }
      strokeIds->InsertNextValue(stroke.FirstLine);
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
  os << indent << "JoinLines: " << (this->JoinLines ? "On" : "Off") << "\n";
}
