#include "SilhouettePass.h"

#include "DisjointSets.h"
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

void SilhouettePass::findSilhouetteTriangles()
{
  const PreparedMesh::IndexBuild build = this->Parameters.IndexesInBackground
    ? PreparedMesh::IndexBuild::Background
    : PreparedMesh::IndexBuild::InCall;
  if (!(this->Parameters.SilhouetteTriangleHierarchy &&
        this->Mesh.findSilhouetteTriangles(this->View, this->For, this->Silhouette, build)))
  {
    this->G = vertexVisibility(this->Mesh, this->View, this->Parameters.Visibility, this->For);
    this->scanForSilhouetteTriangles();
  }
  if (this->Parameters.CullOutsideFrustum)
  {
    this->cullOutsideFrustum();
  }
  if (this->Parameters.FrozenTriangles)
  {
    // SkipSubpixelSmoothing never leaves whole a strip that runs on into
    // another piece's triangles (that piece decides its part by its own
    // strip): the mixed sides of the frozen silhouette triangles mark it.
    if (this->Parameters.SkipSubpixelSmoothing)
    {
      const EdgeTable& edges = this->Mesh.edges();
      for (const Id t : this->Silhouette)
      {
        for (int k = 0; k < 3 && this->isFrozen(t); ++k)
        {
          const Id e = edges.sideEdge(t, k);
          if (this->isMixed(edges.edge(e)))
          {
            this->FrozenMixedEdges.push_back(e);
          }
        }
      }
      std::sort(this->FrozenMixedEdges.begin(), this->FrozenMixedEdges.end());
    }
    this->Silhouette.erase(std::remove_if(this->Silhouette.begin(), this->Silhouette.end(),
                             [this](Id t) { return this->isFrozen(t); }),
      this->Silhouette.end());
  }
}

// Every triangle, with G of every point.
void SilhouettePass::scanForSilhouetteTriangles()
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
}

// SmoothingParameters::CullOutsideFrustum: planes in model coordinates
// from the rows of ModelToClip (w + x >= 0, w - x >= 0, and so for y and
// z), scaled so that they give distances in model units.
void SilhouettePass::cullOutsideFrustum()
{
  const std::size_t before = this->Silhouette.size();
  this->Silhouette.erase(std::remove_if(this->Silhouette.begin(), this->Silhouette.end(),
                           [this](Id t) { return this->beyondFrustum(t); }),
    this->Silhouette.end());
  this->Culled = before - this->Silhouette.size();
}

void SilhouettePass::makeFrustumPlanes()
{
  const ViewGeometry& v = this->View;
  this->FrustumPlanes = { { v.clipRow(3) + v.clipRow(0), v.clipRow(3) - v.clipRow(0),
    v.clipRow(3) + v.clipRow(1), v.clipRow(3) - v.clipRow(1), v.clipRow(3) + v.clipRow(2),
    v.clipRow(3) - v.clipRow(2) } };
  for (glm::dvec4& plane : this->FrustumPlanes)
  {
    const double length = glm::length(glm::dvec3(plane));
    plane = length > 0.0 && std::isfinite(length) ? plane / length : glm::dvec4(0.0);
  }
}

bool SilhouettePass::beyondFrustum(Id t) const
{
  const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(t)];
  const std::vector<glm::dvec3>& points = this->Mesh.points();
  const glm::dvec3& a = points[static_cast<std::size_t>(tri[0])];
  const glm::dvec3& b = points[static_cast<std::size_t>(tri[1])];
  const glm::dvec3& c = points[static_cast<std::size_t>(tri[2])];
  const double margin = std::max({ glm::length(b - a), glm::length(c - b), glm::length(a - c) });
  for (const glm::dvec4& plane : this->FrustumPlanes)
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
}

