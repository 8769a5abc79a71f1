#include "SilhouetteSmoother.h"

#include "FoldGuard.h"
#include "HermiteCurve.h"
#include "LocalRemesher.h"
#include "ShadingNormals.h"
#include "SilhouettePoint.h"
#include "SilhouettePolylines.h"
#include "VertexPerturbation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <mutex>
#include <tuple>
#include <unordered_map>

namespace silsmooth
{

void serialFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)
{
  if (count > 0)
  {
    body(0, count);
  }
}

PreparedMesh::PreparedMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
  const std::vector<glm::dvec3>& normals, std::vector<FeatureEdge> featureEdges,
  const std::vector<glm::dvec3>& cornerNormals, const EdgeTable* edges, NormalWeighting weighting)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , InputPointCount(this->Points.size())
{
  if (!featureEdges.empty())
  {
    // Only edges of the triangles can be feature edges.
    featureEdges = normalizedFeatureEdges(std::move(featureEdges));
    const EdgeTable built = edges ? EdgeTable() : EdgeTable(this->Triangles);
    const EdgeTable& input = edges ? *edges : built;
    std::size_t e = 0;
    featureEdges.erase(std::remove_if(featureEdges.begin(), featureEdges.end(),
                         [&](const FeatureEdge& f) {
                           while (e < input.edgeCount() &&
                             FeatureEdge(input.edge(static_cast<Id>(e)).low,
                               input.edge(static_cast<Id>(e)).high) < f)
                           {
                             ++e;
                           }
                           return e == input.edgeCount() ||
                             FeatureEdge(input.edge(static_cast<Id>(e)).low,
                               input.edge(static_cast<Id>(e)).high) != f;
                         }),
      featureEdges.end());
    this->Features = FeatureCurves(this->Points, std::move(featureEdges));
  }
  if (!this->Features.empty())
  {
    FeatureSplit split = splitAtFeatureEdges(this->Points.size(), this->Triangles, this->Features);
    this->Triangles = std::move(split.Triangles);
    this->CopySources = std::move(split.CopySources);
    this->OnFeature = std::move(split.OnFeature);
    for (const Id source : this->CopySources)
    {
      this->Points.push_back(this->Points[static_cast<std::size_t>(source)]);
    }
  }
  this->Edges = this->Features.empty() && edges ? *edges : EdgeTable(this->Triangles);
  {
    std::vector<int> uses(this->Edges.edgeCount(), 0);
    for (std::size_t t = 0; t < this->Triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        ++uses[static_cast<std::size_t>(this->Edges.sideEdge(static_cast<Id>(t), k))];
      }
    }
    this->OnBoundary.assign(this->Points.size(), 0);
    this->BoundaryEdges.assign(uses.size(), 0);
    for (std::size_t e = 0; e < uses.size(); ++e)
    {
      if (uses[e] == 1)
      {
        this->BoundaryEdges[e] = 1;
        const Edge& edge = this->Edges.edge(static_cast<Id>(e));
        this->OnBoundary[static_cast<std::size_t>(edge.low)] = 1;
        this->OnBoundary[static_cast<std::size_t>(edge.high)] = 1;
      }
    }
  }
  if (!this->Features.empty())
  {
    this->EdgeFeatures.resize(this->Edges.edgeCount());
    for (std::size_t e = 0; e < this->Edges.edgeCount(); ++e)
    {
      const Edge& edge = this->Edges.edge(static_cast<Id>(e));
      this->EdgeFeatures[e] =
        this->Features.find(this->sourcePoint(edge.low), this->sourcePoint(edge.high));
    }
    for (std::size_t t = 0; t < this->Triangles.size(); ++t)
    {
      if (hasRepeatedCorner(this->Triangles[t]))
      {
        continue;
      }
      bool curvedSide = false;
      for (int k = 0; k < 3; ++k)
      {
        const Id f = this->edgeFeature(this->Edges.sideEdge(static_cast<Id>(t), k));
        if (f >= 0)
        {
          this->FeatureSideTriangles.emplace_back(f, static_cast<Id>(t));
          curvedSide = curvedSide || this->Features.isCurved(f);
        }
      }
      if (curvedSide)
      {
        this->FeatureTriangles.push_back(static_cast<Id>(t));
      }
    }
    std::sort(this->FeatureSideTriangles.begin(), this->FeatureSideTriangles.end());
    this->FeatureSideTriangles.erase(
      std::unique(this->FeatureSideTriangles.begin(), this->FeatureSideTriangles.end()),
      this->FeatureSideTriangles.end());
  }

  // Edge neighbours of every vertex (compressed rows), for the perturbation.
  std::vector<Id> degree(this->Points.size() + 1, 0);
  for (std::size_t e = 0; e < this->Edges.edgeCount(); ++e)
  {
    const Edge& edge = this->Edges.edge(static_cast<Id>(e));
    if (edge.low != edge.high)
    {
      ++degree[static_cast<std::size_t>(edge.low) + 1];
      ++degree[static_cast<std::size_t>(edge.high) + 1];
    }
  }
  for (std::size_t v = 1; v < degree.size(); ++v)
  {
    degree[v] += degree[v - 1];
  }
  this->NeighbourOffsets = degree;
  this->Neighbours.resize(static_cast<std::size_t>(degree.back()));
  for (std::size_t e = 0; e < this->Edges.edgeCount(); ++e)
  {
    const Edge& edge = this->Edges.edge(static_cast<Id>(e));
    if (edge.low != edge.high)
    {
      this->Neighbours[static_cast<std::size_t>(degree[static_cast<std::size_t>(edge.low)]++)] =
        edge.high;
      this->Neighbours[static_cast<std::size_t>(degree[static_cast<std::size_t>(edge.high)]++)] =
        edge.low;
    }
  }

  // Given normals for the input's points; feature points (and their copies)
  // and points with no usable given normal get the angle-weighted one.
  std::vector<glm::dvec3> computed;
  bool needComputed = normals.size() != this->InputPointCount || !this->Features.empty();
  if (cornerNormals.size() == this->Triangles.size() * 3 && !this->Triangles.empty())
  {
    this->Normals = this->normalsFromCorners(cornerNormals);
    needComputed = true;
  }
  else if (normals.size() == this->InputPointCount)
  {
    this->Normals.resize(this->Points.size(), glm::dvec3(0.0));
    for (std::size_t i = 0; i < normals.size(); ++i)
    {
      this->Normals[i] =
        this->onFeature(static_cast<Id>(i)) ? glm::dvec3(0.0) : safeNormalize(normals[i]);
      needComputed = needComputed || this->Normals[i] == glm::dvec3(0.0);
    }
  }
  if (needComputed)
  {
    computed = vertexNormals(this->Points, this->Triangles, weighting);
    if (this->Normals.empty())
    {
      this->Normals = std::move(computed);
    }
    else
    {
      for (std::size_t i = 0; i < this->Normals.size(); ++i)
      {
        if (this->Normals[i] == glm::dvec3(0.0))
        {
          this->Normals[i] = computed[i];
        }
      }
    }
  }
}

