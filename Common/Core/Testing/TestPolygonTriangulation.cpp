// Ear clipping (PolygonTriangulation.h) on polygons whose answer is known:
// the triangles tile the polygon (their areas add up to its own, none turned
// against its winding), n - 2 of them over its corners; a ring joined to its
// hole by a slit (the shape of assimp's concave_polygon.obj, which VTK's
// vtkPolygon::Triangulate refuses); corners on straight lines; either
// winding; a tilted plane; and the polygons it must refuse.
#include "PolygonTriangulation.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace silsmooth;

namespace
{

struct Polygon
{
  std::vector<glm::dvec3> Points;
  std::vector<Id> Corners;
};

// A polygon in the plane z = 0 (or tilted), one point per corner.
Polygon Planar(const std::vector<glm::dvec2>& corners)
{
  Polygon p;
  for (const glm::dvec2& c : corners)
  {
    p.Corners.push_back(static_cast<Id>(p.Points.size()));
    p.Points.emplace_back(c.x, c.y, 0.0);
  }
  return p;
}

// The Newell normal: its length is twice the polygon's area.
glm::dvec3 NewellNormal(const Polygon& p)
{
  glm::dvec3 n(0.0);
  for (std::size_t k = 0; k < p.Corners.size(); ++k)
  {
    const glm::dvec3& a = p.Points[static_cast<std::size_t>(p.Corners[k])];
    const glm::dvec3& b = p.Points[static_cast<std::size_t>(p.Corners[(k + 1) % p.Corners.size()])];
    n += glm::cross(a, b);
  }
  return n;
}

struct Tiling
{
  double Area = 0.0; // the triangles' areas, each counted positive
  int Turned = 0;    // triangles facing against the polygon's normal
};

Tiling Measure(const Polygon& p, const std::vector<Triangle>& triangles)
{
  const glm::dvec3 n = NewellNormal(p);
  Tiling t;
  for (const Triangle& tri : triangles)
  {
    const glm::dvec3& a = p.Points[static_cast<std::size_t>(tri[0])];
    const glm::dvec3 cross = glm::cross(p.Points[static_cast<std::size_t>(tri[1])] - a,
      p.Points[static_cast<std::size_t>(tri[2])] - a);
    t.Area += 0.5 * glm::length(cross);
    t.Turned += glm::dot(cross, n) < -1e-12 * glm::dot(n, n) ? 1 : 0;
  }
  return t;
}

// The fan from the first corner, the wrong variant.
std::vector<Triangle> Fan(const Polygon& p)
{
  std::vector<Triangle> fan;
  for (std::size_t k = 1; k + 1 < p.Corners.size(); ++k)
  {
    fan.push_back({ p.Corners[0], p.Corners[k], p.Corners[k + 1] });
  }
  return fan;
}

// A ring between radii 1 and `inner`, `segments` corners on each circle,
// walked as one polygon: the outer circle from its top corner round, down
// the slit to the inner circle's top corner, the inner circle the other way
// round, and back up the slit (its two corners appear twice).
Polygon RingWithSlit(int segments, double inner)
{
  Polygon p;
  for (int k = 0; k < segments; ++k)
  {
    const double a = 2.0 * M_PI * k / segments;
    p.Points.emplace_back(std::sin(a), std::cos(a), 0.0); // outer k
  }
  for (int k = 0; k < segments; ++k)
  {
    const double a = 2.0 * M_PI * k / segments;
    p.Points.emplace_back(inner * std::sin(a), inner * std::cos(a), 0.0); // inner k
  }
  for (int k = 0; k < segments; ++k)
  {
    p.Corners.push_back(k); // outer, clockwise from the top
  }
  p.Corners.push_back(0); // back at the outer top, down the slit
  for (int k = 0; k < segments; ++k)
  {
    p.Corners.push_back(segments + (segments - k) % segments); // inner, the other way
  }
  p.Corners.push_back(segments); // the inner top again, then up the slit to corner 0
  return p;
}

} // namespace

TEST(PolygonTriangulation, AnLShapeIsTiledByFourTriangles)
{
  const Polygon l = Planar({ { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 }, { 0, 0 } });
  std::vector<Triangle> triangles;
  ASSERT_TRUE(triangulatePolygon(l.Points, l.Corners.data(), l.Corners.size(), triangles));
  EXPECT_EQ(triangles.size(), 4u);
  const Tiling t = Measure(l, triangles);
  EXPECT_NEAR(t.Area, 3.0, 1e-12);
  EXPECT_EQ(t.Turned, 0);
  // The fan from corner 0 folds over the notch: the check can fail.
  EXPECT_GT(Measure(l, Fan(l)).Area, 3.0 + 0.5);
}

