// The downstream program of the install test: smooths the silhouette of an
// 80-triangle icosphere for one camera with the installed module and checks
// that the result is new geometry: more triangles than it got, some of them
// marked NewGeometry, and the counts in the field data agree. It also makes
// the render-time mapper of the installed rendering module and gives it the
// same settings (no window: linking and the settings are what is checked).
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIcosphereSource.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSilhouetteSmoothingFilter.h>
#include <vtkSilhouetteSmoothingMapper.h>
#include <vtkUnsignedCharArray.h>

#include <cstdio>

int main()
{
  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(1);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, 0.0, 5.0);
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputConnection(sphere->GetOutputPort());
  smoother->SetCamera(camera);
  smoother->Update();
  vtkPolyData* out = smoother->GetOutput();
  auto* kinds = vtkUnsignedCharArray::SafeDownCast(out->GetCellData()->GetArray("NewGeometry"));
  auto* count = vtkIdTypeArray::SafeDownCast(out->GetFieldData()->GetArray("OutputTriangleCount"));
  vtkIdType marked = 0;
  for (vtkIdType i = 0; kinds && i < kinds->GetNumberOfValues(); ++i)
  {
    marked += kinds->GetValue(i) != 0 ? 1 : 0;
  }
  std::printf("consumer: 80 triangles in, %lld out, %lld new\n",
    static_cast<long long>(out->GetNumberOfPolys()), static_cast<long long>(marked));
  if (!kinds || !count || count->GetValue(0) != out->GetNumberOfPolys() ||
    out->GetNumberOfPolys() <= 80 || marked == 0)
  {
    std::printf("consumer: FAILED\n");
    return 1;
  }
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->GetSmoothingFilter()->SetTolerance(0.25);
  if (mapper->GetSmoothingFilter()->GetTolerance() != 0.25 ||
    !mapper->GetSmoothingFilter()->GetFrustumCulling())
  {
    std::printf("consumer: FAILED: the mapper's smoothing settings\n");
    return 1;
  }
  return 0;
}
