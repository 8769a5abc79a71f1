// The view-independent state of a mesh that the per-frame passes read:
// points (split at feature edges), triangles, unit shading normals, the edge
// table, boundaries, feature curves and neighbours. Built once per input,
// shared by the smoothing (SilhouetteSmoother.h) and the face-based lines
// (Lines/Core/FaceSilhouetteLines.h).
#pragma once

#include "FeatureCurves.h"
#include "MeshTopology.h"
#include "ParallelFor.h"
#include "ShadingNormals.h"
#include "SilhouetteTriangleHierarchy.h"
#include "SurfaceWelding.h" // NormalSeamAngleDegrees
#include "TriangleGrid.h"
#include "ViewGeometry.h"
#include "VisibilityHierarchy.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace silsmooth
{

/// Normals given per triangle corner: a vector (entry 3t + k), or a function
/// of (t, k) that reads them where they are (a caller whose normals are per
/// point, reached through its own triangles, need not copy them per corner:
/// at 1.3M triangles that is 94 MB). Empty: none given.
class CornerNormals
{
public:
  CornerNormals() = default;
  /// A view: it keeps a pointer to `perCorner` (and `of` reads what its
  /// captures refer to), so it is made for one call and never kept.
  explicit CornerNormals(const std::vector<glm::dvec3>& perCorner)
    : PerCorner(&perCorner)
    , Triangles(perCorner.size() / 3)
  {
  }
  CornerNormals(std::function<glm::dvec3(std::size_t t, std::size_t k)> of, std::size_t triangles)
    : Of(std::move(of))
    , Triangles(triangles)
  {
  }
  /// Whether it gives a normal for every corner of `triangleCount` triangles.
  bool covers(std::size_t triangleCount) const
  {
    return triangleCount > 0 && this->Triangles == triangleCount &&
      (this->Of || (this->PerCorner && this->PerCorner->size() == 3 * triangleCount));
  }
  glm::dvec3 operator()(std::size_t t, std::size_t k) const
  {
    return this->Of ? this->Of(t, k) : (*this->PerCorner)[t * 3 + k];
  }

private:
  const std::vector<glm::dvec3>* PerCorner = nullptr;
  std::function<glm::dvec3(std::size_t, std::size_t)> Of;
  std::size_t Triangles = 0;
};

/// The view-independent state: points, triangles, unit shading normals, the
/// edge table and the feature curves. Build it when the input changes, reuse
/// it every frame.
///
/// With feature edges, every point on one is split into one point per smooth
/// group (FeatureCurves.h): the prepared points are the input's, with their
/// ids, followed by the copies, and the triangles refer to the copies where
/// they belong to another group. Without feature edges nothing is split.
class PreparedMesh
{
public:
  /// `normals` may be empty (angle-weighted normals are computed) or hold one
  /// normal per point; a given normal that is zero or not finite is replaced
  /// by the angle-weighted one. Points on feature edges always get the
  /// angle-weighted normal of their smooth group (one given normal cannot
  /// serve two sides of a crease). `featureEdges` are pairs of point ids.
  ///
  /// `cornerNormals`, when not empty, holds a normal per triangle corner
  /// (3t + k) instead of per point, for meshes whose triangles meet at one
  /// point but came with a normal each (welded asset files); `normals` is then
  /// ignored. A point's normal is its corners' normal (the normalised sum of
  /// their distinct usable normals). On a feature point the smooth groups keep
  /// their own corners' normals when those differ between the groups by more
  /// than NormalSeamAngleDegrees (the input told the sides apart, as at a
  /// normal seam); otherwise they get the angle-weighted normal as above.
  ///
  /// `edges`, when given, is the edge table of `triangles`; it saves building
  /// it again when no point is split. `weighting` is how the normals that are
  /// computed are estimated (ShadingNormals.h); "angle-weighted" above means
  /// that estimate.
  PreparedMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
    const std::vector<glm::dvec3>& normals = {}, std::vector<FeatureEdge> featureEdges = {},
    const CornerNormals& cornerNormals = {}, const EdgeTable* edges = nullptr,
    NormalWeighting weighting = NormalWeighting::Angle);

  /// For a deforming mesh: the mesh the constructor above makes from these
  /// arguments and the triangles `earlier` was made from (the caller's to
  /// ensure), with `points` moved. It takes earlier's triangles, split,
  /// edge table, boundaries and neighbours (earlier is left empty, to be
  /// dropped), makes the feature curves (their tangents, and which are
  /// smoothed) and the normals again, builds the hierarchies anew on use,
  /// and adopts the grid of triangle boxes as adoptTriangleGrid() would.
  /// It keeps earlier's apexes(), which the constructor would find again
  /// from the new positions (about 35 ms at 1.3M triangles).
  /// Null, with earlier and `points` untouched, when `points` are not one per input
  /// point or the feature edges would split the mesh elsewhere; the caller
  /// then builds the mesh anew. `edges` is the table of the triangles.
  static std::unique_ptr<PreparedMesh> moved(PreparedMesh& earlier,
    std::vector<glm::dvec3>&& points, const std::vector<glm::dvec3>& normals,
    const std::vector<FeatureEdge>& featureEdges, const CornerNormals& cornerNormals,
    const EdgeTable& edges, NormalWeighting weighting);

  /// Input points, then the copies made by splitting feature points.
  const std::vector<glm::dvec3>& points() const { return this->Points; }
  const std::vector<Triangle>& triangles() const { return this->Triangles; }
  const std::vector<glm::dvec3>& normals() const { return this->Normals; }
  const EdgeTable& edges() const { return this->Edges; }
  /// How many of points() are the input's (the rest are copies).
  std::size_t inputPointCount() const { return this->InputPointCount; }
  /// The input point that prepared point p is (or copies).
  Id sourcePoint(Id p) const
  {
    return static_cast<std::size_t>(p) < this->InputPointCount
      ? p
      : this->CopySources[static_cast<std::size_t>(p) - this->InputPointCount];
  }
  /// Whether prepared point p lies on a feature edge.
  bool onFeature(Id p) const
  {
    return !this->OnFeature.empty() && this->OnFeature[static_cast<std::size_t>(p)] != 0;
  }
  /// Whether prepared point p lies on a boundary edge (an edge of one
  /// triangle): the edge of an open mesh, or a seam where a partitioned mesh
  /// was cut. Such points are never moved by the perturbation, so pieces
  /// still meet.
  bool onBoundary(Id p) const { return this->OnBoundary[static_cast<std::size_t>(p)] != 0; }
  /// Whether edge e is a side of one triangle only (a boundary edge).
  bool isBoundaryEdge(Id e) const { return this->BoundaryEdges[static_cast<std::size_t>(e)] != 0; }
  /// Points where the surface comes to a point, as at a cone's apex
  /// (ConeApexes.h), ascending: the smoothing leaves the silhouette on the
  /// mesh's own edges in their triangles.
  const std::vector<Id>& apexes() const { return this->Apexes; }
  bool isApex(Id p) const
  {
    return !this->Apexes.empty() && std::binary_search(this->Apexes.begin(), this->Apexes.end(), p);
  }
  const FeatureCurves& features() const { return this->Features; }
  /// The feature edge (index into features()) that edge e lies on, or -1.
  Id edgeFeature(Id e) const
  {
    return this->EdgeFeatures.empty() ? -1 : this->EdgeFeatures[static_cast<std::size_t>(e)];
  }
  /// Triangles with a side on a smoothed feature edge, ascending: they are
  /// re-meshed in every frame so that the feature curve is drawn smooth.
  const std::vector<Id>& featureTriangles() const { return this->FeatureTriangles; }
  /// Every (feature edge, triangle with a side on it), sorted: the triangles
  /// of the crease's sides (two or more, one per smooth group).
  const std::vector<std::pair<Id, Id>>& featureSideTriangles() const
  {
    return this->FeatureSideTriangles;
  }
  /// The vertices joined to v by an edge are
  /// neighbours()[neighbourOffsets()[v] .. neighbourOffsets()[v + 1]).
  const std::vector<Id>& neighbourOffsets() const { return this->NeighbourOffsets; }
  const std::vector<Id>& neighbours() const { return this->Neighbours; }
  /// The clustering for VisibilityMethod::Hierarchical, built on first use
  /// (thread-safe); copies of the mesh share it.
  const VisibilityHierarchy& visibilityHierarchy() const;
  /// The grid of the triangles' boxes for the fold guard, built on first use
  /// (thread-safe); copies of the mesh share it. It may be the grid of an
  /// earlier position of the same mesh (adoptTriangleGrid): every triangle's
  /// box now lies within triangleGridSlack() of its box in the grid, so a
  /// query widened by the slack finds every triangle a fresh grid would.
  const TriangleGrid& triangleGrid() const;
  double triangleGridSlack() const { return this->GridSlack; }
  /// Whether the grid is there (built, or adopted).
  bool hasTriangleGrid() const { return this->Grid->Built.load(std::memory_order_acquire); }
  /// How the mesh's whole-mesh indexes are built when a second frame asks
  /// for them: the silhouette triangle tree (findSilhouetteTriangles) and
  /// the fold guard's grid (foldGuardGridForFrame).
  enum class IndexBuild
  {
    /// On a thread of its own, from copies of the mesh's arrays: the calls
    /// answer as without the index (the caller scans) until it is done, so
    /// no frame waits for it (about 0.5 s for the tree and 0.15 s for the
    /// grid at 1.3M triangles). The answers are the same either way; only
    /// the time of a frame differs.
    Background,
    /// In the call itself, which then uses it (tests that must see the
    /// index answer).
    InCall
  };
  /// The grid for a frame's fold checks (FoldGuardMesh::Grid): call once
  /// per frame that checks folds. Null on the mesh's first such frame,
  /// unless the grid is there already (built, or adopted): the fold guard
  /// then scans the triangles, which costs less than building the grid, so a
  /// mesh smoothed once (a filter's run) never builds it. The second frame
  /// builds the grid as `build` says; with IndexBuild::Background, frames
  /// scan until it is done. The frames of a deforming mesh count as one
  /// mesh's (adoptTriangleGrid carries the count) and build in the call,
  /// because the next frames adopt the grid: its second frame builds the
  /// grid, later ones adopt it while the points move little; when the moves
  /// added up outrun it, the next frame builds it anew, and when a single
  /// move outruns it, the frames scan from then on.
  const TriangleGrid* foldGuardGridForFrame(IndexBuild build = IndexBuild::Background) const;
  /// Takes `earlier`'s grid, if it has been built, when this mesh has the
  /// same triangles over moved points (a deforming mesh) and the points
  /// moved little: the slack (earlier's plus the largest coordinate change
  /// of any point) stays under half a grid cell, so queries stay about as
  /// cheap. Building the grid was most of a deforming frame's fold check
  /// (about 150 ms at 1.3M triangles). False otherwise, taking over only
  /// the count of frames and whether a single move outran a grid
  /// (foldGuardGridForFrame).
  bool adoptTriangleGrid(const PreparedMesh& earlier);
  /// The silhouette triangles of `view` from the triangle hierarchy of its
  /// projection (SilhouetteTriangleHierarchy.h), built on the second call
  /// for that projection (thread-safe; copies of the mesh share it). False,
  /// with `out` untouched, on the first call, while the tree is being built
  /// in the background, and when the tree cannot answer: the caller then
  /// scans the triangles.
  bool findSilhouetteTriangles(const ViewGeometry& view, const ParallelFor& parallelFor,
    std::vector<Id>& out, IndexBuild build = IndexBuild::Background) const;
  /// Whether the tree of that projection (parallel or perspective) is built
  /// and answers findSilhouetteTriangles (for tests and benchmarks).
  bool silhouetteTreeReady(bool parallel) const;

  /// For tests: a function every background build (IndexBuild::Background)
  /// calls on its thread before it builds; empty for none (the default).
  /// A test holds the builds there to see frames run while they are not
  /// done. Set it while no build is running.
  static void setBackgroundBuildHook(std::function<void()> hook);

private:
  /// moved()'s: takes earlier's topology.
  PreparedMesh(PreparedMesh& earlier, std::vector<glm::dvec3> points,
    const std::vector<glm::dvec3>& normals, const CornerNormals& cornerNormals,
    NormalWeighting weighting);
  /// adoptTriangleGrid() once the triangles are known to be the same.
  bool adoptTriangleGridOfMoved(const PreparedMesh& earlier);
  // The constructor's steps, in order.
  void splitAtFeatures();
  void findBoundaries();
  void indexFeatureEdges();
  void findNeighbours();
  void chooseNormals(const std::vector<glm::dvec3>& normals, const CornerNormals& cornerNormals,
    NormalWeighting weighting);
  std::vector<glm::dvec3> normalsFromCorners(const CornerNormals& cornerNormals) const;

  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<glm::dvec3> Normals;
  std::vector<Id> Apexes;
  EdgeTable Edges;
  std::size_t InputPointCount = 0;
  std::vector<Id> CopySources;
  std::vector<unsigned char> OnFeature;
  std::vector<unsigned char> OnBoundary;
  std::vector<unsigned char> BoundaryEdges;
  FeatureCurves Features;
  std::vector<Id> EdgeFeatures;
  std::vector<Id> FeatureTriangles;
  std::vector<std::pair<Id, Id>> FeatureSideTriangles;
  std::vector<Id> NeighbourOffsets;
  std::vector<Id> Neighbours;
  struct LazyHierarchy
  {
    std::once_flag Once;
    VisibilityHierarchy Hierarchy;
  };
  std::shared_ptr<LazyHierarchy> Hierarchy = std::make_shared<LazyHierarchy>();
  struct LazyGrid
  {
    std::once_flag Once;
    std::atomic<int> Frames{ 0 };      // foldGuardGridForFrame's calls
    std::atomic<bool> Outrun{ false }; // a single move outran an earlier grid
    /// A deforming mesh's grid (not adopted from the earlier frame's): built
    /// in the call, for the next frames to adopt.
    bool Deforming = false;
    std::atomic<bool> BackgroundStarted{ false };
    /// Grid is complete and may be read (set, with release, after it is
    /// written under Once).
    std::atomic<bool> Built{ false };
    TriangleGrid Grid;
  };
  std::shared_ptr<LazyGrid> Grid = std::make_shared<LazyGrid>();
  double GridSlack = 0.0;
  /// Copies of the arrays the background builds read, made once for the
  /// builds that run at the same time (the tree's and the grid's start in
  /// the same frame): the first build's thread keeps them, the next ones
  /// share them while it lives (weak: they go when the last build ends).
  struct BuildArrays
  {
    std::vector<glm::dvec3> Points;
    std::vector<glm::dvec3> Normals;
    std::vector<Triangle> Triangles;
  };
  struct LazyBuildArrays
  {
    std::mutex Mutex;
    std::weak_ptr<const BuildArrays> Arrays;
  };
  std::shared_ptr<LazyBuildArrays> SharedBuildArrays = std::make_shared<LazyBuildArrays>();
  /// The arrays for a background build: the ones a running build holds, or
  /// new copies.
  std::shared_ptr<const BuildArrays> buildArrays() const;
  /// Runs `build` on a detached thread of its own, over buildArrays() (the
  /// mesh, and every copy of it, may go before it is done; the thread frees
  /// what it holds when it ends), after the test hook. An exception inside
  /// the thread ends it with nothing built. False, with nothing started,
  /// when no thread (or no memory for the copies) could be had: the caller
  /// builds in the call.
  bool startBackgroundBuild(std::function<void(const BuildArrays&)> build) const;
  struct LazyTriangleHierarchy
  {
    std::atomic<int> Searches{ 0 };
    std::once_flag Once;
    /// Tree is complete and may be read (set after it is written).
    std::atomic<bool> Ready{ false };
    SilhouetteTriangleHierarchy Tree;
  };
  /// For parallel views ([0]) and perspective ones ([1]).
  std::shared_ptr<LazyTriangleHierarchy> TriangleHierarchies[2] = {
    std::make_shared<LazyTriangleHierarchy>(), std::make_shared<LazyTriangleHierarchy>()
  };
};

/// The visibility value g of every point (parallel over points).
std::vector<double> vertexVisibility(
  const PreparedMesh& mesh, const ViewGeometry& view, const ParallelFor& parallelFor = serialFor);

} // namespace silsmooth
