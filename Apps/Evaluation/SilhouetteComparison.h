// Xing's evaluation protocol with numbers instead of impressions: from the
// same cameras, the coarse mesh, coarse + smoothing (Wang et al. 2008), the
// earlier methods it is compared with (Wang et al. 2003 boundary curves, and
// PN triangles at the level whose triangle count is nearest ours) and the fine
// reference are rendered; their outlines are compared with the fine
// reference's (and, for every analytic model, with the exact silhouette: the
// sphere's circle in closed form, the other surfaces' outlines through
// ExactSurface's very fine stand-ins, EvaluationModels.h),
// whole frames (filter plus render) are timed over an orbit, and temporal
// coherence is measured over consecutive 1-degree frames.
#ifndef SilhouetteComparison_h
#define SilhouetteComparison_h

#include "EvaluationModels.h"

#include <functional>
#include <string>

#include "vtkSmartPointer.h"

class vtkPolyData;
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
  /// 1-degree steps of the coherence orbit (0: no coherence measure).
  int CoherenceSteps = 30;
  double Tolerance = 0.5;
  /// Called with a short line before each long step (may be empty).
  std::function<void(const std::string&)> Progress;
};

/// Figures of one variant (coarse, coarse + smoothing, Wang 2003, PN
/// triangles or fine).
struct VariantFigures
{
  double Triangles = 0;     ///< rendered triangles, averaged over the views
  double MeanDeviation = 0; ///< outline distance to the fine reference, px
  double MaxDeviation = 0;
  double MeanExact = -1; ///< outline distance to the exact silhouette, px (-1: none)
  double MaxExact = -1;
  double FilterMilliseconds = 0; ///< median per frame (view-dependent filters); PN: once
  double FrameMilliseconds = 0;  ///< median whole frame: filter + render
  /// Temporal coherence over an orbit in 1-degree steps: each step compares
  /// the outline with the outline one step before (both ways, by distance
  /// transform). CoherenceMean: the mean distance of a step, averaged over
  /// the steps (how far the outline moves); CoherenceMax: the largest
  /// distance in any step (the worst local jump), px (-1: not measured).
  /// CoherenceRatio: CoherenceMean over the fine reference's (1: the outline
  /// moves as the smooth surface's does; more: it jumps about).
  double CoherenceMean = -1;
  double CoherenceMax = -1;
  double CoherenceRatio = -1;
  /// The largest amount by which a step's largest distance exceeds the fine
  /// reference's in the same step, px: a jump the smooth surface did not make.
  double CoherenceExcess = -1;
};

struct ModelComparison
{
  std::string Name;
  std::string Description;
  long OriginalTriangles = 0;
  VariantFigures Coarse;
  VariantFigures Smoothed;
  VariantFigures Wang2003; ///< vtkBoundaryCurveSmoothingFilter, same tolerance
  VariantFigures PN;       ///< vtkPNTriangleFilter at PNLevel
  int PNLevel = 1;         ///< k >= 1 whose count is nearest the smoothed one
  VariantFigures Fine;
  double SilhouetteTriangles = 0; ///< averaged over the views
};

ModelComparison CompareModel(const ModelVersions& model, const ComparisonOptions& options);

/// The view-th of `views` cameras of the evaluation's orbit around `mesh`:
/// the framing camera (vtkRenderer::ResetCamera on the bounds, 30-degree view
/// angle) turned by azimuth, the elevation swinging between -25 and +25
/// degrees. The renderer must be in a window of the measuring size.
void PlaceCamera(vtkRenderer* renderer, vtkPolyData* mesh, int view, int views);

struct FrameTiming
{
  double Triangles = 0; ///< rendered in the last frame
  double FilterMilliseconds = 0;
  double FrameMilliseconds = 0;
};

/// The view-dependent filter run in every frame of a timing.
enum class FrameFilter
{
  None,
  Smoothing2008,
  BoundaryCurves2003
};

/// The PN level k >= 1 whose count, triangles x (k+1)^2, is nearest `target`
/// (k = 0 would be the coarse mesh itself).
int NearestPNLevel(double triangles, double target);

/// Whole-frame timing over an orbit of options.TimedFrames frames in a lit,
/// shaded window: each frame moves the camera, updates the filter (when
/// smoothing) and renders to completion. One window serves every timing:
/// creating many GLX windows in a row made VTK 9.1 abort under Xvfb.
class OrbitTimer
{
public:
  explicit OrbitTimer(const ComparisonOptions& options);
  ~OrbitTimer();
  FrameTiming Time(vtkPolyData* mesh, bool smoothing)
  {
    return this->Time(mesh, smoothing ? FrameFilter::Smoothing2008 : FrameFilter::None);
  }
  FrameTiming Time(vtkPolyData* mesh, FrameFilter filter);

private:
  ComparisonOptions Options;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
};

} // namespace silhouette_eval

#endif
