#include "Figures.h"

#include "CameraOptions.h"
#include "CliErrors.h"
#include "Smoothing.h"
#include "TextFormat.h"

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace cli
{
namespace
{

vtkIdType CountFromFieldData(vtkPolyData* smoothed, const char* name)
{
  vtkDataArray* array = smoothed->GetFieldData()->GetArray(name);
  if (!array || array->GetNumberOfTuples() < 1)
  {
    throw RuntimeError(std::string("the filter's output has no field data '") + name + "'");
  }
  return static_cast<vtkIdType>(array->GetTuple1(0));
}

std::array<double, 3> ToArray(const double v[3])
{
  return { v[0], v[1], v[2] };
}

std::string JsonVector(const std::array<double, 3>& v)
{
  return "[" + JsonNumber(v[0]) + ", " + JsonNumber(v[1]) + ", " + JsonNumber(v[2]) + "]";
}

std::string TextVector(const std::array<double, 3>& v)
{
  std::ostringstream text;
  text << std::setprecision(6) << v[0] << " " << v[1] << " " << v[2];
  return text.str();
}

// Milliseconds to the microsecond: finer is noise.
double RoundToMicroseconds(double milliseconds)
{
  return std::round(milliseconds * 1000.0) / 1000.0;
}

} // namespace

std::string JsonString(const std::string& text)
{
  std::string quoted = "\"";
  for (const char c : text)
  {
    switch (c)
    {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\t':
        quoted += "\\t";
        break;
      case '\r':
        quoted += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20)
        {
          char escaped[8];
          std::snprintf(escaped, sizeof(escaped), "\\u%04x", static_cast<unsigned>(c));
          quoted += escaped;
        }
        else
        {
          quoted += c; // UTF-8 passes through
        }
    }
  }
  return quoted + "\"";
}

Figures CollectFigures(const std::string& input, const std::optional<std::string>& output,
  vtkPolyData* smoothed, double prepareMilliseconds, double filterMilliseconds,
  const CameraOptions& options, vtkCamera* camera)
{
  Figures figures;
  figures.Input = input;
  figures.Output = output;
  figures.InputTriangles = CountFromFieldData(smoothed, "InputTriangleCount");
  figures.OutputTriangles = CountFromFieldData(smoothed, "OutputTriangleCount");
  figures.SilhouetteTriangles = CountFromFieldData(smoothed, "SilhouetteTriangleCount");
  figures.NewTriangles = CountFromFieldData(smoothed, "NewTriangleCount");
  figures.NewPoints = CountFromFieldData(smoothed, "NewPointCount");
  figures.ApexTriangles = CountFromFieldData(smoothed, "ApexTriangleCount");
  figures.ChordFallbacks = CountFromFieldData(smoothed, "ChordFallbackCount");
  figures.StraightSilhouettePoints = CountFromFieldData(smoothed, "StraightSilhouettePointCount");
  figures.StraightFeatureSegments = CountFromFieldData(smoothed, "StraightFeatureSegmentCount");
  figures.PinnedPoints = CountFromFieldData(smoothed, "PinnedPointCount");
  figures.CrowdedTriangles = CountFromFieldData(smoothed, "CrowdedTriangleCount");
  figures.UnresolvedFolds = CountFromFieldData(smoothed, "UnresolvedFoldCount");
  figures.PrepareMilliseconds = RoundToMicroseconds(prepareMilliseconds);
  figures.FilterMilliseconds = RoundToMicroseconds(filterMilliseconds);
  figures.Tolerance = options.Tolerance;
  figures.Viewport = options.ViewportSize;
  figures.CameraPosition = ToArray(camera->GetPosition());
  figures.FocalPoint = ToArray(camera->GetFocalPoint());
  figures.ViewUp = ToArray(camera->GetViewUp());
  figures.ViewAngle = camera->GetViewAngle();
  figures.Parallel = camera->GetParallelProjection() != 0;
  return figures;
}

