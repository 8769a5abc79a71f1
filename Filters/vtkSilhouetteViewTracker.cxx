#include "vtkSilhouetteViewTracker.h"

#include "vtkCamera.h"
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

vtkMTimeType ViewTracker::Update(
  vtkCamera* camera, const double model[16], std::array<int, 2> viewport)
{
  std::array<double, 16 + 16 + 17 + 16> now{};
  double* v = now.data();
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
  p[16] = camera->GetLeftEye();
  std::copy(model, model + 16, v + 49);
  // Bitwise (a NaN in the view compares equal to itself) on both sides of
  // the view angle, which SameViewAngle compares.
  constexpr std::size_t angle = 32;
  const bool same = this->Have && viewport == this->LastViewport &&
    SameViewAngle(now[angle], this->Last[angle]) &&
    std::memcmp(now.data(), this->Last.data(), angle * sizeof(double)) == 0 &&
    std::memcmp(now.data() + angle + 1, this->Last.data() + angle + 1,
      (now.size() - angle - 1) * sizeof(double)) == 0;
  if (!same)
  {
    this->Last = now;
    this->LastViewport = viewport;
    this->Have = true;
    this->Time.Modified();
  }
  return this->Time.GetMTime();
}

} // namespace vtkSilhouetteFilterSupport
