// The progressive mesh (Kim and Choe 3.1): coarsening by the paper's edge
// collapses and refining back must give the input exactly, and every level
// must stay a manifold mesh with no triangle flipped.
#include "ProgressiveMesh.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

using silsmooth::Id;
using silsmooth::ProgressiveMesh;
using silsmooth::Triangle;

namespace
{

struct Mesh
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
};

// A closed genus-0 mesh: the octahedron, each face split into level^2
// triangles, pushed onto a bumpy sphere (deterministic bumps).
Mesh bumpySphere(int level)
{
  Mesh mesh;
  std::map<std::tuple<long, long, long>, Id> ids;
  const glm::dvec3 corners[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  const int faces[8][3] = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 },
    { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  const auto point = [&](const glm::dvec3& p) {
    const auto key =
      std::make_tuple(std::lround(p.x * 1e6), std::lround(p.y * 1e6), std::lround(p.z * 1e6));
    auto it = ids.find(key);
    if (it != ids.end())
    {
      return it->second;
    }
    const glm::dvec3 u = glm::normalize(p);
    const double r = 1.0 + 0.08 * std::sin(5.0 * u.x) * std::cos(4.0 * u.y + u.z);
    mesh.points.push_back(r * u);
    const Id id = static_cast<Id>(mesh.points.size() - 1);
    ids.emplace(key, id);
    return id;
  };
  for (const auto& f : faces)
  {
    const glm::dvec3 a = corners[f[0]], b = corners[f[1]], c = corners[f[2]];
    const auto at = [&](int i, int j) {
      return point(a + (b - a) * (double(i) / level) + (c - a) * (double(j) / level));
    };
    for (int i = 0; i < level; ++i)
    {
      for (int j = 0; i + j < level; ++j)
      {
        mesh.triangles.push_back({ at(i, j), at(i + 1, j), at(i, j + 1) });
        if (i + j + 1 < level)
        {
          mesh.triangles.push_back({ at(i + 1, j), at(i + 1, j + 1), at(i, j + 1) });
        }
      }
    }
  }
  return mesh;
}

// An open height field: a grid with a border.
Mesh wavyGrid(int n)
{
  Mesh mesh;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = double(i) / n, y = double(j) / n;
      mesh.points.emplace_back(x, y, 0.1 * std::sin(6.0 * x) * std::cos(5.0 * y));
    }
  }
  const auto id = [n](int i, int j) {
    return static_cast<Id>(j * (n + 1) + i);
  };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      mesh.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      mesh.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return mesh;
}

// Every edge in one or two triangles, each two-triangle edge used once in
// each direction (consistent orientation), no repeated corners.
void expectManifold(const std::vector<Triangle>& triangles, bool closed)
{
  std::map<std::pair<Id, Id>, int> directed;
  for (const Triangle& t : triangles)
  {
    ASSERT_NE(t[0], t[1]);
    ASSERT_NE(t[1], t[2]);
    ASSERT_NE(t[2], t[0]);
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  for (const auto& [edge, count] : directed)
  {
    ASSERT_EQ(count, 1) << "edge used twice in one direction";
    if (closed)
    {
      ASSERT_EQ(directed.count({ edge.second, edge.first }), 1u) << "border on a closed mesh";
    }
  }
}

void expectExactRoundTrip(const Mesh& mesh)
{
  ProgressiveMesh pm(mesh.points, mesh.triangles);
  ASSERT_GT(pm.splitCount(), 0u);
  EXPECT_EQ(pm.level(), pm.splitCount());
  EXPECT_EQ(pm.points(), mesh.points);
  EXPECT_EQ(pm.triangles(), mesh.triangles);
  pm.setLevel(0);
  EXPECT_EQ(pm.triangleCount(), pm.baseTriangleCount());
  pm.setLevel(pm.splitCount());
  EXPECT_EQ(pm.points(), mesh.points); // bit for bit
  EXPECT_EQ(pm.triangles(), mesh.triangles);
  // And again through refineTo / coarsenTo in uneven steps.
  pm.coarsenTo(mesh.triangles.size() / 3);
  EXPECT_LE(pm.triangleCount(), mesh.triangles.size() / 3);
  pm.refineTo(mesh.triangles.size() / 2);
  EXPECT_GE(pm.triangleCount(), mesh.triangles.size() / 2);
  EXPECT_LE(pm.triangleCount(), mesh.triangles.size() / 2 + 1);
  pm.coarsenTo(0);
  EXPECT_EQ(pm.level(), 0u);
  pm.refineTo(mesh.triangles.size());
  EXPECT_EQ(pm.points(), mesh.points);
  EXPECT_EQ(pm.triangles(), mesh.triangles);
}

} // namespace

TEST(ProgressiveMesh, ClosedMeshRefinesBackExactly)
{
  const Mesh mesh = bumpySphere(8); // 512 triangles, 258 points
  expectExactRoundTrip(mesh);
}

TEST(ProgressiveMesh, OpenMeshRefinesBackExactly)
{
  expectExactRoundTrip(wavyGrid(12));
}