// On a cone the normal is constant along each line from the apex, so an
// edge from an apex is all front-facing or all back-facing, as its two
// triangles are, unless they face opposite ways: then the edge is the
// outline, which runs through the apex. The vertices' normals make the edge
// mixed anyway (the apex's one normal is the axis; the far end's may be
// blended with a base's across a rim not found as a crease), and the
// crossing they give falls anywhere along it: the outline stopped short of
// the tip, or ran round the far side. The crossing is put at the end whose
// vertex disagrees with the triangles: the apex, unless the far end does.
// Returns the apex's vertex, the far end's, or -1 for another edge.
Id SilhouettePass::apexEdgeCrossing(Id e, const std::vector<std::pair<Id, Id>>& apexSides) const
{
  auto it = std::lower_bound(apexSides.begin(), apexSides.end(), std::make_pair(e, Id{ 0 }));
  if (it == apexSides.end() || it->first != e)
  {
    return -1;
  }
  const Edge& edge = this->Mesh.edges().edge(e);
  const bool lowIsApex = this->Mesh.isApex(edge.low);
  const Id apex = lowIsApex ? edge.low : edge.high;
  const Id far = lowIsApex ? edge.high : edge.low;
  const auto& points = this->Mesh.points();
  const glm::dvec3& farPoint = points[static_cast<std::size_t>(far)];
  int front = 0;
  int back = 0;
  for (; it != apexSides.end() && it->first == e; ++it)
  {
    const glm::dvec3 face =
      areaVector(points, this->Mesh.triangles()[static_cast<std::size_t>(it->second)]);
    ++(isVisible(this->View.visibility(farPoint, face)) ? front : back);
  }
  const bool bothWays = front > 0 && back > 0;
  return bothWays || this->visibleAt(far) == (front > 0) ? apex : far;
}

