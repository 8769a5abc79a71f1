#ifndef Figures_h
#define Figures_h

#include <vtkType.h>

#include <array>
#include <optional>
#include <ostream>
#include <string>

class vtkCamera;
class vtkPolyData;

namespace cli
{

struct CameraOptions;

/// What `smooth` and `render` print about one run of the filter.
struct Figures
{
  std::string Input;
  std::optional<std::string> Output;
  vtkIdType InputTriangles = 0;
  vtkIdType OutputTriangles = 0;
  vtkIdType SilhouetteTriangles = 0;
  vtkIdType NewTriangles = 0;
  vtkIdType NewPoints = 0;
  /// Silhouette triangles at cone apexes, kept on the mesh's edges.
  vtkIdType ApexTriangles = 0;
  /// The fold guard's fallbacks (vtkSilhouetteSmoothingFilter::FoldPrevention).
  vtkIdType ChordFallbacks = 0;
  vtkIdType StraightSilhouettePoints = 0;
  vtkIdType StraightFeatureSegments = 0;
  vtkIdType PinnedPoints = 0;
  vtkIdType CrowdedTriangles = 0;
  vtkIdType UnresolvedFolds = 0;
  double PrepareMilliseconds = 0.0;
  double FilterMilliseconds = 0.0;
  double Tolerance = 0.0;
  std::array<int, 2> Viewport{};
  std::array<double, 3> CameraPosition{};
  std::array<double, 3> FocalPoint{};
  std::array<double, 3> ViewUp{};
  double ViewAngle = 0.0;
  bool Parallel = false;
  /// With `render --lod`: the file's triangles (InputTriangles are the
  /// extracted mesh's) and the time the hierarchy and its first cut took.
  struct LevelOfDetail
  {
    long long SourceTriangles = 0;
    double BuildMilliseconds = 0.0;
  };
  std::optional<LevelOfDetail> Lod;
};

/// `text` as a JSON string literal, quotes and control characters escaped.
std::string JsonString(const std::string& text);

/// Gathers the figures; the counts come from the field data of the filter's
/// output. Throws RuntimeError if one of those arrays is missing.
Figures CollectFigures(const std::string& input, const std::optional<std::string>& output,
  vtkPolyData* smoothed, double prepareMilliseconds, double filterMilliseconds,
  const CameraOptions& options, vtkCamera* camera);

/// One "name: value" line per figure.
void PrintFiguresAsText(std::ostream& out, const Figures& figures);

/// One JSON object on one line.
void PrintFiguresAsJson(std::ostream& out, const Figures& figures);

} // namespace cli

#endif
