#include "IntersectionLines.h"

#include "CoreTestMeshes.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace silsmooth;
using coretest::makeSoup;
using coretest::unitSphere;

namespace
{

/// An axis-aligned box [low, high], outward, 8 points and 12 triangles,
/// appended to `points` and `triangles`.
void addBox(const glm::dvec3& low, const glm::dvec3& high, std::vector<glm::dvec3>& points,
  std::vector<Triangle>& triangles)
{
  const Id base = static_cast<Id>(points.size());
  for (int k = 0; k < 8; ++k)
  {
    points.emplace_back(k & 1 ? high.x : low.x, k & 2 ? high.y : low.y, k & 4 ? high.z : low.z);
  }
  // Outward quads over the corner bits (x 1, y 2, z 4).
  const int quads[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& q : quads)
  {
    triangles.push_back({ base + q[0], base + q[1], base + q[2] });
    triangles.push_back({ base + q[0], base + q[2], base + q[3] });
  }
}

/// A box poking through the face x = 2 of the box [0, 2]^3: they meet along
/// the rectangle x = 2, y in [0.4, 1.3], z in [0.6, 1.7] (perimeter 4),
/// whose corners lie on no diagonal of the big box's faces.
void pokingBoxes(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles)
{
  addBox({ 0, 0, 0 }, { 2, 2, 2 }, points, triangles);
  addBox({ 1, 0.4, 0.6 }, { 3, 1.3, 1.7 }, points, triangles);
}

double lengthOf(const IntersectionLine& line)
{
  double length = 0.0;
  for (std::size_t i = 1; i < line.Points.size(); ++i)
  {
    length += glm::length(line.Points[i] - line.Points[i - 1]);
  }
  return length;
}

double totalLength(const std::vector<IntersectionLine>& lines)
{
  double length = 0.0;
  for (const IntersectionLine& line : lines)
  {
    length += lengthOf(line);
  }
  return length;
}

} // namespace

TEST(IntersectionLines, BoxesPokingThroughMeetAlongOneClosedRectangle)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  pokingBoxes(points, triangles);
  const std::vector<IntersectionLine> lines = intersectionLines(points, triangles);
  ASSERT_EQ(lines.size(), 1u);
  const IntersectionLine& loop = lines[0];
  ASSERT_GE(loop.Points.size(), 5u);
  EXPECT_EQ(loop.Points.front(), loop.Points.back()); // closed, to the bit
  EXPECT_EQ(loop.Triangles.size(), loop.Points.size());
  EXPECT_NEAR(lengthOf(loop), 4.0, 1e-12);
  for (const glm::dvec3& p : loop.Points)
  {
    EXPECT_EQ(p.x, 2.0);
    // On the rectangle's boundary.
    const double off = std::min(
      { std::abs(p.y - 0.4), std::abs(p.y - 1.3), std::abs(p.z - 0.6), std::abs(p.z - 1.7) });
    EXPECT_LT(off, 1e-12) << p.y << " " << p.z;
    EXPECT_GE(p.y, 0.4 - 1e-12);
    EXPECT_LE(p.y, 1.3 + 1e-12);
    EXPECT_GE(p.z, 0.6 - 1e-12);
    EXPECT_LE(p.z, 1.7 + 1e-12);
  }
}

TEST(IntersectionLines, ASurfaceThatDoesNotPassThroughItselfHasNone)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  addBox({ 0, 0, 0 }, { 2, 2, 2 }, points, triangles);
  EXPECT_TRUE(intersectionLines(points, triangles).empty());
  // Apart, and face to face (coplanar contact has nothing to draw).
  addBox({ 3, 0, 0 }, { 4, 1, 1 }, points, triangles);
  addBox({ 2, 0.5, 0.5 }, { 2.5, 1, 1 }, points, triangles);
  EXPECT_TRUE(intersectionLines(points, triangles).empty());
  // A closed sphere, whose neighbours share corners.
  unitSphere(24, 48, points, triangles);
  EXPECT_TRUE(intersectionLines(points, triangles).empty());
}

