// Consistent orientation of a triangle mesh, per connected component
// (vtkPolyDataNormals' Consistency and AutoOrientNormals, for the core).
// Shading normals and visibility need the triangles of a surface to agree on
// which side is out; meshes as files give them often do not (inside-out
// exports, patches stitched with the other winding). View-independent.
//
// Rules:
//   - Two triangles sharing an edge that only they use (a manifold edge) are
//     consistent when they run along it in opposite directions. Orientation
//     spreads across manifold edges only: an edge of three or more triangles
//     separates components, and triangles that repeat a vertex are left as
//     they are and join nothing.
//   - A component whose triangles cannot all agree (a Moebius strip, or
//     triangles stitched inconsistently across a non-orientable loop) keeps
//     the orientation spread from its lowest triangle in breadth-first order;
//     the edges left inconsistent are counted.
//   - Which side is out: a closed component (every edge shared by exactly two
//     of its triangles, all consistent) faces so that its signed volume is
//     positive. Any other component faces the way the given normals point
//     (summed over its corners) or, without normals, the way most of its
//     area already faces.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace silsmooth
{

struct Orientation
{
  /// Per triangle: 1 when it must be reversed to agree with its component.
  std::vector<unsigned char> Reversed;
  /// Per triangle: its component (0, 1, ... in order of lowest triangle), or
  /// -1 for a triangle that repeats a vertex.
  std::vector<Id> Component;
  std::size_t ReversedCount = 0;
  std::size_t ComponentCount = 0;
  /// Manifold edges whose two triangles still disagree (non-orientable).
  std::size_t InconsistentEdgeCount = 0;
};

/// `cornerNormals` may be empty, or hold a normal per triangle corner (3t + k)
/// for the open components' choice of side.
/// `table`, when given, is the edge table of `triangles` (saves building it).
Orientation orientConsistently(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& cornerNormals = {},
  const EdgeTable* table = nullptr);

/// The triangle with two corners exchanged when `reversed` (its winding
/// turned, its first corner kept).
inline Triangle oriented(const Triangle& t, bool reversed)
{
  return reversed ? Triangle{ { t[0], t[2], t[1] } } : t;
}

} // namespace silsmooth