std::vector<glm::dvec3> PreparedMesh::normalsFromCorners(
  const std::vector<glm::dvec3>& cornerNormals) const
{
  const std::size_t count = this->Points.size();
  std::vector<glm::dvec3> first(count, glm::dvec3(0.0));
  std::vector<glm::dvec3> sum(count, glm::dvec3(0.0));
  std::vector<unsigned char> mixed(count, 0);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t p = static_cast<std::size_t>(this->Triangles[t][k]);
      const glm::dvec3 n = safeNormalize(cornerNormals[t * 3 + k]);
      if (n == glm::dvec3(0.0))
      {
        continue;
      }
      if (first[p] == glm::dvec3(0.0))
      {
        first[p] = n;
        sum[p] = n;
      }
      else if (n != first[p])
      {
        mixed[p] = 1;
        sum[p] += n;
      }
    }
  }
  std::vector<glm::dvec3> result(count);
  for (std::size_t p = 0; p < count; ++p)
  {
    result[p] = mixed[p] ? safeNormalize(sum[p]) : first[p];
  }
  if (this->Features.empty())
  {
    return result;
  }
  // A feature point's groups keep their corners' normals only where those
  // tell the sides of the crease apart.
  const double cosLimit = std::cos(NormalSeamAngleDegrees * 3.14159265358979323846 / 180.0);
  std::vector<unsigned char> distinct(this->InputPointCount, 0);
  for (std::size_t p = this->InputPointCount; p < count; ++p)
  {
    const std::size_t s = static_cast<std::size_t>(this->sourcePoint(static_cast<Id>(p)));
    const glm::dvec3& a = result[s];
    const glm::dvec3& b = result[p];
    if (a == glm::dvec3(0.0) || b == glm::dvec3(0.0) || glm::dot(a, b) < cosLimit)
    {
      distinct[s] = 1;
    }
  }
  for (std::size_t p = 0; p < count; ++p)
  {
    const std::size_t s = static_cast<std::size_t>(this->sourcePoint(static_cast<Id>(p)));
    if (this->onFeature(static_cast<Id>(p)) && !distinct[s])
    {
      result[p] = glm::dvec3(0.0);
    }
  }
  return result;
}

std::vector<double> vertexVisibility(
  const PreparedMesh& mesh, const ViewGeometry& view, const ParallelFor& parallelFor)
{
  const std::vector<glm::dvec3>& points = mesh.points();
  const std::vector<glm::dvec3>& normals = mesh.normals();
  std::vector<double> g(points.size());
  parallelFor(points.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      g[i] = view.visibility(points[i], normals[i]);
    }
  });
  return g;
}

const TriangleGrid& PreparedMesh::triangleGrid() const
{
  std::call_once(
    this->Grid->Once, [this] { this->Grid->Grid = TriangleGrid(this->Points, this->Triangles); });
  return this->Grid->Grid;
}

const VisibilityHierarchy& PreparedMesh::visibilityHierarchy() const
{
  std::call_once(this->Hierarchy->Once,
    [this] { this->Hierarchy->Hierarchy = VisibilityHierarchy(this->Points, this->Normals); });
  return this->Hierarchy->Hierarchy;
}

std::vector<double> vertexVisibility(const PreparedMesh& mesh, const ViewGeometry& view,
  VisibilityMethod method, const ParallelFor& parallelFor)
{
  if (method != VisibilityMethod::Hierarchical)
  {
    return vertexVisibility(mesh, view, parallelFor);
  }
  std::vector<double> g;
  mesh.visibilityHierarchy().classify(view, g, parallelFor);
  return g;
}

namespace
{

bool isVisible(double g)
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

  SmoothingResult run()
  {
    this->G = vertexVisibility(this->Mesh, this->View, this->Parameters.Visibility, this->For);
    this->findSilhouetteTriangles();
    // Each round re-meshes the whole frame with the fallbacks decided so far;
    // a round that finds no fold, or no fallback left to take, is the last.
    // Rounds are bounded: every round but the last takes a fallback, and
    // there are at most two per silhouette triangle and one per moved point.
    // After the first, a round checks only what its fallbacks changed: the
    // triangles they re-meshed differently, and those around points whose
    // move differs from the round before (FoldGuardFrame::CheckSources).
    std::vector<Id> changedTriangles;
    std::vector<std::pair<Id, glm::dvec3>> movedBefore;
    for (std::size_t round = 0;; ++round)
    {
      this->remeshFrame();
      if (!this->Parameters.PreventFolds)
      {
        break;
      }
      // Points whose move differs from the round before (moved only then,
      // only now, or elsewhere now): their triangles changed.
      const std::vector<std::pair<Id, glm::dvec3>>& moved = this->Result.MovedPoints;
      std::vector<Id> aroundPoints;
      {
        std::size_t a = 0;
        std::size_t b = 0;
        while (a < movedBefore.size() || b < moved.size())
        {
          if (b == moved.size() ||
            (a < movedBefore.size() && movedBefore[a].first < moved[b].first))
          {
            aroundPoints.push_back(movedBefore[a++].first);
          }
          else if (a == movedBefore.size() || moved[b].first < movedBefore[a].first)
          {
            aroundPoints.push_back(moved[b++].first);
          }
          else
          {
            if (movedBefore[a].second != moved[b].second)
            {
              aroundPoints.push_back(moved[b].first);
            }
            ++a;
            ++b;
          }
        }
      }
      const FoldFindings findings = (round == 0 || !this->Parameters.IncrementalFoldChecks)
        ? this->findFrameFolds(nullptr, nullptr)
        : this->findFrameFolds(&changedTriangles, &aroundPoints);
      movedBefore = moved;
      changedTriangles.clear();
      if (!findings.any() || !this->takeFallbacks(findings, changedTriangles))
      {
        this->Result.UnresolvedFolds = findings.Turned + findings.Cutting;
        this->Result.FoldGuardRounds = round;
        break;
      }
    }
    this->Result.PinnedPoints = this->Pinned.size();
    this->Result.CulledTriangles = this->Culled;
    this->Result.StraightSilhouettePoints = this->StraightEdges.size();
    this->Result.StraightFeatureSegments = this->StraightFeatures.size();
    for (const auto& level : this->Levels)
    {
      this->Result.ChordFallbackTriangles += level.second >= ChordLevel ? 1 : 0;
    }
    return std::move(this->Result);
  }

private:
  // Fallback levels of a silhouette triangle (FoldGuard.h).
  static constexpr unsigned char ChordLevel = 1;    // no interior samples
  static constexpr unsigned char StraightLevel = 2; // and points on its edges

