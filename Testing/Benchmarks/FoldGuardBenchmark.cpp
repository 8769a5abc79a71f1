// Benchmark, not a test: what the fold guard (FoldGuard.h) adds to the
// core's frame, measured side by side in one run. Per mesh, every random
// view is smoothed with the guard on and off, in alternating order so that
// neither always finds warm caches; single thread, medians. The meshes are
// icospheres (convex: the guard finds nothing to undo, so this is the price
// of the check itself) and tori (saddles, where it re-meshes some frames).
//
//   fold_guard_benchmark [--views N] [--max-triangles T]
#include "BenchmarkMeshes.h"
#include "BenchmarkTiming.h"
#include "SilhouetteSmoother.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace benchmark_meshes;

namespace
{

struct GuardCost
{
  double OnMs = 0.0;
  double OffMs = 0.0;
  double NewTriangles = 0.0; ///< per frame, guard on (median)
};

GuardCost Measure(const silsmooth::PreparedMesh& mesh, int views)
{
  std::mt19937_64 random(1);
  std::vector<double> on;
  std::vector<double> off;
  std::vector<double> added;
  for (int v = 0; v < views; ++v)
  {
    const ViewGeometry view = randomView(random, v % 3 == 2);
    for (int k = 0; k < 2; ++k)
    {
      silsmooth::SmoothingParameters parameters;
      parameters.PreventFolds = (k + v) % 2 == 0;
      std::size_t count = 0;
      const double ms = benchmark_timing::Milliseconds(
        [&] { count = smoothSilhouettes(mesh, view, parameters).newTriangleCount(); });
      (parameters.PreventFolds ? on : off).push_back(ms);
      if (parameters.PreventFolds)
      {
        added.push_back(static_cast<double>(count));
      }
    }
  }
  return { benchmark_timing::Median(on), benchmark_timing::Median(off),
    benchmark_timing::Median(added) };
}

} // namespace

int main(int argc, char* argv[])
{
  int views = 30;
  long long maxTriangles = 1400000;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--views") && i + 1 < argc)
    {
      views = std::max(2, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--max-triangles") && i + 1 < argc)
    {
      maxTriangles = std::atoll(argv[++i]);
    }
    else
    {
      std::fprintf(stderr, "usage: fold_guard_benchmark [--views N] [--max-triangles T]\n");
      return 2;
    }
  }
  std::vector<Mesh> meshes;
  for (int level = 4; level <= 8; ++level)
  {
    if (20LL << (2 * level) <= maxTriangles)
    {
      meshes.push_back(icosphere(level));
    }
  }
  for (int n : { 72, 216, 648 })
  {
    if (2LL * n * (n / 2) <= maxTriangles)
    {
      meshes.push_back(torus(n, n / 2));
    }
  }
  std::printf("%d views per mesh (two in three perspective), single thread, median ms\n\n", views);
  std::printf("| mesh | triangles | new triangles | guard on ms | guard off ms | on / off | "
              "guard us per new triangle |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  for (const Mesh& input : meshes)
  {
    const silsmooth::PreparedMesh mesh(input.Points, input.Triangles, input.Normals);
    mesh.triangleGrid(); // built once per mesh, with the rest of the cache
    const GuardCost cost = Measure(mesh, views);
    std::printf("| %s | %zu | %.0f | %.2f | %.2f | %.2f | %.2f |\n", input.Name.c_str(),
      input.Triangles.size(), cost.NewTriangles, cost.OnMs, cost.OffMs, cost.OnMs / cost.OffMs,
      1000.0 * (cost.OnMs - cost.OffMs) / std::max(1.0, cost.NewTriangles));
    std::fflush(stdout);
  }
  return 0;
}
