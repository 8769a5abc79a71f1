#ifndef Smoothing_h
#define Smoothing_h

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkCamera;
class vtkPolyData;
class vtkSilhouetteSmoothingFilter;

namespace cli
{

struct CameraOptions;

/// How many per-frame runs the median filter time is taken over.
constexpr int TimedFilterRuns = 5;

struct SmoothingRun
{
  /// The filter, up to date for `camera`: feed mappers from it.
  vtkSmartPointer<vtkSilhouetteSmoothingFilter> Filter;
  /// Wall time of the first Update(): the view-independent preparation
  /// (triangulation, edge table, normals) plus one frame, in milliseconds.
  double PrepareMilliseconds = 0.0;
  /// Median wall time of one frame once prepared: what every camera move
  /// costs, in milliseconds.
  double MedianMilliseconds = 0.0;
  /// The filter's warnings (one line each), e.g. about the input's normals.
  std::vector<std::string> Warnings;
};

/**
 * Runs vtkSilhouetteSmoothingFilter on `mesh` for `camera` and the viewport
 * and tolerance of `options`: once to prepare, then TimedFilterRuns more
 * frames (re-executed with Modified(), which keeps the prepared cache) for
 * the median per-frame time. Throws RuntimeError with the filter's error
 * (e.g. NaN coordinates).
 */
SmoothingRun SmoothSilhouette(vtkPolyData* mesh, vtkCamera* camera, const CameraOptions& options);

/// Writes one of the filter's warnings to stderr as one line
/// ("silhouette: warning: ..."), the filter's settings it names given as the
/// options that set them (WeldTolerance as --weld-tolerance).
void PrintFilterWarning(const std::string& warning);

/// Sets the filter's tolerance, feature and perturbation options from `options`.
void ApplySmoothingOptions(vtkSilhouetteSmoothingFilter* filter, const CameraOptions& options);

} // namespace cli

#endif
