// vtkFaceSilhouetteLines (issue 8): the face-based silhouette of Xing's
// Fig. 6b. Known answers on an icosphere with exact normals: every point on
// its edge where the linear g is zero, one segment per silhouette triangle,
// closed loops, near the exact contour circle; the view follows the camera
// by value; a prop's matrix equals transforming the data; errors.
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include "vtkFaceSilhouetteLines.h"

#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace
{

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool CheckSphereViews()
{
  vtkSmartPointer<vtkPolyData> sphere = silhouette_test::Icosphere(3); // 1,280 triangles
  vtkNew<vtkFaceSilhouetteLines> lines;
  lines->SetInputData(sphere);
  double worst = 0.0;
  int views = 0;
  for (const auto& direction : silhouette_test::SphereDirections(24))
  {
    const double distance = 3.0 + 0.1 * views;
    vtkSmartPointer<vtkCamera> camera = silhouette_test::CameraLookingAtOrigin(direction, distance);
    lines->SetCamera(camera);
    lines->Update();
    vtkPolyData* out = lines->GetOutput();
    vtkDataArray* ends = out->GetPointData()->GetArray("EdgeEnds");
    vtkDataArray* t = out->GetPointData()->GetArray("EdgeParameter");
    CHECK(ends && t && out->GetPointData()->GetNormals(), "the documented arrays");
    const vtkIdType triangles =
      vtkIdTypeArray::SafeDownCast(out->GetFieldData()->GetArray("SilhouetteTriangleCount"))
        ->GetValue(0);
    double eye[3];
    camera->GetPosition(eye);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      // On the edge between its two ends, at the zero of the linear g
      // (exact normals: g(V) = V . (E - V) = V . E - 1).
      double p[3], a[3], b[3];
      out->GetPoint(i, p);
      sphere->GetPoint(static_cast<vtkIdType>(ends->GetComponent(i, 0)), a);
      sphere->GetPoint(static_cast<vtkIdType>(ends->GetComponent(i, 1)), b);
      const double s = t->GetTuple1(i);
      CHECK(s >= 0.0 && s <= 1.0, "the parameter is on the edge");
      for (int k = 0; k < 3; ++k)
      {
        CHECK(std::abs(p[k] - (a[k] + s * (b[k] - a[k]))) < 1e-12, "the point is on its edge");
      }
      const double ga = Dot(a, eye) - Dot(a, a);
      const double gb = Dot(b, eye) - Dot(b, b);
      CHECK((ga >= 0) != (gb >= 0), "the edge is mixed");
      CHECK(std::abs((1 - s) * ga + s * gb) < 1e-9, "g interpolates to zero there");
      // The exact contour: |p| = 1 and p . E = 1.
      const double d = std::sqrt(Dot(eye, eye));
      const double along = Dot(p, eye) / d;
      double across[3];
      for (int k = 0; k < 3; ++k)
      {
        across[k] = p[k] - along * eye[k] / d;
      }
      worst = std::max(worst,
        std::hypot(along - 1.0 / d, std::sqrt(Dot(across, across)) - std::sqrt(1 - 1 / (d * d))));
    }
    // Closed loops that use every segment once: one segment per silhouette
    // triangle, one point per mixed edge (each shared by two segments).
    vtkIdType segments = 0;
    auto it = vtk::TakeSmartPointer(out->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      CHECK(n >= 4 && ids[0] == ids[n - 1], "every polyline is a closed loop");
      segments += n - 1;
    }
    CHECK(segments == triangles && triangles > 0, "one segment per silhouette triangle");
    CHECK(out->GetNumberOfPoints() == segments, "every point is shared by two segments");
    ++views;
  }
  // Chords of a level-3 icosphere (edges about 0.16): the sagitta is ~0.003.
  std::printf(
    "icosphere 3, %d views: largest distance from the exact contour %.5f\n", views, worst);
  CHECK(worst < 0.01, "near the exact contour");
  return true;
}

bool CheckPipeline()
{
  vtkSmartPointer<vtkPolyData> sphere = silhouette_test::Icosphere(2);
  vtkNew<vtkFaceSilhouetteLines> lines;
  lines->SetInputData(sphere);
  vtkSmartPointer<vtkCamera> camera = silhouette_test::CameraLookingAtOrigin({ 0.2, 0.3, 1 }, 4);
  lines->SetCamera(camera);
  lines->Update();
  const vtkMTimeType first = lines->GetMTime();
  camera->SetClippingRange(0.5, 100);
  CHECK(lines->GetMTime() == first, "a clipping-range change does not re-run it");
  camera->Azimuth(10);
  CHECK(lines->GetMTime() > first, "a camera move re-runs it");

  // A prop matrix gives what transforming the data gives.
  vtkNew<vtkTransform> transform;
  transform->Translate(0.3, -0.2, 0.1);
  transform->RotateWXYZ(30, 1, 2, 3);
  transform->Scale(1.5, 1.5, 1.5);
  lines->SetModelMatrix(transform->GetMatrix());
  lines->Update();
  vtkNew<vtkPolyData> moved;
  moved->DeepCopy(lines->GetOutput());
  moved->GetPoints()->Modified();
  vtkNew<vtkTransformPolyDataFilter> apply;
  apply->SetTransform(transform);
  apply->SetInputData(sphere);
  apply->Update();
  vtkNew<vtkFaceSilhouetteLines> direct;
  direct->SetInputConnection(apply->GetOutputPort());
  direct->SetCamera(camera);
  direct->Update();
  CHECK(direct->GetOutput()->GetNumberOfPoints() == moved->GetNumberOfPoints(),
    "the same number of points with a model matrix");
  double worst = 0.0;
  for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    transform->TransformPoint(moved->GetPoint(i), p);
    direct->GetOutput()->GetPoint(i, q);
    worst =
      std::max({ worst, std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2]) });
  }
  CHECK(worst < 1e-5, "a model matrix is the same as transforming the data");
  return true;
}

bool CheckErrors()
{
  vtkNew<vtkFaceSilhouetteLines> lines;
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkTest::ErrorObserver> executive;
  lines->AddObserver(vtkCommand::ErrorEvent, errors);
  lines->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  lines->SetInputData(silhouette_test::Icosphere(1));
  CHECK(lines->GetExecutive()->Update() == 0, "no camera fails");
  CHECK(errors->GetError() &&
      std::string(errors->GetErrorMessage()).find("No camera") != std::string::npos,
    "the missing camera is named");
  vtkNew<vtkPolyData> empty;
  lines->SetInputData(empty);
  lines->SetCamera(silhouette_test::CameraLookingAtOrigin({ 0, 0, 1 }, 3));
  CHECK(lines->GetExecutive()->Update() == 1, "empty input is fine");
  CHECK(lines->GetOutput()->GetNumberOfPoints() == 0, "empty input gives empty output");
  return true;
}

} // namespace

int TestFaceSilhouetteLines(int, char*[])
{
  bool ok = CheckSphereViews();
  ok = CheckPipeline() && ok;
  ok = CheckErrors() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
