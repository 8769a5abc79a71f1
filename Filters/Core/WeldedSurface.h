// A mesh as asset files store it, prepared for smoothing on the surface it
// stands for, and each frame's result put back onto the mesh's own points.
//
// Preparation (once per input):
//   1. points at one position are one surface vertex (SurfaceWelding.h);
//   2. the triangles over surface vertices are oriented consistently per
//      component (SurfaceOrientation.h), and given normals that point
//      against the oriented surface at their point are reversed;
//   3. normal seams (points at one position with different normals) are
//      feature edges, besides the marked and detected ones (normals that are
//      only the triangles' own normals, flat shading, are not used at all);
//   4. the PreparedMesh is built on those triangles, with every corner's own
//      normal.
//
// Output (each frame), the invariants the VTK filters rely on:
//   - output points are the input's points with their ids, then copies of
//     input points (a point whose corners fall in more than one smooth group
//     of the prepared mesh: one copy per extra group), then the added points;
//   - every kept triangle has the input triangle's own point ids, wound as
//     most triangles of its connected part are written (a triangle written
//     against its part's winding is turned over: with one winding per part,
//     every triangle faces the side its points' normals face, which VTK's
//     lighting needs; an input wound consistently keeps its winding, an
//     inside-out part included); a re-meshed triangle's replacements use its
//     own points at its corners and wind as its part;
//   - an added point is made once per distinct set of input points it is
//     interpolated from in the triangles that use it: across an edge whose
//     two triangles share point ids it is one point (no crack), across a
//     texture seam it is one point per side, at the same position (the seam
//     stays a seam, each side with its own texture coordinates);
//   - with nothing to weld, orient or split, the output is point for point
//     and triangle for triangle the PreparedMesh's own (assembleTriangles).
#pragma once

#include "SilhouetteSmoother.h"

