// A multiresolution mesh for view-dependent refinement (issue 18): Hoppe's
// vertex hierarchy ("View-dependent refinement of progressive meshes",
// SIGGRAPH 1997), built from an edge-collapse sequence (QuadricSimplifier's,
// RecordSequence).
//
// Read in reverse, the sequence is a list of vertex splits from a base mesh up
// to the input; each split is a node. Split j brings back point `Removed` next
// to point `Kept`, and the two triangles of their edge, LeftFace and RightFace
// (input triangle ids; every triangle keeps its id at every level, only its
// corners change). When the split was recorded, LeftFace's third corner was the
// wedge point l and RightFace's r; Neighbours are the faces next to LeftFace
// across (Kept, l) and (Removed, l), and next to RightFace across (Kept, r) and
// (Removed, r) (Hoppe's fn0..fn3).
//
// The rule that keeps any extracted mesh valid (Hoppe's, section 4): split j
// may be applied when Kept is a point of the mesh and its four neighbour faces
// are in the mesh, whatever their corners are then; it is undone when neither
// point has been split further and no applied split needs its two faces. So the
// parents of j are the split that makes Kept what it is (the previous split of
// Kept, or the split that brought Kept back) and the splits that brought its
// neighbour faces; any set of splits closed under "parent of" gives a mesh, the
// same for every order of applying them. With no split applied it is the base
// mesh; with all of them the input (same triangles with the same corners in
// the same order, same positions bit for bit). The tests check that every cut
// of a closed manifold is a closed manifold of the same genus.
//
// The vertex tree: once split j is applied, the next splits of its two points
// are NextSplitOfKept (the next finer split of Kept) and FirstSplitOfRemoved
// (the coarsest split of Removed): j's children in the tree. The tree is not
// the dependency graph: a split may need parents outside its subtree
// (SelectiveRefinement applies them first, as Hoppe's forced splits).
//
// Bounds for view-dependent tests, each containing its tree children's (so a
// test that grows with them asks for a node whenever it asks for a child): a
// sphere around every corner position of the split's two stars (before and
// after), the cone of their triangles' normals and of the input's point
// normals at their corners (the normals a contour is drawn with), and an error
// in model units: the larger distance from the split's two points to the star
// of Kept after the collapse, plus the larger error of the two children
// (additive down the tree, so never below what a finer collapse undid).
#pragma once

