// Benchmark, not a test: the hierarchical vertex visibility (paper III-B,
// VisibilityHierarchy) against the plain per-vertex pass, alone and inside the
// whole per-frame pass, on icospheres (every normal distinct: the hard case
// for clustering), tori and the refined bunny (flat refined faces share
// normals). Single-threaded; times are medians over random views, half
// perspective (eye 2.5 to 6 radii from the centre) and half parallel.
// "prepare" is the PreparedMesh (edge table, normals) every input pays; the
// hierarchy is built on the first hierarchical frame on top of it.
//
//   visibility_benchmark [--views N] [--max-triangles T] [--bunny file.ply] [--no-frame]
#include "BenchmarkMeshes.h"
#include "BenchmarkTiming.h"
#include "SilhouetteSmoother.h"
#include "VisibilityHierarchy.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace silsmooth;

using namespace benchmark_meshes;

namespace
{

// One row of the table: the mesh's visibility both ways, and with `frame`
// its whole pass both ways. False after saying so when the two ways differ.
bool MeasureMesh(const Mesh& input, int views, bool frame)
{
  std::unique_ptr<PreparedMesh> prepared;
  const double prepare = benchmark_timing::Milliseconds([&] {
    prepared = std::make_unique<PreparedMesh>(input.Points, input.Triangles, input.Normals);
  });
  const PreparedMesh& mesh = *prepared;
  const double build = benchmark_timing::Milliseconds([&] { mesh.visibilityHierarchy(); });
  std::mt19937_64 random(1);
  std::vector<double> plainMs, treeMs, framePlainMs, frameTreeMs;
  double decided = 0.0;
  double checksum = 0.0;
  for (int v = 0; v < views; ++v)
  {
    const ViewGeometry view = randomView(random, v % 2 == 1);
    std::vector<double> a;
    std::vector<double> b;
    // Alternate which goes first, so that neither always finds warm caches.
    for (int k = 0; k < 2; ++k)
    {
      if ((k + v / 2) % 2 == 0)
      {
        plainMs.push_back(benchmark_timing::Milliseconds(
          [&] { a = vertexVisibility(mesh, view, VisibilityMethod::PerVertex); }));
      }
      else
      {
        treeMs.push_back(benchmark_timing::Milliseconds(
          [&] { b = vertexVisibility(mesh, view, VisibilityMethod::Hierarchical); }));
      }
    }
    for (std::size_t i = 0; i < a.size(); ++i)
    {
      if ((a[i] >= 0.0) != (b[i] >= 0.0))
      {
        std::fprintf(stderr, "%s: decisions differ at vertex %zu\n", input.Name.c_str(), i);
        return false;
      }
    }
    VisibilityHierarchy::Statistics statistics;
    mesh.visibilityHierarchy().classify(view, b, nullptr, &statistics);
    decided += static_cast<double>(statistics.DecidedVertices) / std::max<std::size_t>(1, a.size());
    if (frame)
    {
      for (int k = 0; k < 2; ++k)
      {
        SmoothingParameters parameters;
        const bool plainNow = (k + v / 2) % 2 == 0;
        parameters.Visibility =
          plainNow ? VisibilityMethod::PerVertex : VisibilityMethod::Hierarchical;
        double added = 0.0;
        const double ms = benchmark_timing::Milliseconds([&] {
          added = static_cast<double>(smoothSilhouettes(mesh, view, parameters).NewPoints.size());
        });
        (plainNow ? framePlainMs : frameTreeMs).push_back(ms);
        checksum += plainNow ? added : -added;
      }
    }
  }
  if (checksum != 0.0)
  {
    std::fprintf(stderr, "%s: the two passes added different points\n", input.Name.c_str());
    return false;
  }
  const double plain = benchmark_timing::Median(plainMs);
  const double tree = benchmark_timing::Median(treeMs);
  std::printf("| %s | %zu | %.1f | %.1f | %.3f | %.3f | %.2f | %.1f |", input.Name.c_str(),
    input.Triangles.size(), prepare, build, plain, tree, tree / plain, 100.0 * decided / views);
  if (frame)
  {
    const double fp = benchmark_timing::Median(framePlainMs);
    const double ft = benchmark_timing::Median(frameTreeMs);
    std::printf(" %.2f | %.2f | %.2f |\n", fp, ft, ft / fp);
  }
  else
  {
    std::printf(" - | - | - |\n");
  }
  std::fflush(stdout);
  return true;
}

} // namespace

int main(int argc, char* argv[])
{
  int views = 40;
  long long maxTriangles = 1400000;
  bool frame = true;
  std::string bunnyPath = SILHOUETTE_DATA_DIR "/bunny.ply";
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
    else if (!std::strcmp(argv[i], "--bunny") && i + 1 < argc)
    {
      bunnyPath = argv[++i];
    }
    else if (!std::strcmp(argv[i], "--no-frame"))
    {
      frame = false;
    }
    else
    {
      std::fprintf(stderr,
        "usage: visibility_benchmark [--views N] [--max-triangles T] [--bunny file.ply] "
        "[--no-frame]\n");
      return 2;
    }
  }

  std::vector<Mesh> meshes;
  for (int level = 3; level <= 8; ++level)
  {
    if (20LL << (2 * level) <= maxTriangles)
    {
      meshes.push_back(icosphere(level));
    }
  }
  for (int n : { 24, 72, 216, 648 })
  {
    if (2LL * n * (n / 2) <= maxTriangles)
    {
      meshes.push_back(torus(n, n / 2));
    }
  }
  const Mesh bunny = readBunny(bunnyPath);
  if (bunny.Points.empty())
  {
    std::fprintf(stderr, "no bunny at %s: skipped\n", bunnyPath.c_str());
  }
  else
  {
    Mesh refined = bunny;
    for (int level = 0; refined.Triangles.size() <= static_cast<std::size_t>(maxTriangles); ++level)
    {
      refined.Name = "bunny, refined " + std::to_string(level) + "x";
      meshes.push_back(refined);
      coretest::splitInFour(refined.Points, refined.Triangles, false);
    }
  }

  std::printf(
    "%d views per mesh (half perspective, half parallel), single thread, median ms\n\n", views);
  std::printf("| mesh | triangles | prepare ms | hierarchy build ms | plain ms | hierarchical ms | "
              "ratio | decided %% | "
              "frame plain ms | frame hierarchical ms | frame ratio |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Mesh& input : meshes)
  {
    if (!MeasureMesh(input, views, frame))
    {
      return 1;
    }
  }
  return 0;
}