TEST(IntersectionLines, ATriangleSoupChainsAsTheWeldedSurface)
{
  std::vector<glm::dvec3> points, soupPoints;
  std::vector<Triangle> triangles, soupTriangles;
  pokingBoxes(points, triangles);
  makeSoup(points, triangles, soupPoints, soupTriangles);
  const std::vector<IntersectionLine> lines = intersectionLines(soupPoints, soupTriangles);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());
  EXPECT_NEAR(lengthOf(lines[0]), 4.0, 1e-12);
}

namespace
{

/// Two unit UV spheres (24 rings, 48 sectors) centred at x = -0.5 and
/// 0.5, the second turned about x by `turn` radians: they meet along a curve
/// near the circle x = 0, radius sqrt(0.75). Their polyhedra stand at most
/// 1 - cos(pi / 24) = 0.0086 inside the spheres.
void overlappingSpheres(
  double turn, std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles)
{
  std::vector<glm::dvec3> right;
  std::vector<Triangle> rightTriangles;
  unitSphere(24, 48, points, triangles);
  unitSphere(24, 48, right, rightTriangles);
  for (glm::dvec3& p : points)
  {
    p = glm::dvec3(p.z - 0.5, p.x, p.y); // poles on x, so the curve crosses many rings
  }
  const Id base = static_cast<Id>(points.size());
  for (const glm::dvec3& p : right)
  {
    const double c = std::cos(turn), s = std::sin(turn);
    points.emplace_back(p.y + 0.5, c * p.z - s * p.x, s * p.z + c * p.x);
  }
  for (const Triangle& t : rightTriangles)
  {
    triangles.push_back({ t[0] + base, t[1] + base, t[2] + base });
  }
}

void expectNearTheCircle(const std::vector<IntersectionLine>& lines)
{
  for (const IntersectionLine& line : lines)
  {
    for (const glm::dvec3& p : line.Points)
    {
      EXPECT_LT(std::abs(p.x), 0.01);
      EXPECT_LT(std::abs(std::hypot(p.y, p.z) - std::sqrt(0.75)), 0.01);
    }
  }
  // About the circle's length, 2 pi sqrt(0.75) = 5.441.
  EXPECT_NEAR(totalLength(lines), 2.0 * M_PI * std::sqrt(0.75), 0.05);
}

} // namespace

TEST(IntersectionLines, OverlappingSpheresMeetAlongOneLoop)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  overlappingSpheres(0.3, points, triangles);
  const std::vector<IntersectionLine> lines = intersectionLines(points, triangles);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());
  expectNearTheCircle(lines);
}

TEST(IntersectionLines, PartsLaidOutAlikeMeetAlongOneLoop)
{
  // Unturned, the spheres are mirror images: their rings' sides lie in the
  // same planes, and the curve crosses sides of both where they cross each
  // other, as often as not at no triangle's interior. A test that wants a
  // side through an interior (trianglesIntersect's) left a quarter of the
  // curve out in pieces (a user's trial, 2026-12-04).
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  overlappingSpheres(0.0, points, triangles);
  const std::vector<IntersectionLine> lines = intersectionLines(points, triangles);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());
  expectNearTheCircle(lines);
}