TEST(PolygonTriangulation, ARingJoinedToItsHoleByASlitIsTiled)
{
  for (const int segments : { 8, 32 })
  {
    const Polygon ring = RingWithSlit(segments, 0.93);
    const double area = 0.5 * glm::length(NewellNormal(ring));
    std::vector<Triangle> triangles;
    ASSERT_TRUE(
      triangulatePolygon(ring.Points, ring.Corners.data(), ring.Corners.size(), triangles))
      << segments;
    EXPECT_EQ(triangles.size(), ring.Corners.size() - 2);
    const Tiling t = Measure(ring, triangles);
    EXPECT_NEAR(t.Area, area, 1e-9 * area) << segments;
    EXPECT_EQ(t.Turned, 0) << segments;
    // The fan covers the hole: about eight times the ring's area here.
    EXPECT_GT(Measure(ring, Fan(ring)).Area, 2.0 * area) << segments;
  }
}

TEST(PolygonTriangulation, CornersOnStraightSidesKeepTheirTriangles)
{
  // A unit square with a corner in the middle of each side, and a notch.
  const Polygon p = Planar({ { 0, 0 }, { 0.5, 0 }, { 1, 0 }, { 1, 0.5 }, { 1, 1 }, { 0.5, 1 },
    { 0.5, 0.5 }, { 0.25, 1 }, { 0, 1 }, { 0, 0.5 } });
  const double area = 0.5 * glm::length(NewellNormal(p));
  std::vector<Triangle> triangles;
  ASSERT_TRUE(triangulatePolygon(p.Points, p.Corners.data(), p.Corners.size(), triangles));
  EXPECT_EQ(triangles.size(), p.Corners.size() - 2);
  const Tiling t = Measure(p, triangles);
  EXPECT_NEAR(t.Area, area, 1e-12);
  EXPECT_EQ(t.Turned, 0);
  // Every corner is in a triangle (none is left as a T-junction).
  std::vector<int> used(p.Points.size(), 0);
  for (const Triangle& tri : triangles)
  {
    for (const Id c : tri)
    {
      ++used[static_cast<std::size_t>(c)];
    }
  }
  for (std::size_t k = 0; k < used.size(); ++k)
  {
    EXPECT_GT(used[k], 0) << "corner " << k;
  }
}

TEST(PolygonTriangulation, EitherWindingAndATiltedPlane)
{
  Polygon l = Planar({ { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 }, { 0, 0 } });
  std::reverse(l.Corners.begin(), l.Corners.end()); // clockwise seen from +z
  // Tilted: rotate about the x axis by 60 degrees, then move away.
  const double c = std::cos(M_PI / 3.0);
  const double s = std::sin(M_PI / 3.0);
  for (glm::dvec3& p : l.Points)
  {
    p = glm::dvec3(p.x, c * p.y - s * p.z, s * p.y + c * p.z) + glm::dvec3(10, -3, 7);
  }
  std::vector<Triangle> triangles;
  ASSERT_TRUE(triangulatePolygon(l.Points, l.Corners.data(), l.Corners.size(), triangles));
  const Tiling t = Measure(l, triangles);
  EXPECT_NEAR(t.Area, 3.0, 1e-9);
  EXPECT_EQ(t.Turned, 0); // wound as the polygon, clockwise
}

TEST(PolygonTriangulation, RefusesWhatItCannotTile)
{
  std::vector<Triangle> triangles{ { 7, 8, 9 } };
  // A bow tie crosses itself.
  const Polygon bowTie = Planar({ { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } });
  EXPECT_FALSE(
    triangulatePolygon(bowTie.Points, bowTie.Corners.data(), bowTie.Corners.size(), triangles));
  // All corners on one line: no area, no plane.
  const Polygon line = Planar({ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 3, 0 } });
  EXPECT_FALSE(
    triangulatePolygon(line.Points, line.Corners.data(), line.Corners.size(), triangles));
  // A corner that is not finite, and one that is not a point.
  Polygon l = Planar({ { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 }, { 0, 0 } });
  l.Points[3].x = std::nan("");
  EXPECT_FALSE(triangulatePolygon(l.Points, l.Corners.data(), l.Corners.size(), triangles));
  l.Points[3].x = 1.0;
  l.Corners[2] = 99;
  EXPECT_FALSE(triangulatePolygon(l.Points, l.Corners.data(), l.Corners.size(), triangles));
  // Nothing was appended.
  ASSERT_EQ(triangles.size(), 1u);
  EXPECT_EQ(triangles[0][0], 7);
}
