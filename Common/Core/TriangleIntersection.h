// Whether two triangles of one surface cut through each other: the test
// behind "no new self-intersection" (issue 13), used by the smoothing pass's
// fold guard (FoldGuard.h) and by the evaluation that counts folds.
//
// Rule: two triangles intersect improperly when an edge of one crosses the
// interior of the other, strictly: the edge's ends lie on opposite sides of
// the other's plane (each farther from it than a tolerance relative to the
// triangles' size) and the crossing lies inside the other triangle, away
// from its sides by a relative tolerance. Corners at one position count as
// shared. Then:
//   - triangles sharing two corners (an edge) never intersect improperly:
//     away from a fold onto each other (which the orientation test catches)
//     they meet only along that edge;
//   - triangles sharing one corner V intersect improperly when the side
//     opposite V of one crosses the other: the sides from V cross the other's
//     plane only at V;
//   - triangles sharing nothing intersect improperly when any side of either
//     crosses the other: the segment two non-coplanar triangles have in
//     common ends where a side of one meets the other.
// A triangle with two corners at one position (a needle, as asset files
// hold), or with its corners on a line up to rounding (twice its area at
// most 1e-12 of its longest side squared), has no interior and cuts
// nothing. Coplanar triangles and contacts
// that merely touch (a corner on the other,
// an edge through another's side) do not count: they have no volume of
// overlap to show and are measure-zero in floating point.
#pragma once

#include <glm/vec3.hpp>

namespace silsmooth
{

struct TriangleCorners
{
  glm::dvec3 P[3];
};

/// What the rule needs of a triangle, computed once for a triangle tested
/// against many (shapeOf).
struct TriangleShape
{
  TriangleCorners Corners;
  glm::dvec3 UnitNormal{ 0.0 }; // zero when the corners span no area
  double Area2 = 0.0;           // twice the area
  double AxisSpan = 0.0;        // the largest coordinate difference along a side
  double LongestSide = 0.0;
  bool NoInterior = true; // a needle or a line (the rule above)
};

TriangleShape shapeOf(const TriangleCorners& t);

/// Whether a and b cut through each other (the rule above).
bool trianglesIntersect(const TriangleCorners& a, const TriangleCorners& b);
/// The same for shapes made by shapeOf, with the same answer.
bool trianglesIntersect(const TriangleShape& a, const TriangleShape& b);

/// How near (relative to the triangles' size) trianglesTouch lets triangles
/// come.
constexpr double TouchTolerance = 1e-4;

/// Whether a and b cut through each other or come within TouchTolerance of
/// it: the same rule with the tolerances reversed (an edge that ends within
/// the tolerance of the other's plane, or crosses it within the tolerance
/// outside its sides, counts). Used for input triangles: a new triangle that
/// cuts another where their input triangles only touched, or missed each
/// other by a rounding error, is the input's near-contact showing, not a
/// fold of the re-meshing (an asset file may hold two sheets a millionth of
/// its size apart).
bool trianglesTouch(const TriangleCorners& a, const TriangleCorners& b);

/// How far from edge-on (relative: the cosine between a triangle's normal
/// and the normal sum) a facing must be to count in turnedOverAgainst.
constexpr double FacingTolerance = 1e-9;

/// Whether `piece` (a new triangle) and `input` (the input triangle it
/// replaces) face opposite ways with respect to `normalSum` (the sum of the
/// piece's corners' shading normals): one against it, the other not, each by
/// more than FacingTolerance (a piece seen edge-on is not turned over, and a
/// flat piece of its input triangle never is, whatever rounding does). A
/// triangle with no interior (the rule above) faces no way and is never
/// turned over.
bool turnedOverAgainst(
  const TriangleCorners& piece, const TriangleCorners& input, const glm::dvec3& normalSum);

/// Whether triangle t and the closed box [low, high] share a point (the
/// separating-axis test: the box's axes, the triangle's normal and the
/// crosses of its sides with the box's axes), counting a gap of up to 1e-9
/// of their joint size as shared: it may report a rounding-level miss as a
/// meeting, never a meeting as a miss. Triangles that cut through each other
/// share a point, so a triangle that does not meet another's box cannot cut
/// it: the fold guard's narrowing of candidates (FoldGuard.h).
bool triangleMeetsBox(const TriangleCorners& t, const glm::dvec3& low, const glm::dvec3& high);

/// Whether the open segment (u, v) crosses the interior of triangle t
/// strictly (the rule's building block).
bool segmentCrossesTriangle(const glm::dvec3& u, const glm::dvec3& v, const TriangleCorners& t);

} // namespace silsmooth
