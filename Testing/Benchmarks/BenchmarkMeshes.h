// The meshes and views the core benchmarks share (header only, no VTK):
// icospheres with exact normals (every normal distinct), tori, the refined
// bunny, and random views around the unit ball.
#ifndef BenchmarkMeshes_h
#define BenchmarkMeshes_h

#include "CoreTestMeshes.h"
#include "MeshTopology.h"
#include "ViewGeometry.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace benchmark_meshes
{

using silsmooth::Id;
using silsmooth::Triangle;
using silsmooth::ViewGeometry;

struct Mesh
{
  std::string Name;
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<glm::dvec3> Normals; // empty: angle-weighted
};

inline Mesh icosphere(int level)
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
    coretest::splitInFour(mesh.Points, mesh.Triangles, true);
  }
  mesh.Normals = mesh.Points; // exact
  mesh.Name = "icosphere " + std::to_string(level);
  return mesh;
}

// Torus R = 1, r = 0.4 with exact normals, u x v grid (2uv triangles).
inline Mesh torus(int u, int v)
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
inline Mesh readBunny(const std::string& path)
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

inline ViewGeometry randomView(std::mt19937_64& random, bool parallel)
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

} // namespace benchmark_meshes

#endif
