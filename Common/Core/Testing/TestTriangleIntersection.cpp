// The improper-intersection rule of TriangleIntersection.h on cases whose
// answer is known exactly: piercing, crossing near a side, shared corners and
// edges, touching contacts and coplanar pairs.
#include "TriangleIntersection.h"

#include <gtest/gtest.h>

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