#include "MeshTopology.h"
#include "Progress.h"
#include "QuadricSimplifier.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace silsmooth
{

/// A sphere; Radius < 0 means empty.
struct BoundingSphere
{
  glm::dvec3 Center{ 0.0 };
  double Radius = -1.0;

  void add(const glm::dvec3& point);
  void add(const BoundingSphere& other);
};

/// The directions within HalfAngle (radians) of the unit Axis; HalfAngle < 0
/// means empty, >= pi every direction.
struct NormalCone
{
  glm::dvec3 Axis{ 0.0, 0.0, 1.0 };
  double HalfAngle = -1.0;

  void add(const glm::dvec3& unitNormal);
  void add(const NormalCone& other);
};

class VertexHierarchy
{
public:
  using Index = std::int32_t;
  static constexpr Index None = -1;

  /// What each corner of a split's new face is: Kept, Removed or the wedge point.
  enum CornerRole : std::uint8_t
  {
    KeptCorner = 0,
    RemovedCorner = 1,
    WedgeCorner = 2
  };

  struct Node
  {
    Id Kept = 0;
    Id Removed = 0;
    glm::dvec3 KeptFine{ 0.0 };    ///< Kept's position with the split applied
    glm::dvec3 KeptCoarse{ 0.0 };  ///< Kept's position without it
    glm::dvec3 RemovedFine{ 0.0 }; ///< Removed's position with the split applied
    /// The shading normals that suit those positions: each the unit sum of
    /// the input point normals of the points the vertex stands for there
    /// (its own alone, for a vertex no collapse reached), leaving out a
    /// collapsed cluster whose normal is more than 45 degrees from the kept
    /// one's (across a crease, where a sum would shade each side as the
    /// other).
    glm::vec3 KeptFineNormal{ 0.0f };
    glm::vec3 KeptCoarseNormal{ 0.0f };
    glm::vec3 RemovedFineNormal{ 0.0f };
    Index LeftFace = None;
    Index RightFace = None;
    std::array<CornerRole, 3> LeftRoles{};
    std::array<CornerRole, 3> RightRoles{};
    /// Next to LeftFace across (Kept, l), (Removed, l); next to RightFace
    /// across (Kept, r), (Removed, r).
    std::array<Index, 4> Neighbours{ None, None, None, None };
    Index NextSplitOfKept = None;
    Index FirstSplitOfRemoved = None;
    BoundingSphere Bound;
    NormalCone Normals;
    double Error = 0.0;
  };

  VertexHierarchy() = default;
  /// `sequence` must be a collapse sequence of this mesh, as QuadricSimplifier
  /// records it: each collapse along an edge of exactly two triangles
  /// (std::invalid_argument otherwise). Triangles that name a point twice are
  /// left out, as the simplifier leaves them out. `pointNormals`: the input's
  /// unit point normals, or empty for its angle-weighted ones. `progress` gets
  /// the share of the sequence read; false stops the build (aborted()).
  VertexHierarchy(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
    const std::vector<CollapseRecord>& sequence, std::vector<glm::dvec3> pointNormals = {},
    const ProgressCallback& progress = {});

  bool aborted() const { return this->Aborted; }

  std::size_t nodeCount() const { return this->Nodes.size(); }
  const Node& node(Index j) const { return this->Nodes[static_cast<std::size_t>(j)]; }

  /// Splits that must be applied before j, and the splits that need j.
  const Index* parentsBegin(Index j) const { return this->span(this->Parents, j); }
  const Index* parentsEnd(Index j) const { return this->span(this->Parents, j + 1); }
  const Index* childrenBegin(Index j) const { return this->span(this->Children, j); }
  const Index* childrenEnd(Index j) const { return this->span(this->Children, j + 1); }

  /// The coarsest split of each point of the base mesh (the vertex trees' roots).
  const std::vector<Index>& rootSplits() const { return this->Roots; }
  /// Every input triangle that names no point twice, with its corners in the
  /// base mesh; `baseFaces()` are the ones in it.
  const std::vector<Triangle>& baseCorners() const { return this->BaseCorners; }
  const std::vector<Index>& baseFaces() const { return this->BaseFaces; }
  /// Every point's position in the base mesh (the input's for points no
  /// collapse moved).
  const std::vector<glm::dvec3>& basePositions() const { return this->BasePositions; }
  /// Every point's shading normal in the base mesh (the Node normals' rule).
  const std::vector<glm::vec3>& baseNormals() const { return this->BaseNormals; }
  /// Input triangles (faces are numbered as the input's triangles).
  std::size_t faceCount() const { return this->BaseCorners.size(); }
  /// The input's unit point normals the bounds were made with (given, or
  /// angle-weighted; zero where a point has none).
  const std::vector<glm::dvec3>& pointNormals() const { return this->PointNormals; }

private:
  struct Table
  {
    std::vector<std::size_t> Offsets{ 0 };
    std::vector<Index> Items;
  };
  const Index* span(const Table& table, Index j) const
  {
    return table.Items.data() + table.Offsets[static_cast<std::size_t>(j)];
  }

  std::vector<Node> Nodes;
  Table Parents;
  Table Children;
  std::vector<Index> Roots;
  std::vector<Triangle> BaseCorners;
  std::vector<Index> BaseFaces;
  std::vector<glm::dvec3> BasePositions;
  std::vector<glm::vec3> BaseNormals;
  std::vector<glm::dvec3> PointNormals;
  bool Aborted = false;

  friend class VertexHierarchyBuilder;
};

} // namespace silsmooth