TEST(ProgressiveMesh, ClosedMeshCoarsensToATetrahedronAndStaysManifold)
{
  const Mesh mesh = bumpySphere(6);
  ProgressiveMesh pm(mesh.points, mesh.triangles);
  // Genus 0: every collapse removes two triangles; the link condition stops at 4 points.
  EXPECT_EQ(pm.baseTriangleCount(), 4u);
  for (std::size_t level = 0; level <= pm.splitCount(); ++level)
  {
    pm.setLevel(level);
    const std::vector<Triangle> triangles = pm.triangles();
    ASSERT_EQ(triangles.size(), pm.baseTriangleCount() + 2 * level);
    expectManifold(triangles, true);
    // No triangle faces inwards: the signed volume stays positive.
    double volume = 0.0;
    for (const Triangle& t : triangles)
    {
      volume += glm::dot(pm.points()[t[0]], glm::cross(pm.points()[t[1]], pm.points()[t[2]])) / 6.0;
    }
    EXPECT_GT(volume, 0.0) << "level " << level;
  }
}

TEST(ProgressiveMesh, BorderKeepsItsPointsAndStaysManifold)
{
  const Mesh mesh = wavyGrid(10);
  ProgressiveMesh pm(mesh.points, mesh.triangles);
  pm.setLevel(0);
  expectManifold(pm.triangles(), false);
  // F_boun makes moving the border expensive: at half the triangles the
  // four corners are still there, where they were.
  pm.refineTo(mesh.triangles.size() / 2);
  expectManifold(pm.triangles(), false);
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  std::vector<Id> pointIds, triangleIds;
  pm.compact(points, triangles, pointIds, triangleIds);
  EXPECT_EQ(triangles.size(), pm.triangleCount());
  for (Id corner : { Id(0), Id(10), Id(110), Id(120) })
  {
    EXPECT_NE(std::find(pointIds.begin(), pointIds.end(), corner), pointIds.end());
    EXPECT_EQ(pm.points()[corner], mesh.points[corner]);
  }
}

TEST(ProgressiveMesh, CostFollowsThePaper)
{
  // Flat interior: F_vol = 0 and F_boun = 0, so the first collapses are free.
  const Mesh flat = [] {
    Mesh m = wavyGrid(4);
    for (glm::dvec3& p : m.points)
    {
      p.z = 0.0;
    }
    return m;
  }();
  ProgressiveMesh pm(flat.points, flat.triangles);
  ASSERT_GT(pm.splitCount(), 0u);
  EXPECT_EQ(pm.splits().back().cost, 0.0); // the first collapse made
  EXPECT_DOUBLE_EQ(ProgressiveMesh::Lambda, 1.0 / 3.0);
}

TEST(ProgressiveMesh, TriangleCountDoesNotDependOnThePath)
{
  const Mesh mesh = bumpySphere(6);
  ProgressiveMesh pm(mesh.points, mesh.triangles);
  for (std::size_t count : { 0u, 5u, 101u, 150u, 287u, 288u, 1000u })
  {
    pm.setLevel(0);
    pm.setTriangleCount(count);
    const std::size_t fromBelow = pm.level();
    pm.setLevel(pm.splitCount());
    pm.setTriangleCount(count);
    EXPECT_EQ(pm.level(), fromBelow) << count;
    EXPECT_TRUE(pm.triangleCount() >= count || pm.level() == pm.splitCount());
    if (pm.level() > 0)
    {
      pm.setLevel(pm.level() - 1);
      EXPECT_LT(pm.triangleCount(), count); // the lowest such level
    }
  }
}

TEST(ProgressiveMesh, MinimumTrianglesStopsTheSequence)
{
  const Mesh mesh = bumpySphere(6);
  ProgressiveMesh pm(mesh.points, mesh.triangles, 100);
  EXPECT_GE(pm.baseTriangleCount(), 100u);
  EXPECT_LE(pm.baseTriangleCount(), 101u);
  EXPECT_EQ(pm.triangles(), mesh.triangles);
}

TEST(ProgressiveMesh, RejectsBadIds)
{
  EXPECT_THROW(
    ProgressiveMesh({ glm::dvec3(0.0) }, { Triangle{ 0, 1, 2 } }), std::invalid_argument);
  ProgressiveMesh empty({}, {});
  EXPECT_EQ(empty.splitCount(), 0u);
  EXPECT_EQ(empty.triangleCount(), 0u);
}

TEST(ProgressiveMesh, AwkwardInputIsKeptAndComesBackExactly)
{
  // A closed mesh plus: a fin (an edge in three triangles), a triangle with a
  // repeated corner, a zero-area triangle, an unused point.
  Mesh mesh = bumpySphere(4);
  const Id a = mesh.triangles[0][0];
  const Id b = mesh.triangles[0][1];
  mesh.points.push_back(glm::dvec3(3.0, 0.0, 0.0));
  const Id fin = static_cast<Id>(mesh.points.size() - 1);
  mesh.triangles.push_back({ a, b, fin });
  mesh.triangles.push_back({ a, a, b });
  mesh.points.push_back(mesh.points[b]);
  mesh.triangles.push_back({ b, static_cast<Id>(mesh.points.size() - 1), a });
  mesh.points.push_back(glm::dvec3(9.0));
  ProgressiveMesh pm(mesh.points, mesh.triangles);
  EXPECT_GT(pm.splitCount(), 0u);
  pm.setLevel(0);
  for (const Triangle& t : pm.triangles())
  {
    for (Id v : t)
    {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, static_cast<Id>(mesh.points.size()));
    }
  }
  pm.setLevel(pm.splitCount());
  EXPECT_EQ(pm.points(), mesh.points);
  EXPECT_EQ(pm.triangles(), mesh.triangles);
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  std::vector<Id> pointIds, triangleIds;
  pm.compact(points, triangles, pointIds, triangleIds);
  EXPECT_EQ(points.size(), mesh.points.size() - 1); // the unused point is left out
  EXPECT_EQ(triangles.size(), mesh.triangles.size());
}
