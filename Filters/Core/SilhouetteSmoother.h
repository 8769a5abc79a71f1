// The per-frame silhouette smoothing pass of Wang et al. 2008 over a mesh whose
// view-independent data (edge table, shading normals) is prepared once
// (PreparedMesh.h).
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
#include "ParallelFor.h"
#include "PreparedMesh.h"
#include "SurfaceWelding.h"
#include "ViewGeometry.h"

#include <glm/vec3.hpp>

#include <array>
#include <utility>
#include <vector>

namespace silsmooth
{

/// How the pass finds the vertices facing the viewer (paper III-B). Both make
/// bitwise the same decisions, so the output does not depend on the choice.
enum class VisibilityMethod
{
  /// g = N . (E - V) at every vertex: one dot product each.
  PerVertex,
  /// Clusters of vertices decided by one cone test (VisibilityHierarchy.h).
  Hierarchical
};

/// The fold guard's fallbacks in force at the end of a frame
/// (SmoothingResult::Fallbacks), for the next frame of the same viewer
/// (SmoothingParameters::FallbacksBefore). Lists ascending by id.
struct FoldFallbacks
{
  /// Silhouette triangles and their levels: 1 re-meshed along the chord, 2
  /// with their silhouette points on their straight edges too.
  std::vector<std::pair<Id, unsigned char>> Triangles;
  /// Feature segments drawn by their chords.
  std::vector<Id> FeatureSegments;
};

struct SmoothingParameters
{
  SamplingParameters Sampling;
  /// Lower the vertices around concave silhouette segments so that the
  /// smoothed curve is not blocked (see VertexPerturbation.h).
  bool PerturbConcaveSilhouettes = true;
  VisibilityMethod Visibility = VisibilityMethod::PerVertex;
  /// Find the silhouette triangles through the prepared mesh's triangle
  /// hierarchy (SilhouetteTriangleHierarchy.h) instead of scanning every
  /// triangle, once the mesh has been searched before for a view of the
  /// same projection (the second search builds the tree: a mesh smoothed for
  /// one view, or with new points every frame, never pays for it). The
  /// triangles found, and so the output, are the same either way
  /// (core.SilhouetteTriangleHierarchy compares them); Visibility then
  /// matters only for the scans.
  bool SilhouetteTriangleHierarchy = true;
  /// Build that tree, and the fold guard's grid of triangle boxes, on threads
  /// of their own, scanning until each is done, so that no frame waits for
  /// them (PreparedMesh::IndexBuild; a deforming mesh's grid is built in the
  /// frame, for the next frames to adopt). False builds them in the second
  /// frame, which then uses them (for tests of their answers).
  bool IndexesInBackground = true;
  /// Re-mesh folding triangles again, more conservatively, until none folds
  /// (FoldGuard.h): a silhouette triangle whose new triangles turn over or
  /// cut through another output triangle is re-meshed along the chord
  /// between its silhouette points (no interior samples), then with its
  /// silhouette points on its straight edges (shared with the neighbours
  /// across them, which are re-meshed again too), then with its curved
  /// feature segments straight; a moved point whose triangles fold stays in
  /// place. Each step is counted in the result.
  bool PreventFolds = true;
  /// Silhouette triangles at a cone's apex (PreparedMesh::apexes) keep the
  /// silhouette on their straight edges and chords: the apex's one normal
  /// would round the cone into a dome. Off: smoothed like any other.
  bool KeepApexesPointed = true;
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
  /// The most points a frame's sampling may add, 0 for no bound. When the
  /// samples the frame's segments want (one silhouette segment per re-meshed
  /// silhouette triangle, one feature segment per curved feature edge, each
  /// counted once) would add more interior points than that, each segment's
  /// samples are capped at the largest count that keeps them within it (the
  /// cap wins over MinimumSamples): a segment that wants fewer is sampled as
  /// without it, and leaves its share to the others. Until 2026-12-06 the
  /// cap was an even share, 2 + budget / segments, so a few close segments
  /// among thousands of far ones lowered every segment (a user's close-up of
  /// a finely divided part). The cap depends only on the frame's counts, so
  /// the output stays the same for any thread count.
  std::size_t MaximumSampledPoints = 0;
  /// Leave out the silhouette triangles the view cannot show: those whose
  /// three corners lie beyond one plane of the view frustum (ModelToClip's
  /// six) by more than the triangle's longest side. A triangle's smoothed
  /// curves stay within half its longest side of it (the end tangents are
  /// at most twice the chord, eq. 4), so nothing the view shows changes,
  /// and a crack where a culled triangle meets a re-meshed one lies beyond
  /// that plane too. With SkipSubpixelSmoothing, a curved feature segment
  /// whose sides are all such is drawn by its chord (in
  /// SmoothingResult::SubpixelFeatureIds). For renderers
  /// (vtkSilhouetteSmoothingMapper); a mesh written to a file wants every
  /// silhouette smoothed.
  bool CullOutsideFrustum = false;
  /// Leave as they are the silhouette triangles whose smoothing would move
  /// no point of the image by more than Sampling.TolerancePixels (a part of
  /// it after being smoothed: SubpixelBefore), when their whole strip of the silhouette (the
  /// silhouette triangles joined to them through mixed edges) is such: a strip with one triangle
  /// beyond it is smoothed whole (SilhouettePass::skipSubpixelSmoothing). The bound: the re-meshing
  /// moves a point of the triangle no farther than its silhouette points move off their edges plus
  /// the silhouette segment's parametricDeviationBound (HermiteCurve.h), and ViewGeometry's
  /// pixelShiftBound turns that into pixels. Their silhouette points sit on
  /// the straight edges, and their silhouette is the chord between them. On a mesh fine for its
  /// view (a 1.3M-triangle sphere at 1024x768 moves by thousandths of a pixel) the whole silhouette
  /// is such, and the pass costs little more than finding it. For renderers
  /// (vtkSilhouetteSmoothingMapper): a mesh written to a file has no pixels.
  /// Likewise a curved feature segment whose curve moves no point of its
  /// sides' triangles by more than the tolerance (its parametricDeviationBound) is drawn by its
  /// chord, and its sides are not re-meshed for it (a CAD part's finely divided rims: a
  /// 21,600-triangle part re-meshed 21,588 feature triangles every frame for nothing the image
  /// shows). On a piece of a partitioned mesh, a strip with a side that may be a seam
  /// (BoundaryMayBeSeam) or that runs on into frozen triangles, and a segment with such a
  /// side, are always smoothed: the piece across decides its part alike.
  bool SkipSubpixelSmoothing = false;
  /// The frame before, when the caller keeps it (the mapper): the triangles
  /// SkipSubpixelSmoothing left whole (SmoothingResult::SubpixelTriangleIds)
  /// and the triangles re-meshed (SmoothingResult::RemeshedTriangles), both
  /// ascending. A strip with a triangle re-meshed before, and none left whole,
  /// is left whole only within SubpixelEntryFraction of the tolerance; any
  /// other within the tolerance. A strip whose largest move lies near the
  /// tolerance then does not switch between smoothed and whole from frame to
  /// frame. Without them every frame is a first one.
  const std::vector<Id>* SubpixelBefore = nullptr;
  const std::vector<Id>* RemeshedBefore = nullptr;
  /// The same for curved feature segments: those drawn by their chords in
  /// the frame before (SmoothingResult::SubpixelFeatureIds), ascending. A
  /// segment not among them is drawn by its chord only within
  /// SubpixelEntryFraction of the tolerance. Null: every frame a first one.
  const std::vector<Id>* SubpixelFeaturesBefore = nullptr;
  /// The fold guard's fallbacks of the frame before (its
  /// SmoothingResult::Fallbacks), when the caller keeps them (the mapper).
  /// The frame starts with none, as any frame does. A silhouette triangle
  /// found folding goes at once to the level it had there, when that is
  /// above the next level, and the feature segments beside it that were
  /// drawn by their chords there are drawn so at once. A coarse mesh's folds
  /// stay put from one frame of an orbit to the next; without this each
  /// frame climbs to them again, one level a round (assimp's spider took 2 to
  /// 4 rounds a frame). Only a triangle found folding in this frame takes
  /// one (it may take a higher level than this frame alone would give it): a
  /// triangle whose curve no longer folds is drawn curved, and a frame in
  /// which nothing folds is the frame without them. Null: every triangle
  /// climbs from the first level.
  const FoldFallbacks* FallbacksBefore = nullptr;
  /// Chain the silhouette into SmoothingResult::Polylines. Off when only the
  /// surface is wanted (the mapper): the triangles SkipSubpixelSmoothing
  /// leaves out then cost nothing past their test (their silhouette points,
  /// wanted only by the polylines, are not made).
  bool SilhouettePolylines = true;
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
  /// Silhouette triangles left as they are, their smoothing below a pixel
  /// tolerance (SmoothingParameters::SkipSubpixelSmoothing); not in
  /// SilhouetteTriangleCount.
  std::size_t SubpixelTriangles = 0;
  /// Those triangles, ascending (for SmoothingParameters::SubpixelBefore).
  std::vector<Id> SubpixelTriangleIds;
  /// Curved feature segments (PreparedMesh::features) drawn by their
  /// chords, their curves within the tolerance in the image
  /// (SmoothingParameters::SkipSubpixelSmoothing), ascending.
  std::vector<Id> SubpixelFeatureIds;
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
  /// Of the chord fallbacks, the silhouette triangles re-meshed straight
  /// without a test, because too many triangles crowd around them (a fan of
  /// thousands around one point, FoldGuard.h).
  std::size_t CrowdedTriangles = 0;
  std::size_t UnresolvedFolds = 0;
  /// How many times the frame was re-meshed because of folds.
  std::size_t FoldGuardRounds = 0;
  /// The fallbacks in force at the end of the frame but those at apexes
  /// (for SmoothingParameters::FallbacksBefore). Empty without PreventFolds.
  FoldFallbacks Fallbacks;
  /// Fallbacks taken from FallbacksBefore: triangles raised to their level
  /// there past the next one, and feature segments drawn straight with them.
  std::size_t ReusedFallbacks = 0;
  /// Silhouette triangles at a cone's apex (PreparedMesh::apexes), re-meshed
  /// with the silhouette on their edges and chords; not counted above.
  std::size_t ApexTriangles = 0;
  /// The cap of MaximumSampledPoints when it lowered a segment's samples,
  /// else 0.
  int SampleBudgetMaximum = 0;

  std::size_t newTriangleCount() const { return this->Replacements.size(); }
};

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

/// SmoothingParameters::SubpixelBefore: the part of the tolerance a strip of
/// the silhouette smoothed in the frame before must keep within to be left
/// whole. A quarter of margin: an orbit's bounds change by a few percent a
/// frame.
constexpr double SubpixelEntryFraction = 0.75;

SmoothingResult smoothSilhouettes(const PreparedMesh& mesh, const ViewGeometry& view,
  const SmoothingParameters& parameters, const ParallelFor& parallelFor = serialFor);

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