  void remeshFrame()
  {
    this->EdgePoints.clear();
    this->FeatureSilhouettePoints.clear();
    this->FeatureSamplePoints.clear();
    this->FrameFeatureTriangles.clear();
    this->Concave.clear();
    this->Result = SmoothingResult();
    this->computeSilhouettePoints();
    this->applySampleBudget();
    this->countFeatureSamples();
    std::vector<std::vector<Id>> segments;
    segments.reserve(this->Silhouette.size());
    // Silhouette triangles and feature triangles, merged in ascending order.
    const std::vector<Id>& features = this->featureTrianglesOfFrame();
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < this->Silhouette.size() || j < features.size())
    {
      const bool takeSilhouette =
        j == features.size() || (i < this->Silhouette.size() && this->Silhouette[i] <= features[j]);
      const Id t = takeSilhouette ? this->Silhouette[i] : features[j];
      const bool silhouette = takeSilhouette;
      const bool feature = j < features.size() && features[j] == t;
      i += takeSilhouette ? 1 : 0;
      j += feature ? 1 : 0;
      if (!silhouette && this->isFrozen(t))
      {
        continue; // a frozen feature triangle (frozen silhouette ones are not listed)
      }
      this->Result.RemeshedTriangles.push_back(t);
      if (feature)
      {
        this->remeshWithFeatures(t, silhouette, segments);
        this->Result.RemeshKinds.push_back(RemeshKind::Feature);
      }
      else
      {
        this->remeshTriangle(t, segments);
        this->Result.RemeshKinds.push_back(RemeshKind::Silhouette);
      }
      this->Result.ReplacementOffsets.push_back(this->Result.Replacements.size());
    }
    this->Result.SilhouetteTriangleCount = this->Silhouette.size();
    this->Result.SampleBudgetMaximum = this->SampleCapBit ? this->SampleCap : 0;
    this->Result.Polylines = chainSegments(segments);
    this->Result.ConcaveSegmentCount = this->Concave.size();
    if (this->Parameters.PerturbConcaveSilhouettes && !this->Concave.empty())
    {
      this->Result.MovedPoints = perturbVerticesBelowConcaveSegments(this->Concave,
        this->Mesh.points(), this->Mesh.normals(), this->Mesh.triangles(),
        this->Mesh.neighbourOffsets(), this->Mesh.neighbours());
      // A feature point has a copy on the other side of its crease that
      // does not move with it: moving one would open the crease. A point on
      // a boundary may be on a seam whose other side is another piece of
      // the mesh, which cannot know about the move. A pinned point folded
      // its triangles in an earlier round.
      auto& moved = this->Result.MovedPoints;
      moved.erase(std::remove_if(moved.begin(), moved.end(),
                    [this](const std::pair<Id, glm::dvec3>& m) {
                      return this->Mesh.onFeature(m.first) || this->Mesh.onBoundary(m.first) ||
                        std::binary_search(this->Pinned.begin(), this->Pinned.end(), m.first);
                    }),
        moved.end());
      this->keepOutputFacingOut();
    }
  }

  FoldFindings findFrameFolds(
    const std::vector<Id>* checkSources, const std::vector<Id>* checkPoints) const
  {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    positions.reserve(this->Result.NewPoints.size());
    normals.reserve(this->Result.NewPoints.size());
    for (const NewPoint& p : this->Result.NewPoints)
    {
      positions.push_back(p.Position);
      normals.push_back(p.Normal);
    }
    const FoldGuardMesh mesh{ this->Mesh.points(), this->Mesh.normals(), this->Mesh.triangles(),
      this->Mesh.triangleGrid() };
    const FoldGuardFrame frame{ this->Result.RemeshedTriangles, this->Result.ReplacementOffsets,
      this->Result.Replacements, positions, normals, this->Result.MovedPoints, checkSources,
      checkPoints };
    return findFolds(mesh, frame, this->For);
  }

  // Raises the fallback level of every folding silhouette triangle and pins
  // every folding moved point; false when none could be taken. `changed`
  // gets the input triangles that the next round must check again
  // (ascending): the folding ones, and those it re-meshes differently.
  bool takeFallbacks(const FoldFindings& findings, std::vector<Id>& changed)
  {
    bool taken = false;
    std::vector<Id> newEdges;
    const EdgeTable& edges = this->Mesh.edges();
    for (std::size_t i = 0; i < findings.FoldingRemeshed.size(); ++i)
    {
      const Id t = this->Result.RemeshedTriangles[i];
      if (!findings.FoldingRemeshed[i])
      {
        continue;
      }
      changed.push_back(t); // checked again, whether or not a fallback is left
      const bool silhouette =
        std::binary_search(this->Silhouette.begin(), this->Silhouette.end(), t);
      if (!silhouette || this->levelOf(t) >= StraightLevel)
      {
        // Last: its curved feature segments become their chords, on every
        // side of their creases.
        for (int k = 0; k < 3; ++k)
        {
          const Id e = edges.sideEdge(t, k);
          const Id f = this->Mesh.edgeFeature(e);
          if (f >= 0 && this->Mesh.features().isCurved(f) && !this->isStraightened(f) &&
            !this->mayBeSeam(e))
          {
            this->StraightFeatures.insert(
              std::upper_bound(this->StraightFeatures.begin(), this->StraightFeatures.end(), f), f);
            taken = true;
            // Every side of the crease samples the segment.
            const auto& sides = this->Mesh.featureSideTriangles();
            for (auto it = std::lower_bound(sides.begin(), sides.end(), std::make_pair(f, Id{ 0 }));
                 it != sides.end() && it->first == f; ++it)
            {
              changed.push_back(it->second);
            }
          }
        }
        continue;
      }
      unsigned char& level = this->Levels[t];
      ++level;
      taken = true;
      if (level == StraightLevel)
      {
        // Its silhouette points, shared with the triangles across its mixed
        // edges; those on feature edges stay on the feature curve, which
        // the other sides of the crease sample too, and those on a seam
        // between pieces stay on the curve, which the piece across computes
        // too (it cannot know of this fallback).
        for (int k = 0; k < 3; ++k)
        {
          const Id e = edges.sideEdge(t, k);
          if (this->isMixed(edges.edge(e)) && this->Mesh.edgeFeature(e) < 0 &&
            !this->mayBeSeam(e) &&
            !std::binary_search(this->StraightEdges.begin(), this->StraightEdges.end(), e))
          {
            newEdges.push_back(e);
          }
        }
      }
    }
    std::sort(newEdges.begin(), newEdges.end());
    newEdges.erase(std::unique(newEdges.begin(), newEdges.end()), newEdges.end());
    if (!newEdges.empty())
    {
      // The triangles across them share the points (both are silhouette
      // triangles: the edges are mixed).
      for (const Id t : this->Silhouette)
      {
        for (int k = 0; k < 3; ++k)
        {
          if (std::binary_search(newEdges.begin(), newEdges.end(), edges.sideEdge(t, k)))
          {
            changed.push_back(t);
          }
        }
      }
      std::vector<Id> merged;
      std::set_union(this->StraightEdges.begin(), this->StraightEdges.end(), newEdges.begin(),
        newEdges.end(), std::back_inserter(merged));
      this->StraightEdges = std::move(merged);
    }
    for (const Id p : findings.FoldingMovedPoints)
    {
      if (!std::binary_search(this->Pinned.begin(), this->Pinned.end(), p))
      {
        this->Pinned.insert(std::upper_bound(this->Pinned.begin(), this->Pinned.end(), p), p);
        taken = true;
      }
    }
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    return taken;
  }

  // An edge whose ends differ in visibility: it holds a silhouette point.
  bool isMixed(const Edge& edge) const
  {
    return isVisible(this->G[static_cast<std::size_t>(edge.low)]) !=
      isVisible(this->G[static_cast<std::size_t>(edge.high)]);
  }

  bool mayBeSeam(Id e) const
  {
    return this->Parameters.BoundaryMayBeSeam && this->Mesh.isBoundaryEdge(e);
  }

  bool isStraightened(Id feature) const
  {
    return std::binary_search(
      this->StraightFeatures.begin(), this->StraightFeatures.end(), feature);
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

  void findSilhouetteTriangles()
  {
    const std::vector<Triangle>& triangles = this->Mesh.triangles();
    // Each vertex's side as a byte: the triangle pass reads three per
    // triangle at random, and bytes stay in cache where doubles do not.
    std::vector<unsigned char> visible(this->G.size());
    this->For(this->G.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t v = begin; v < end; ++v)
      {
        visible[v] = isVisible(this->G[v]) ? 1 : 0;
      }
    });
    // Each sub-range collects its own silhouette triangles (ascending);
    // the ranges are then joined in order, so the list does not depend on
    // how the range was split.
    std::mutex rangesMutex;
    std::vector<std::pair<std::size_t, std::vector<Id>>> ranges;
    this->For(triangles.size(), [&](std::size_t begin, std::size_t end) {
      std::vector<Id> found;
      for (std::size_t t = begin; t < end; ++t)
      {
        const Triangle& tri = triangles[t];
        const unsigned char v0 = visible[static_cast<std::size_t>(tri[0])];
        const unsigned char v1 = visible[static_cast<std::size_t>(tri[1])];
        const unsigned char v2 = visible[static_cast<std::size_t>(tri[2])];
        if ((v0 != v1 || v1 != v2) && !hasRepeatedCorner(tri))
        {
          found.push_back(static_cast<Id>(t));
        }
      }
      const std::lock_guard<std::mutex> lock(rangesMutex);
      ranges.emplace_back(begin, std::move(found));
    });
    std::sort(
      ranges.begin(), ranges.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& range : ranges)
    {
      this->Silhouette.insert(this->Silhouette.end(), range.second.begin(), range.second.end());
    }
    if (this->Parameters.CullOutsideFrustum)
    {
      this->cullOutsideFrustum();
    }
    if (this->Parameters.FrozenTriangles)
    {
      this->Silhouette.erase(std::remove_if(this->Silhouette.begin(), this->Silhouette.end(),
                               [this](Id t) { return this->isFrozen(t); }),
        this->Silhouette.end());
    }
  }

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
  void cullOutsideFrustum()
  {
    const glm::dmat4& m = this->View.ModelToClip;
    auto row = [&m](int i) {
      return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]);
    };
    std::array<glm::dvec4, 6> planes{ { row(3) + row(0), row(3) - row(0), row(3) + row(1),
      row(3) - row(1), row(3) + row(2), row(3) - row(2) } };
    for (glm::dvec4& plane : planes)
    {
      const double length = glm::length(glm::dvec3(plane));
      plane = length > 0.0 && std::isfinite(length) ? plane / length : glm::dvec4(0.0);
    }
    const std::vector<Triangle>& triangles = this->Mesh.triangles();
    const std::vector<glm::dvec3>& points = this->Mesh.points();
    const std::size_t before = this->Silhouette.size();
    this->Silhouette.erase(std::remove_if(this->Silhouette.begin(), this->Silhouette.end(),
                             [&](Id t) {
                               const Triangle& tri = triangles[static_cast<std::size_t>(t)];
                               const glm::dvec3& a = points[static_cast<std::size_t>(tri[0])];
                               const glm::dvec3& b = points[static_cast<std::size_t>(tri[1])];
                               const glm::dvec3& c = points[static_cast<std::size_t>(tri[2])];
                               const double margin = std::max(
                                 { glm::length(b - a), glm::length(c - b), glm::length(a - c) });
                               for (const glm::dvec4& plane : planes)
                               {
                                 auto beyond = [&](const glm::dvec3& p) {
                                   return glm::dot(glm::dvec3(plane), p) + plane.w < -margin;
                                 };
                                 if (beyond(a) && beyond(b) && beyond(c))
                                 {
                                   return true;
                                 }
                               }
                               return false;
                             }),
      this->Silhouette.end());
    this->Culled = before - this->Silhouette.size();
  }

  // One silhouette point per mixed edge, in ascending edge order, so both
  // triangles of an edge use the same point (the crack-free rule). On a feature edge
  // the silhouette bridge is the edge's feature segment (III-D, case (a)).
  void computeSilhouettePoints()
  {
    const EdgeTable& edges = this->Mesh.edges();
    std::vector<Id> mixedEdges;
    for (const Id t : this->Silhouette)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Id e = edges.sideEdge(t, k);
        if (this->isMixed(edges.edge(e)))
        {
          mixedEdges.push_back(e);
        }
      }
    }
    std::sort(mixedEdges.begin(), mixedEdges.end());
    mixedEdges.erase(std::unique(mixedEdges.begin(), mixedEdges.end()), mixedEdges.end());

    const auto& points = this->Mesh.points();
    const auto& normals = this->Mesh.normals();
    const Id pointCount = static_cast<Id>(points.size());
    this->EdgePoints.reserve(mixedEdges.size());
    for (const Id e : mixedEdges)
    {
      const Edge& edge = edges.edge(e);
      const std::size_t lo = static_cast<std::size_t>(edge.low);
      const std::size_t hi = static_cast<std::size_t>(edge.high);
      // Walked from the end with the smaller position (x, then y, then z; the
      // id only for coincident ends), not the smaller id: then the point comes
      // out bit for bit the same in every piece of a partitioned mesh (the
      // ids differ between pieces), and pieces meet without a crack.
      const bool lowFirst = std::make_tuple(points[lo].x, points[lo].y, points[lo].z, lo) <
        std::make_tuple(points[hi].x, points[hi].y, points[hi].z, hi);
      const std::size_t a = lowFirst ? lo : hi;
      const std::size_t b = lowFirst ? hi : lo;
      const VisibilityQuadratic h = visibilityAlongEdge(normals[a],
        this->View.towardViewerFrom(points[a]), normals[b], this->View.towardViewerFrom(points[b]));
      // G holds only signs for hierarchically decided vertices: the values here.
      const double t =
        std::clamp(silhouetteParameter(h, this->View.visibility(points[a], normals[a]),
                     this->View.visibility(points[b], normals[b])),
          EdgeParameterMargin, 1.0 - EdgeParameterMargin);
      NewPoint p;
      const Id feature = this->Mesh.edgeFeature(e);
      if (feature >= 0)
      {
        const bool forward = this->Mesh.sourcePoint(static_cast<Id>(a)) ==
          this->Mesh.features().edges()[feature].first;
        const double along = forward ? t : 1.0 - t;
        p.Position = this->featurePoint(feature, along);
        this->FeatureSilhouettePoints.push_back({ feature, e, along });
      }
      else if (std::binary_search(this->StraightEdges.begin(), this->StraightEdges.end(), e))
      {
        p.Position = (1.0 - t) * points[a] + t * points[b];
      }
      else
      {
        p.Position =
          makeCircleApproximatingCurve(points[a], normals[a], points[b], normals[b]).evaluate(t);
      }
      p.Normal = safeNormalize((1.0 - t) * normals[a] + t * normals[b]);
      if (p.Normal == glm::dvec3(0.0))
      {
        // Opposite normals at the ends: no interpolated direction exists.
        p.Normal = t < 0.5 ? normals[a] : normals[b];
      }
      const double u = lowFirst ? t : 1.0 - t; // from the low id to the high id
      p.Sources = { edge.low, edge.high, edge.high };
      p.Weights = { 1.0 - u, u, 0.0 };
      EdgeSilhouettePoint sp;
      sp.Edge = e;
      sp.Point = pointCount + static_cast<Id>(this->Result.NewPoints.size());
      sp.HighWeight = u;
      this->Result.NewPoints.push_back(p);
      this->EdgePoints.push_back(sp);
    }
    // By feature edge, for featureSamples().
    std::sort(this->FeatureSilhouettePoints.begin(), this->FeatureSilhouettePoints.end(),
      [](const FeatureSilhouettePoint& x, const FeatureSilhouettePoint& y) {
        return x.Feature != y.Feature ? x.Feature < y.Feature : x.Edge < y.Edge;
      });
  }

  // The triangles re-meshed for their feature sides in this frame: those
  // with a smoothed (curved) feature side, every frame, and those with a side
  // on a straight feature edge that the silhouette crosses, from any side of
  // the crease: each side has its own normals, so the silhouette may cross
  // the crease on one side only, and the others must still split the edge at
  // that point (or the output has a T-junction there).
  const std::vector<Id>& featureTrianglesOfFrame()
  {
    std::vector<Id> straight;
    for (const FeatureSilhouettePoint& point : this->FeatureSilhouettePoints)
    {
      if (this->Mesh.features().isCurved(point.Feature))
      {
        continue;
      }
      const auto& sides = this->Mesh.featureSideTriangles();
      auto it =
        std::lower_bound(sides.begin(), sides.end(), std::make_pair(point.Feature, Id{ 0 }));
      for (; it != sides.end() && it->first == point.Feature; ++it)
      {
        straight.push_back(it->second);
      }
    }
    if (straight.empty())
    {
      return this->Mesh.featureTriangles();
    }
    std::sort(straight.begin(), straight.end());
    this->FrameFeatureTriangles.clear();
    std::set_union(this->Mesh.featureTriangles().begin(), this->Mesh.featureTriangles().end(),
      straight.begin(), straight.end(), std::back_inserter(this->FrameFeatureTriangles));
    this->FrameFeatureTriangles.erase(
      std::unique(this->FrameFeatureTriangles.begin(), this->FrameFeatureTriangles.end()),
      this->FrameFeatureTriangles.end());
    return this->FrameFeatureTriangles;
  }

  bool crossedBySilhouette(Id feature) const
  {
    return std::binary_search(this->FeatureSilhouettePoints.begin(),
      this->FeatureSilhouettePoints.end(), FeatureSilhouettePoint{ feature, -1, 0.0 },
      [](const FeatureSilhouettePoint& x, const FeatureSilhouettePoint& y) {
        return x.Feature < y.Feature;
      });
  }

  // SmoothingParameters::MaximumSampledPoints, shared evenly by the frame's
  // silhouette triangles and feature edges: the most samples a segment may
  // have in this frame, 0 for no cap.
  void applySampleBudget()
  {
    this->SampleCap = 0;
    this->SampleCapBit = false;
    const std::size_t budget = this->Parameters.MaximumSampledPoints;
    if (budget == 0)
    {
      return;
    }
    const std::size_t segments =
      std::max<std::size_t>(1, this->Silhouette.size() + this->Mesh.features().edges().size());
    const std::size_t perSegment = 2 + budget / segments;
    if (perSegment < static_cast<std::size_t>(this->Parameters.Sampling.MaximumSamples))
    {
      this->SampleCap = static_cast<int>(perSegment);
    }
  }

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
  void countFeatureSamples()
  {
    const FeatureCurves& features = this->Mesh.features();
    this->FeatureSampleCounts.assign(features.edges().size(), 2);
    if (this->Mesh.featureTriangles().empty())
    {
      return;
    }
    this->For(features.edges().size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t f = begin; f < end; ++f)
      {
        if (features.isCurved(static_cast<Id>(f)) && !this->isStraightened(static_cast<Id>(f)))
        {
          const HermiteCurve& curve = features.curve(static_cast<Id>(f));
          // Eq. 8 wants the arc's turning: the end tangents give it here.
          this->FeatureSampleCounts[f] =
            this->sampleCount(curve, safeNormalize(curve.T0), safeNormalize(curve.T1));
        }
      }
    });
  }

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
    const bool v0 = isVisible(this->G[static_cast<std::size_t>(tri[0])]);
    const bool v1 = isVisible(this->G[static_cast<std::size_t>(tri[1])]);
    return (v0 == v1) ? 2 : (isVisible(this->G[static_cast<std::size_t>(tri[2])]) == v0 ? 1 : 0);
  }

  // Samples the silhouette segment from P to Q across the triangle with
  // corners (a, b, c), a the lone one, adding its interior samples as new
  // points; records it if concave. P and Q are given with their barycentric
  // positions in (a, b, c); the samples lie on the chord between them there.
  std::vector<PolygonPoint> sampleSilhouetteSegment(
    Id t, const std::array<Id, 3>& corners, const PolygonPoint& p, const PolygonPoint& q)
  {
    std::vector<PolygonPoint> interior;
    if (p.Point == q.Point)
    {
      return interior;
    }
    const glm::dvec3 nP = this->normalOf(p.Point);
    const glm::dvec3 nQ = this->normalOf(q.Point);
    const HermiteCurve segment =
      makeCircleApproximatingCurve(this->positionOf(p.Point), nP, this->positionOf(q.Point), nQ);
    const int samples = this->levelOf(t) >= ChordLevel ? 2 : this->sampleCount(segment, nP, nQ);
    if (isConcaveSegment(segment.P0, nP, segment.P1, nQ))
    {
      const glm::dvec3 midNormal = safeNormalize(nP + nQ);
      if (midNormal != glm::dvec3(0.0))
      {
        const glm::dvec3 middle = segment.evaluate(0.5);
        this->Concave.push_back({ t, segment.P0, segment.P1, middle, midNormal,
          safeNormalize(this->View.towardViewerFrom(middle)) });
      }
    }
    for (int i = 1; i + 1 < samples; ++i)
    {
      const double s = static_cast<double>(i) / (samples - 1);
      NewPoint sample;
      sample.Position = segment.evaluate(s);
      sample.Normal = safeNormalize((1.0 - s) * nP + s * nQ);
      if (sample.Normal == glm::dvec3(0.0))
      {
        sample.Normal = s < 0.5 ? nP : nQ;
      }
      // Linear along the chord P -> Q in the triangle's parameter domain.
      const glm::dvec3 bary = (1.0 - s) * p.Bary + s * q.Bary;
      sample.Sources = { corners[0], corners[1], corners[2] };
      sample.Weights = { bary.x, bary.y, bary.z };
      interior.push_back({ this->nextPointId(), bary, false });
      this->Result.NewPoints.push_back(sample);
    }
    return interior;
  }

  // P on side a-b and Q on side a-c of a silhouette triangle, a = corners[0].
  std::pair<PolygonPoint, PolygonPoint> silhouettePointsOf(
    Id t, int lone, const std::array<Id, 3>& corners) const
  {
    const EdgeTable& edges = this->Mesh.edges();
    const EdgeSilhouettePoint& p = this->silhouettePointOf(edges.sideEdge(t, lone));
    const EdgeSilhouettePoint& q = this->silhouettePointOf(edges.sideEdge(t, (lone + 2) % 3));
    // Weight of the far corner (B for P, C for Q) in the point's combination.
    const double pTowardB = (corners[1] > corners[0]) ? p.HighWeight : 1.0 - p.HighWeight;
    const double qTowardC = (corners[2] > corners[0]) ? q.HighWeight : 1.0 - q.HighWeight;
    return { { p.Point, glm::dvec3(1.0 - pTowardB, pTowardB, 0.0), true },
      { q.Point, glm::dvec3(1.0 - qTowardC, 0.0, qTowardC), true } };
  }

  void remeshTriangle(Id t, std::vector<std::vector<Id>>& segments)
  {
    const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(t)];
    const int lone = this->loneCorner(tri);
    const std::array<Id, 3> corners{ { tri[lone], tri[(lone + 1) % 3], tri[(lone + 2) % 3] } };
    const auto [p, q] = this->silhouettePointsOf(t, lone, corners);

    // The re-meshing works in the flat triangle, where P and Q sit on their
    // edges and the samples on the chord between them.
    const glm::dvec3 flatA = this->positionOf(corners[0]);
    const glm::dvec3 flatB = this->positionOf(corners[1]);
    const glm::dvec3 flatC = this->positionOf(corners[2]);
    auto flat = [&](const glm::dvec3& bary) {
      return bary.x * flatA + bary.y * flatB + bary.z * flatC;
    };
    SilhouetteTriangleLayout layout;
    layout.Lone = corners[0];
    layout.BaseFirst = corners[1];
    layout.BaseSecond = corners[2];
    layout.BaseFirstPosition = flatB;
    layout.BaseSecondPosition = flatC;
    layout.Chain.push_back(p.Point);
    layout.ChainPositions.push_back(flat(p.Bary));
    for (const PolygonPoint& sample : this->sampleSilhouetteSegment(t, corners, p, q))
    {
      layout.Chain.push_back(sample.Point);
      layout.ChainPositions.push_back(flat(sample.Bary));
    }
    layout.Chain.push_back(q.Point);
    layout.ChainPositions.push_back(flat(q.Bary));

    remeshSilhouetteTriangle(layout, this->Result.Replacements);
    if (layout.Chain.front() != layout.Chain.back())
    {
      segments.push_back(layout.Chain);
    }
  }

  // The points inside the feature segment on edge e, made once per frame and
  // shared by the edge's triangles, as (parameter along the segment, point id):
  // its samples, and the silhouette points that the other sides of the crease
  // have on the same segment (copies with this side's normal), so that both
  // sides split the curve at the same points (no crack, no T-junction).
  const std::vector<std::pair<double, Id>>& featureSamples(Id e)
  {
    const auto found = this->FeatureSamplePoints.find(e);
    if (found != this->FeatureSamplePoints.end())
    {
      return found->second;
    }
    const Id f = this->Mesh.edgeFeature(e);
    const FeatureCurves& features = this->Mesh.features();
    const Edge& edge = this->Mesh.edges().edge(e);
    const bool forward = this->Mesh.sourcePoint(edge.low) == features.edges()[f].first;
    const Id from = forward ? edge.low : edge.high;
    const Id to = forward ? edge.high : edge.low;
    const glm::dvec3 n0 = this->normalOf(from);
    const glm::dvec3 n1 = this->normalOf(to);
    const HermiteCurve& curve = features.curve(f);
    const int samples = this->FeatureSampleCounts[static_cast<std::size_t>(f)];
    std::vector<double> parameters;
    for (int i = 1; i + 1 < samples; ++i)
    {
      parameters.push_back(static_cast<double>(i) / (samples - 1));
    }
    const auto onFeature = std::equal_range(this->FeatureSilhouettePoints.begin(),
      this->FeatureSilhouettePoints.end(), FeatureSilhouettePoint{ f, -1, 0.0 },
      [](const FeatureSilhouettePoint& x, const FeatureSilhouettePoint& y) {
        return x.Feature < y.Feature;
      });
    for (auto other = onFeature.first; other != onFeature.second; ++other)
    {
      if (other->Edge != e)
      {
        parameters.push_back(other->Along);
      }
    }
    std::vector<std::pair<double, Id>> points;
    for (const double s : parameters)
    {
      points.emplace_back(s, this->nextPointId());
      NewPoint sample;
      sample.Position = this->featurePoint(f, s);
      sample.Normal = safeNormalize((1.0 - s) * n0 + s * n1);
      if (sample.Normal == glm::dvec3(0.0))
      {
        sample.Normal = s < 0.5 ? n0 : n1;
      }
      sample.Sources = { from, to, to };
      sample.Weights = { 1.0 - s, s, 0.0 };
      this->Result.NewPoints.push_back(sample);
    }
    return this->FeatureSamplePoints.emplace(e, std::move(points)).first->second;
  }

  // Re-meshing with feature segments (Fig. 12): the triangle's outline runs
  // through the samples of its smoothed feature sides (and its silhouette
  // points); a silhouette triangle is cut along its silhouette segment into
  // two polygons. Each polygon is convex in the triangle's parameter domain
  // and is fanned from its best vertex (the vertex opposite a single feature
  // side, Fig. 12a) or from an added centre point (Fig. 12b).
  void remeshWithFeatures(Id t, bool silhouette, std::vector<std::vector<Id>>& segments)
  {
    const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(t)];
    const EdgeTable& edges = this->Mesh.edges();
    const FeatureCurves& features = this->Mesh.features();
    const int first = silhouette ? this->loneCorner(tri) : 0;
    const std::array<Id, 3> corners{ { tri[first], tri[(first + 1) % 3], tri[(first + 2) % 3] } };
    PolygonPoint p;
    PolygonPoint q;
    if (silhouette)
    {
      std::tie(p, q) = this->silhouettePointsOf(t, first, corners);
    }

    std::vector<PolygonPoint> outline;
    std::size_t pIndex = 0;
    std::size_t qIndex = 0;
    for (int j = 0; j < 3; ++j)
    {
      glm::dvec3 from(0.0);
      from[j] = 1.0;
      glm::dvec3 to(0.0);
      to[(j + 1) % 3] = 1.0;
      outline.push_back({ corners[static_cast<std::size_t>(j)], from, true });
      // Points inside the side, by their parameter from this corner.
      std::vector<std::pair<double, PolygonPoint>> inside;
      const Id e = edges.sideEdge(t, (first + j) % 3);
      const Id f = this->Mesh.edgeFeature(e);
      if (f >= 0 && (features.isCurved(f) || this->crossedBySilhouette(f)))
      {
        const bool forward =
          this->Mesh.sourcePoint(corners[static_cast<std::size_t>(j)]) == features.edges()[f].first;
        for (const auto& [s, id] : this->featureSamples(e))
        {
          const double along = forward ? s : 1.0 - s;
          inside.push_back({ along, { id, (1.0 - along) * from + along * to, false } });
        }
      }
      if (silhouette && (j == 0 || j == 2))
      {
        const PolygonPoint& point = j == 0 ? p : q;
        inside.push_back({ j == 0 ? point.Bary.y : 1.0 - point.Bary.z, point });
      }
      std::stable_sort(inside.begin(), inside.end(),
        [](const auto& x, const auto& y) { return x.first < y.first; });
      for (const auto& entry : inside)
      {
        if (silhouette && entry.second.Point == p.Point)
        {
          pIndex = outline.size();
        }
        if (silhouette && entry.second.Point == q.Point)
        {
          qIndex = outline.size();
        }
        outline.push_back(entry.second);
      }
    }

    if (!silhouette)
    {
      this->fanPolygon(corners, outline);
      return;
    }
    const std::vector<PolygonPoint> chain = this->sampleSilhouetteSegment(t, corners, p, q);
    // The lone corner's side: a ... P, the segment, Q ... back to a.
    std::vector<PolygonPoint> lone(outline.begin(), outline.begin() + pIndex + 1);
    lone.insert(lone.end(), chain.begin(), chain.end());
    lone.insert(lone.end(), outline.begin() + qIndex, outline.end());
    // The base side: P ... b ... c ... Q, then the segment back to P.
    std::vector<PolygonPoint> base(outline.begin() + pIndex, outline.begin() + qIndex + 1);
    base.insert(base.end(), chain.rbegin(), chain.rend());
    this->fanPolygon(corners, lone);
    this->fanPolygon(corners, base);

    std::vector<Id> segment{ p.Point };
    for (const PolygonPoint& sample : chain)
    {
      segment.push_back(sample.Point);
    }
    segment.push_back(q.Point);
    segments.push_back(std::move(segment));
  }

  void fanPolygon(const std::array<Id, 3>& corners, const std::vector<PolygonPoint>& polygon)
  {
    const glm::dvec3 flatA = this->positionOf(corners[0]);
    const glm::dvec3 flatB = this->positionOf(corners[1]);
    const glm::dvec3 flatC = this->positionOf(corners[2]);
    std::vector<Id> ids;
    std::vector<glm::dvec3> flat;
    std::vector<unsigned char> apex;
    glm::dvec3 centre(0.0);
    int apexCount = 0;
    for (const PolygonPoint& point : polygon)
    {
      ids.push_back(point.Point);
      flat.push_back(point.Bary.x * flatA + point.Bary.y * flatB + point.Bary.z * flatC);
      apex.push_back(point.Apex ? 1 : 0);
      if (point.Apex)
      {
        centre += point.Bary;
        ++apexCount;
      }
    }
    centre /= std::max(apexCount, 1);
    const glm::dvec3 flatCentre = centre.x * flatA + centre.y * flatB + centre.z * flatC;
    const int chosen = chooseFanApex(ids, flat, apex, flatCentre);
    Id centreId = -1;
    if (chosen < 0)
    {
      NewPoint point;
      point.Position = flatCentre;
      point.Normal = safeNormalize(centre.x * this->normalOf(corners[0]) +
        centre.y * this->normalOf(corners[1]) + centre.z * this->normalOf(corners[2]));
      if (point.Normal == glm::dvec3(0.0))
      {
        point.Normal = this->normalOf(corners[0]);
      }
      point.Sources = corners;
      point.Weights = { centre.x, centre.y, centre.z };
      centreId = this->nextPointId();
      this->Result.NewPoints.push_back(point);
    }
    emitFan(ids, chosen, centreId, this->Result.Replacements);
  }

  // The output triangles around the moved points (kept input triangles and
  // replacements alike) must not turn over.
  void keepOutputFacingOut()
  {
    const std::vector<std::pair<Id, glm::dvec3>>& moved = this->Result.MovedPoints;
    // A mark per mesh point (moved points are mesh points), set here and
    // cleared below: the scan over every triangle reads a byte per corner
    // instead of searching the moved list (at 1.3M triangles that search
    // was a third of a frame).
    std::vector<unsigned char>& mark = this->MovedMark;
    mark.resize(this->Mesh.points().size(), 0);
    for (const auto& m : moved)
    {
      mark[static_cast<std::size_t>(m.first)] = 1;
    }
    auto isMoved = [&mark](Id v) {
      return v >= 0 && static_cast<std::size_t>(v) < mark.size() &&
        mark[static_cast<std::size_t>(v)] != 0;
    };
    auto touchesMoved = [&isMoved](const Triangle& t) {
      return isMoved(t[0]) || isMoved(t[1]) || isMoved(t[2]);
    };
    std::vector<Triangle> around;
    const std::vector<Triangle>& triangles = this->Mesh.triangles();
    std::size_t next = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      if (next < this->Result.RemeshedTriangles.size() &&
        this->Result.RemeshedTriangles[next] == static_cast<Id>(t))
      {
        ++next; // replaced: its replacements are checked below
        continue;
      }
      if (touchesMoved(triangles[t]))
      {
        around.push_back(triangles[t]);
      }
    }
    for (const Triangle& t : this->Result.Replacements)
    {
      if (touchesMoved(t))
      {
        around.push_back(t);
      }
    }
    for (const auto& m : moved)
    {
      mark[static_cast<std::size_t>(m.first)] = 0;
    }
    keepTrianglesFacingOut(
      this->Result.MovedPoints, around, [this](Id id) { return this->positionOf(id); },
      [this](Id id) { return this->normalOf(id); });
  }

  const PreparedMesh& Mesh;
  const ViewGeometry& View;
  const SmoothingParameters& Parameters;
  const SamplingParameters& Sampling;
  int SampleCap = 0; // applySampleBudget
  std::atomic<bool> SampleCapBit{ false };
  const ParallelFor& For;
  std::vector<double> G;
  std::size_t Culled = 0; // silhouette triangles outside the frustum
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
  std::vector<Id> StraightFeatures;
  std::vector<Id> Pinned;
};

} // namespace

