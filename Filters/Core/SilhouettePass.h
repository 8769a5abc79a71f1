// One view's pass of the method (SilhouetteSmoother.h's smoothSilhouettes):
// the silhouette triangles and their silhouette points, the samples along the
// Hermite bridges and the feature curves, the local re-meshing, the vertex
// perturbation and the fold guard's rounds. Internal to the core: the class
// is split over three files by step,
//   SilhouettePass.cpp           the frame: run, re-meshing rounds, fallbacks,
//                                the output kept facing out;
//   SilhouettePassSampling.cpp   which triangles the silhouette crosses, where
//                                on their edges, and how many samples each
//                                bridge and feature segment gets;
//   SilhouettePassRemeshing.cpp  the samples of a bridge, the polygons and
//                                fans that replace a silhouette triangle.
// Small helpers stay inline here: the passes call them per triangle.
#pragma once

#include "FoldGuard.h"
#include "HermiteCurve.h"
#include "SilhouetteSmoother.h"
#include "VertexPerturbation.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <unordered_map>
#include <utility>
#include <vector>

namespace silsmooth
{
namespace detail
{
inline bool isVisible(double g)
{
  return g >= 0.0;
}

// A silhouette point as the triangles of its edge see it.
struct EdgeSilhouettePoint
{
  Id Edge = -1;
  Id Point = -1;         // output point id
  double HighWeight = 0; // parameter from the edge's low end to its high end
};

// A point of a polygon being fanned in a re-meshed triangle: its output id and
// where it sits in the triangle's parameter domain (barycentric in the
// re-meshed corner order). Corners and silhouette points may be fan apexes.
struct PolygonPoint
{
  Id Point = -1;
  glm::dvec3 Bary{ 0.0 };
  bool Apex = false;
};

class SilhouettePass
{
public:
  SilhouettePass(const PreparedMesh& mesh, const ViewGeometry& view,
    const SmoothingParameters& parameters, const ParallelFor& parallelFor)
    : Mesh(mesh)
    , View(view)
    , Parameters(parameters)
    , Sampling(parameters.Sampling)
    , For(parallelFor)
  {
  }

  SmoothingResult run();

private:
  // Fallback levels of a silhouette triangle (FoldGuard.h).
  static constexpr unsigned char ChordLevel = 1;    // no interior samples
  static constexpr unsigned char StraightLevel = 2; // and points on its edges

  void straightenAtApexes();
  // SmoothingParameters::FallbacksBefore: triangle t's level there (0 when
  // none), and whether feature segment f was drawn straight there.
  unsigned char rememberedLevel(Id t) const;
  bool rememberedStraight(Id f) const;
  // Draws by their chords the curved feature segments on t's sides that
  // may be straightened (not on a seam) and that `straighten` accepts;
  // adds every side of each to `changed`. True when it took any.
  template<typename Accept>
  bool straightenSideFeatures(Id t, std::vector<Id>& changed, Accept straighten);
  // SmoothingResult::Fallbacks, at the end of the frame.
  void listFallbacks();
  // Whether input triangle t has a corner at a cone's apex (PreparedMesh::apexes).
  bool hasApexCorner(Id t) const;
  // Adds to `edges` the sides of silhouette triangle t whose silhouette
  // points its straight level puts on the straight edge: mixed sides that
  // are neither feature edges nor possible seams.
  void straightSidesOf(Id t, std::vector<Id>& edges) const;
  // The end of mixed edge e at which its silhouette point sits, when e
  // runs from an apex (apexSides: such edges' silhouette triangles,
  // sorted); -1 for any other edge.
  Id apexEdgeCrossing(Id e, const std::vector<std::pair<Id, Id>>& apexSides) const;
  // SmoothingParameters::SkipSubpixelSmoothing: fills Subpixel, and puts
  // their silhouette points on the straight edges.
  void skipSubpixelSmoothing();
  // A mixed edge's silhouette point on its curved bridge, as
  // computeSilhouettePoints makes it, and how far that is from its place on
  // the straight edge.
  struct CurvedCrossing
  {
    Id Edge;
    glm::dvec3 Position;
    glm::dvec3 Normal;
    double Moved;
  };
  void curvedCrossing(CurvedCrossing& crossing) const;
  // SmoothingParameters::SkipSubpixelSmoothing for feature segments: fills
  // SubpixelFeatures and CurvedFeatureTriangles.
  void skipSubpixelFeatures();
  // A silhouette triangle's sides (sideEdge order), and which are mixed.
  struct TriangleSides
  {
    std::array<Id, 3> Edges;
    std::array<bool, 3> Mixed;
  };
  // How far, in pixels, re-meshing silhouette triangle t would move a point
  // of it at most, from the crossings of its mixed edges (by edge);
  // infinite for one that is not a candidate (a feature or seam side, an
  // apex, a repeated corner).
  double smoothingShiftPixels(
    Id t, const TriangleSides& sides, const std::vector<CurvedCrossing>& crossings) const;
  bool isSubpixel(Id t) const
  {
    return std::binary_search(this->Subpixel.begin(), this->Subpixel.end(), t);
  }
  // The silhouette point's parameter on mixed edge `edge`, from end a to
  // end b: a is the end with the smaller position (x, then y, then z; the
  // id only for coincident ends), not the smaller id, so that the point
  // comes out bit for bit the same in every piece of a partitioned mesh
  // (the ids differ between pieces), and pieces meet without a crack.
  double crossingParameter(const Edge& edge, std::size_t& a, std::size_t& b) const;
  // The shading normal at parameter t from point a to point b of an edge:
  // the ends' normals interpolated, or the nearer end's where they cancel.
  glm::dvec3 edgeNormal(std::size_t a, std::size_t b, double t) const;
  void remeshFrame();

