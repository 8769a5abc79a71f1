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

namespace
{

struct Mesh
{
  std::string Name;
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<glm::dvec3> Normals; // empty: angle-weighted
};

// Splits every triangle in four at its edge midpoints; onSphere projects the
// new points onto the unit sphere.
void refine(Mesh& mesh, bool onSphere)
{
  std::map<std::pair<Id, Id>, Id> middles;
  auto middle = [&](Id a, Id b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    const auto it = middles.find(key);
    if (it != middles.end())
    {
      return it->second;
    }
    glm::dvec3 p =
      0.5 * (mesh.Points[static_cast<std::size_t>(a)] + mesh.Points[static_cast<std::size_t>(b)]);
    mesh.Points.push_back(onSphere ? glm::normalize(p) : p);
    return middles[key] = static_cast<Id>(mesh.Points.size() - 1);
  };
  std::vector<Triangle> finer;
  finer.reserve(mesh.Triangles.size() * 4);
  for (const Triangle& t : mesh.Triangles)
  {
    const Id ab = middle(t[0], t[1]);
    const Id bc = middle(t[1], t[2]);
    const Id ca = middle(t[2], t[0]);
    finer.push_back({ t[0], ab, ca });
    finer.push_back({ ab, t[1], bc });
    finer.push_back({ ca, bc, t[2] });
    finer.push_back({ ab, bc, ca });
  }
  mesh.Triangles = std::move(finer);
}

Mesh icosphere(int level)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh mesh;
  mesh.Points = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
    { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  for (glm::dvec3& p : mesh.Points)
  {
    p = glm::normalize(p);
  }
  mesh.Triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };
  for (int l = 0; l < level; ++l)
  {
    refine(mesh, true);
  }
  mesh.Normals = mesh.Points; // exact
  mesh.Name = "icosphere " + std::to_string(level);
  return mesh;
}

// Torus R = 1, r = 0.4 with exact normals, u x v grid (2uv triangles).
Mesh torus(int u, int v)
{
  Mesh mesh;
  for (int i = 0; i < u; ++i)
  {
    const double a = 2.0 * M_PI * i / u;
    for (int j = 0; j < v; ++j)
    {
      const double b = 2.0 * M_PI * j / v;
      const glm::dvec3 n(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
      mesh.Points.push_back(glm::dvec3(std::cos(a), std::sin(a), 0.0) + 0.4 * n);
      mesh.Normals.push_back(n);
    }
  }
  auto id = [&](int i, int j) {
    return static_cast<Id>((i % u) * v + (j % v));
  };
  for (int i = 0; i < u; ++i)
  {
    for (int j = 0; j < v; ++j)
    {
      mesh.Triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      mesh.Triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  mesh.Name = "torus " + std::to_string(u) + "x" + std::to_string(v);
  return mesh;
}

// The binary PLY of Data/ (float x y z; uchar count, int ids), centred and
// scaled to the unit ball; empty on any surprise.
Mesh readBunny(const std::string& path)
{
  Mesh mesh;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long vertices = 0;
  long faces = 0;
  while (std::getline(in, line) && line != "end_header")
  {
    std::sscanf(line.c_str(), "element vertex %ld", &vertices);
    std::sscanf(line.c_str(), "element face %ld", &faces);
  }
  if (!in || vertices <= 0 || faces <= 0)
  {
    return {};
  }
  glm::dvec3 lo(1e300);
  glm::dvec3 hi(-1e300);
  for (long i = 0; i < vertices; ++i)
  {
    float xyz[3];
    in.read(reinterpret_cast<char*>(xyz), sizeof xyz);
    mesh.Points.emplace_back(xyz[0], xyz[1], xyz[2]);
    lo = glm::min(lo, mesh.Points.back());
    hi = glm::max(hi, mesh.Points.back());
  }
  for (long f = 0; f < faces && in; ++f)
  {
    unsigned char count = 0;
    in.read(reinterpret_cast<char*>(&count), 1);
    std::vector<int> ids(count);
    in.read(reinterpret_cast<char*>(ids.data()), static_cast<std::streamsize>(count * sizeof(int)));
    for (int k = 1; k + 1 < count; ++k)
    {
      mesh.Triangles.push_back(
        { ids[0], ids[static_cast<std::size_t>(k)], ids[static_cast<std::size_t>(k) + 1] });
    }
  }
  if (!in)
  {
    return {};
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = 0.5 * glm::length(hi - lo);
  for (glm::dvec3& p : mesh.Points)
  {
    p = (p - centre) / radius;
  }
  mesh.Name = "bunny";
  return mesh;
}

ViewGeometry randomView(std::mt19937_64& random, bool parallel)
{
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> distance(2.5, 6.0);
  glm::dvec3 direction(gauss(random), gauss(random), gauss(random));
  direction = glm::normalize(direction);
  ViewGeometry view;
  view.Parallel = parallel;
  view.Eye = distance(random) * direction;
  view.TowardViewer = direction;
  const glm::dvec3 up = std::abs(direction.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dmat4 look = glm::lookAt(view.Eye, glm::dvec3(0.0), up);
  const glm::dmat4 projection = parallel
    ? glm::ortho(-1.3, 1.3, -1.0, 1.0, 0.1, 20.0)
    : glm::perspective(glm::radians(30.0), 1024.0 / 768.0, 0.1, 20.0);
  view.ModelToClip = projection * look;
  return view;
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
      refine(refined, false);
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
          return 1;
        }
      }
      VisibilityHierarchy::Statistics statistics;
      mesh.visibilityHierarchy().classify(view, b, nullptr, &statistics);
      decided +=
        static_cast<double>(statistics.DecidedVertices) / std::max<std::size_t>(1, a.size());
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
      return 1;
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
  }
  return 0;
}
