// A cut through a VertexHierarchy that follows the view (issue 18): the set
// of applied nodes, kept closed under "parent of" (so the mesh it gives is
// always one the hierarchy guarantees), changed incrementally from one frame
// to the next, as Hoppe's view-dependent refinement of progressive meshes is.
//
// adapt() takes a test with two questions per node: should it be applied
// (needs), and, for an applied one, should it stay (keeps; a looser question,
// for hysteresis). It then
//   1. undoes, repeatedly, applied nodes with no applied child that the test
//      would not keep, and
//   2. asks, for every point of the mesh, whether its next split is needed,
//      and applies the needed ones, each after its unapplied parents (Hoppe's
//      forced splits); the splits of the points a split brings are asked next.
// Only the front is examined: the applied nodes with no applied child, the
// next split of every point of the mesh, and what the changes expose; a frame
// costs the front and the change, not the input. When needs() grows with the
// node bounds, which contain their vertex-tree children's, every needed node
// ends applied; every applied node is kept or is a parent of one that is.
//
// The mesh of the cut is kept up to date as splits are applied and undone, as
// Hoppe's vsplit and ecol do: the active faces (input triangle ids, in no
// particular order), their corners, the faces at each point and every point's
// position. A split renames Kept to Removed in the faces around Kept from its
// neighbour face (Removed, l) round to (Removed, r), and adds its two faces.
#pragma once

#include "VertexHierarchy.h"

#include <cstddef>
#include <vector>

namespace silsmooth
{

/// What adapt() asks of a node. Implementations must not change the cut.
class RefinementTest
{
public:
  virtual ~RefinementTest() = default;
  /// Whether an unapplied node should be applied.
  virtual bool needs(VertexHierarchy::Index node) const = 0;
  /// Whether an applied node should stay applied (at least needs(node)).
  virtual bool keeps(VertexHierarchy::Index node) const { return this->needs(node); }
};

/// A cut's mesh compacted: the points its triangles use, in the order first
/// used, with `PointIds` their input ids; triangles renumbered to match, with
/// `TriangleIds` their input triangle ids.
struct ExtractedMesh
{
  std::vector<glm::dvec3> Points;
  /// Per point, the shading normal that suits its position now: the unit
  /// sum of the input normals of the points it stands for
  /// (VertexHierarchy::Node; its own, in float, when it stands for itself).
  std::vector<glm::vec3> Normals;
  std::vector<Triangle> Triangles;
  std::vector<Id> PointIds;
  std::vector<Id> TriangleIds;
};

struct AdaptStatistics
{
  std::size_t Applied = 0;   ///< nodes applied by this call
  std::size_t Undone = 0;    ///< nodes undone by this call
  std::size_t Evaluated = 0; ///< questions asked of the test
  std::size_t Forced = 0;    ///< nodes applied only because a needed node needs them
};

class SelectiveRefinement
{
public:
  using Index = VertexHierarchy::Index;

  /// Starts at the base mesh (no node applied). The hierarchy must outlive this.
  explicit SelectiveRefinement(const VertexHierarchy& hierarchy);

  AdaptStatistics adapt(const RefinementTest& test);
  /// Applies every node: the input mesh.
  void applyAll();
  /// Undoes every node: the base mesh.
  void undoAll();

  bool isApplied(Index node) const { return this->Applied[static_cast<std::size_t>(node)] != 0; }
  std::size_t appliedCount() const { return this->AppliedNodes; }

  /// The active faces (input triangle ids), unordered, and their corners now.
  const std::vector<Index>& activeFaces() const { return this->Active.items(); }
  const Triangle& corners(Index face) const
  {
    return this->Corners[static_cast<std::size_t>(face)];
  }
  std::size_t triangleCount() const { return this->Active.items().size(); }
  /// Every point's position in the current mesh (points not in it keep a stale one).
  const std::vector<glm::dvec3>& positions() const { return this->Positions; }

  /// The current mesh compacted (ExtractedMesh). O(triangles).
  void extract(ExtractedMesh& mesh) const;

private:
  // A set of indices with O(1) insert and erase (by swapping with the last).
  class IndexSet
  {
  public:
    explicit IndexSet(std::size_t universe = 0)
      : Where(universe, -1)
    {
    }
    void insert(Index i);
    void erase(Index i);
    bool contains(Index i) const { return this->Where[static_cast<std::size_t>(i)] >= 0; }
    const std::vector<Index>& items() const { return this->Items; }

  private:
    std::vector<Index> Items;
    std::vector<Index> Where;
  };

  void apply(Index node);
  void undo(Index node);
  // The point other than `kept` that faces `a` and `b` share (the wedge point now).
  Id sharedPoint(Index a, Index b, Id kept) const;
  // The faces around `kept` from `first` to `last`, leaving `first` away from `wedge`.
  void fanBetween(Id kept, Index first, Index last, Id wedge, std::vector<Index>& fan) const;
  void addFace(Index face);
  void removeFace(Index face);
  // Face keeps being active; its corner `from` becomes `to` (moving it
  // between the two points' lists).
  void renameCorner(Index face, Id from, Id to);
  // Applies `node` after its unapplied parents, adding each to `applied`.
  void applyWithParents(Index node, std::vector<Index>& applied);

  const VertexHierarchy& Hierarchy;
  std::vector<glm::dvec3> Positions;
  std::vector<glm::vec3> Normals;
  std::vector<Triangle> Corners;           // per face
  std::vector<std::vector<Index>> FacesOf; // per point: the active faces at it
  std::vector<unsigned char> Applied;
  std::vector<Index> UnappliedParents; // per node
  std::vector<Index> AppliedChildren;  // per node
  IndexSet Active;                     // faces
  IndexSet NextSplits;                 // the next split of every point of the mesh
  IndexSet Undoable;                   // applied, no child applied
  std::size_t AppliedNodes = 0;
  mutable std::vector<Id> PointStamp; // for extract()
  std::vector<Index> Fan;             // for apply()
};

} // namespace silsmooth