TEST(IntersectionLines, BoxesWhoseFacesLineUpMeetWhereTheyCross)
{
  // Unit cubes offset by (0.5, 0.5, 0.5): one closed path of three unit
  // halves on each (length 3), through the diagonals' ends of the faces.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  addBox({ 0, 0, 0 }, { 1, 1, 1 }, points, triangles);
  addBox({ 0.5, 0.5, 0.5 }, { 1.5, 1.5, 1.5 }, points, triangles);
  std::vector<IntersectionLine> lines = intersectionLines(points, triangles);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());
  EXPECT_NEAR(totalLength(lines), 3.0, 1e-12);

  // Offset by (0.5, 0.5, 0), their tops and bottoms in one plane: two
  // vertical unit lines, and nothing where a side of one lies on the
  // other's top or bottom (they touch there; they do not cross).
  points.clear();
  triangles.clear();
  addBox({ 0, 0, 0 }, { 1, 1, 1 }, points, triangles);
  addBox({ 0.5, 0.5, 0 }, { 1.5, 1.5, 1 }, points, triangles);
  lines = intersectionLines(points, triangles);
  ASSERT_EQ(lines.size(), 2u);
  for (const IntersectionLine& line : lines)
  {
    EXPECT_NEAR(lengthOf(line), 1.0, 1e-12);
    EXPECT_EQ(line.Points.front().x, line.Points.back().x);
    EXPECT_EQ(line.Points.front().y, line.Points.back().y);
  }

  // A plus sign of two 3 x 1 x 1 boxes: four unit lines at its inner corners.
  points.clear();
  triangles.clear();
  addBox({ -1.5, -0.5, 0 }, { 1.5, 0.5, 1 }, points, triangles);
  addBox({ -0.5, -1.5, 0 }, { 0.5, 1.5, 1 }, points, triangles);
  lines = intersectionLines(points, triangles);
  EXPECT_EQ(lines.size(), 4u);
  EXPECT_NEAR(totalLength(lines), 4.0, 1e-12);
}

TEST(IntersectionLines, ACurveThroughACornerIsWhole)
{
  // A tetrahedron with one corner, v, on the face x = 2 of the box [0, 2]^3
  // (in the face's lower triangle, off its diagonal), one corner inside the
  // box and two outside: the plane x = 2 cuts it in the triangle v, p, q,
  // through v itself. The two faces of the tetrahedron at v meet the box's
  // face only in pairs with one crossing of a side (the corner is on the
  // plane, so no side of it crosses the plane there); without the corner as
  // an end those pairs gave no segment, and the loop lost v and the stretch
  // to the face's diagonal on either side of it.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  addBox({ 0, 0, 0 }, { 2, 2, 2 }, points, triangles);
  const Id base = static_cast<Id>(points.size());
  const glm::dvec3 v(2.0, 1.0, 0.8);
  const glm::dvec3 a(2.5, 0.6, 0.7);
  const glm::dvec3 b(2.5, 1.5, 0.8);
  const glm::dvec3 c(1.5, 1.0, 1.5);
  points.insert(points.end(), { v, a, b, c });
  triangles.push_back({ base, base + 1, base + 2 });
  triangles.push_back({ base, base + 2, base + 3 });
  triangles.push_back({ base, base + 3, base + 1 });
  triangles.push_back({ base + 1, base + 3, base + 2 });
  const std::vector<IntersectionLine> lines = intersectionLines(points, triangles);
  ASSERT_EQ(lines.size(), 1u);
  const IntersectionLine& loop = lines[0];
  EXPECT_EQ(loop.Points.front(), loop.Points.back());
  const glm::dvec3 p = 0.5 * (a + c);
  const glm::dvec3 q = 0.5 * (b + c);
  EXPECT_NEAR(lengthOf(loop), glm::length(p - v) + glm::length(q - p) + glm::length(v - q), 1e-12);
  bool throughTheCorner = false;
  for (const glm::dvec3& point : loop.Points)
  {
    EXPECT_NEAR(point.x, 2.0, 1e-12);
    throughTheCorner = throughTheCorner || point == v;
  }
  EXPECT_TRUE(throughTheCorner);
}

