// The improper-intersection rule of TriangleIntersection.h on cases whose
// answer is known exactly: piercing, crossing near a side, shared corners and
// edges, touching contacts and coplanar pairs; and whether a triangle meets a
// box.
#include "TriangleIntersection.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace silsmooth;

namespace
{

TriangleCorners tri(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c)
{
  return TriangleCorners{ { a, b, c } };
}

const TriangleCorners Floor = tri({ 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 });

} // namespace

TEST(TriangleIntersection, PiercingTrianglesIntersectEitherWayRound)
{
  const TriangleCorners wall = tri({ 0.5, 0.5, -1 }, { 0.5, 0.5, 1 }, { 3, 3, 0 });
  EXPECT_TRUE(trianglesIntersect(Floor, wall));
  EXPECT_TRUE(trianglesIntersect(wall, Floor));
}

TEST(TriangleIntersection, SeparatedTrianglesDoNot)
{
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 0, 0, 0.1 }, { 2, 0, 0.1 }, { 0, 2, 0.1 })));
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 3, 3, -1 }, { 3, 3, 1 }, { 4, 3, 0 })));
}

TEST(TriangleIntersection, CrossingJustInsideASideCountsJustOutsideDoesNot)
{
  // A vertical segment through the floor at distance d inside / outside the
  // hypotenuse x + y = 2.
  const double d = 1e-4;
  const TriangleCorners inside = tri({ 1 - d, 1 - d, -1 }, { 1 - d, 1 - d, 1 }, { 1 - d, 5, 1 });
  const TriangleCorners outside = tri({ 1 + d, 1 + d, -1 }, { 1 + d, 1 + d, 1 }, { 1 + d, 5, 1 });
  EXPECT_TRUE(trianglesIntersect(Floor, inside));
  EXPECT_FALSE(trianglesIntersect(Floor, outside));
}

TEST(TriangleIntersection, EdgeNeighboursNeverIntersect)
{
  // Folded up, flat, and folded right over onto the floor (that last one is
  // the orientation test's case, not this one's).
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 2, 0, 0 }, { 0, 0, 0 }, { 1, -1, 1 })));
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 2, 0, 0 }, { 0, 0, 0 }, { 1, -1, 0 })));
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 2, 0, 0 }, { 0, 0, 0 }, { 1, 1, 1e-3 })));
}

TEST(TriangleIntersection, CornerNeighboursIntersectOnlyBeyondTheCorner)
{
  // Sharing the corner (0, 0, 0): one rises away from the floor, one dips
  // through it (its far side crosses the floor's interior), and one lies in
  // another plane but crosses the floor with its far side.
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 0, 0, 0 }, { -1, 0, 1 }, { 0, -1, 1 })));
  EXPECT_TRUE(trianglesIntersect(Floor, tri({ 0, 0, 0 }, { 1, 0.5, -1 }, { 0.5, 1, 1 })));
  EXPECT_TRUE(trianglesIntersect(tri({ 0, 0, 0 }, { 1, 0.5, -1 }, { 0.5, 1, 1 }), Floor));
  // Touching the floor along a line from the corner only: the far side
  // ends on the floor's plane.
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 0, 0, 0 }, { 1, 0.5, 0 }, { 0.5, 1, 1 })));
}

TEST(TriangleIntersection, TouchingAndCoplanarContactsDoNotCount)
{
  // A corner resting on the floor's interior.
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 0.5, 0.5, 0 }, { 1, 0.5, 1 }, { 0.5, 1, 1 })));
  // Overlapping in the floor's plane.
  EXPECT_FALSE(trianglesIntersect(Floor, tri({ 0.5, 0.5, 0 }, { 3, 0.5, 0 }, { 0.5, 3, 0 })));
}

TEST(TriangleIntersection, DegenerateTrianglesIntersectNothing)
{
  const TriangleCorners needle = tri({ 0.5, 0.5, -1 }, { 0.5, 0.5, 1 }, { 0.5, 0.5, 1 });
  EXPECT_FALSE(trianglesIntersect(needle, needle));
  // A needle with two corners at one position, through the floor.
  const TriangleCorners spike = tri({ 0.5, 0.5, -1 }, { 0.6, 0.5, 1 }, { 0.5, 0.5, -1 });
  EXPECT_FALSE(trianglesIntersect(Floor, spike));
  EXPECT_FALSE(trianglesTouch(Floor, spike));
  // Corners on a line through the floor (distinct positions): no interior.
  const TriangleCorners line = tri({ 0.5, 0.5, -1 }, { 0.5, 0.5, 0.5 }, { 0.5, 0.5, 1 });
  EXPECT_FALSE(trianglesIntersect(Floor, line));
  EXPECT_FALSE(trianglesIntersect(line, Floor));
  // A thin sliver well above rounding still cuts.
  const TriangleCorners sliver = tri({ 0.5, 0.5, -1 }, { 0.5 + 1e-5, 0.5, 0 }, { 0.5, 0.5, 1 });
  EXPECT_TRUE(trianglesIntersect(Floor, sliver));
  EXPECT_TRUE(segmentCrossesTriangle({ 0.5, 0.5, -1 }, { 0.5, 0.5, 1 }, Floor));
  EXPECT_FALSE(segmentCrossesTriangle({ 0.5, 0.5, -1 }, { 0.5, 0.5, 1 }, needle));
}