  FoldFindings findFrameFolds(
    const std::vector<Id>* checkSources, const std::vector<Id>* checkPoints);

  // Raises the fallback level of every folding silhouette triangle and pins
  // every folding moved point; false when none could be taken. `changed`
  // gets the input triangles that the next round must check again
  // (ascending): the folding ones, and those it re-meshes differently.
  bool takeFallbacks(const FoldFindings& findings, std::vector<Id>& changed);

  // Whether point v faces the viewer: from G when the frame computed it,
  // directly otherwise (the triangle hierarchy's frames compute no G; both
  // give the same sign, VisibilityCones.h).
  bool visibleAt(Id v) const
  {
    const std::size_t i = static_cast<std::size_t>(v);
    return this->G.empty()
      ? isVisible(this->View.visibility(this->Mesh.points()[i], this->Mesh.normals()[i]))
      : isVisible(this->G[i]);
  }

  // An edge whose ends differ in visibility: it holds a silhouette point.
  bool isMixed(const Edge& edge) const
  {
    return this->visibleAt(edge.low) != this->visibleAt(edge.high);
  }

  bool mayBeSeam(Id e) const
  {
    return this->Parameters.BoundaryMayBeSeam && this->Mesh.isBoundaryEdge(e);
  }

  // Drawn by its chord in this frame: by the fold guard's fallback, or as
  // a SubpixelFeatures segment.
  bool isStraightened(Id feature) const
  {
    return std::binary_search(
             this->StraightFeatures.begin(), this->StraightFeatures.end(), feature) ||
      this->isSubpixelFeature(feature);
  }
  bool isSubpixelFeature(Id feature) const
  {
    return !this->SubpixelFeatures.empty() &&
      std::binary_search(this->SubpixelFeatures.begin(), this->SubpixelFeatures.end(), feature);
  }

  // The point at parameter `along` of a feature segment: on its curve, or on
  // its chord once the fold guard straightened it (every side of the crease
  // computes the same point either way).
  glm::dvec3 featurePoint(Id feature, double along) const
  {
    const FeatureCurves& features = this->Mesh.features();
    if (!this->isStraightened(feature))
    {
      return features.curve(feature).evaluate(along);
    }
    const auto& ends = features.edges()[static_cast<std::size_t>(feature)];
    const auto& points = this->Mesh.points();
    return (1.0 - along) * points[static_cast<std::size_t>(ends.first)] +
      along * points[static_cast<std::size_t>(ends.second)];
  }

  unsigned char levelOf(Id t) const
  {
    if (this->Levels.empty())
    {
      return 0;
    }
    const auto it = this->Levels.find(t);
    return it == this->Levels.end() ? 0 : it->second;
  }

  void findSilhouetteTriangles();
  void scanForSilhouetteTriangles();

  // SmoothingParameters::FrozenTriangles.
  bool isFrozen(Id t) const
  {
    const std::vector<unsigned char>* frozen = this->Parameters.FrozenTriangles;
    return frozen && static_cast<std::size_t>(t) < frozen->size() &&
      (*frozen)[static_cast<std::size_t>(t)] != 0;
  }

  // SmoothingParameters::CullOutsideFrustum: planes in model coordinates
  // from the rows of ModelToClip (w + x >= 0, w - x >= 0, and so for y and
  // z), scaled so that they give distances in model units.
  void cullOutsideFrustum();
  // Whether triangle t lies beyond one of the frustum's planes by more than
  // its longest side (its smoothed curves stay within half of it).
  // (The planes: makeFrustumPlanes, at the start of a pass that culls.)
  bool beyondFrustum(Id t) const;
  void makeFrustumPlanes();
  std::array<glm::dvec4, 6> FrustumPlanes;

