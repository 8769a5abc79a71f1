// Triangles of a planar polygon by ear clipping: for the polygons a fan from
// the first corner would fold over (concave ones), as asset files hold them.
//
// Rules:
//   - The polygon's plane is the one its Newell normal gives; the corners
//     are projected onto it, and the triangles are wound as the polygon is
//     (each one's normal on the Newell normal's side).
//   - Weakly simple polygons are handled: a hole joined to the outline by a
//     slit walked there and back (assimp's concave_polygon.obj, a ring),
//     corners repeated, and corners on a straight line. A corner at the
//     position of an ear's corner does not block that ear.
//   - On success there are count - 2 triangles over the polygon's own
//     corners, tiling it: their areas add up to the polygon's. Corners left on
//     a straight line at the end make triangles of no area, which keep every
//     corner joined to its neighbours.
//   - False, with nothing appended, for a polygon that crosses itself (no
//     ear is left to clip while the corners left still enclose area), for
//     one of no area or with a corner that is not finite, and for one that
//     would cost more than about 2e8 steps to clip (its corners squared,
//     for each ear tried): the caller falls back on a fan.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace silsmooth
{

bool triangulatePolygon(const std::vector<glm::dvec3>& points, const Id* corners, std::size_t count,
  std::vector<Triangle>& out);

} // namespace silsmooth
