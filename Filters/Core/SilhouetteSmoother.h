// The per-frame silhouette smoothing pass of Wang et al. 2008 over a mesh whose
// view-independent data (edge table, shading normals) is prepared once.
//
// Steps, each in its own unit: vertex visibility (ViewGeometry), silhouette
// triangles, one silhouette point per mixed edge on its silhouette bridge
// (HermiteCurve, SilhouettePoint), silhouette segments and their adaptive
// sampling (AdaptiveSampling), local re-meshing (LocalRemesher), the
// silhouette polylines (SilhouettePolylines), and the vertex perturbation
// for concave segments (VertexPerturbation).
#pragma once

#include "AdaptiveSampling.h"
#include "FeatureCurves.h"
#include "MeshTopology.h"
#include "ShadingNormals.h"
#include "SurfaceWelding.h"
#include "TriangleGrid.h"
#include "ViewGeometry.h"
#include "VisibilityHierarchy.h"

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace silsmooth
{

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
    const std::vector<glm::dvec3>& cornerNormals = {}, const EdgeTable* edges = nullptr,
    NormalWeighting weighting = NormalWeighting::Angle);

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
  /// (thread-safe); copies of the mesh share it.
  const TriangleGrid& triangleGrid() const;

private:
  // The constructor's steps, in order.
  void splitAtFeatures();
  void findBoundaries();
  void indexFeatureEdges();
  void findNeighbours();
  void chooseNormals(const std::vector<glm::dvec3>& normals,
    const std::vector<glm::dvec3>& cornerNormals, NormalWeighting weighting);
  std::vector<glm::dvec3> normalsFromCorners(const std::vector<glm::dvec3>& cornerNormals) const;

  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<glm::dvec3> Normals;
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
    TriangleGrid Grid;
  };
  std::shared_ptr<LazyGrid> Grid = std::make_shared<LazyGrid>();
};

/// How the pass finds the vertices facing the viewer (paper III-B). Both make
/// bitwise the same decisions, so the output does not depend on the choice.
enum class VisibilityMethod
{
  /// g = N . (E - V) at every vertex: one dot product each.
  PerVertex,
  /// Clusters of vertices decided by one cone test (VisibilityHierarchy.h).
  Hierarchical
};

struct SmoothingParameters
{
  SamplingParameters Sampling;
  /// Lower the vertices around concave silhouette segments so that the
  /// smoothed curve is not blocked (see VertexPerturbation.h).
  bool PerturbConcaveSilhouettes = true;
  VisibilityMethod Visibility = VisibilityMethod::PerVertex;
  /// Re-mesh folding triangles again, more conservatively, until none folds
  /// (FoldGuard.h): a silhouette triangle whose new triangles turn over or
  /// cut through another output triangle is re-meshed along the chord
  /// between its silhouette points (no interior samples), then with its
  /// silhouette points on its straight edges (shared with the neighbours
  /// across them, which are re-meshed again too), then with its curved
  /// feature segments straight; a moved point whose triangles fold stays in
  /// place. Each step is counted in the result.
  bool PreventFolds = true;
  /// The mesh is one piece of a partitioned mesh: its boundary edges may be
  /// seams with other pieces, which compute the same silhouette points and
  /// feature segments there and cannot know of a fallback, so the fold
  /// guard leaves those curved (a fold only that would undo is counted as
  /// unresolved). Otherwise boundary edges are the surface's open border.
  bool BoundaryMayBeSeam = false;
  /// After the first round, check only what the fallbacks changed
  /// (FoldGuardFrame::CheckSources); the findings, and so the output, are
  /// those of checking everything every round (core.SilhouetteSmoother
  /// compares both), at a fraction of the cost. False checks everything.
  bool IncrementalFoldChecks = true;
  /// The most points a frame's sampling may add, 0 for no bound. A frame
  /// caps each segment's samples at 2 + MaximumSampledPoints / (silhouette
  /// triangles + feature edges) when that is below MaximumSamples (the cap
  /// wins over MinimumSamples). A silhouette triangle holds one silhouette
  /// segment and a feature edge one feature segment, so the frame's samples
  /// stay within about the budget however its segments share it; a segment
  /// that wants fewer samples than the cap is sampled as without it. The cap
  /// depends only on the frame's counts, so the output stays the same for
  /// any thread count.
  std::size_t MaximumSampledPoints = 0;
  /// Leave out the silhouette triangles the view cannot show: those whose
  /// three corners lie beyond one plane of the view frustum (ModelToClip's
  /// six) by more than the triangle's longest side. A triangle's smoothed
  /// curves stay within half its longest side of it (the end tangents are
  /// at most twice the chord, eq. 4), so nothing the view shows changes,
  /// and a crack where a culled triangle meets a re-meshed one lies beyond
  /// that plane too. For renderers (vtkSilhouetteSmoothingMapper); a mesh
  /// written to a file wants every silhouette smoothed.
  bool CullOutsideFrustum = false;
  /// One entry per prepared triangle, or empty: a non-zero entry is a
  /// triangle that is never re-meshed (a ghost cell of a partitioned
  /// mesh's piece, which its own piece re-meshes). It still counts for the
  /// normals, the adjacency and the silhouette points on its edges, so the
  /// piece that owns it computes the same ones. Not owned: must outlive
  /// the call.
  const std::vector<unsigned char>* FrozenTriangles = nullptr;
};

