// Vertex perturbation for concave silhouettes (Wang et al. 2008, III-E,
// Fig. 14 and 15).
//
// In a saddle region the smoothed silhouette curve is concave and lies behind
// the neighbouring triangles of the coarse mesh, which keep showing the
// polygonal outline. A silhouette segment from S1 to S2 (normals N1, N2,
// F = S2 - S1) is concave when N1 . F > 0 and N2 . F < 0. Each concave segment
// i has the plane P_i through its midpoint M_i = S(1/2) with the interpolated
// normal N_i there; the plane contains the viewing direction and the segment
// lies above it. Every vertex of the segment's triangle and every vertex
// joined to those by an edge is lowered along -R, R the normalised sum of the
// N_i of the planes it must clear, just far enough to lie on or below all of
// them, so that none of its triangles blocks the segments from the eye (which
// is on the planes). Vertices already below stay where they are.
//
// Taken literally this folds the surface on coarse meshes (measured: 22
// flipped triangles in 120 torus views, and a trefoil knot's outline 27 times
// worse), because a 1-ring vertex far to the side of a segment is above its
// local plane without being able to block it. So the vertices that must clear
// a segment's plane are chosen, each rule for a reason:
// - the corners of the segment's own triangle that lie alongside the segment
//   (their position along the chord within the chord's extent, widened by
//   half a chord) and in front of it (nearer the eye than the midpoint,
//   within a quarter chord): the re-meshed fans reach the curve from them;
// - every corner of a nearby triangle (one with a corner among the paper's
//   neighbouring vertices that is above the plane) that actually hides part
//   of the segment: a line of sight from one of a few points of the segment
//   to the eye crosses it. An earlier rule took every neighbouring vertex
//   alongside and in front of the segment instead; it moved vertices that
//   hide nothing (the knot's outline got worse: evaluation ratio 0.67 against
//   0.35 without perturbation) and missed vertices that do (the hole of a
//   32 x 16 torus stayed 1.76 px off the exact contour in
//   module.TestSaddleAccuracy). Measured with the occlusion rule: that test's
//   worst view 0.27 / 1.28 px (mean / max; 1.76 before; 2.28 unperturbed),
//   24 x 12 torus 0.32 / 1.99 (0.35 / 2.15 before; 1.21 / 3.39 unperturbed);
//   evaluation ratios torus 0.26 (0.29 before), knot 0.65 (0.67), and the
//   torus's distance to the exact silhouette 0.83 / 4.2 px (0.87 / 8.2).
//   Cost: about 0.25 ms more per frame on the 600-triangle knot (0.65 to
//   0.9 ms), none measurable on the torus. The occlusion rule alone (the own
//   triangle's corners too only when a triangle hides the segment) gave the
//   knot 0.35 but left the 24 x 12 hole 0.55 / 3.1 px off; every corner of
//   the own triangle, alongside or not, gave the knot 0.79;
// - only vertices whose shading normal leans towards R move (they are on the
//   silhouette region; a vertex facing the viewer moved sideways folds the
//   visible surface);
// - a move is at most twice the segments' bulge (a vertex that must move
//   further is not in front of the curve but, say, across a thin tube: the
//   knot's outline got 2.5 times worse without this);
// - a move that would turn one of the vertex's triangles over is halved until
//   it does not, or cancelled.
// Even so the effect is mixed on coarse tubes: on the 600-triangle trefoil
// knot the outline's mean distance to the fine reference grows (evaluation
// ratio 0.35 without perturbation, 0.65 with it), while the torus's inner rim
// is uncovered (0.42 -> 0.26). What is left on the 24 x 12 torus (up to 2 px
// at the ends of the hole's oval) is hidden by triangles there, mostly the
// re-meshed fans of neighbouring silhouette triangles, whose corners these
// rules leave in place or move too little (the flat input triangle that
// stands in for a fan in the occlusion test does not reach the curve).
#pragma once

#include "MeshTopology.h"

#include <functional>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

namespace silsmooth
{

struct ConcaveSegment
{
  Id Triangle = -1;    ///< the silhouette triangle that holds the segment
  glm::dvec3 Start;    ///< S(0)
  glm::dvec3 End;      ///< S(1)
  glm::dvec3 Midpoint; ///< M_i = S(1/2)
  glm::dvec3 Normal;   ///< N_i, unit
  /// Unit direction from M_i towards the eye (the viewer, in parallel projection).
  glm::dvec3 TowardViewer;
};

/// True when the segment from s1 (normal n1) to s2 (normal n2) is concave.
bool isConcaveSegment(
  const glm::dvec3& s1, const glm::dvec3& n1, const glm::dvec3& s2, const glm::dvec3& n2);

/// Planes whose normal makes a cosine below this with R are left out of a
/// vertex's displacement: moving along R could barely clear them, and would
/// need an unbounded step.
constexpr double MinimumPlaneAlignment = 0.2;
/// A vertex moves only when its shading normal makes at least this cosine
/// with R.
constexpr double MinimumNormalAlignment = 0.5;
/// Points of a concave segment whose lines of sight are tested against the
/// nearby triangles.
constexpr int OcclusionProbes = 7;
/// A vertex moves at most this many times the largest bulge (distance from
/// S(1/2) to the chord's midpoint) of the segments it answers to.
constexpr double MaximumStepInBulges = 2.0;

/// The new positions of the vertices that must move, as (vertex id,
/// position) pairs in ascending id order. `neighbours(v)` lists the vertices
/// joined to v by an edge.
std::vector<std::pair<Id, glm::dvec3>> perturbVerticesBelowConcaveSegments(
  const std::vector<ConcaveSegment>& segments, const std::vector<glm::dvec3>& points,
  const std::vector<glm::dvec3>& normals, const std::vector<Triangle>& triangles,
  const std::vector<Id>& neighbourOffsets, const std::vector<Id>& neighbours);

/// Shortens the moves that would turn one of `triangles` over: its face
/// normal against the sum of its vertex normals, where it was not before the
/// move. Each offending move is halved, up to 8 times, then cancelled.
/// `position` and `normal` give a point's unmoved position and its normal.
void keepTrianglesFacingOut(std::vector<std::pair<Id, glm::dvec3>>& moved,
  const std::vector<Triangle>& triangles, const std::function<glm::dvec3(Id)>& position,
  const std::function<glm::dvec3(Id)>& normal);

} // namespace silsmooth
