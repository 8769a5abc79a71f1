// Benchmark, not a test: the filter's cost per frame against mesh size,
// beside the floor for producing a new mesh (a DeepCopy of the input), VTK's
// own camera-dependent filter (vtkPolyDataSilhouette) on the same mesh and
// camera, and the filter with its fold guard off (FoldPrevention). Every frame moves the camera, so
// every frame re-runs the filter; the one-off cost of building the view-independent cache is
// reported apart. Times are medians over the frames, measured side by side in one run.
//
//   silhouette_benchmark [--frames N] [--max-level L] [--markdown]
#include "BenchmarkTiming.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIcosphereSource.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataSilhouette.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

using benchmark_timing::Median;
using benchmark_timing::Milliseconds;

namespace
{

void Orbit(vtkCamera* camera, int frame)
{
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, 4.0);
  camera->SetViewUp(0, 1, 0);
  camera->Azimuth(7.0 * frame);
  camera->Elevation(3.0 * frame - 20.0);
  camera->OrthogonalizeViewUp();
}

} // namespace

int main(int argc, char* argv[])
{
  int frames = 15;
  int maxLevel = 8;
  bool markdown = false;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
    {
      frames = std::max(3, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--max-level") && i + 1 < argc)
    {
      maxLevel = std::clamp(std::atoi(argv[++i]), 2, 9);
    }
    else if (!std::strcmp(argv[i], "--markdown"))
    {
      markdown = true;
    }
    else
    {
      std::fprintf(stderr,
        "usage: silhouette_benchmark [--frames N] [--max-level L] [--markdown]\n"
        "  icospheres of 20*4^L triangles for L = 3..max-level (default 8: 1.3M),\n"
        "  N camera positions each (default 15), 1024x768 viewport, tolerance 0.5 px\n");
      return 2;
    }
  }
  if (markdown)
  {
    std::printf(
      "| triangles | cache build ms | filter ms/frame | DeepCopy ms | ratio to DeepCopy | "
      "vtkPolyDataSilhouette ms | ratio to it | no fold guard ms | ratio to it | silhouette "
      "triangles | added triangles |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  }
  else
  {
    std::printf("%10s %10s %10s %10s %8s %10s %8s %10s %8s %10s %10s\n", "triangles", "cache ms",
      "filter ms", "copy ms", "x copy", "vtkSil ms", "x vtkSil", "noguard ms", "x noguard",
      "sil tris", "added");
  }
  for (int level = 3; level <= maxLevel; ++level)
  {
    vtkNew<vtkIcosphereSource> sphere;
    sphere->SetSubdivisionLevel(level);
    sphere->Update();
    vtkPolyData* mesh = sphere->GetOutput();

    vtkNew<vtkCamera> camera;
    vtkNew<vtkSilhouetteSmoothingFilter> smoother;
    smoother->SetInputData(mesh);
    smoother->SetCamera(camera);
    smoother->SetViewportSize(1024, 768);
    Orbit(camera, 0);
    const double cacheAndFrame = Milliseconds([&] { smoother->Update(); });
    vtkNew<vtkSilhouetteSmoothingFilter> unguarded;
    unguarded->SetInputData(mesh);
    unguarded->SetCamera(camera);
    unguarded->SetViewportSize(1024, 768);
    unguarded->FoldPreventionOff();
    unguarded->Update();

    vtkNew<vtkPolyDataSilhouette> vtkSilhouette;
    vtkSilhouette->SetInputData(mesh);
    vtkSilhouette->SetCamera(camera);
    vtkSilhouette->SetDirectionToCameraOrigin();
    vtkSilhouette->Update(); // builds its own edge cache

    std::vector<double> filterMs, copyMs, vtkMs, unguardedMs;
    double silhouetteTriangles = 0;
    double addedTriangles = 0;
    for (int frame = 1; frame <= frames; ++frame)
    {
      Orbit(camera, frame);
      // The filter with and without its fold guard run in turns first, so
      // neither gains from running second on warm caches.
      if (frame % 2)
      {
        unguardedMs.push_back(Milliseconds([&] { unguarded->Update(); }));
      }
      filterMs.push_back(Milliseconds([&] { smoother->Update(); }));
      if (frame % 2 == 0)
      {
        unguardedMs.push_back(Milliseconds([&] { unguarded->Update(); }));
      }
      vtkMs.push_back(Milliseconds([&] { vtkSilhouette->Update(); }));
      vtkNew<vtkPolyData> copy;
      copyMs.push_back(Milliseconds([&] { copy->DeepCopy(mesh); }));
      silhouetteTriangles +=
        smoother->GetOutput()->GetFieldData()->GetArray("SilhouetteTriangleCount")->GetTuple1(0);
      addedTriangles +=
        static_cast<double>(smoother->GetOutput()->GetNumberOfPolys() - mesh->GetNumberOfPolys());
    }
    const double filter = Median(filterMs);
    const double copy = Median(copyMs);
    const double other = Median(vtkMs);
    const double noGuard = Median(unguardedMs);
    const long long triangles = static_cast<long long>(mesh->GetNumberOfPolys());
    const double cache = std::max(0.0, cacheAndFrame - filter);
    if (markdown)
    {
      std::printf(
        "| %lld | %.1f | %.2f | %.2f | %.1f | %.2f | %.2f | %.2f | %.2f | %.0f | %.0f |\n",
        triangles, cache, filter, copy, filter / copy, other, filter / other, noGuard,
        filter / noGuard, silhouetteTriangles / frames, addedTriangles / frames);
    }
    else
    {
      std::printf("%10lld %10.1f %10.2f %10.2f %8.1f %10.2f %8.2f %10.2f %8.2f %10.0f %10.0f\n",
        triangles, cache, filter, copy, filter / copy, other, filter / other, noGuard,
        filter / noGuard, silhouetteTriangles / frames, addedTriangles / frames);
    }
    std::fflush(stdout);
  }
  return 0;
}
