#include "vtkSilhouetteViewTracker.h"

#include "vtkCamera.h"
#include "vtkHomogeneousTransform.h"
#include "vtkMatrix4x4.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

namespace vtkSilhouetteFilterSupport
{

bool ViewTracker::SameViewAngle(double now, double last)
{
  // vtkWindowToImageFilter renders its grab with a copy of the camera whose
  // view angle went through a float (and back through tan and atan): that is
  // the same view, and smoothing it again would double a screenshot's cost.
  // A few floats' rounding moves a silhouette by under 1e-3 px.
  constexpr double Rounding = 4.0 * FLT_EPSILON;
  return std::memcmp(&now, &last, sizeof(double)) == 0 ||
    (std::isfinite(now) && std::isfinite(last) &&
      std::abs(now - last) <= Rounding * std::max(std::abs(now), std::abs(last)));
}

ViewTracker::Key ViewTracker::KeyOf(
  vtkCamera* camera, const double model[16], std::array<int, 2> viewport)
{
  Key key;
  key.Viewport = viewport;
  double* v = key.Values.data();
  std::copy(&camera->GetModelViewTransformMatrix()->Element[0][0],
    &camera->GetModelViewTransformMatrix()->Element[0][0] + 16, v);
  if (camera->GetUseExplicitProjectionTransformMatrix() &&
    camera->GetExplicitProjectionTransformMatrix())
  {
    std::copy(&camera->GetExplicitProjectionTransformMatrix()->Element[0][0],
      &camera->GetExplicitProjectionTransformMatrix()->Element[0][0] + 16, v + 16);
  }
  double* p = v + 32;
  p[0] = camera->GetViewAngle();
  p[1] = camera->GetParallelScale();
  p[2] = camera->GetParallelProjection();
  p[3] = camera->GetUseHorizontalViewAngle();
  camera->GetWindowCenter(p + 4);
  camera->GetViewShear(p + 6);
  p[9] = camera->GetEyeAngle();
  p[10] = camera->GetUseExplicitProjectionTransformMatrix();
  p[11] = camera->GetUseOffAxisProjection();
  p[12] = camera->GetEyeSeparation();
  camera->GetScreenBottomLeft(p + 13);
  // Which eye draws, while a stereo render draws one (its projection is
  // sheared for it); 0 otherwise.
  p[16] = camera->GetStereo() ? (camera->GetLeftEye() ? 1.0 : 2.0) : 0.0;
  std::copy(model, model + 16, v + 49);
  // The user transform's matrix, by value: it can change without the camera.
  if (vtkHomogeneousTransform* user = camera->GetUserTransform())
  {
    const vtkMatrix4x4* matrix = user->GetMatrix();
    std::copy(&matrix->Element[0][0], &matrix->Element[0][0] + 16, v + 65);
  }
  return key;
}

bool ViewTracker::SameView(const Key& a, const Key& b)
{
  // Bitwise (a NaN in the view compares equal to itself) on both sides of
  // the view angle, which SameViewAngle compares.
  constexpr std::size_t angle = 32;
  return a.Viewport == b.Viewport && SameViewAngle(a.Values[angle], b.Values[angle]) &&
    std::memcmp(a.Values.data(), b.Values.data(), angle * sizeof(double)) == 0 &&
    std::memcmp(a.Values.data() + angle + 1, b.Values.data() + angle + 1,
      (a.Values.size() - angle - 1) * sizeof(double)) == 0;
}

vtkMTimeType ViewTracker::Update(
  vtkCamera* camera, const double model[16], std::array<int, 2> viewport)
{
  const Key now = KeyOf(camera, model, viewport);
  if (!this->Have || !SameView(now, this->Last))
  {
    this->Last = now;
    this->Have = true;
    this->Time.Modified();
  }
  return this->Time.GetMTime();
}

} // namespace vtkSilhouetteFilterSupport
