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

SmoothingResult SilhouettePass::run()
{
  if (this->Parameters.CullOutsideFrustum)
  {
    this->makeFrustumPlanes();
  }
  this->findSilhouetteTriangles();
  this->straightenAtApexes();
  this->skipSubpixelSmoothing();
  this->skipSubpixelFeatures();
  this->PresetStraightEdges = this->StraightEdges.size();
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
        if (b == moved.size() || (a < movedBefore.size() && movedBefore[a].first < moved[b].first))
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
      this->Result.UnresolvedFolds = findings.Turned + findings.Cutting + findings.Crowded;
      this->Result.FoldGuardRounds = round;
      break;
    }
  }
  if (this->Parameters.PreventFolds)
  {
    this->listFallbacks();
  }
  this->Result.ReusedFallbacks = this->ReusedFallbacks;
  this->Result.PinnedPoints = this->Pinned.size();
  this->Result.CulledTriangles = this->Culled;
  this->Result.StraightSilhouettePoints = this->StraightEdges.size() - this->PresetStraightEdges;
  this->Result.StraightFeatureSegments = this->StraightFeatures.size();
  for (const auto& level : this->Levels)
  {
    this->Result.ChordFallbackTriangles += level.second >= ChordLevel ? 1 : 0;
  }
  this->Result.ApexTriangles = this->ApexTriangles;
  this->Result.CrowdedTriangles = this->CrowdedTriangles;
  this->Result.ChordFallbackTriangles -= this->ApexTriangles;
  return std::move(this->Result);
}

// A silhouette triangle with an apex corner (PreparedMesh::apexes) keeps
// the silhouette on its own edges and chords from the start: the curves
// through the apex's one normal would round the cone into a dome. Points on
// feature curves and seams stay where the other sides put them, as for the
// fold guard's fallback.
void SilhouettePass::straightenAtApexes()
{
  if (!this->Parameters.KeepApexesPointed || this->Mesh.apexes().empty())
  {
    return;
  }
  for (const Id t : this->Silhouette)
  {
    if (!this->hasApexCorner(t))
    {
      continue;
    }
    this->Levels[t] = StraightLevel;
    ++this->ApexTriangles;
    this->straightSidesOf(t, this->StraightEdges);
  }
  std::sort(this->StraightEdges.begin(), this->StraightEdges.end());
  this->StraightEdges.erase(
    std::unique(this->StraightEdges.begin(), this->StraightEdges.end()), this->StraightEdges.end());
}

bool SilhouettePass::hasApexCorner(Id t) const
{
  const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(t)];
  return this->Mesh.isApex(tri[0]) || this->Mesh.isApex(tri[1]) || this->Mesh.isApex(tri[2]);
}

void SilhouettePass::straightSidesOf(Id t, std::vector<Id>& edges) const
{
  const EdgeTable& table = this->Mesh.edges();
  for (int k = 0; k < 3; ++k)
  {
    const Id e = table.sideEdge(t, k);
    if (this->isMixed(table.edge(e)) && this->Mesh.edgeFeature(e) < 0 && !this->mayBeSeam(e))
    {
      edges.push_back(e);
    }
  }
}

unsigned char SilhouettePass::rememberedLevel(Id t) const
{
  const FoldFallbacks* before = this->Parameters.FallbacksBefore;
  if (!before)
  {
    return 0;
  }
  const auto it = std::lower_bound(before->Triangles.begin(), before->Triangles.end(),
    std::make_pair(t, static_cast<unsigned char>(0)));
  return it != before->Triangles.end() && it->first == t && it->second <= StraightLevel ? it->second
                                                                                        : 0;
}

bool SilhouettePass::rememberedStraight(Id f) const
{
  const FoldFallbacks* before = this->Parameters.FallbacksBefore;
  return before &&
    std::binary_search(before->FeatureSegments.begin(), before->FeatureSegments.end(), f);
}

