#include "SilhouetteViewSupport.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include "ShadingNormals.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace silsmooth_vtk
{

namespace
{

bool AllFinite(const double* values, int count)
{
  for (int i = 0; i < count; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      return false;
    }
  }
  return true;
}

} // namespace

vtkCamera* ActiveCamera(vtkCamera* camera, vtkRenderer* renderer)
{
  if (camera)
  {
    return camera;
  }
  return renderer && renderer->IsActiveCameraCreated() ? renderer->GetActiveCamera() : nullptr;
}

void ModelMatrixOf(vtkProp3D* prop, vtkMatrix4x4* matrix, double out[16])
{
  if (prop)
  {
    prop->GetMatrix(out);
  }
  else if (matrix)
  {
    std::copy(&matrix->Element[0][0], &matrix->Element[0][0] + 16, out);
  }
  else
  {
    vtkMatrix4x4::Identity(out);
  }
}

std::array<int, 2> ViewportOf(vtkRenderer* renderer, const int fallback[2])
{
  if (renderer)
  {
    const int* size = renderer->GetSize();
    if (size[0] > 0 && size[1] > 0)
    {
      return { size[0], size[1] };
    }
  }
  return { fallback[0], fallback[1] };
}

bool ViewSignature::operator==(const ViewSignature& o) const
{
  return std::memcmp(this, &o, sizeof(o)) == 0;
}

ViewSignature SignatureOf(vtkCamera* camera, const double model[16], std::array<int, 2> viewport)
{
  ViewSignature view; // zeroed as a whole: no padding garbage for memcmp
  std::memset(&view, 0, sizeof(view));
  std::copy(&camera->GetModelViewTransformMatrix()->Element[0][0],
    &camera->GetModelViewTransformMatrix()->Element[0][0] + 16, view.ModelView.begin());
  if (camera->GetUseExplicitProjectionTransformMatrix() &&
    camera->GetExplicitProjectionTransformMatrix())
  {
    std::copy(&camera->GetExplicitProjectionTransformMatrix()->Element[0][0],
      &camera->GetExplicitProjectionTransformMatrix()->Element[0][0] + 16,
      view.ExplicitProjection.begin());
  }
  double* p = view.Projection.data();
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
  camera->GetScreenBottomLeft(p + 13); // with UseOffAxisProjection
  p[16] = camera->GetLeftEye();
  std::copy(model, model + 16, view.Model.begin());
  view.Viewport = viewport;
  return view;
}

vtkMTimeType ViewTracker::Update(
  vtkCamera* camera, const double model[16], std::array<int, 2> viewport)
{
  const ViewSignature view = SignatureOf(camera, model, viewport);
  if (!this->HaveView || view != this->Last)
  {
    this->Last = view;
    this->HaveView = true;
    this->Time.Modified();
  }
  return this->Time.GetMTime();
}

std::string MakeViewGeometry(vtkCamera* camera, const double model[16], std::array<int, 2> viewport,
  silsmooth::ViewGeometry& view)
{
  double modelView[16];
  vtkMatrix4x4::Multiply4x4(
    &camera->GetModelViewTransformMatrix()->Element[0][0], model, modelView);
  const double determinant = vtkMatrix4x4::Determinant(modelView);
  if (!AllFinite(model, 16) || !AllFinite(modelView, 16) || !(std::abs(determinant) > 0.0) ||
    !std::isfinite(determinant) || model[12] != 0.0 || model[13] != 0.0 || model[14] != 0.0 ||
    model[15] != 1.0)
  {
    return "The view is degenerate: the model matrix or the camera is singular, not "
           "affine, or not finite.";
  }
  if (viewport[0] < 1 || viewport[1] < 1)
  {
    return "The viewport size must be at least 1 x 1 pixels, not " + std::to_string(viewport[0]) +
      " x " + std::to_string(viewport[1]) + ".";
  }
  double inverse[16];
  vtkMatrix4x4::Invert(modelView, inverse);

  view.Parallel = camera->GetParallelProjection() != 0;
  view.ViewportWidth = viewport[0];
  view.ViewportHeight = viewport[1];
  double eye[4] = { 0, 0, 0, 1 };
  vtkMatrix4x4::MultiplyPoint(inverse, eye, eye);
  view.Eye = glm::dvec3(eye[0], eye[1], eye[2]) / eye[3];
  double toward[4] = { 0, 0, 1, 0 };
  vtkMatrix4x4::MultiplyPoint(inverse, toward, toward);
  view.TowardViewer = silsmooth::safeNormalize(glm::dvec3(toward[0], toward[1], toward[2]));

  // Model -> clip = (projection * view) * model, into glm's column-major form.
  double composite[16];
  vtkMatrix4x4::DeepCopy(composite,
    camera->GetCompositeProjectionTransformMatrix(
      static_cast<double>(viewport[0]) / viewport[1], -1.0, 1.0));
  double clip[16];
  vtkMatrix4x4::Multiply4x4(composite, model, clip);
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      view.ModelToClip[col][row] = clip[row * 4 + col];
    }
  }
  return std::string();
}

bool ExtractTriangles(vtkPolyData* input, std::vector<silsmooth::Triangle>& triangles,
  std::vector<vtkIdType>& triangleCell, vtkIdType& tooSmall)
{
  triangles.clear();
  triangleCell.clear();
  tooSmall = 0;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType cellOffset = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkIdType cellId = cellOffset;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cellId)
  {
    polys->GetCurrentCell(npts, pts);
    tooSmall += npts < 3 ? 1 : 0;
    for (vtkIdType k = 1; k + 1 < npts; ++k)
    {
      triangles.push_back({ pts[0], pts[k], pts[k + 1] });
      triangleCell.push_back(cellId);
    }
  }
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cellId)
  {
    strips->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      if (k % 2 == 0)
      {
        triangles.push_back({ pts[k], pts[k + 1], pts[k + 2] });
      }
      else
      {
        triangles.push_back({ pts[k + 1], pts[k], pts[k + 2] });
      }
      triangleCell.push_back(cellId);
    }
  }
  for (const silsmooth::Triangle& t : triangles)
  {
    for (const silsmooth::Id id : t)
    {
      if (id < 0 || id >= numPoints)
      {
        return false;
      }
    }
  }
  return true;
}

std::vector<glm::dvec3> PointNormalsOf(vtkPolyData* input)
{
  std::vector<glm::dvec3> normals;
  vtkDataArray* given = input->GetPointData()->GetNormals();
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (given && given->GetNumberOfComponents() == 3 && given->GetNumberOfTuples() == numPoints)
  {
    normals.resize(static_cast<std::size_t>(numPoints));
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      double n[3];
      given->GetTuple(i, n);
      normals[static_cast<std::size_t>(i)] = glm::dvec3(n[0], n[1], n[2]);
    }
  }
  return normals;
}

} // namespace silsmooth_vtk
