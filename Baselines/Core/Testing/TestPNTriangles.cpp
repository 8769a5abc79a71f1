// Curved PN triangles (Vlachos et al. 2001): counts, corners kept, flat stays
// flat, watertight on a closed input, and a sphere's normals give a rounder
// surface; progress is reported and a stop leaves nothing.
#include "PNTriangles.h"

#include "CoreTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

using silsmooth::Id;
using silsmooth::PNTriangleResult;
using silsmooth::Triangle;

namespace
{

const std::vector<glm::dvec3> octahedronPoints{ { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 },
  { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
const std::vector<Triangle> octahedronTriangles{ { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 },
  { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };

} // namespace

TEST(PNTriangles, CountsAndCornersKept)
{
  for (int level = 0; level <= 5; ++level)
  {
    const PNTriangleResult r = silsmooth::tessellatePNTriangles(
      octahedronPoints, octahedronTriangles, octahedronPoints, level);
    EXPECT_EQ(r.Triangles.size(), octahedronTriangles.size() * (level + 1) * (level + 1));
    // V - E + F = 2 for the closed output.
    const std::size_t edges = 12 * (level + 1) + 8 * 3 * level * (level + 1) / 2;
    EXPECT_EQ(r.Points.size() + r.Triangles.size(), edges + 2);
    for (std::size_t i = 0; i < octahedronPoints.size(); ++i)
    {
      EXPECT_EQ(r.Points[i], octahedronPoints[i]);
    }
  }
}

TEST(PNTriangles, WatertightOnAClosedInput)
{
  const PNTriangleResult r =
    silsmooth::tessellatePNTriangles(octahedronPoints, octahedronTriangles, octahedronPoints, 4);
  std::map<std::pair<Id, Id>, int> directed;
  for (const Triangle& t : r.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  for (const auto& [edge, count] : directed)
  {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({ edge.second, edge.first }), 1u);
  }
  // The patches of the two triangles of an edge agree there (to rounding),
  // and the shared point is the one both use.
  const std::array<glm::dvec3, 3> p0{ { octahedronPoints[0], octahedronPoints[2],
    octahedronPoints[4] } };
  const std::array<glm::dvec3, 3> p1{ { octahedronPoints[2], octahedronPoints[0],
    octahedronPoints[5] } };
  for (int i = 1; i < 5; ++i)
  {
    const double t = i / 5.0;
    const glm::dvec3 a = silsmooth::pnPosition(p0, p0, 1.0 - t, t, 0.0);
    const glm::dvec3 b = silsmooth::pnPosition(p1, p1, t, 1.0 - t, 0.0);
    EXPECT_LT(glm::distance(a, b), 1e-14);
  }
}

TEST(PNTriangles, FlatStaysFlat)
{
  // A planar fan with the plane's normal at every point.
  const glm::dvec3 normal = glm::normalize(glm::dvec3(1, 2, 3));
  const glm::dvec3 u = glm::normalize(glm::cross(normal, glm::dvec3(0, 0, 1)));
  const glm::dvec3 v = glm::cross(normal, u);
  std::vector<glm::dvec3> points{ glm::dvec3(0.5, -1, 2) };
  std::vector<Triangle> triangles;
  for (int i = 0; i < 6; ++i)
  {
    const double angle = i * M_PI / 3.0 + 0.1 * i;
    points.push_back(points[0] + (1.0 + 0.3 * i) * (std::cos(angle) * u + std::sin(angle) * v));
    triangles.push_back({ 0, 1 + i, 1 + (i + 1) % 6 });
  }
  const std::vector<glm::dvec3> normals(points.size(), normal);
  const PNTriangleResult r = silsmooth::tessellatePNTriangles(points, triangles, normals, 3);
  for (std::size_t i = 0; i < r.Points.size(); ++i)
  {
    EXPECT_NEAR(glm::dot(r.Points[i] - points[0], normal), 0.0, 1e-12);
    EXPECT_LT(glm::distance(r.Normals[i], normal), 1e-12);
  }
}

TEST(PNTriangles, SphereNormalsRoundTheOctahedron)
{
  // Exact sphere normals: the patches bulge towards the unit sphere; the
  // flat faces' centres are at 1/sqrt(3) = 0.577 from the centre.
  const PNTriangleResult r =
    silsmooth::tessellatePNTriangles(octahedronPoints, octahedronTriangles, octahedronPoints, 6);
  double nearest = 1.0;
  for (const glm::dvec3& p : r.Points)
  {
    nearest = std::min(nearest, glm::length(p));
    EXPECT_LT(glm::length(p), 1.0 + 1e-12);
  }
  EXPECT_GT(nearest, 0.75);
  // Normals of the output are unit and point outwards.
  for (std::size_t i = 0; i < r.Points.size(); ++i)
  {
    EXPECT_NEAR(glm::length(r.Normals[i]), 1.0, 1e-12);
    EXPECT_GT(glm::dot(r.Normals[i], r.Points[i]), 0.0);
  }
}

TEST(PNTriangles, ProgressRisesAndAStopLeavesNothing)
{
  // A sphere of about 8,000 triangles: reports every 4,096 edges or
  // triangles, rising from 0 and below 1; the result is the same as without
  // a callback. A callback that stops at the second report leaves an empty,
  // aborted result.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(64, 64, points, triangles);
  std::vector<double> heard;
  const PNTriangleResult watched =
    silsmooth::tessellatePNTriangles(points, triangles, points, 2, [&heard](double done) {
      heard.push_back(done);
      return true;
    });
  const PNTriangleResult plain = silsmooth::tessellatePNTriangles(points, triangles, points, 2);
  EXPECT_FALSE(watched.Aborted);
  EXPECT_EQ(watched.Points, plain.Points);
  EXPECT_EQ(watched.Triangles, plain.Triangles);
  ASSERT_GE(heard.size(), 5u);
  EXPECT_EQ(heard.front(), 0.0);
  EXPECT_TRUE(std::is_sorted(heard.begin(), heard.end()));
  EXPECT_LT(heard.back(), 1.0);
  int calls = 0;
  const PNTriangleResult stopped = silsmooth::tessellatePNTriangles(
    points, triangles, points, 2, [&calls](double) { return ++calls < 2; });
  EXPECT_TRUE(stopped.Aborted);
  EXPECT_TRUE(stopped.Points.empty() && stopped.Triangles.empty());
  EXPECT_EQ(calls, 2);
}