// One silhouette point per mixed edge, in ascending edge order, so both
// triangles of an edge use the same point (the crack-free rule). On a feature edge
// the silhouette bridge is the edge's feature segment (III-D, case (a)).
void SilhouettePass::computeSilhouettePoints()
{
  const EdgeTable& edges = this->Mesh.edges();
  const bool apexes = this->Parameters.KeepApexesPointed && !this->Mesh.apexes().empty();
  std::vector<Id> mixedEdges;
  std::vector<std::pair<Id, Id>> apexSides; // (mixed edge from an apex, triangle)
  const bool subpixelPoints = this->Parameters.SilhouettePolylines;
  for (const Id t : this->Silhouette)
  {
    if (!subpixelPoints && !this->Subpixel.empty() && this->isSubpixel(t))
    {
      continue; // kept whole, and no polyline wants its points
    }
    for (int k = 0; k < 3; ++k)
    {
      const Id e = edges.sideEdge(t, k);
      const Edge& edge = edges.edge(e);
      if (this->isMixed(edge))
      {
        mixedEdges.push_back(e);
        if (apexes && this->Mesh.isApex(edge.low) != this->Mesh.isApex(edge.high))
        {
          apexSides.emplace_back(e, t);
        }
      }
    }
  }
  std::sort(mixedEdges.begin(), mixedEdges.end());
  mixedEdges.erase(std::unique(mixedEdges.begin(), mixedEdges.end()), mixedEdges.end());
  std::sort(apexSides.begin(), apexSides.end());

  const auto& points = this->Mesh.points();
  const auto& normals = this->Mesh.normals();
  const Id pointCount = static_cast<Id>(points.size());
  this->EdgePoints.reserve(mixedEdges.size());
  for (const Id e : mixedEdges)
  {
    const Edge& edge = edges.edge(e);
    std::size_t a = 0;
    std::size_t b = 0;
    double t = this->crossingParameter(edge, a, b);
    const bool lowFirst = a == static_cast<std::size_t>(edge.low);
    NewPoint p;
    const Id feature = this->Mesh.edgeFeature(e);
    const Id crossing =
      feature < 0 && !this->mayBeSeam(e) ? this->apexEdgeCrossing(e, apexSides) : Id{ -1 };
    if (crossing >= 0)
    {
      t = crossing == static_cast<Id>(a) ? EdgeParameterMargin : 1.0 - EdgeParameterMargin;
    }
    if (feature >= 0)
    {
      const bool forward =
        this->Mesh.sourcePoint(static_cast<Id>(a)) == this->Mesh.features().edges()[feature].first;
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
    p.Normal = this->edgeNormal(a, b, t);
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

double SilhouettePass::crossingParameter(const Edge& edge, std::size_t& a, std::size_t& b) const
{
  const auto& points = this->Mesh.points();
  const auto& normals = this->Mesh.normals();
  const std::size_t lo = static_cast<std::size_t>(edge.low);
  const std::size_t hi = static_cast<std::size_t>(edge.high);
  const bool lowFirst = std::make_tuple(points[lo].x, points[lo].y, points[lo].z, lo) <
    std::make_tuple(points[hi].x, points[hi].y, points[hi].z, hi);
  a = lowFirst ? lo : hi;
  b = lowFirst ? hi : lo;
  const VisibilityQuadratic h = visibilityAlongEdge(normals[a],
    this->View.towardViewerFrom(points[a]), normals[b], this->View.towardViewerFrom(points[b]));
  // G holds only signs for hierarchically decided vertices: the values here.
  return std::clamp(silhouetteParameter(h, this->View.visibility(points[a], normals[a]),
                      this->View.visibility(points[b], normals[b])),
    EdgeParameterMargin, 1.0 - EdgeParameterMargin);
}

// A triangle is a candidate when it is smoothed like any other (no feature
// or seam side, not at an apex: those keep their own rules) and its
// smoothing stays within the tolerance. A re-meshed silhouette triangle
// splits both its mixed sides at its silhouette points, so the triangles
// across must be re-meshed too, or the output has a T-junction there:
// candidates stay whole only where every silhouette triangle joined to them
// through mixed sides (their strip of the silhouette, usually one loop of
// the outline) is a candidate, and then all their silhouette points sit on
// the straight edges (for the silhouette's polylines). A strip with one
// triangle beyond the tolerance is smoothed whole, as without the option.
// A strip smoothed in the frame before (SmoothingParameters::SubpixelBefore)
// must keep within SubpixelEntryFraction of the tolerance to be left whole:
// without that margin an outline near the tolerance blinked between the two.
void SilhouettePass::skipSubpixelSmoothing()
{
  this->Subpixel.clear();
  if (!this->Parameters.SkipSubpixelSmoothing || this->Silhouette.empty())
  {
    return;
  }
  // The mixed sides, and each mixed edge's silhouette point (computed once
  // for the two triangles of the edge). Reading a triangle's sides and their
  // ends' visibility is a cache miss each on a large mesh: on threads.
  const EdgeTable& edges = this->Mesh.edges();
  const std::size_t count = this->Silhouette.size();
  std::vector<TriangleSides> ownSides(count);
  this->For(count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Id e = edges.sideEdge(this->Silhouette[i], k);
        ownSides[i].Edges[k] = e;
        ownSides[i].Mixed[k] = this->isMixed(edges.edge(e));
      }
    }
  });
  std::vector<std::pair<Id, std::size_t>> sides; // (mixed edge, entry of Silhouette)
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (ownSides[i].Mixed[k])
      {
        sides.emplace_back(ownSides[i].Edges[k], i);
      }
    }
  }
  std::sort(sides.begin(), sides.end());
  std::vector<CurvedCrossing> crossings;
  for (const auto& side : sides)
  {
    if (crossings.empty() || crossings.back().Edge != side.first)
    {
      crossings.push_back({ side.first, {}, {}, 0.0 });
    }
  }
  this->For(crossings.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
    {
      this->curvedCrossing(crossings[c]);
    }
  });
  // 2: within SubpixelEntryFraction of the tolerance (a strip of them is
  // left whole); 1: within the tolerance (left whole unless the strip was
  // smoothed before); 0: neither.
  const double tolerance = this->Sampling.TolerancePixels;
  std::vector<unsigned char> candidate(count, 0);
  this->For(count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      const double shift = this->smoothingShiftPixels(this->Silhouette[i], ownSides[i], crossings);
      candidate[i] = shift <= SubpixelEntryFraction * tolerance ? 2 : (shift <= tolerance ? 1 : 0);
    }
  });
  // The strips: silhouette triangles joined through the mixed sides they share.
  DisjointSets strips(count);
  for (std::size_t s = 1; s < sides.size(); ++s)
  {
    if (sides[s].first == sides[s - 1].first)
    {
      strips.unite(sides[s].second, sides[s - 1].second);
    }
  }
  // By root: the least level of the strip's triangles, and whether one of
  // them was left whole, or re-meshed, in the frame before.
  std::vector<unsigned char> least(count, 2);
  std::vector<unsigned char> wholeBefore(count, 0);
  std::vector<unsigned char> smoothedBefore(count, 0);
  const auto listed = [](const std::vector<Id>* ids, Id t) {
    return ids && std::binary_search(ids->begin(), ids->end(), t);
  };
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::size_t root = strips.find(i);
    least[root] = std::min(least[root], candidate[i]);
    wholeBefore[root] |= listed(this->Parameters.SubpixelBefore, this->Silhouette[i]) ? 1 : 0;
    smoothedBefore[root] |= listed(this->Parameters.RemeshedBefore, this->Silhouette[i]) ? 1 : 0;
  }
  std::vector<unsigned char> stripOfCandidates(count, 0); // by root
  for (std::size_t i = 0; i < count; ++i)
  {
    stripOfCandidates[i] =
      least[i] == 2 || (least[i] == 1 && (wholeBefore[i] || !smoothedBefore[i])) ? 1 : 0;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (stripOfCandidates[strips.find(i)])
    {
      this->Subpixel.push_back(this->Silhouette[i]); // ascending, as Silhouette is
    }
  }
  if (this->Subpixel.empty() || !this->Parameters.SilhouettePolylines)
  {
    return; // without polylines, their silhouette points are not made at all
  }
  std::vector<Id> straight = this->StraightEdges;
  for (const auto& side : sides)
  {
    if (stripOfCandidates[strips.find(side.second)])
    {
      straight.push_back(side.first);
    }
  }
  std::sort(straight.begin(), straight.end());
  straight.erase(std::unique(straight.begin(), straight.end()), straight.end());
  this->StraightEdges = std::move(straight);
}