#include <array>
#include <cstddef>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace silsmooth
{

struct SurfaceOptions
{
  /// Join points at one position (step 1). Off: point ids alone say which
  /// triangles meet, as before.
  bool Weld = true;
  /// 0: equal coordinates only; d > 0: points within d (transitively).
  double WeldTolerance = 0.0;
  /// Orient consistently (step 2).
  bool Orient = true;
  /// Normal seams are feature edges (step 3).
  bool NormalSeams = true;
  /// Dihedral-angle feature detection on the welded, oriented triangles.
  bool DetectFeatures = false;
  double FeatureAngleDegrees = 30.0;
  /// Creases between flat faces (flatSidedCreases), on the same triangles.
  bool DetectFlatCreases = true;
  double FlatCreaseAngleDegrees = 65.0;
  /// How the normals the input does not give are estimated (the VTK
  /// filter's default, vtkSilhouetteSmoothingFilter::NormalEstimation).
  NormalWeighting Normals = NormalWeighting::Area;
};

/// What preparation found, for the filters' field data and warnings.
struct SurfaceStatistics
{
  std::size_t WeldedPointCount = 0; ///< points joined to a lower point
  std::size_t ReversedTriangleCount = 0;
  std::size_t ComponentCount = 0;
  std::size_t InconsistentEdgeCount = 0; ///< non-orientable edges left
  /// Triangles with a back-to-back twin on the same surface vertices (a
  /// double-sided sheet whose sides share their points: welding could not
  /// keep the sides apart, and their normals cancel).
  std::size_t BackToBackTriangleCount = 0;
  std::size_t NormalSeamEdgeCount = 0;
  std::size_t FlatCreaseEdgeCount = 0;
  /// The given normals were face normals (flat shading: they split along at
  /// least half of the edges, and every corner of all but 1% of the
  /// triangles carries its triangle's normal): they say nothing about the
  /// smooth surface or its creases, so they were not used.
  bool FlatShadedNormals = false;
  /// Edges between distinct welded points at most 1e-5 of the mesh's size
  /// long (nearCopyEdges, SurfaceWelding.h), and the longest of them.
  std::size_t NearCopyEdgeCount = 0;
  double LongestNearCopyEdge = 0.0;
  /// Edges between copies of a point that differ by rounding (at most
  /// RoundingCopyRelative of the mesh's size apart): with an exact weld
  /// asked for, their points were welded with a tolerance just above the
  /// longest (as a parametric grid's seam computed twice needs).
  std::size_t RoundingCopyEdgeCount = 0;
};

/// Copies of a point joined by an edge at most this fraction of the mesh's
/// size apart differ by rounding, not by design: vtkParametricTorus's seam
/// points lie 3e-15 of it apart, while the nearest distinct sheets in real
/// assets lie about 1e-6 apart (the Wuson's).
constexpr double RoundingCopyRelative = 1e-9;

/// One frame's output, in output point ids (see the header comment).
struct SurfaceFrame
{
  /// Added point i (output id outputPointCount() + i) is result.NewPoints[
  /// Added[i].NewPoint], interpolated from the input points Added[i].Sources
  /// with that point's weights.
  struct AddedPoint
  {
    std::size_t NewPoint = 0;
    std::array<Id, 3> Sources{ { 0, 0, 0 } };
  };
  std::vector<AddedPoint> Added;
  /// All output triangles in input order, re-meshed ones replaced in place;
  /// per triangle the input triangle it came from and 0 (kept) or its
  /// RemeshKind. Filled by the one-argument assemble() only; the other
  /// writes them into the caller's buffers.
  std::vector<Triangle> Triangles;
  std::vector<Id> SourceTriangle;
  std::vector<unsigned char> Kind;
  /// The silhouette polylines, in output ids.
  std::vector<std::vector<Id>> Polylines;
  /// Output points (input points and copies) moved by the perturbation.
  std::vector<std::pair<Id, glm::dvec3>> Moved;
  /// assembleChanges() only: the input triangles whose place in the output
  /// changes, ascending (the re-meshed ones, and the kept ones with a corner
  /// the perturbation moved).
  std::vector<Id> ReplacedTriangles;
};

class WeldedSurface
{
public:
  /// `normals` one per point or empty; `markedFeatures` pairs of point ids
  /// (line cells along triangle edges). Points must be finite.
  /// `parallelFor` runs the feature tests' loops (the same surface whatever
  /// its split).
  WeldedSurface(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
    const std::vector<glm::dvec3>& normals, const std::vector<FeatureEdge>& markedFeatures,
    const SurfaceOptions& options, const ParallelFor& parallelFor = serialFor);

  /// The same surface with its points moved, for a deforming mesh (a time
  /// series: new points, the same cells): the welding, the orientation and
  /// the edge table are kept; the normals, the normal seams, the features
  /// found by angle and the prepared mesh are made again. Returns false,
  /// and leaves the surface as it was, when the move changes what the kept
  /// parts assume: a point welded to another no longer at its position, a
  /// weld tolerance (welds by distance are not checked), another point
  /// count, or features that come out different (the points split per
  /// smooth group, and so the output's points, would change); the caller
  /// then builds the surface anew. Invariant: after a true return the
  /// surface is the one the constructor makes from the same arguments, as
  /// long as the orientation it chose still holds and no points that were
  /// apart have come together (neither is checked: the constructor would
  /// weld such points, a moved surface keeps them apart), but for the cone
  /// apexes, which stay those found first (PreparedMesh::moved).
  bool movePoints(std::vector<glm::dvec3> points, const std::vector<glm::dvec3>& normals,
    const std::vector<FeatureEdge>& markedFeatures, const SurfaceOptions& options,
    const ParallelFor& parallelFor = serialFor);

  const PreparedMesh& prepared() const { return *this->Prepared; }
  const SurfaceStatistics& statistics() const { return this->Statistics; }
  std::size_t inputPointCount() const { return this->InputPointCount; }
  /// Input points plus copies: the output ids before the added points.
  std::size_t outputPointCount() const { return this->OutputPrepared.size(); }
  /// The input point that output point o (< outputPointCount()) is or copies.
  Id outputSource(Id o) const
  {
    return static_cast<std::size_t>(o) < this->InputPointCount
      ? o
      : this->CopySources[static_cast<std::size_t>(o) - this->InputPointCount];
  }
  /// The prepared point whose shading normal output point o takes.
  Id outputPrepared(Id o) const { return this->OutputPrepared[static_cast<std::size_t>(o)]; }
  /// Whether output point o's normal is the prepared surface's reversed:
  /// most triangles using it were reversed by the orientation, and keep the
  /// input's own winding in the output. Normals that agree with the written
  /// winding are lit from either side (VTK flips a normal on a back face);
  /// the oriented normals on an inside-out mesh's own winding rendered it
  /// black. An added point follows its first source input point.
  /// Whether the output writes input triangle t turned over from its input
  /// winding (its part is written the other way round: see the header).
  bool writtenTurnedOver(Id t) const
  {
    const std::size_t i = static_cast<std::size_t>(t);
    return i < this->Written.size() && this->Written[i] != this->Reversed[i];
  }

  bool outputNormalReversed(Id o) const
  {
    return !this->OutputNormalReversed.empty() &&
      this->OutputNormalReversed[static_cast<std::size_t>(o)] != 0;
  }
  /// The input triangles as given (own ids, own winding).
  const std::vector<Triangle>& inputTriangles() const { return this->InputTriangles; }

  /// How many triangles assemble() writes for `result`.
  std::size_t outputTriangleCount(const SmoothingResult& result) const;
  /// The frame, with its triangles written straight into the caller's
  /// buffers (room for outputTriangleCount(result) triangles: 3 ids each in
  /// `triangles`, one entry each in `sourceTriangle` and `kind`), as the VTK
  /// adapter's cell arrays want them; no copy of the whole mesh is made.
  /// IdType is Id or long long (vtkIdType), instantiated for both.
  template<typename IdType>
  SurfaceFrame assemble(const SmoothingResult& result, IdType* triangles, IdType* sourceTriangle,
    unsigned char* kind) const;
  /// The same, into the frame's own vectors (for tests and tools).
  SurfaceFrame assemble(const SmoothingResult& result) const;
  /// Only what the frame changes, for a renderer that keeps drawing the
  /// base mesh (assemble() of an empty result: the kept triangles as they
  /// are): ReplacedTriangles, and in Triangles, SourceTriangle and Kind what
  /// takes their place, in their order (a kept triangle with a moved corner
  /// as itself, kind 0). Added, Polylines and Moved are assemble()'s, with
  /// the same ids. Invariant: replacing each ReplacedTriangles[i] of the
  /// base mesh by the Triangles whose SourceTriangle is ReplacedTriangles[i]
  /// gives assemble()'s triangles, in assemble()'s order. The cost is in
  /// the re-meshed triangles, not the mesh.
  SurfaceFrame assembleChanges(const SmoothingResult& result) const;

private:
  // What the given normals are: usable, flat shading (face normals, not
  // used), and their seams.
  struct GivenNormals
  {
    bool Use = false;
    bool FlatShaded = false;
    std::vector<FeatureEdge> Seams;
  };
  GivenNormals examineNormals(const std::vector<glm::dvec3>& points,
    const std::vector<glm::dvec3>& normals, const std::vector<Triangle>* welded,
    const EdgeTable* table) const;
  // The topology movePoints keeps: welds the points, builds the edge table,
  // orients the triangles (Vertex, Welded, Table, Reversed, Components).
  GivenNormals weldAndOrient(const std::vector<glm::dvec3>& points,
    const std::vector<glm::dvec3>& normals, const SurfaceOptions& options);
  // Output points: an input point per prepared point of its first corner,
  // and a copy per (prepared point, input point) pair beyond it
  // (OutputPrepared, CornerOutput, CopySources).
  void mapOutputPoints();
  // The output points of each prepared point, and the one that stands for
  // it (OutputsOffsets, OutputsOf, PreparedHome).
  void chooseWrittenWinding();
  void indexOutputsByPrepared();
  // Everything that depends on the points' positions and the normals, on
  // the kept welding, orientation and edge table. With `reusable` (the
  // prepared mesh of earlier positions), its topology is taken when the
  // features split the mesh as before (PreparedMesh::moved; `*reused` says
  // whether it was, and reusable is then empty; the dihedral angles are
  // then computed in MovedFaceNormals and MovedCosines).
  std::unique_ptr<PreparedMesh> prepareGeometry(std::vector<glm::dvec3> points,
    const std::vector<glm::dvec3>& normals, const GivenNormals& given,
    const std::vector<FeatureEdge>& markedFeatures, const SurfaceOptions& options,
    SurfaceStatistics& statistics, const ParallelFor& parallelFor, PreparedMesh* reusable = nullptr,
    bool* reused = nullptr);
  Id outputOfPreparedCorner(std::size_t t, Id prepared) const;
  /// assemble() over the prepared triangles `only` (ascending), or over all
  /// of them when `only` is null.
  template<typename IdType>
  SurfaceFrame assembleSome(const SmoothingResult& result, const std::vector<Id>* only,
    IdType* triangles, IdType* sourceTriangle, unsigned char* kind) const;
  /// assembleSome's last steps: the silhouette polylines in output ids
  /// (`firstCopy`: each new point's first output copy, or -1; a point on no
  /// output triangle is added) and the perturbation's moved output points.
  void addPolylinesAndMoves(
    const SmoothingResult& result, std::vector<Id>& firstCopy, SurfaceFrame& frame) const;
  /// assembleSome into the frame's own vectors (`count` triangles).
  SurfaceFrame assembleInto(
    const SmoothingResult& result, const std::vector<Id>* only, std::size_t count) const;

  std::size_t InputPointCount = 0;
  std::vector<Triangle> InputTriangles;
  std::vector<unsigned char> Reversed;
  /// The topology kept by movePoints: each point's surface vertex, the
  /// welded and oriented triangles, their edge table, and each triangle's
  /// component (or empty).
  std::vector<Id> Vertex;
  std::vector<Triangle> Welded;
  EdgeTable Table;
  EdgeSides Sides; // of Table, for the dihedral angles of every move
  /// The dihedral angles' buffers, kept from one move to the next (a
  /// deforming mesh's frame would otherwise take 47 MB of fresh memory at
  /// 1.3M triangles, whose page faults cost about 10 ms); empty until the
  /// first move.
  std::vector<glm::dvec3> MovedFaceNormals;
  std::vector<double> MovedCosines;
  /// The same for the given normals' agreement with the area normals.
  std::vector<double> MovedAgreementTerms;
  std::vector<Id> Components;
  /// Per triangle: whether the output writes it reversed from the oriented
  /// surface (its part's majority winding; chooseWrittenWinding).
  std::vector<unsigned char> Written;
  std::unique_ptr<PreparedMesh> Prepared;
  SurfaceStatistics Statistics;
  std::vector<Id> CopySources;
  std::vector<Id> OutputPrepared;
  /// Output id of input corner 3t + k.
  std::vector<Id> CornerOutput;
  // Per output point (input points and copies): outputNormalReversed; empty
  // when no triangle was reversed.
  std::vector<unsigned char> OutputNormalReversed;
  /// One output id per prepared point (for polylines), and all of them (for
  /// the perturbation): OutputsOf[OutputsOffsets[p] .. OutputsOffsets[p + 1]).
  std::vector<Id> PreparedHome;
  std::vector<Id> OutputsOffsets;
  std::vector<Id> OutputsOf;
  /// The prepared triangles around each prepared point (for the kept
  /// triangles a moved point changes): TrianglesOf[TrianglesOffsets[p] ..
  /// TrianglesOffsets[p + 1]), built on the first assembleChanges().
  mutable std::once_flag TrianglesOfBuilt;
  mutable std::vector<Id> TrianglesOffsets;
  mutable std::vector<Id> TrianglesOf;
};

} // namespace silsmooth