  // One silhouette point per mixed edge, in ascending edge order, so both
  // triangles of an edge use the same point (the crack-free rule). On a feature edge
  // the silhouette bridge is the edge's feature segment (III-D, case (a)).
  void computeSilhouettePoints();

  // The triangles re-meshed for their feature sides in this frame: those
  // with a smoothed (curved) feature side, every frame, unless each such
  // side is a SubpixelFeatures segment, and those with a side
  // on a straight feature edge that the silhouette crosses, from any side of
  // the crease: each side has its own normals, so the silhouette may cross
  // the crease on one side only, and the others must still split the edge at
  // that point (or the output has a T-junction there).
  const std::vector<Id>& featureTrianglesOfFrame();

  bool crossedBySilhouette(Id feature) const
  {
    return std::binary_search(this->FeatureSilhouettePoints.begin(),
      this->FeatureSilhouettePoints.end(), FeatureSilhouettePoint{ feature, -1, 0.0 },
      [](const FeatureSilhouettePoint& x, const FeatureSilhouettePoint& y) {
        return x.Feature < y.Feature;
      });
  }

  // SmoothingParameters::MaximumSampledPoints: the most samples a segment
  // may have in this frame (SampleCap), 0 for no cap; the largest cap that
  // keeps the samples the frame's segments want within the budget.
  void applySampleBudget();

  // silhouetteSampleCount, within the frame's cap; notes when the cap bites.
  int sampleCount(const HermiteCurve& segment, const glm::dvec3& n0, const glm::dvec3& n1)
  {
    const int wanted = silhouetteSampleCount(segment, n0, n1, this->View, this->Sampling);
    if (this->SampleCap > 0 && wanted > this->SampleCap)
    {
      this->SampleCapBit.store(true, std::memory_order_relaxed);
      return this->SampleCap;
    }
    return wanted;
  }

  // Points per smoothed feature segment in this view (both ends counted), by
  // the same rule as silhouette segments. Both sides of a crease use the
  // segment's one count, so their samples coincide. Straight ones keep 2.
  void countFeatureSamples();

  const EdgeSilhouettePoint& silhouettePointOf(Id edge) const
  {
    const auto it = std::lower_bound(this->EdgePoints.begin(), this->EdgePoints.end(), edge,
      [](const EdgeSilhouettePoint& p, Id e) { return p.Edge < e; });
    return *it; // present: every mixed side of a silhouette triangle was added
  }

  glm::dvec3 positionOf(Id point) const
  {
    const Id pointCount = static_cast<Id>(this->Mesh.points().size());
    return point < pointCount
      ? this->Mesh.points()[static_cast<std::size_t>(point)]
      : this->Result.NewPoints[static_cast<std::size_t>(point - pointCount)].Position;
  }

  glm::dvec3 normalOf(Id point) const
  {
    const Id pointCount = static_cast<Id>(this->Mesh.points().size());
    return point < pointCount
      ? this->Mesh.normals()[static_cast<std::size_t>(point)]
      : this->Result.NewPoints[static_cast<std::size_t>(point - pointCount)].Normal;
  }

  Id nextPointId() const
  {
    return static_cast<Id>(this->Mesh.points().size() + this->Result.NewPoints.size());
  }

  // The corner that differs in visibility from the other two.
  int loneCorner(const Triangle& tri) const
  {
    const bool v0 = this->visibleAt(tri[0]);
    const bool v1 = this->visibleAt(tri[1]);
    return (v0 == v1) ? 2 : (this->visibleAt(tri[2]) == v0 ? 1 : 0);
  }

  // Samples the silhouette segment from P to Q across the triangle with
  // corners (a, b, c), a the lone one, adding its interior samples as new
  // points; records it if concave. P and Q are given with their barycentric
  // positions in (a, b, c); the samples lie on the chord between them there.
  std::vector<PolygonPoint> sampleSilhouetteSegment(
    Id t, const std::array<Id, 3>& corners, const PolygonPoint& p, const PolygonPoint& q);

  // P on side a-b and Q on side a-c of a silhouette triangle, a = corners[0].
  std::pair<PolygonPoint, PolygonPoint> silhouettePointsOf(
    Id t, int lone, const std::array<Id, 3>& corners) const;
  // Silhouette triangle t's corners with the lone one first (`lone` gets
  // its index in the triangle), as silhouettePointsOf takes them.
  std::array<Id, 3> cornersFromLone(Id t, int& lone) const
  {
    const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(t)];
    lone = this->loneCorner(tri);
    return { { tri[lone], tri[(lone + 1) % 3], tri[(lone + 2) % 3] } };
  }
  // The silhouette segment from point p to point q (eq. 5 with their
  // normals, which nP and nQ get).
  HermiteCurve silhouetteSegment(Id p, Id q, glm::dvec3& nP, glm::dvec3& nQ) const
  {
    nP = this->normalOf(p);
    nQ = this->normalOf(q);
    return makeCircleApproximatingCurve(this->positionOf(p), nP, this->positionOf(q), nQ);
  }