// A curved feature segment is drawn by its chord in this frame when its
// curve moves no point of its sides' triangles by more than the tolerance
// in the image: re-meshing puts the samples at C(u) where the flat side has
// the chord's point at u, so no point of a side triangle moves farther than
// the curve's parametricDeviationBound (HermiteCurve.h). The decision is
// the segment's, so every side of the crease makes it alike (their shared
// edge stays whole or is split at the same samples). A segment on a
// boundary that may be a seam, or with a side in another piece (frozen), is
// always smoothed: the other piece sees other triangles. A segment drawn curved in the frame before
// (SmoothingParameters::SubpixelFeaturesBefore) needs SubpixelEntryFraction
// of the tolerance, as a strip of the silhouette does. With
// CullOutsideFrustum, a side that the view cannot show (beyondFrustum)
// needs no bound: a segment whose every side lies outside the view is drawn
// by its chord too (close to a finely divided part, segments passing by the
// eye wanted hundreds of samples each).
void SilhouettePass::skipSubpixelFeatures()
{
  this->SubpixelFeatures.clear();
  this->CurvedFeatureTriangles.clear();
  if (!this->Parameters.SkipSubpixelSmoothing || this->Mesh.featureTriangles().empty())
  {
    return;
  }
  const FeatureCurves& features = this->Mesh.features();
  const auto& sides = this->Mesh.featureSideTriangles();
  const auto& points = this->Mesh.points();
  const EdgeTable& edges = this->Mesh.edges();
  const std::vector<Id>* before = this->Parameters.SubpixelFeaturesBefore;
  const double tolerance = this->Sampling.TolerancePixels;
  const bool culling = this->Parameters.CullOutsideFrustum;
  std::vector<unsigned char> straight(features.edges().size(), 0);
  this->For(straight.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      const Id f = static_cast<Id>(i);
      if (!features.isCurved(f))
      {
        continue;
      }
      const double moved = parametricDeviationBound(features.curve(f));
      const bool wasStraight = !before || std::binary_search(before->begin(), before->end(), f);
      const double limit = wasStraight ? tolerance : SubpixelEntryFraction * tolerance;
      bool within = true;
      for (auto it = std::lower_bound(sides.begin(), sides.end(), std::make_pair(f, Id{ 0 }));
           within && it != sides.end() && it->first == f; ++it)
      {
        const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(it->second)];
        within = !this->isFrozen(it->second); // the other piece's side decides there
        if (within && culling && this->beyondFrustum(it->second))
        {
          continue; // the view cannot show it, nor its curve (cullOutsideFrustum's margin)
        }
        for (int k = 0; k < 3 && within; ++k)
        {
          const Id e = edges.sideEdge(it->second, k);
          within = !(this->Mesh.edgeFeature(e) == f && this->mayBeSeam(e));
        }
        within = within &&
          this->View.pixelShiftBound(points[static_cast<std::size_t>(tri[0])],
            points[static_cast<std::size_t>(tri[1])], points[static_cast<std::size_t>(tri[2])],
            moved) <= limit;
      }
      straight[i] = within ? 1 : 0;
    }
  });
  for (std::size_t f = 0; f < straight.size(); ++f)
  {
    if (straight[f])
    {
      this->SubpixelFeatures.push_back(static_cast<Id>(f));
    }
  }
  if (this->SubpixelFeatures.empty())
  {
    return;
  }
  for (const auto& side : sides)
  {
    if (features.isCurved(side.first) && !straight[static_cast<std::size_t>(side.first)])
    {
      this->CurvedFeatureTriangles.push_back(side.second);
    }
  }
  std::sort(this->CurvedFeatureTriangles.begin(), this->CurvedFeatureTriangles.end());
  this->CurvedFeatureTriangles.erase(
    std::unique(this->CurvedFeatureTriangles.begin(), this->CurvedFeatureTriangles.end()),
    this->CurvedFeatureTriangles.end());
}

