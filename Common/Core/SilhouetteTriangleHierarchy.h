// Finding a frame's silhouette triangles without reading the whole mesh
// (issue 15): the triangles are clustered once, view-independently, by the
// S^3 vectors of their corners (VisibilityCones.h), in a binary tree of
// cones. Per frame a node whose cone is decided, either way, holds no
// silhouette triangle and is skipped whole; only the triangles of undecided
// leaves are evaluated, corner by corner. Near the silhouette that is a band
// of leaves; on a smooth mesh of a million triangles, a few percent of it.
//
// Exactness: find() gives exactly the triangles without a repeated corner
// whose corners do not all have the same side, visible (g >= 0) or not,
// where g = view.visibility(P, N) as evaluated directly; ascending, whatever
// parallelFor does. A decided cone covers every corner vector of every
// triangle below it, so each corner has the decided sign (the margin of
// VisibilityCones.h). Triangles with a corner the cones cannot hold (not
// clusterable) are evaluated every frame, and a view without a query vector
// makes find() return false (the caller then scans every triangle).
#pragma once

#include "MeshTopology.h"
#include "ParallelFor.h"
#include "ViewGeometry.h"
#include "VisibilityCones.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace silsmooth
{

class SilhouetteTriangleHierarchy
{
public:
  SilhouetteTriangleHierarchy() = default;
  /// One tree, for perspective views or for parallel ones. The mesh's arrays
  /// are read here and again by find(), which must be given the same ones;
  /// every corner must index `points` (as a prepared mesh's do).
  SilhouetteTriangleHierarchy(const std::vector<glm::dvec3>& points,
    const std::vector<glm::dvec3>& normals, const std::vector<Triangle>& triangles,
    bool perspective);

  /// Work counts of one find() call, for benchmarks and tests.
  struct Statistics
  {
    std::size_t VisitedNodes = 0;
    std::size_t EvaluatedTriangles = 0; // corner by corner
  };

  /// Puts the silhouette triangles of `view` in `out` (the rule above).
  /// False, with `out` untouched, when this tree cannot answer: a view of
  /// the other projection, a view without a query vector, or a mesh too
  /// large for the tree (more than 2^32 triangles).
  bool find(const ViewGeometry& view, const std::vector<glm::dvec3>& points,
    const std::vector<glm::dvec3>& normals, const std::vector<Triangle>& triangles,
    const ParallelFor& parallelFor, std::vector<Id>& out, Statistics* statistics = nullptr) const;

private:
  void findInSubtree(std::int32_t root, const ViewGeometry& view, const glm::dvec4& query,
    const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals,
    const std::vector<Triangle>& triangles, std::vector<Id>& out, Statistics& statistics) const;

  bool Built = false;
  bool Perspective = true;
  visibility_cones::Conditioning Map;
  std::vector<visibility_cones::ConeNode> Nodes;
  /// Roots of the subtrees handed to parallel workers, covering the tree.
  std::vector<std::int32_t> Tasks;
  /// The clustered triangles in tree order.
  std::vector<std::uint32_t> Order;
  /// Triangles evaluated in every frame (a corner not clusterable).
  std::vector<Id> Direct;
};

} // namespace silsmooth