TEST(IntersectionLines, ARingInTheOtherPartsFaceIsTheCurve)
{
  // A UV sphere of radius 0.5 centred on the face z = 1 of the box
  // [-1, 1]^3, its equator's ring of 16 points in that face: the surfaces
  // cross along the ring's sides, which no triangle crosses (each triangle
  // at the ring touches the face along a side). One closed loop, the
  // 16-gon, every point in the face. Raised by 0.1 the sphere touches
  // nothing at a side and the loop is the cut of its band, nearer the pole.
  for (const double lift : { 0.0, 0.1 })
  {
    std::vector<glm::dvec3> points;
    std::vector<Triangle> triangles;
    addBox({ -1, -1, -1 }, { 1, 1, 1 }, points, triangles);
    std::vector<glm::dvec3> sphere;
    std::vector<Triangle> sphereTriangles;
    unitSphere(8, 16, sphere, sphereTriangles);
    const Id base = static_cast<Id>(points.size());
    for (const glm::dvec3& p : sphere)
    {
      points.push_back(0.5 * p + glm::dvec3(0.0, 0.0, 1.0 - lift));
      ASSERT_TRUE(lift != 0.0 || std::abs(p.z) > 0.1 || points.back().z == 1.0);
    }
    for (const Triangle& t : sphereTriangles)
    {
      triangles.push_back({ t[0] + base, t[1] + base, t[2] + base });
    }
    const std::vector<IntersectionLine> lines = intersectionLines(points, triangles);
    ASSERT_EQ(lines.size(), 1u) << "lift " << lift;
    EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());
    for (const glm::dvec3& p : lines[0].Points)
    {
      EXPECT_NEAR(p.z, 1.0, 1e-12);
    }
    if (lift == 0.0)
    {
      EXPECT_NEAR(lengthOf(lines[0]), 16.0 * std::sin(M_PI / 16.0), 1e-12);
    }
    else
    {
      EXPECT_GT(lengthOf(lines[0]), 2.0);
      EXPECT_LT(lengthOf(lines[0]), 16.0 * std::sin(M_PI / 16.0));
    }
  }
}

TEST(IntersectionLines, PartsWithACornerInCommonCrossThere)
{
  // The sphere of the test above on an 8 x 8 grid of squares in z = 1
  // (each split by a diagonal): four of its equator's points are grid
  // points, which the search welds to one vertex each, so the sphere's
  // triangles there share a vertex with the grid's. They are parts that
  // only touch at those points, not neighbours on one sheet: the curve
  // still runs through them, one closed 16-gon.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  constexpr int cells = 8;
  for (int j = 0; j <= cells; ++j)
  {
    for (int i = 0; i <= cells; ++i)
    {
      points.emplace_back(-1.0 + 0.25 * i, -1.0 + 0.25 * j, 1.0);
    }
  }
  for (int j = 0; j < cells; ++j)
  {
    for (int i = 0; i < cells; ++i)
    {
      const Id corner = j * (cells + 1) + i;
      triangles.push_back({ corner, corner + 1, corner + cells + 2 });
      triangles.push_back({ corner, corner + cells + 2, corner + cells + 1 });
    }
  }
  std::vector<glm::dvec3> sphere;
  std::vector<Triangle> sphereTriangles;
  unitSphere(8, 16, sphere, sphereTriangles);
  const Id base = static_cast<Id>(points.size());
  int shared = 0;
  for (const glm::dvec3& p : sphere)
  {
    // Coordinates within rounding of a grid line put on it (cos(pi / 2) is
    // 6e-17, not 0), so that the points at 0, 90, 180 and 270 degrees are
    // grid points to the bit.
    glm::dvec3 at = 0.5 * p + glm::dvec3(0.0, 0.0, 1.0);
    for (int k = 0; k < 3; ++k)
    {
      const double line = 0.25 * std::round(4.0 * at[k]);
      at[k] = std::abs(at[k] - line) < 1e-12 ? line : at[k];
    }
    points.push_back(at);
    for (Id g = 0; g < base; ++g)
    {
      shared += points.back() == points[static_cast<std::size_t>(g)] ? 1 : 0;
    }
  }
  ASSERT_EQ(shared, 4); // the case under test: equator points that are grid points
  for (const Triangle& t : sphereTriangles)
  {
    triangles.push_back({ t[0] + base, t[1] + base, t[2] + base });
  }
  const std::vector<IntersectionLine> lines = intersectionLines(points, triangles);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());
  EXPECT_NEAR(lengthOf(lines[0]), 16.0 * std::sin(M_PI / 16.0), 1e-12);
}