  void remeshTriangle(Id t, std::vector<std::vector<Id>>& segments);
  // A Subpixel triangle, kept as it is: only its silhouette segment, the
  // chord between its silhouette points on its straight edges.
  void addSubpixelSegment(Id t, std::vector<std::vector<Id>>& segments) const;

  // The points inside the feature segment on edge e, made once per frame and
  // shared by the edge's triangles, as (parameter along the segment, point id):
  // its samples, and the silhouette points that the other sides of the crease
  // have on the same segment (copies with this side's normal), so that both
  // sides split the curve at the same points (no crack, no T-junction).
  const std::vector<std::pair<double, Id>>& featureSamples(Id e);

  // Re-meshing with feature segments (Fig. 12): the triangle's outline runs
  // through the samples of its smoothed feature sides (and its silhouette
  // points); a silhouette triangle is cut along its silhouette segment into
  // two polygons. Each polygon is convex in the triangle's parameter domain
  // and is fanned from its best vertex (the vertex opposite a single feature
  // side, Fig. 12a) or from an added centre point (Fig. 12b).
  void remeshWithFeatures(Id t, bool silhouette, std::vector<std::vector<Id>>& segments);

  void fanPolygon(const std::array<Id, 3>& corners, const std::vector<PolygonPoint>& polygon);

  // The output triangles around the moved points (kept input triangles and
  // replacements alike) must not turn over.
  void keepOutputFacingOut();

  const PreparedMesh& Mesh;
  const ViewGeometry& View;
  const SmoothingParameters& Parameters;
  const SamplingParameters& Sampling;
  int SampleCap = 0; // applySampleBudget
  std::atomic<bool> SampleCapBit{ false };
  const ParallelFor& For;
  /// g of every point, or empty when the triangle hierarchy found the
  /// silhouette triangles (visibleAt).
  std::vector<double> G;
  std::size_t Culled = 0; // silhouette triangles outside the frustum
  /// The fold checks' grid (PreparedMesh::foldGuardGridForFrame), asked for
  /// at the frame's first check.
  bool FoldGridAsked = false;
  const TriangleGrid* FoldGrid = nullptr;
  std::vector<Id> Silhouette;
  std::vector<unsigned char> MovedMark; // keepOutputFacingOut's, all 0 between calls
  std::vector<EdgeSilhouettePoint> EdgePoints;
  std::vector<int> FeatureSampleCounts;
  std::unordered_map<Id, std::vector<std::pair<double, Id>>> FeatureSamplePoints;
  struct FeatureSilhouettePoint
  {
    Id Feature;
    Id Edge;
    double Along; // parameter along the feature segment
  };
  std::vector<FeatureSilhouettePoint> FeatureSilhouettePoints;
  std::vector<Id> FrameFeatureTriangles;
  std::vector<ConcaveSegment> Concave;
  SmoothingResult Result;
  // The fold guard's fallbacks, kept across rounds: levels of silhouette
  // triangles, edges whose silhouette point is on the straight edge, and
  // points the perturbation leaves in place (both ascending).
  std::unordered_map<Id, unsigned char> Levels;
  std::vector<Id> StraightEdges;
  // How many of them were straight before the first round (at apexes and
  // Subpixel triangles): not fallbacks.
  std::size_t PresetStraightEdges = 0;
  // Silhouette triangles kept as they are (skipSubpixelSmoothing), ascending.
  std::vector<Id> Subpixel;
  // Curved feature segments drawn by their chords in this frame, their
  // curves within the tolerance of them in the image (skipSubpixelFeatures),
  // ascending; and, when there are any, the triangles with a side on one of
  // the other curved segments (PreparedMesh::featureTriangles without
  // those that only SubpixelFeatures put there), ascending.
  std::vector<Id> SubpixelFeatures;
  std::vector<Id> CurvedFeatureTriangles;
  // Mixed sides of frozen silhouette triangles, ascending (only with
  // SkipSubpixelSmoothing): a strip through one is always smoothed.
  std::vector<Id> FrozenMixedEdges;
  std::size_t ApexTriangles = 0;
  std::size_t CrowdedTriangles = 0; // sent straight untested (FoldGuard.h)
  std::vector<Id> StraightFeatures;
  std::vector<Id> Pinned;
  std::size_t ReusedFallbacks = 0; // SmoothingResult::ReusedFallbacks
};

} // namespace detail
} // namespace silsmooth