template<typename Accept>
bool SilhouettePass::straightenSideFeatures(Id t, std::vector<Id>& changed, Accept straighten)
{
  const EdgeTable& edges = this->Mesh.edges();
  bool taken = false;
  for (int k = 0; k < 3; ++k)
  {
    const Id e = edges.sideEdge(t, k);
    const Id f = this->Mesh.edgeFeature(e);
    if (f >= 0 && this->Mesh.features().isCurved(f) && !this->isStraightened(f) &&
      !this->mayBeSeam(e) && straighten(f))
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
  return taken;
}

// Every fallback in force but those at apexes (straightenAtApexes): their
// level is not one a fold asked for, and a next frame with
// KeepApexesPointed off would reuse it.
void SilhouettePass::listFallbacks()
{
  FoldFallbacks& out = this->Result.Fallbacks;
  const bool apexes = this->Parameters.KeepApexesPointed && !this->Mesh.apexes().empty();
  for (const auto& level : this->Levels)
  {
    if (!apexes || !this->hasApexCorner(level.first))
    {
      out.Triangles.push_back(level);
    }
  }
  std::sort(out.Triangles.begin(), out.Triangles.end());
  out.FeatureSegments = this->StraightFeatures;
}

void SilhouettePass::remeshFrame()
{
  this->EdgePoints.clear();
  this->FeatureSilhouettePoints.clear();
  this->FeatureSamplePoints.clear();
  this->FrameFeatureTriangles.clear();
  this->Concave.clear();
  this->Result = SmoothingResult();
  this->computeSilhouettePoints();
  this->SampleCap = 0; // the counts wanted first, then the budget's cap
  this->SampleCapBit = false;
  this->countFeatureSamples();
  this->applySampleBudget();
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
    if (silhouette && !feature && !this->Subpixel.empty() && this->isSubpixel(t))
    {
      if (this->Parameters.SilhouettePolylines)
      {
        this->addSubpixelSegment(t, segments);
      }
      continue;
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
  this->Result.SilhouetteTriangleCount = this->Silhouette.size() - this->Subpixel.size();
  this->Result.SubpixelTriangles = this->Subpixel.size();
  this->Result.SubpixelTriangleIds = this->Subpixel;
  this->Result.SubpixelFeatureIds = this->SubpixelFeatures;
  this->Result.SampleBudgetMaximum = this->SampleCapBit ? this->SampleCap : 0;
  if (this->Parameters.SilhouettePolylines)
  {
    this->Result.Polylines = chainSegments(segments);
  }
  this->Result.ConcaveSegmentCount = this->Concave.size();
  if (this->Parameters.PerturbConcaveSilhouettes && !this->Concave.empty())
  {
    this->Result.MovedPoints =
      perturbVerticesBelowConcaveSegments(this->Concave, this->Mesh.points(), this->Mesh.normals(),
        this->Mesh.triangles(), this->Mesh.neighbourOffsets(), this->Mesh.neighbours());
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

FoldFindings SilhouettePass::findFrameFolds(
  const std::vector<Id>* checkSources, const std::vector<Id>* checkPoints)
{
  if (!this->FoldGridAsked)
  {
    this->FoldGrid = this->Mesh.foldGuardGridForFrame(this->Parameters.IndexesInBackground
        ? PreparedMesh::IndexBuild::Background
        : PreparedMesh::IndexBuild::InCall);
    this->FoldGridAsked = true;
  }
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
    this->FoldGrid, this->FoldGrid ? this->Mesh.triangleGridSlack() : 0.0 };
  const FoldGuardFrame frame{ this->Result.RemeshedTriangles, this->Result.ReplacementOffsets,
    this->Result.Replacements, positions, normals, this->Result.MovedPoints, checkSources,
    checkPoints };
  return findFolds(mesh, frame, this->For);
}

// Raises the fallback level of every folding silhouette triangle and pins
// every folding moved point; false when none could be taken. `changed`
// gets the input triangles that the next round must check again
// (ascending): the folding ones, and those it re-meshes differently.
bool SilhouettePass::takeFallbacks(const FoldFindings& findings, std::vector<Id>& changed)
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
    const bool silhouette = std::binary_search(this->Silhouette.begin(), this->Silhouette.end(), t);
    if (!silhouette || this->levelOf(t) >= StraightLevel)
    {
      // Last: its curved feature segments become their chords, on every
      // side of their creases.
      taken |= this->straightenSideFeatures(t, changed, [](Id) { return true; });
      continue;
    }
    unsigned char& level = this->Levels[t];
    // Untested (crowded) ones go straight at once: only that needs no test.
    // One that needed a higher level in the frame before goes there at once,
    // with the feature segments beside it that were straight there.
    const bool crowded = findings.FoldingRemeshed[i] == 2;
    this->CrowdedTriangles += crowded ? 1 : 0;
    const unsigned char next = crowded ? StraightLevel : static_cast<unsigned char>(level + 1);
    const unsigned char remembered = this->rememberedLevel(t);
    this->ReusedFallbacks += remembered > next ? 1 : 0;
    level = std::max(next, remembered);
    taken = true;
    if (this->Parameters.FallbacksBefore && this->straightenSideFeatures(t, changed, [this](Id f) {
          return this->rememberedStraight(f);
        }))
    {
      ++this->ReusedFallbacks;
    }
    if (level == StraightLevel)
    {
      // Its silhouette points, shared with the triangles across its mixed
      // edges; those on feature edges stay on the feature curve, which
      // the other sides of the crease sample too, and those on a seam
      // between pieces stay on the curve, which the piece across computes
      // too (it cannot know of this fallback).
      this->straightSidesOf(t, newEdges);
    }
  }
  std::sort(newEdges.begin(), newEdges.end());
  newEdges.erase(std::unique(newEdges.begin(), newEdges.end()), newEdges.end());
  newEdges.erase(std::remove_if(newEdges.begin(), newEdges.end(),
                   [this](Id e) {
                     return std::binary_search(
                       this->StraightEdges.begin(), this->StraightEdges.end(), e);
                   }),
    newEdges.end());
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

// The output triangles around the moved points (kept input triangles and
// replacements alike) must not turn over.
void SilhouettePass::keepOutputFacingOut()
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

} // namespace detail
} // namespace silsmooth
