// The curves where parts of one surface pass through each other, for a line
// drawing (issue 16): two spheres joined without a union, a figure's head
// sunk into its body (assimp's spider). Such a curve is an edge of the
// image, but neither a silhouette, a crease nor a border.
//
// Rule: points are welded first, as surfaceEdgeLines welds them. Two
// triangles that share no welded vertex cross when each has corners on both
// sides of the other's plane (a touch along a side, or a shared plane, is no
// crossing); they then meet along a segment whose ends are where a side of
// one crosses the other, its sides included within 1e-9 of its size (where
// parts are laid out alike, the curve crosses sides of both). Each end is
// named by that side (its welded ends) and the triangle it crosses; the next
// pair along the curve crosses the same side through the same triangle, so
// segments chain by name, without a tolerance, into points equal to the bit
// (the side is always taken from its lower welded end). An end found from
// both triangles (a side of each, crossing) is one point; the pieces that
// meet there under two names are joined afterwards, where exactly two ends
// lie within 1e-9 of the curves' size. Where the curve passes through a
// corner of one triangle (the corner within 1e-12 of the other's plane, and
// in it), that corner is an end, named by the corner and the triangle it
// lies in. A pair whose crossings are not two adds no segment. A side lying
// in a triangle's plane (both ends within 1e-12), whose two triangles lie
// clearly on either side of that plane, carries the curve: the part of it
// inside the triangle is a segment (a sphere's equator ring in a box's
// face); sides whose triangles are on one side only touch.
//
// Invariants: every point lies on both triangles of its segment (up to
// rounding); polylines stop where other than two pieces meet (curves that
// cross), and a closed loop repeats its first point at the end, to the bit.
// Triangles sharing a vertex are not tested when they lie on one sheet
// (joined across shared sides): a surface that folds onto its neighbour has
// no curve to draw there. Parts that only touch at a point are sheets of
// their own, and are tested there.
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
