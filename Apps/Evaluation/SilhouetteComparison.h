// Xing's evaluation protocol with numbers instead of impressions: from the
// same cameras, the coarse mesh, coarse + smoothing and the fine reference are
// rendered; their outlines are compared with the fine reference's (and, for
// the sphere and the torus, with the exact silhouette), and whole frames
// (filter plus render) are timed over an orbit.
#ifndef SilhouetteComparison_h
#define SilhouetteComparison_h

#include "EvaluationModels.h"

#include <functional>
#include <string>

#include "vtkSmartPointer.h"

class vtkRenderWindow;
class vtkRenderer;

namespace silhouette_eval
{

struct ComparisonOptions
{
  int Width = 1024;
  int Height = 768;
  int Views = 12;       ///< camera positions for the outline deviations
  int TimedFrames = 30; ///< orbit frames for the whole-frame medians
  double Tolerance = 0.5;
  /// Called with a short line before each long step (may be empty).
  std::function<void(const std::string&)> Progress;
};

/// Figures of one variant (coarse, coarse + smoothing or fine).
struct VariantFigures
{
  double Triangles = 0;     ///< rendered triangles, averaged over the views
  double MeanDeviation = 0; ///< outline distance to the fine reference, px
  double MaxDeviation = 0;
  double MeanExact = -1; ///< outline distance to the exact silhouette, px (-1: none)
  double MaxExact = -1;
  double FilterMilliseconds = 0; ///< median per frame (smoothing only)
  double FrameMilliseconds = 0;  ///< median whole frame: filter + render
};

struct ModelComparison
{
  std::string Name;
  std::string Description;
  long OriginalTriangles = 0;
  VariantFigures Coarse;
  VariantFigures Smoothed;
  VariantFigures Fine;
  double SilhouetteTriangles = 0; ///< averaged over the views
};

ModelComparison CompareModel(const ModelVersions& model, const ComparisonOptions& options);

struct FrameTiming
{
  double Triangles = 0; ///< rendered in the last frame
  double FilterMilliseconds = 0;
  double FrameMilliseconds = 0;
};

/// Whole-frame timing over an orbit of options.TimedFrames frames in a lit,
/// shaded window: each frame moves the camera, updates the filter (when
/// smoothing) and renders to completion. One window serves every timing:
/// creating many GLX windows in a row made VTK 9.1 abort under Xvfb.
class OrbitTimer
{
public:
  explicit OrbitTimer(const ComparisonOptions& options);
  ~OrbitTimer();
  FrameTiming Time(vtkPolyData* mesh, bool smoothing);

private:
  ComparisonOptions Options;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
};

} // namespace silhouette_eval

#endif