/// A point the pass adds. Its other attributes (texture coordinates, scalars)
/// are the linear combination `Weights` of the input points `Sources`.
struct NewPoint
{
  glm::dvec3 Position{ 0.0 };
  glm::dvec3 Normal{ 0.0 };
  std::array<Id, 3> Sources{ { 0, 0, 0 } };
  std::array<double, 3> Weights{ { 0.0, 0.0, 0.0 } };
};

/// How a re-meshed triangle was re-meshed (the VTK filter's NewGeometry).
enum class RemeshKind : unsigned char
{
  Silhouette = 1, ///< along a silhouette segment only
  Feature = 2     ///< with one or more feature segments (Fig. 12)
};

struct SmoothingResult
{
  /// Added points; the i-th has id points().size() + i in the output.
  std::vector<NewPoint> NewPoints;
  /// Prepared triangles that were re-meshed, ascending: the silhouette
  /// triangles and the triangles with a side on a smoothed feature edge.
  std::vector<Id> RemeshedTriangles;
  /// Per entry of RemeshedTriangles: how it was re-meshed.
  std::vector<RemeshKind> RemeshKinds;
  /// How many of RemeshedTriangles the silhouette crosses.
  std::size_t SilhouetteTriangleCount = 0;
  /// Silhouette triangles left out as outside the view frustum
  /// (SmoothingParameters::CullOutsideFrustum).
  std::size_t CulledTriangles = 0;
  /// The triangles replacing RemeshedTriangles[i] are
  /// Replacements[ReplacementOffsets[i] .. ReplacementOffsets[i + 1]).
  std::vector<std::size_t> ReplacementOffsets{ 0 };
  std::vector<Triangle> Replacements;
  /// The smoothed silhouette, chained across triangles, as output point ids.
  std::vector<std::vector<Id>> Polylines;
  /// Silhouette segments found concave (III-E), and the input points that
  /// were lowered below their planes: (id, new position), ascending ids.
  std::size_t ConcaveSegmentCount = 0;
  std::vector<std::pair<Id, glm::dvec3>> MovedPoints;

  /// The fold guard's fallbacks (SmoothingParameters::PreventFolds):
  /// silhouette triangles re-meshed along the chord only, silhouette
  /// points put back on their straight edges, curved feature segments
  /// replaced by their chords (on every side of the crease), moved points
  /// left in place, and folding triangles left because no fallback was left
  /// to take (none by FoldGuard.h's invariant, but for rounding).
  std::size_t ChordFallbackTriangles = 0;
  std::size_t StraightSilhouettePoints = 0;
  std::size_t StraightFeatureSegments = 0;
  std::size_t PinnedPoints = 0;
  std::size_t UnresolvedFolds = 0;
  /// How many times the frame was re-meshed because of folds.
  std::size_t FoldGuardRounds = 0;
  /// The cap of MaximumSampledPoints when it lowered a segment's samples,
  /// else 0.
  int SampleBudgetMaximum = 0;

  std::size_t newTriangleCount() const { return this->Replacements.size(); }
};

/// Runs body(begin, end) over sub-ranges covering [0, count). The VTK adapter
/// passes vtkSMPTools; the default is a plain loop. Results never depend on
/// how the range is split.
using ParallelFor =
  std::function<void(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)>;
void serialFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body);

/// Silhouette points are kept at least this far (in edge parameter) from the
/// ends of their edge. A point closer to the triangle's lone vertex would make
/// the region between them a sliver, and any fan over the bulging curve there
/// stands on edge (one flipped triangle in 120 torus views before this rule).
/// The clamp is continuous, so it adds no jump of its own; on the exact-sphere
/// test it changes the mean outline error by less than 0.001 px. (The
/// silhouette can still jump when a vertex changes visibility in perspective:
/// eq. 7's quadratic may have its root far from the edge's end then. A known
/// limitation of the paper's approximation; parallel projection is linear.)
constexpr double EdgeParameterMargin = 0.01;

SmoothingResult smoothSilhouettes(const PreparedMesh& mesh, const ViewGeometry& view,
  const SmoothingParameters& parameters, const ParallelFor& parallelFor = serialFor);

/// The visibility value g of every point (parallel over points).
std::vector<double> vertexVisibility(
  const PreparedMesh& mesh, const ViewGeometry& view, const ParallelFor& parallelFor = serialFor);
/// The same decisions by either method; with Hierarchical, vertices of
/// decided clusters hold +1 or -1 instead of g (the sign is what counts).
std::vector<double> vertexVisibility(const PreparedMesh& mesh, const ViewGeometry& view,
  VisibilityMethod method, const ParallelFor& parallelFor = serialFor);

/// Convenience for tests and tools: all output triangles, in input order with
/// each re-meshed triangle replaced in place, and per triangle the input
/// triangle it came from and whether it is new geometry (0 for a kept
/// triangle, else the RemeshKind's value).
void assembleTriangles(const PreparedMesh& mesh, const SmoothingResult& result,
  std::vector<Triangle>& triangles, std::vector<Id>& sourceTriangle,
  std::vector<unsigned char>& isNew);

} // namespace silsmooth
