// The curves where parts of one surface pass through each other, for a line
// drawing (issue 16): two spheres joined without a union, a figure's head
// sunk into its body (assimp's spider). Such a curve is an edge of the
// image, but neither a silhouette, a crease nor a border.
//
// Rule: points are welded first, as surfaceEdgeLines welds them. Two
// triangles that share no welded vertex and cut through each other
// (trianglesIntersect's rule) meet along a segment, whose ends are where a
// side of one crosses the interior of the other. Each end is named by that
// side (its welded ends) and the triangle it crosses; the next pair along the
// curve crosses the same side through the same triangle, so segments chain
// by name, without a tolerance, and the two compute the point alike (the
// side is always taken from its lower welded end), so the chained points are
// equal to the bit. A pair whose crossings are not exactly two (a curve
// through a corner, up to rounding) adds no segment, and the curve stops
// there.
//
// Invariants: every point lies on both triangles of its segment (up to
// rounding: it is on a side of one and found inside the other); polylines
// stop where other than two segments meet, and a closed loop repeats its
// first point at the end. Triangles sharing a vertex are not tested: a
// surface that folds onto its neighbour has no curve to draw there.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

struct IntersectionLine
{
  std::vector<glm::dvec3> Points;
  /// Per point, a triangle it lies on (for its point data).
  std::vector<Id> Triangles;
};

/// The polylines where the surface passes through itself: the open ones
/// first, then the closed loops. `weldTolerance` as
/// SurfaceEdgeLineParameters'.
std::vector<IntersectionLine> intersectionLines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, double weldTolerance = 0.0);

} // namespace silsmooth