void SilhouettePass::curvedCrossing(CurvedCrossing& crossing) const
{
  const auto& points = this->Mesh.points();
  const auto& normals = this->Mesh.normals();
  std::size_t a = 0;
  std::size_t b = 0;
  const double u = this->crossingParameter(this->Mesh.edges().edge(crossing.Edge), a, b);
  crossing.Position =
    makeCircleApproximatingCurve(points[a], normals[a], points[b], normals[b]).evaluate(u);
  crossing.Moved = glm::length(crossing.Position - ((1.0 - u) * points[a] + u * points[b]));
  crossing.Normal = this->edgeNormal(a, b, u);
}

glm::dvec3 SilhouettePass::edgeNormal(std::size_t a, std::size_t b, double t) const
{
  const auto& normals = this->Mesh.normals();
  const glm::dvec3 normal = safeNormalize((1.0 - t) * normals[a] + t * normals[b]);
  // Opposite normals at the ends: no interpolated direction exists.
  return normal != glm::dvec3(0.0) ? normal : (t < 0.5 ? normals[a] : normals[b]);
}

double SilhouettePass::smoothingShiftPixels(
  Id t, const TriangleSides& sides, const std::vector<CurvedCrossing>& crossings) const
{
  constexpr double never = HUGE_VAL;
  const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(t)];
  if (hasRepeatedCorner(tri) || this->levelOf(t) != 0)
  {
    return never; // an apex's (straight already), or no interior
  }
  const CurvedCrossing* at[2] = { nullptr, nullptr };
  for (int k = 0; k < 3; ++k)
  {
    const Id e = sides.Edges[k];
    if (this->Mesh.edgeFeature(e) >= 0 || this->mayBeSeam(e) ||
      (!this->FrozenMixedEdges.empty() &&
        std::binary_search(this->FrozenMixedEdges.begin(), this->FrozenMixedEdges.end(), e)))
    {
      return never;
    }
    if (sides.Mixed[k])
    {
      const auto found = std::lower_bound(crossings.begin(), crossings.end(), e,
        [](const CurvedCrossing& c, Id edge) { return c.Edge < edge; });
      at[at[0] ? 1 : 0] = &*found; // every mixed side's edge is there
    }
  }
  if (!at[0] || !at[1])
  {
    return never;
  }
  // The segment's samples sit on the chord between the flat points: each
  // moves by its slide off the chord between the lifted points plus the
  // lifted points' own moves, interpolated.
  const double moved = std::max(at[0]->Moved, at[1]->Moved) +
    parametricDeviationBound(
      makeCircleApproximatingCurve(at[0]->Position, at[0]->Normal, at[1]->Position, at[1]->Normal));
  const auto& points = this->Mesh.points();
  return this->View.pixelShiftBound(points[static_cast<std::size_t>(tri[0])],
    points[static_cast<std::size_t>(tri[1])], points[static_cast<std::size_t>(tri[2])], moved);
}

