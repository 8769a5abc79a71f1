// The render-time mapper's bounds hold what it draws (issue 15), as a
// vtkPolyDataMapper's fed by the filter do: a camera reset or a clipping
// range fitted to GetBounds() takes in the smoothed curves, which bulge
// beyond the coarse mesh. For coarse spheres, the torus and the coarse bunny,
// over 48 views each (perspective and parallel, near and far), after each
// render the mapper's bounds hold the filter's output for that view and are
// no larger than that output joined with the input. The wrong variant, the
// input's own bounds (what the mapper reported before), must be left by some
// view of the icosahedron and of the bunny, or the check could not fail.
// Before the first render, after the input changes and with smoothing off,
// the bounds are the input's.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSilhouetteSmoothingMapper.h"

#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <cstdio>
#include <string>

using namespace silhouette_test;

namespace
{

// How far `inner` reaches beyond `outer` (0 when inside), over all six sides.
double Excess(const double inner[6], const double outer[6])
{
  double excess = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    excess = std::max(excess, outer[2 * axis] - inner[2 * axis]);
    excess = std::max(excess, inner[2 * axis + 1] - outer[2 * axis + 1]);
  }
  return excess;
}

double Diagonal(const double b[6])
{
  const double low[3] = { b[0], b[2], b[4] };
  const double high[3] = { b[1], b[3], b[5] };
  return std::sqrt(vtkMath::Distance2BetweenPoints(low, high));
}

bool SameBounds(const double a[6], const double b[6])
{
  return Excess(a, b) == 0.0 && Excess(b, a) == 0.0;
}

// Returns false on a failure; `leftInput` tells whether some view's output
// left the input's own bounds (the wrong variant's failure).
bool CheckMesh(const std::string& name, vtkPolyData* mesh, bool& leftInput)
{
  constexpr int Size = 300;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Size, Size);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);

  double inputBounds[6];
  mesh->GetBounds(inputBounds);
  const double slack = 1e-12 * Diagonal(inputBounds);
  double mapperBounds[6];
  mapper->GetBounds(mapperBounds);
  if (!SameBounds(mapperBounds, inputBounds))
  {
    std::printf("FAIL %s: before the first render the bounds are not the input's\n", name.c_str());
    return false;
  }

  // The filter as the mapper smooths: the same view, frustum culling on.
  // Sub-pixel silhouettes are smoothed by both: the mapper keeps what it left
  // whole in its last frame while the filter's requests keep no history,
  // and this test is about the bounds of one and the same output. Likewise
  // the fold fallbacks the mapper reuses from frame to frame.
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  filter->SetInputData(mesh);
  filter->SetViewportSize(Size, Size);
  filter->FrustumCullingOn();
  mapper->GetSmoothingFilter()->SkipSubpixelSmoothingOff();
  mapper->GetSmoothingFilter()->ReuseFoldFallbacksOff();
  double worst = 0.0; // how far the output reaches beyond the input's bounds
  int views = 0;
  bool ok = true;
  for (const auto& direction : SphereDirections(12))
  {
    for (const double distance : { 2.5, 8.0 })
    {
      for (const bool parallel : { false, true })
      {
        renderer->SetActiveCamera(CameraAroundMesh(mesh, direction, distance, parallel));
        window->Render();
        filter->SetCamera(renderer->GetActiveCamera());
        filter->Update();
        vtkPolyData* drawn = filter->GetOutput();
        if (mapper->GetNewTriangleCount() == 0 ||
          drawn->GetNumberOfPolys() !=
            mesh->GetNumberOfPolys() - mapper->GetReplacedTriangleCount() +
              mapper->GetPatchTriangleCount())
        {
          std::printf(
            "FAIL %s: the mapper and the filter did not smooth the same view\n", name.c_str());
          return false;
        }
        double drawnBounds[6];
        drawn->GetBounds(drawnBounds);
        mapper->GetBounds(mapperBounds);
        worst = std::max(worst, Excess(drawnBounds, inputBounds));
        double joined[6];
        for (int k = 0; k < 6; ++k)
        {
          joined[k] = k % 2 == 0 ? std::min(drawnBounds[k], inputBounds[k])
                                 : std::max(drawnBounds[k], inputBounds[k]);
        }
        if (Excess(drawnBounds, mapperBounds) > slack || Excess(mapperBounds, joined) > slack)
        {
          std::printf("FAIL %s: the drawing reaches %g beyond the mapper's bounds, which reach "
                      "%g beyond it and the input\n",
            name.c_str(), Excess(drawnBounds, mapperBounds), Excess(mapperBounds, joined));
          ok = false;
        }
        ++views;
      }
    }
  }
  leftInput = worst > slack;
  std::printf("%s: %d views; the smoothed mesh reaches %.4g beyond the input's bounds at most "
              "(%.2f%% of its diagonal)\n",
    name.c_str(), views, worst, 100.0 * worst / Diagonal(inputBounds));

  mapper->SmoothingOff();
  mapper->GetBounds(mapperBounds);
  const bool offIsInput = SameBounds(mapperBounds, inputBounds);
  mapper->SmoothingOn();
  // The input changed in place since the last render: its own bounds until
  // it is rendered again.
  mesh->Modified();
  mapper->GetBounds(mapperBounds);
  const bool newInputIsInput = SameBounds(mapperBounds, inputBounds);
  if (!offIsInput || !newInputIsInput)
  {
    std::printf("FAIL %s: the bounds are not the input's %s\n", name.c_str(),
      offIsInput ? "for an input not rendered yet" : "with smoothing off");
    ok = false;
  }
  return ok;
}

} // namespace

int TestSmoothingMapperBounds(int argc, char* argv[])
{
  const SphereTorusBunny meshes = MakeSphereTorusBunny(argc, argv);
  if (!meshes.Bunny)
  {
    return EXIT_FAILURE;
  }
  struct Case
  {
    std::string Name;
    vtkPolyData* Mesh;
    bool MustLeaveInput; // the wrong variant fails here
  };
  vtkSmartPointer<vtkPolyData> icosahedron = Icosphere(0);
  vtkSmartPointer<vtkPolyData> coarseSphere = Icosphere(1);
  // The finer spheres and the torus have points at their extremes along
  // every axis, so nothing can leave their boxes there.
  const Case cases[] = { { "icosahedron", icosahedron, true },
    { "icosphere 1", coarseSphere, false }, { "sphere", meshes.Sphere, false },
    { "torus", meshes.Torus, false }, { "coarse bunny", meshes.Bunny, true } };
  bool ok = true;
  for (const Case& c : cases)
  {
    bool leftInput = false;
    ok = CheckMesh(c.Name, c.Mesh, leftInput) && ok;
    if (c.MustLeaveInput && !leftInput)
    {
      std::printf(
        "FAIL %s: no view left the input's bounds, so the wrong variant passes\n", c.Name.c_str());
      ok = false;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
