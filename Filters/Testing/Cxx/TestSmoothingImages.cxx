// Image regression (issue 2): the sphere, the torus and the coarse bunny,
// each shaded after smoothing (left) and as a wireframe with the new geometry
// in red (right, Xing's Fig. 1, third panel), in one window compared with
// Testing/Data/Baseline/TestSmoothingImages.png.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include "SilhouetteTestSupport.h"

#include <cstdio>

namespace
{

void AddPanel(vtkRenderWindow* window, vtkPolyData* mesh, int row, int column, double azimuth,
  double elevation, bool newGeometry)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(0.5 * column, 1.0 - (row + 1) / 3.0, 0.5 * (column + 1), 1.0 - row / 3.0);
  renderer->SetBackground(1, 1, 1);
  window->AddRenderer(renderer);

  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(mesh);
  smoother->SetRenderer(renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(smoother->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  silhouette_test::StyleImageActor(mapper, actor, newGeometry ? 1 : 0);
  renderer->AddActor(actor);
  renderer->ResetCamera(mesh->GetBounds());
  renderer->GetActiveCamera()->Azimuth(azimuth);
  renderer->GetActiveCamera()->Elevation(elevation);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->GetActiveCamera()->Zoom(1.4);
  renderer->ResetCameraClippingRange();
}

} // namespace

int TestSmoothingImages(int argc, char* argv[])
{
  const silhouette_test::SphereTorusBunny meshes =
    silhouette_test::MakeSphereTorusBunny(argc, argv);
  if (!meshes.Bunny)
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(900, 900);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  vtkPolyData* rowMeshes[3] = { meshes.Sphere, meshes.Torus, meshes.Bunny };
  const double views[3][2] = { { 20, 15 }, { 10, 50 }, { 30, 10 } };
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 2; ++column)
    {
      AddPanel(window, rowMeshes[row], row, column, views[row][0], views[row][1], column == 1);
    }
  }
  window->Render();
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
