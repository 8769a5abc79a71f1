// Small exact meshes and a simple view shared by the core tests.
#pragma once

#include "MeshTopology.h"
#include "ViewGeometry.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace coretest
{

/// A view from `eye` with a crude projection that is enough for sampling
/// (x/z-like scaling) on a 1000 x 1000 viewport.
inline silsmooth::ViewGeometry perspectiveFrom(const glm::dvec3& eye)
{
  silsmooth::ViewGeometry view;
  view.Eye = eye;
  view.ModelToClip = glm::dmat4(0.5);
  view.ModelToClip[3][3] = 1.0;
  view.ViewportWidth = 1000;
  view.ViewportHeight = 1000;
  return view;
}

/// A unit UV sphere, outward, poles on z; every point is on the sphere, so
/// the points are also the exact normals.
inline void unitSphere(int rings, int sectors, std::vector<glm::dvec3>& points,
  std::vector<silsmooth::Triangle>& triangles)
{
  using silsmooth::Id;
  const double pi = 3.14159265358979323846;
  points.assign(1, glm::dvec3(0, 0, 1));
  triangles.clear();
  for (int r = 1; r < rings; ++r)
  {
    const double theta = pi * r / rings;
    for (int s = 0; s < sectors; ++s)
    {
      const double phi = 2.0 * pi * s / sectors;
      points.emplace_back(
        std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  }
  points.emplace_back(0, 0, -1);
  const Id south = static_cast<Id>(points.size() - 1);
  auto at = [sectors](int r, int s) {
    return static_cast<Id>(1 + (r - 1) * sectors + s % sectors);
  };
  for (int s = 0; s < sectors; ++s)
  {
    triangles.push_back({ 0, at(1, s), at(1, s + 1) });
    triangles.push_back({ south, at(rings - 1, s + 1), at(rings - 1, s) });
    for (int r = 1; r + 1 < rings; ++r)
    {
      triangles.push_back({ at(r, s), at(r + 1, s), at(r + 1, s + 1) });
      triangles.push_back({ at(r, s), at(r + 1, s + 1), at(r, s + 1) });
    }
  }
}

/// A torus about z (ring radius 1, tube radius r), u x v quads split in two.
inline void torus(int u, int v, double r, std::vector<glm::dvec3>& points,
  std::vector<silsmooth::Triangle>& triangles)
{
  using silsmooth::Id;
  const double pi = 3.14159265358979323846;
  points.clear();
  triangles.clear();
  for (int i = 0; i < u; ++i)
  {
    const double a = 2.0 * pi * i / u;
    for (int j = 0; j < v; ++j)
    {
      const double b = 2.0 * pi * j / v;
      points.emplace_back((1.0 + r * std::cos(b)) * std::cos(a),
        (1.0 + r * std::cos(b)) * std::sin(a), r * std::sin(b));
    }
  }
  auto at = [u, v](int i, int j) {
    return static_cast<Id>((i % u) * v + j % v);
  };
  for (int i = 0; i < u; ++i)
  {
    for (int j = 0; j < v; ++j)
    {
      triangles.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  }
}

/// A capped cylinder of `sides` sides (axis z, unit radius, z in [-1, 1]),
/// outward: side quads split in two, each cap a fan about its centre.
inline void cappedCylinder(
  int sides, std::vector<glm::dvec3>& points, std::vector<silsmooth::Triangle>& triangles)
{
  using silsmooth::Id;
  const double pi = 3.14159265358979323846;
  const Id n = sides;
  points.clear();
  triangles.clear();
  for (const double z : { -1.0, 1.0 })
  {
    for (int i = 0; i < sides; ++i)
    {
      const double a = 2.0 * pi * i / sides;
      points.emplace_back(std::cos(a), std::sin(a), z);
    }
  }
  points.emplace_back(0, 0, -1);
  points.emplace_back(0, 0, 1);
  const Id bottom = 2 * n;
  const Id top = 2 * n + 1;
  for (Id i = 0; i < n; ++i)
  {
    const Id j = (i + 1) % n;
    triangles.push_back({ i, j, n + j });
    triangles.push_back({ i, n + j, n + i });
    triangles.push_back({ top, n + i, n + j });
    triangles.push_back({ bottom, j, i });
  }
}

/// Directed-edge bookkeeping: a closed, consistently oriented 2-manifold has
/// every directed edge once and its reverse once.
struct ManifoldCheck
{
  int Unpaired = 0;
  int Repeated = 0;
  int Degenerate = 0;
  bool closedManifold() const { return Unpaired == 0 && Repeated == 0 && Degenerate == 0; }
};

inline ManifoldCheck checkManifold(const std::vector<silsmooth::Triangle>& triangles)
{
  ManifoldCheck check;
  std::map<std::pair<silsmooth::Id, silsmooth::Id>, int> directed;
  for (const silsmooth::Triangle& t : triangles)
  {
    if (silsmooth::hasRepeatedCorner(t))
    {
      ++check.Degenerate;
    }
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)] }];
    }
  }
  for (const auto& [edge, count] : directed)
  {
    check.Repeated += count > 1 ? 1 : 0;
    check.Unpaired += directed.count({ edge.second, edge.first }) ? 0 : 1;
  }
  return check;
}

