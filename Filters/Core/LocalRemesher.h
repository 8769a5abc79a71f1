// Local re-meshing of one silhouette triangle (Wang et al. 2008, III-E, Fig. 11;
// docs/methods.md, "How the open choices were closed": crack-free, re-meshing).
//
// A silhouette triangle (A, B, C) has one vertex A whose visibility differs from
// B's and C's. Its sides AB and AC carry the silhouette points P and Q, and the
// sampled silhouette segment runs P = s0, s1, ..., sn = Q across it. The
// triangle is cut along that polyline into
//   - the lone side, polygon A P s1 ... Q: a fan from A;
//   - the base side, polygon P B C Q s(n-1) ... s1: the triangle (B, C, sk)
//     plus fans from B over s0..sk and from C over sk..sn. The split sk
//     maximises the worst triangle shape, measured in the flat triangle
//     (the parameter domain): shape in 3D would not do, because the curve's
//     bulge gives a triangle standing on edge a good 3D shape. A fan from a
//     vertex that lies almost on the chord's line makes such standing slivers.
// Both polygons are convex in the triangle's parameter domain (the samples lie
// on the chord PQ there), so every new triangle keeps the orientation of the
// input triangle. Sides AB and AC are split only at P and Q, which the
// neighbouring triangle across each side shares (one silhouette point per
// edge), and side BC is never split: the result is crack-free and introduces
// no T-junction. A caller may pass a vertex's id as a silhouette point (the
// point lies on that vertex); triangles that would repeat an id are then
// dropped, a zero-length edge collapse that keeps a closed manifold closed.
//
// Triangles with feature segments (Fig. 12) are cut into polygons that are
// convex in the parameter domain too, but whose points may lie on any side;
// chooseFanApex and emitFan triangulate those.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>
#include <vector>

namespace silsmooth
{

struct SilhouetteTriangleLayout
{
  /// Corners in the input triangle's orientation: A is the lone vertex.
  Id Lone = -1;
  Id BaseFirst = -1;  ///< B, after A in the triangle's order
  Id BaseSecond = -1; ///< C
  /// P (on AB), interior samples, Q (on AC): point ids.
  std::vector<Id> Chain;
  /// Positions in the plane of the input triangle (the parameter domain):
  /// B, C, and the chain's points where they sit on the chord P-Q there
  /// (same order as Chain).
  glm::dvec3 BaseFirstPosition{ 0.0 };
  glm::dvec3 BaseSecondPosition{ 0.0 };
  std::vector<glm::dvec3> ChainPositions;
};

/// Appends the triangles that replace the silhouette triangle to `out` and
/// returns how many were appended.
std::size_t remeshSilhouetteTriangle(
  const SilhouetteTriangleLayout& layout, std::vector<Triangle>& out);

/// For a polygon (point ids and positions in the parameter domain, in the
/// input triangle's orientation) that is convex there, with runs of collinear
/// points: the vertex among `isCandidate` from which a fan has the best worst
/// triangle shape, or -1 when a fan from `centre` (an interior point the
/// caller adds) is better by more than a factor of two, or when no vertex fan
/// is proper (a vertex on the line of a run of points cannot fan it).
int chooseFanApex(const std::vector<Id>& ids, const std::vector<glm::dvec3>& flat,
  const std::vector<unsigned char>& isCandidate, const glm::dvec3& centre);

/// Appends the fan of the polygon from vertex `apex`, or from the point
/// `centreId` when apex is -1; triangles that would repeat an id are dropped.
/// Returns how many were appended.
std::size_t emitFan(const std::vector<Id>& ids, int apex, Id centreId, std::vector<Triangle>& out);

} // namespace silsmooth
