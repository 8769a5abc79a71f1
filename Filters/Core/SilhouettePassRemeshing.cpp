#include "SilhouettePass.h"

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
namespace detail
{

// Samples the silhouette segment from P to Q across the triangle with
// corners (a, b, c), a the lone one, adding its interior samples as new
// points; records it if concave. P and Q are given with their barycentric
// positions in (a, b, c); the samples lie on the chord between them there.
std::vector<PolygonPoint> SilhouettePass::sampleSilhouetteSegment(
  Id t, const std::array<Id, 3>& corners, const PolygonPoint& p, const PolygonPoint& q)
{
  std::vector<PolygonPoint> interior;
  if (p.Point == q.Point)
  {
    return interior;
  }
  glm::dvec3 nP;
  glm::dvec3 nQ;
  const HermiteCurve segment = this->silhouetteSegment(p.Point, q.Point, nP, nQ);
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
std::pair<PolygonPoint, PolygonPoint> SilhouettePass::silhouettePointsOf(
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

void SilhouettePass::remeshTriangle(Id t, std::vector<std::vector<Id>>& segments)
{
  int lone = 0;
  const std::array<Id, 3> corners = this->cornersFromLone(t, lone);
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

void SilhouettePass::addSubpixelSegment(Id t, std::vector<std::vector<Id>>& segments) const
{
  int lone = 0;
  const std::array<Id, 3> corners = this->cornersFromLone(t, lone);
  const auto [p, q] = this->silhouettePointsOf(t, lone, corners);
  if (p.Point != q.Point)
  {
    segments.push_back({ p.Point, q.Point });
  }
}

// The points inside the feature segment on edge e, made once per frame and
// shared by the edge's triangles, as (parameter along the segment, point id):
// its samples, and the silhouette points that the other sides of the crease
// have on the same segment (copies with this side's normal), so that both
// sides split the curve at the same points (no crack, no T-junction).
const std::vector<std::pair<double, Id>>& SilhouettePass::featureSamples(Id e)
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
void SilhouettePass::remeshWithFeatures(
  Id t, bool silhouette, std::vector<std::vector<Id>>& segments)
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
    std::stable_sort(
      inside.begin(), inside.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
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

void SilhouettePass::fanPolygon(
  const std::array<Id, 3>& corners, const std::vector<PolygonPoint>& polygon)
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

} // namespace detail
} // namespace silsmooth