// Every corner its own point (what VTK's OBJ reader makes of a textured
// asset): corner 3t + k is point 3t + k.
inline void makeSoup(const std::vector<glm::dvec3>& points,
  const std::vector<silsmooth::Triangle>& triangles, std::vector<glm::dvec3>& soupPoints,
  std::vector<silsmooth::Triangle>& soupTriangles)
{
  soupPoints.clear();
  soupTriangles.clear();
  for (const silsmooth::Triangle& t : triangles)
  {
    const silsmooth::Id base = static_cast<silsmooth::Id>(soupPoints.size());
    for (const silsmooth::Id p : t)
    {
      soupPoints.push_back(points[static_cast<std::size_t>(p)]);
    }
    soupTriangles.push_back({ { base, base + 1, base + 2 } });
  }
}

/// Splits every triangle in four at its edge midpoints (each shared edge's
/// midpoint made once); `onSphere` projects the new points onto the unit
/// sphere.
inline void splitInFour(
  std::vector<glm::dvec3>& points, std::vector<silsmooth::Triangle>& triangles, bool onSphere)
{
  using silsmooth::Id;
  std::map<std::pair<Id, Id>, Id> middles;
  auto middle = [&](Id a, Id b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    const auto it = middles.find(key);
    if (it != middles.end())
    {
      return it->second;
    }
    const glm::dvec3 p =
      0.5 * (points[static_cast<std::size_t>(a)] + points[static_cast<std::size_t>(b)]);
    points.push_back(onSphere ? glm::normalize(p) : p);
    return middles[key] = static_cast<Id>(points.size() - 1);
  };
  std::vector<silsmooth::Triangle> finer;
  finer.reserve(triangles.size() * 4);
  for (const silsmooth::Triangle& t : triangles)
  {
    const Id ab = middle(t[0], t[1]);
    const Id bc = middle(t[1], t[2]);
    const Id ca = middle(t[2], t[0]);
    finer.push_back({ t[0], ab, ca });
    finer.push_back({ ab, t[1], bc });
    finer.push_back({ ca, bc, t[2] });
    finer.push_back({ ab, bc, ca });
  }
  triangles = std::move(finer);
}

/// A unit sphere (unitSphere) and the same triangles as a soup (makeSoup).
struct SphereAndSoup
{
  std::vector<glm::dvec3> Points;
  std::vector<silsmooth::Triangle> Triangles;
  std::vector<glm::dvec3> SoupPoints;
  std::vector<silsmooth::Triangle> SoupTriangles;
};

inline SphereAndSoup sphereAndSoup(int rings, int sectors)
{
  SphereAndSoup meshes;
  unitSphere(rings, sectors, meshes.Points, meshes.Triangles);
  makeSoup(meshes.Points, meshes.Triangles, meshes.SoupPoints, meshes.SoupTriangles);
  return meshes;
}

} // namespace coretest
