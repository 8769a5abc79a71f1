#include "vtkSilhouetteViewTracker.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"

#include <algorithm>
#include <cstring>

namespace vtkSilhouetteFilterSupport
{

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
  // Bitwise: a NaN in the view compares equal to itself.
  if (!this->Have || std::memcmp(now.data(), this->Last.data(), sizeof(now)) != 0 ||
    viewport != this->LastViewport)
  {
    this->Last = now;
    this->LastViewport = viewport;
    this->Have = true;
    this->Time.Modified();
  }
  return this->Time.GetMTime();
}

} // namespace vtkSilhouetteFilterSupport