// The triangles re-meshed for their feature sides in this frame: those
// with a smoothed (curved) feature side, every frame, and those with a side
// on a straight feature edge that the silhouette crosses, from any side of
// the crease: each side has its own normals, so the silhouette may cross
// the crease on one side only, and the others must still split the edge at
// that point (or the output has a T-junction there).
const std::vector<Id>& SilhouettePass::featureTrianglesOfFrame()
{
  const std::vector<Id>& curved =
    this->SubpixelFeatures.empty() ? this->Mesh.featureTriangles() : this->CurvedFeatureTriangles;
  std::vector<Id> straight;
  for (const FeatureSilhouettePoint& point : this->FeatureSilhouettePoints)
  {
    if (this->Mesh.features().isCurved(point.Feature) && !this->isSubpixelFeature(point.Feature))
    {
      continue;
    }
    const auto& sides = this->Mesh.featureSideTriangles();
    auto it = std::lower_bound(sides.begin(), sides.end(), std::make_pair(point.Feature, Id{ 0 }));
    for (; it != sides.end() && it->first == point.Feature; ++it)
    {
      straight.push_back(it->second);
    }
  }
  if (straight.empty())
  {
    return curved;
  }
  std::sort(straight.begin(), straight.end());
  this->FrameFeatureTriangles.clear();
  std::set_union(curved.begin(), curved.end(), straight.begin(), straight.end(),
    std::back_inserter(this->FrameFeatureTriangles));
  this->FrameFeatureTriangles.erase(
    std::unique(this->FrameFeatureTriangles.begin(), this->FrameFeatureTriangles.end()),
    this->FrameFeatureTriangles.end());
  return this->FrameFeatureTriangles;
}

// SmoothingParameters::MaximumSampledPoints: when the samples the frame's
// segments want (its re-meshed silhouette triangles' and its curved feature
// segments', as FeatureSampleCounts holds them uncapped) would add more
// interior points than the budget, the largest cap on a segment's samples
// that keeps them within it (segments wanting fewer keep theirs, and leave
// their share to the others); 0 for no cap. Feature counts are capped here,
// silhouette segments as they are sampled (sampleCount).
void SilhouettePass::applySampleBudget()
{
  const std::size_t budget = this->Parameters.MaximumSampledPoints;
  if (budget == 0)
  {
    return;
  }
  // Quick way out: every segment at its most fits.
  const std::size_t segments = this->Silhouette.size() - this->Subpixel.size() +
    this->Mesh.features().curvedCount() -
    std::min(this->SubpixelFeatures.size(), this->Mesh.features().curvedCount());
  const std::size_t most =
    static_cast<std::size_t>(std::max(this->Parameters.Sampling.MaximumSamples - 2, 0));
  if (segments == 0 || segments <= budget / std::max<std::size_t>(most, 1))
  {
    return;
  }
  std::vector<int> wanted; // samples per segment, both ends counted
  wanted.reserve(segments);
  for (const int count : this->FeatureSampleCounts)
  {
    if (count > 2)
    {
      wanted.push_back(count);
    }
  }
  for (const Id t : this->Silhouette)
  {
    if ((!this->Subpixel.empty() && this->isSubpixel(t)) || this->levelOf(t) >= ChordLevel)
    {
      continue;
    }
    int lone = 0;
    const std::array<Id, 3> corners = this->cornersFromLone(t, lone);
    const auto [p, q] = this->silhouettePointsOf(t, lone, corners);
    if (p.Point == q.Point)
    {
      continue;
    }
    glm::dvec3 nP;
    glm::dvec3 nQ;
    const HermiteCurve segment = this->silhouetteSegment(p.Point, q.Point, nP, nQ);
    wanted.push_back(silhouetteSampleCount(segment, nP, nQ, this->View, this->Sampling));
  }
  const auto interior = [&wanted](int cap) {
    std::size_t sum = 0;
    for (const int w : wanted)
    {
      sum += static_cast<std::size_t>(std::max(0, std::min(w, cap) - 2));
    }
    return sum;
  };
  int high = 2;
  for (const int w : wanted)
  {
    high = std::max(high, w);
  }
  if (interior(high) <= budget)
  {
    return;
  }
  int low = 2; // fits: no interior samples
  while (high - low > 1)
  {
    const int middle = low + (high - low) / 2;
    (interior(middle) <= budget ? low : high) = middle;
  }
  this->SampleCap = low;
  for (int& count : this->FeatureSampleCounts)
  {
    if (count > this->SampleCap)
    {
      count = this->SampleCap;
      this->SampleCapBit = true;
    }
  }
}

// Points per smoothed feature segment in this view (both ends counted), by
// the same rule as silhouette segments. Both sides of a crease use the
// segment's one count, so their samples coincide. Straight ones keep 2.
void SilhouettePass::countFeatureSamples()
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

} // namespace detail
} // namespace silsmooth
