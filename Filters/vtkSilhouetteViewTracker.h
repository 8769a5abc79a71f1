// The view a view-dependent filter or mapper last smoothed for, compared by
// value (part of vtkSilhouetteFilterSupport, in a header of its own with
// VTK types only, so that the render-time mapper's module can use it too).
// Private to the modules' build (not wrapped, not installed).
#ifndef vtkSilhouetteViewTracker_h
#define vtkSilhouetteViewTracker_h

#include "vtkTimeStamp.h"
#include "vtkType.h"

#include <array>

class vtkCamera;

namespace vtkSilhouetteFilterSupport
{

/// Remembers the last view a filter saw, compared by value. The camera's own
/// MTime is not enough: renderers reset its clipping range every frame, which
/// would re-run the filter for nothing, while a prop's matrix or a window's
/// size can change without touching the camera at all. So the view is the
/// camera's model-view matrix (position, orientation, model and user-view
/// transforms), its projection parameters (not the clipping range) and user
/// transform (applied after the projection), the
/// model matrix and the viewport, compared bitwise (a NaN in the view compares
/// equal to itself instead of re-running the filter on every update), except
/// for the view angle, which may differ by a float's rounding
/// (SameViewAngle).
class ViewTracker
{
public:
  /// A view, by value: what Update compares.
  struct Key
  {
    std::array<double, 16 + 16 + 17 + 16 + 16> Values{};
    std::array<int, 2> Viewport{};
  };
  static Key KeyOf(vtkCamera* camera, const double model[16], std::array<int, 2> viewport);
  /// Whether two keys are one view (bitwise, but for SameViewAngle).
  static bool SameView(const Key& a, const Key& b);

  /// The time the view last changed (updated by this call).
  vtkMTimeType Update(vtkCamera* camera, const double model[16], std::array<int, 2> viewport);

  /// Whether two view angles (degrees) are one view's: bitwise equal, or
  /// apart by at most a few floats' rounding (a window-to-image grab's copy
  /// of the camera).
  static bool SameViewAngle(double now, double last);

private:
  Key Last;
  bool Have = false;
  vtkTimeStamp Time;
};

} // namespace vtkSilhouetteFilterSupport

#endif