TEST(TriangleIntersection, ScaleDoesNotChangeTheAnswer)
{
  for (const double s : { 1e-6, 1.0, 1e6 })
  {
    const TriangleCorners floor = tri({ 0, 0, 0 }, { 2 * s, 0, 0 }, { 0, 2 * s, 0 });
    const TriangleCorners wall =
      tri({ 0.5 * s, 0.5 * s, -s }, { 0.5 * s, 0.5 * s, s }, { 3 * s, 3 * s, 0 });
    const TriangleCorners above =
      tri({ 0, 0, 0.1 * s }, { 2 * s, 0, 0.1 * s }, { 0, 2 * s, 0.1 * s });
    EXPECT_TRUE(trianglesIntersect(floor, wall)) << s;
    EXPECT_FALSE(trianglesIntersect(floor, above)) << s;
  }
}

TEST(TriangleIntersection, TurnedOverMeansFacingOppositeWaysClearly)
{
  const glm::dvec3 up(0, 0, 1);
  const TriangleCorners reversed = tri({ 0, 0, 0 }, { 0, 2, 0 }, { 2, 0, 0 });
  EXPECT_TRUE(turnedOverAgainst(reversed, Floor, up));
  EXPECT_TRUE(turnedOverAgainst(Floor, reversed, up));
  EXPECT_FALSE(turnedOverAgainst(Floor, Floor, up));
  // Either way round against the normals: both facing away is no turn.
  EXPECT_FALSE(turnedOverAgainst(reversed, reversed, up));
  // A piece seen edge-on, or degenerate, is not turned over.
  const TriangleCorners edgeOn = tri({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 1 });
  EXPECT_FALSE(turnedOverAgainst(edgeOn, Floor, glm::dvec3(0, 1, 0)));
  EXPECT_FALSE(turnedOverAgainst(tri({ 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }), Floor, up));
  // Tilted past edge-on by a little: turned over.
  const TriangleCorners tilted = tri({ 0, 0, 0 }, { 0, 1, -1e-3 }, { 1, 0, 0 });
  EXPECT_TRUE(turnedOverAgainst(tilted, Floor, up));
}

namespace
{

// The part of triangle t inside the box [low, high], by clipping it with
// the box's six planes (Sutherland and Hodgman): empty exactly when they do
// not meet. An answer found another way than triangleMeetsBox's axes.
int cornersInsideBox(const TriangleCorners& t, const glm::dvec3& low, const glm::dvec3& high)
{
  std::vector<glm::dvec3> polygon(t.P, t.P + 3);
  for (int axis = 0; axis < 3; ++axis)
  {
    for (const bool keepAbove : { true, false })
    {
      const double bound = keepAbove ? low[axis] : high[axis];
      auto inside = [&](const glm::dvec3& p) {
        return keepAbove ? p[axis] >= bound : p[axis] <= bound;
      };
      std::vector<glm::dvec3> kept;
      for (std::size_t i = 0; i < polygon.size(); ++i)
      {
        const glm::dvec3& a = polygon[i];
        const glm::dvec3& b = polygon[(i + 1) % polygon.size()];
        if (inside(a))
        {
          kept.push_back(a);
        }
        if (inside(a) != inside(b))
        {
          kept.push_back(a + (bound - a[axis]) / (b[axis] - a[axis]) * (b - a));
        }
      }
      polygon = kept;
    }
  }
  return static_cast<int>(polygon.size());
}

} // namespace

TEST(TriangleIntersection, TriangleMeetsBoxAsClippingFindsIt)
{
  // Random triangles against random boxes, long thin ones among them (a
  // fan's slivers, the case the test narrows candidates for); cases within
  // 1e-6 of touching, where either answer is right, are left out.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int meeting = 0;
  int apart = 0;
  for (int n = 0; n < 20000; ++n)
  {
    const glm::dvec3 a(u(rng), u(rng), u(rng));
    const glm::dvec3 b = n % 2 ? glm::dvec3(u(rng), u(rng), u(rng)) : -a;
    const glm::dvec3 c =
      n % 2 ? glm::dvec3(u(rng), u(rng), u(rng)) : -a + 0.01 * glm::dvec3(u(rng), u(rng), u(rng));
    const TriangleCorners t = tri(a, b, c);
    const glm::dvec3 centre(u(rng), u(rng), u(rng));
    const glm::dvec3 half = 0.2 * glm::abs(glm::dvec3(u(rng), u(rng), u(rng)));
    const bool surely = cornersInsideBox(t, centre - half + 1e-6, centre + half - 1e-6) > 0;
    const bool maybe = cornersInsideBox(t, centre - half - 1e-6, centre + half + 1e-6) > 0;
    if (surely == maybe)
    {
      EXPECT_EQ(triangleMeetsBox(t, centre - half, centre + half), surely) << n;
      ++(surely ? meeting : apart);
    }
  }
  EXPECT_GT(meeting, 300); // both answers well exercised
  EXPECT_GT(apart, 1000);
  // Touching counts: a corner on a face, a side along an edge.
  EXPECT_TRUE(triangleMeetsBox(Floor, { 2, 0, -1 }, { 3, 1, 0 }));
  EXPECT_TRUE(triangleMeetsBox(Floor, { 1, 1, 0 }, { 2, 2, 1 })); // the hypotenuse's middle
  EXPECT_FALSE(triangleMeetsBox(Floor, { 1.01, 1.01, -1 }, { 2, 2, 1 }));
}
