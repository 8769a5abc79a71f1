// Progressive mesh of Kim and Choe, "Stylized Silhouette Rendering Using
// Progressive Meshes" (3.1), after Hoppe 1996: the input is coarsened by
// repeated edge collapses, cheapest first, and each collapse is recorded as
// the vertex split that undoes it. The mesh can then be moved to any level
// of the sequence, down to the base mesh and back up to the input, which
// is given back exactly (same positions bit for bit, same triangles with the
// same corners in the same order).
//
// Cost of collapsing edge e = (a, b) into position v (eq. 1, lambda = 1/3):
//
//   F_C = lambda F_vol(e, v) d(e) + (1 - lambda) L(e)^2 F_boun(e, v)
//
// with what we chose where the paper is vague:
// - F_vol = | sum_i V(v, t_i) |, the net signed volume of the tetrahedra
//   between v and the triangles t_i around a and b before the collapse (the
//   paper's sum of [v, v0, v1, v2] / 6): the volume the collapse adds or
//   removes. Zero on flat regions.
// - d(e) = degree(a) + degree(b), the number of edges at each end.
// - F_boun = || sum_i (1/2)(v x v0 + v0 x v1 + v1 x v) ||, the summed area
//   vectors between v and the border edges e_i = (v0, v1) at a or b; zero
//   for edges with no end on the border.
// - The paper does not optimise v (it does not use Lindstrom's procedure); we
//   try v in {a, b, (a + b) / 2} and keep the cheapest, except that an end on
//   the border stays where it is (v is that end) so the border keeps its
//   shape, and an edge whose two ends are on the border without being a
//   border edge is not collapsed (it would pinch the surface).
// - Ties (flat interior regions, F_C = 0) are broken by L(e)^2, then by the
//   vertex ids, so the sequence is deterministic.
// A collapse is refused when it would make the mesh non-manifold (the link
// condition: the vertices next to both a and b are exactly the far corners
// of the triangles on e), flip a triangle (its normal would turn by 90
// degrees or more, or vanish), or leave a closed component with fewer than
// four vertices (a tetrahedron is the smallest closed base mesh). Meant for
// manifold input; elsewhere it stays safe: the points of an edge in three or
// more triangles and the corners of a triangle with a repeated corner are
// frozen (never collapsed), and every input comes back exactly.
//
// A collapse keeps one end's id: the end v sits on (the lower id for the
// midpoint) is `kept` and moves to v, the other is `removed` and leaves the
// mesh; triangles on e leave, triangles at `removed` get `kept` in its
// place. Triangle ids never change, so a level's triangles are the input's
// triangles that are active, with corners renamed; points used by no
// triangle are never active.
#pragma once

#include "MeshTopology.h"
#include "Progress.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace silsmooth
{

struct VertexSplit
{
  Id kept = 0;                      ///< the vertex that splits (kept by the collapse)
  Id removed = 0;                   ///< the vertex the split brings back
  glm::dvec3 keptBefore{ 0.0 };     ///< kept's position before the collapse (after the split)
  glm::dvec3 keptAfter{ 0.0 };      ///< kept's position after the collapse (the v chosen)
  std::vector<Id> removedTriangles; ///< triangles on the edge (1 or 2)
  std::vector<std::pair<Id, int>> renamedCorners; ///< (triangle, corner) that was `removed`
  double cost = 0.0;                              ///< F_C of the collapse
};

class ProgressiveMesh
{
public:
  static constexpr double Lambda = 1.0 / 3.0;

  /// Builds the sequence down to as few triangles as the rules allow (or to
  /// `minimumTriangles`), then leaves the mesh at its full (input) level.
  /// `progress` gets the share of the triangles removed so far, every 256
  /// collapses; when it returns false the build stops and aborted() is true
  /// (the mesh is then unusable).
  ProgressiveMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
    std::size_t minimumTriangles = 0, const ProgressCallback& progress = {});

  bool aborted() const { return this->Aborted; }

  std::size_t splitCount() const { return this->Splits.size(); }
  /// The splits, from the base mesh up: split i undoes collapse (count-1-i).
  const std::vector<VertexSplit>& splits() const { return this->Splits; }
  /// Number of splits applied to the base mesh: 0 (base) .. splitCount() (input).
  std::size_t level() const { return this->Level; }
  std::size_t triangleCount() const { return this->ActiveTriangles; }
  std::size_t vertexCount() const { return this->ActiveVertices; }
  std::size_t baseTriangleCount() const { return this->BaseTriangles; }
  std::size_t fullTriangleCount() const { return this->Triangles.size(); }

  void setLevel(std::size_t level);
  /// Applies splits until there are at least `count` triangles (or the input).
  void refineTo(std::size_t count);
  /// Applies collapses until there are at most `count` triangles (or the base).
  void coarsenTo(std::size_t count);
  /// Moves to the lowest level with at least `count` triangles (the input
  /// when there is none), whatever the current level: the result depends
  /// on `count` only.
  void setTriangleCount(std::size_t count);

  /// The current mesh over the input's point ids: every point (removed ones
  /// keep their input position) and the active triangles in input order.
  const std::vector<glm::dvec3>& points() const { return this->Points; }
  std::vector<Triangle> triangles() const;
  /// The current mesh compacted: active points only (in id order) with
  /// `pointIds[i]` the input id of point i; triangles renumbered to match,
  /// in input order, with `triangleIds` their input ids.
  void compact(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles,
    std::vector<Id>& pointIds, std::vector<Id>& triangleIds) const;

private:
  void applySplit(const VertexSplit& split);
  void applyCollapse(const VertexSplit& split);

  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<char> TriangleActive;
  std::vector<VertexSplit> Splits; // base -> input order
  std::size_t Level = 0;
  std::size_t ActiveTriangles = 0;
  std::size_t ActiveVertices = 0;
  std::size_t BaseTriangles = 0;
  std::vector<char> VertexActive;
  bool Aborted = false;
};

} // namespace silsmooth
