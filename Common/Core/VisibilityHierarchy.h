// Hierarchical vertex visibility (paper III-B): vertices are clustered once,
// view-independently, by their normals (parallel projection) or by the 4D
// vectors V' = (N, -N.V) on S^3 (perspective; E' = (E, 1) and
// sign(E'.V') = sign(g)). Per frame, whole clusters are found visible or
// invisible from one test, and only the undecided ones are evaluated vertex by
// vertex.
//
// Deviation from the paper: the paper cuts the sphere into longitude/latitude
// cells and decides a cell from its corners. A latitude circle is not a great
// circle, so a cell can hold points of the other sign while all its corners
// agree: the corner test is not conservative. Here every cluster is a node of
// a binary tree (median splits of the unit vectors along their widest
// coordinate) bounded by a cone: unit axis A and half-angle T such that every
// member is within T of A (leaves measure T from their members, parents bound
// their children's cones). For a unit query Q at angle a from A, all members
// are visible when a + T < pi/2 - margin and all invisible when
// a - T > pi/2 + margin; otherwise the children decide, and leaves evaluate
// each vertex exactly.
//
// Exactness: classify() makes bitwise the same decisions as
// ViewGeometry::visibility() >= 0. Undecided vertices get exactly that value.
// A vertex in a decided cluster gets +1 or -1, and a decision is only taken
// when the true g is at least about 3.7e-8 |N| |E - V| away from zero, nine
// orders of magnitude beyond the rounding of the direct dot product, so the
// direct evaluation has the same sign. For conditioning, the perspective
// vectors are built in coordinates centred on the bounding box and scaled by
// a power of two of its size; the eye is mapped the same way (the sign of g
// is invariant under that map). Vertices with a zero, tiny, huge or non-finite
// normal or position, and views with a non-finite or huge eye, are evaluated
// directly.
#pragma once

#include "ViewGeometry.h"
#include "VisibilityCones.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace silsmooth
{

class VisibilityHierarchy
{
public:
  /// Same signature as silsmooth::ParallelFor (SilhouetteSmoother.h).
  using ParallelForFunction =
    std::function<void(std::size_t, const std::function<void(std::size_t, std::size_t)>&)>;

  VisibilityHierarchy() = default;
  /// `normals` holds one normal per point (any length is handled exactly;
  /// they are compared as directions). A point without a normal (normals
  /// shorter than points) counts as having a zero one; extra normals are
  /// ignored. Keeps copies of the points and normals in tree order (about
  /// 80 bytes a vertex with the nodes), so the caller's arrays may go.
  VisibilityHierarchy(
    const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals);

  /// Work counts of one classify() call, for benchmarks.
  struct Statistics
  {
    std::size_t DecidedVertices = 0; // written +1 / -1 from a cluster test
    std::size_t ExactVertices = 0;   // evaluated directly
    std::size_t VisitedNodes = 0;
  };

  /// Fills g (resized to the point count) so that g[i] >= 0 exactly when
  /// view.visibility(points[i], normals[i]) >= 0. Undecided vertices get that
  /// value itself, vertices of decided clusters +1 or -1. The result does not
  /// depend on how parallelFor splits the work (null: serial).
  void classify(const ViewGeometry& view, std::vector<double>& g,
    const ParallelForFunction& parallelFor = nullptr, Statistics* statistics = nullptr) const;

  std::size_t pointCount() const { return this->PointCount; }
  std::size_t nodeCount() const
  {
    return this->Parallel.Nodes.size() + this->Perspective.Nodes.size();
  }

private:
  // One tree over the clustered vertices, which it stores in its own order
  // (original id, normal and, for perspective, point) so that leaves read
  // memory in order.
  struct Tree
  {
    std::vector<visibility_cones::ConeNode> Nodes;
    /// Roots of the subtrees handed to parallel workers, covering the tree.
    std::vector<std::int32_t> Tasks;
    std::vector<std::uint32_t> Order;
    std::vector<glm::dvec3> Points; // empty for the parallel tree
    std::vector<glm::dvec3> Normals;
  };

  static void buildTree(Tree& tree, const std::vector<glm::dvec4>& vectors);
  static void classifySubtree(const Tree& tree, std::int32_t root, const ViewGeometry& view,
    const glm::dvec4& query, double* g, Statistics& statistics);

  std::size_t PointCount = 0;
  /// Vertices outside the trees, always evaluated directly, with their data.
  std::vector<std::uint32_t> Direct;
  std::vector<glm::dvec3> DirectPoints;
  std::vector<glm::dvec3> DirectNormals;
  /// The map of vertices to S^3 (perspective conditioning).
  visibility_cones::Conditioning Map;
  Tree Parallel;
  Tree Perspective;
};

} // namespace silsmooth