void PrintFiguresAsText(std::ostream& out, const Figures& figures)
{
  out << "input:                " << figures.Input << "\n"
      << "output:               " << figures.Output.value_or("(none)") << "\n"
      << "input triangles:      " << figures.InputTriangles << "\n"
      << "output triangles:     " << figures.OutputTriangles << "\n"
      << "silhouette triangles: " << figures.SilhouetteTriangles << "\n"
      << "new triangles:        " << figures.NewTriangles << "\n"
      << "new points:           " << figures.NewPoints << "\n"
      << "apex triangles:       " << figures.ApexTriangles << "\n"
      << "fold fallbacks:       " << figures.ChordFallbacks << " chord, "
      << figures.StraightSilhouettePoints << " straight points, " << figures.StraightFeatureSegments
      << " straight feature segments, " << figures.PinnedPoints << " pinned points, "
      << figures.CrowdedTriangles << " crowded, " << figures.UnresolvedFolds << " unresolved\n"
      << "first update:         " << std::fixed << std::setprecision(3)
      << figures.PrepareMilliseconds << " ms (prepares the mesh, then one frame)\n"
      << "filter time:          " << figures.FilterMilliseconds << " ms per frame (median of "
      << TimedFilterRuns << " runs)\n"
      << std::defaultfloat << std::setprecision(6) << "tolerance:            " << figures.Tolerance
      << " px\n"
      << "viewport:             " << figures.Viewport[0] << "x" << figures.Viewport[1] << "\n"
      << "camera position:      " << TextVector(figures.CameraPosition) << "\n"
      << "focal point:          " << TextVector(figures.FocalPoint) << "\n"
      << "view up:              " << TextVector(figures.ViewUp) << "\n"
      << "view angle:           " << figures.ViewAngle << " deg\n"
      << "projection:           " << (figures.Parallel ? "parallel" : "perspective") << "\n";
}

void PrintFiguresAsJson(std::ostream& out, const Figures& figures)
{
  out << "{\"input\": " << JsonString(figures.Input)
      << ", \"output\": " << (figures.Output ? JsonString(*figures.Output) : "null")
      << ", \"input_triangles\": " << figures.InputTriangles
      << ", \"output_triangles\": " << figures.OutputTriangles
      << ", \"silhouette_triangles\": " << figures.SilhouetteTriangles
      << ", \"new_triangles\": " << figures.NewTriangles
      << ", \"new_points\": " << figures.NewPoints
      << ", \"apex_triangles\": " << figures.ApexTriangles
      << ", \"fold_fallbacks\": {\"chord_triangles\": " << figures.ChordFallbacks
      << ", \"straight_points\": " << figures.StraightSilhouettePoints
      << ", \"straight_feature_segments\": " << figures.StraightFeatureSegments
      << ", \"pinned_points\": " << figures.PinnedPoints
      << ", \"crowded_triangles\": " << figures.CrowdedTriangles
      << ", \"unresolved\": " << figures.UnresolvedFolds << "}"
      << ", \"prepare_ms\": " << JsonNumber(figures.PrepareMilliseconds)
      << ", \"filter_ms\": " << JsonNumber(figures.FilterMilliseconds)
      << ", \"tolerance\": " << JsonNumber(figures.Tolerance) << ", \"viewport\": ["
      << figures.Viewport[0] << ", " << figures.Viewport[1] << "]"
      << ", \"camera\": {\"position\": " << JsonVector(figures.CameraPosition)
      << ", \"focal_point\": " << JsonVector(figures.FocalPoint)
      << ", \"view_up\": " << JsonVector(figures.ViewUp)
      << ", \"view_angle\": " << JsonNumber(figures.ViewAngle)
      << ", \"parallel\": " << (figures.Parallel ? "true" : "false") << "}";
  if (figures.Lod)
  {
    out << ", \"level_of_detail\": {\"source_triangles\": " << figures.Lod->SourceTriangles
        << ", \"build_ms\": " << JsonNumber(figures.Lod->BuildMilliseconds) << "}";
  }
  out << "}\n";
}

} // namespace cli