SmoothingResult smoothSilhouettes(const PreparedMesh& mesh, const ViewGeometry& view,
  const SmoothingParameters& parameters, const ParallelFor& parallelFor)
{
  return SilhouettePass(mesh, view, parameters, parallelFor).run();
}

void assembleTriangles(const PreparedMesh& mesh, const SmoothingResult& result,
  std::vector<Triangle>& triangles, std::vector<Id>& sourceTriangle,
  std::vector<unsigned char>& isNew)
{
  triangles.clear();
  sourceTriangle.clear();
  isNew.clear();
  std::size_t next = 0;
  const std::vector<Triangle>& input = mesh.triangles();
  for (std::size_t t = 0; t < input.size(); ++t)
  {
    if (next < result.RemeshedTriangles.size() &&
      result.RemeshedTriangles[next] == static_cast<Id>(t))
    {
      for (std::size_t r = result.ReplacementOffsets[next]; r < result.ReplacementOffsets[next + 1];
           ++r)
      {
        triangles.push_back(result.Replacements[r]);
        sourceTriangle.push_back(static_cast<Id>(t));
        isNew.push_back(static_cast<unsigned char>(result.RemeshKinds[next]));
      }
      ++next;
      continue;
    }
    triangles.push_back(input[t]);
    sourceTriangle.push_back(static_cast<Id>(t));
    isNew.push_back(0);
  }
}

} // namespace silsmooth
