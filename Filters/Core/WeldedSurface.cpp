#include "WeldedSurface.h"

#include "FiniteVector.h"
#include "ShadingNormals.h"
#include "SurfaceOrientation.h"
#include "SurfaceWelding.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace silsmooth
{

namespace
{

// Whether every corner of all but 1% of the triangles (of non-zero area)
// carries its triangle's own normal, either way up (within the seam angle).
bool hasFaceNormals(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
  const std::vector<glm::dvec3>& normals)
{
  const double cosLimit = std::cos(NormalSeamAngleDegrees * 3.14159265358979323846 / 180.0);
  std::size_t faces = 0;
  std::size_t flat = 0;
  for (const Triangle& t : triangles)
  {
    const glm::dvec3& a = points[static_cast<std::size_t>(t[0])];
    const glm::dvec3 face = safeNormalize(glm::cross(
      points[static_cast<std::size_t>(t[1])] - a, points[static_cast<std::size_t>(t[2])] - a));
    if (face == glm::dvec3(0.0))
    {
      continue;
    }
    ++faces;
    bool all = true;
    for (const Id p : t)
    {
      const glm::dvec3 n = safeNormalize(normals[static_cast<std::size_t>(p)]);
      all = all && std::abs(glm::dot(n, face)) >= cosLimit;
    }
    flat += all ? 1 : 0;
  }
  return faces > 0 && flat * 100 >= faces * 99;
}

} // namespace

WeldedSurface::WeldedSurface(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
  const std::vector<glm::dvec3>& normals, const std::vector<FeatureEdge>& markedFeatures,
  const SurfaceOptions& options, const ParallelFor& parallelFor)
  : InputPointCount(points.size())
  , InputTriangles(std::move(triangles))
{
  const GivenNormals given = this->weldAndOrient(points, normals, options);
  this->Prepared = this->prepareGeometry(
    std::move(points), normals, given, markedFeatures, options, this->Statistics, parallelFor);
  this->mapOutputPoints();
  this->indexOutputsByPrepared();
}

WeldedSurface::GivenNormals WeldedSurface::weldAndOrient(const std::vector<glm::dvec3>& points,
  const std::vector<glm::dvec3>& normals, const SurfaceOptions& options)
{
  const std::size_t n = this->InputPointCount;
  this->Vertex.resize(n);
  if (options.Weld)
  {
    this->Vertex = weldCoincidentPoints(points, options.WeldTolerance);
  }
  else
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      this->Vertex[i] = static_cast<Id>(i);
    }
  }
  std::vector<Triangle> welded = weldTriangles(this->InputTriangles, this->Vertex);
  // One edge table for the whole preparation: built for the welded
  // triangles, its sides turned with the triangles once they are oriented.
  EdgeTable table(welded);
  if (options.Weld && !(options.WeldTolerance > 0.0))
  {
    // Copies that differ by rounding are one point (rare: the weld and the
    // table are made again). Unwelded, they left a parametric torus's seam
    // open, reported as non-orientable, with a spike in its outline.
    const NearCopies rounding = nearCopyEdges(points, table, RoundingCopyRelative);
    if (rounding.EdgeCount > 0)
    {
      this->Statistics.RoundingCopyEdgeCount = rounding.EdgeCount;
      this->Vertex = weldCoincidentPoints(points, 2.0 * rounding.LongestEdge);
      welded = weldTriangles(this->InputTriangles, this->Vertex);
      table = EdgeTable(welded);
    }
  }
  if (options.Weld)
  {
    // Points of separate parts that only touch are one vertex no longer
    // (rare: the table is then built again).
    std::vector<Id> withinSheets = weldWithinSheets(this->InputTriangles, this->Vertex, table);
    if (withinSheets != this->Vertex)
    {
      this->Vertex = std::move(withinSheets);
      welded = weldTriangles(this->InputTriangles, this->Vertex);
      table = EdgeTable(welded);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    this->Statistics.WeldedPointCount += this->Vertex[i] != static_cast<Id>(i) ? 1 : 0;
  }
  const std::vector<unsigned char> twins = backToBackTwins(welded, table);
  this->Statistics.BackToBackTriangleCount =
    static_cast<std::size_t>(std::count(twins.begin(), twins.end(), 1));
  const NearCopies nearCopies = nearCopyEdges(points, table);
  this->Statistics.NearCopyEdgeCount = nearCopies.EdgeCount;
  this->Statistics.LongestNearCopyEdge = nearCopies.LongestEdge;
  GivenNormals given = this->examineNormals(points, normals, &welded, &table);
  std::vector<glm::dvec3> cornerNormals;
  if (given.Use)
  {
    cornerNormals.resize(welded.size() * 3);
    for (std::size_t t = 0; t < welded.size(); ++t)
    {
      for (std::size_t k = 0; k < 3; ++k)
      {
        cornerNormals[t * 3 + k] = normals[static_cast<std::size_t>(this->InputTriangles[t][k])];
      }
    }
  }

  this->Reversed.assign(welded.size(), 0);
  if (options.Orient)
  {
    Orientation orientation = orientConsistently(points, welded, cornerNormals, &table);
    this->Reversed = std::move(orientation.Reversed);
    this->Components = std::move(orientation.Component);
    this->Statistics.ReversedTriangleCount = orientation.ReversedCount;
    this->Statistics.ComponentCount = orientation.ComponentCount;
    this->Statistics.InconsistentEdgeCount = orientation.InconsistentEdgeCount;
  }
  for (std::size_t t = 0; t < welded.size(); ++t)
  {
    welded[t] = oriented(welded[t], this->Reversed[t] != 0);
  }
  if (this->Statistics.ReversedTriangleCount > 0)
  {
    table = table.withSidesReversed(this->Reversed);
  }
  this->Welded = std::move(welded);
  this->Table = std::move(table);
  this->Sides = edgeSidesOf(this->Welded, this->Table);
  return given;
}

void WeldedSurface::mapOutputPoints()
{
  const std::size_t n = this->InputPointCount;
  auto inputCorner = [this](std::size_t t, std::size_t k) -> std::size_t {
    return this->Reversed[t] && k != 0 ? 3 - k : k;
  };
  std::vector<Id>& vertex = this->Vertex;
  // Output points: each input point stands for the prepared point of its
  // first corner; a corner that falls in another prepared point (another
  // smooth group) gets a copy of its input point, one per such pair.
  const std::vector<Triangle>& prepared = this->Prepared->triangles();
  this->OutputPrepared.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    this->OutputPrepared[i] = vertex[i];
  }
  std::vector<unsigned char> claimed(n, 0);
  this->CornerOutput.assign(prepared.size() * 3, -1);
  std::map<std::pair<Id, Id>, Id> copies; // (prepared point, input point) -> output id
  std::vector<std::pair<std::size_t, std::pair<Id, Id>>> pending;
  for (std::size_t t = 0; t < prepared.size(); ++t)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t c = inputCorner(t, k);
      const Id own = this->InputTriangles[t][c];
      const Id p = prepared[t][k];
      if (!claimed[static_cast<std::size_t>(own)])
      {
        claimed[static_cast<std::size_t>(own)] = 1;
        this->OutputPrepared[static_cast<std::size_t>(own)] = p;
      }
      if (this->OutputPrepared[static_cast<std::size_t>(own)] == p)
      {
        this->CornerOutput[t * 3 + c] = own;
      }
      else
      {
        copies.emplace(std::make_pair(p, own), -1);
        pending.push_back({ t * 3 + c, { p, own } });
      }
    }
  }
  // Copies in prepared order (then input order): without welding that is the
  // prepared mesh's own order of feature copies.
  for (auto& copy : copies)
  {
    copy.second = static_cast<Id>(n + this->CopySources.size());
    this->CopySources.push_back(copy.first.second);
    this->OutputPrepared.push_back(copy.first.first);
  }
  for (const auto& corner : pending)
  {
    this->CornerOutput[corner.first] = copies.at(corner.second);
  }
  this->chooseWrittenWinding();
  // Each output point's normal agrees with the winding its triangles are
  // written in (one winding per connected part: chooseWrittenWinding).
  this->OutputNormalReversed.clear();
  if (std::find(this->Written.begin(), this->Written.end(), 1) != this->Written.end())
  {
    std::vector<long> votes(this->OutputPrepared.size(), 0);
    for (std::size_t corner = 0; corner < this->CornerOutput.size(); ++corner)
    {
      votes[static_cast<std::size_t>(this->CornerOutput[corner])] +=
        this->Written[corner / 3] ? 1 : -1;
    }
    this->OutputNormalReversed.resize(votes.size());
    for (std::size_t o = 0; o < votes.size(); ++o)
    {
      this->OutputNormalReversed[o] = votes[o] > 0 ? 1 : 0;
    }
  }
}

void WeldedSurface::chooseWrittenWinding()
{
  // Per connected part, the winding most of its triangles are written in
  // (relative to the oriented surface); a triangle in no part keeps its own.
  this->Written = this->Reversed;
  if (this->Components.empty())
  {
    return;
  }
  std::vector<long> votes;
  for (std::size_t t = 0; t < this->Reversed.size(); ++t)
  {
    const Id c = this->Components[t];
    if (c >= 0)
    {
      if (static_cast<std::size_t>(c) >= votes.size())
      {
        votes.resize(static_cast<std::size_t>(c) + 1, 0);
      }
      votes[static_cast<std::size_t>(c)] += this->Reversed[t] ? 1 : -1;
    }
  }
  for (std::size_t t = 0; t < this->Reversed.size(); ++t)
  {
    const Id c = this->Components[t];
    if (c >= 0)
    {
      this->Written[t] = votes[static_cast<std::size_t>(c)] > 0 ? 1 : 0;
    }
  }
}

void WeldedSurface::indexOutputsByPrepared()
{
  const std::size_t n = this->InputPointCount;
  const std::size_t preparedCount = this->Prepared->points().size();
  this->PreparedHome.assign(preparedCount, -1);
  std::vector<Id> degree(preparedCount + 1, 0);
  for (std::size_t o = 0; o < this->OutputPrepared.size(); ++o)
  {
    ++degree[static_cast<std::size_t>(this->OutputPrepared[o]) + 1];
  }
  for (std::size_t p = 1; p < degree.size(); ++p)
  {
    degree[p] += degree[p - 1];
  }
  this->OutputsOffsets = degree;
  this->OutputsOf.resize(this->OutputPrepared.size());
  for (std::size_t o = 0; o < this->OutputPrepared.size(); ++o)
  {
    const std::size_t p = static_cast<std::size_t>(this->OutputPrepared[o]);
    this->OutputsOf[static_cast<std::size_t>(degree[p]++)] = static_cast<Id>(o);
  }
  for (std::size_t p = 0; p < preparedCount; ++p)
  {
    // Prefer the point itself (no welding: the identity).
    const Id begin = this->OutputsOffsets[p];
    const Id end = this->OutputsOffsets[p + 1];
    for (Id k = begin; k < end; ++k)
    {
      if (this->OutputsOf[static_cast<std::size_t>(k)] == static_cast<Id>(p) ||
        this->PreparedHome[p] < 0)
      {
        this->PreparedHome[p] = this->OutputsOf[static_cast<std::size_t>(k)];
      }
    }
    if (this->PreparedHome[p] < 0)
    {
      this->PreparedHome[p] =
        p < n ? static_cast<Id>(p) : this->Prepared->sourcePoint(static_cast<Id>(p));
    }
  }
}

WeldedSurface::GivenNormals WeldedSurface::examineNormals(const std::vector<glm::dvec3>& points,
  const std::vector<glm::dvec3>& normals, const std::vector<Triangle>* welded,
  const EdgeTable* table) const
{
  // Normal seams exist only where points coincide. Flat shading: the normals
  // split along most edges, each corner carrying its triangle's own normal
  // (a fine smooth mesh has normals close to its faces' too, but no seams).
  GivenNormals given;
  const std::size_t n = this->InputPointCount;
  if (normals.size() == n && this->Statistics.WeldedPointCount > 0)
  {
    std::size_t interior = 0;
    given.Seams = normalSeamEdges(this->InputTriangles, this->Vertex, normals,
      NormalSeamAngleDegrees, &interior, welded, table);
    given.FlatShaded = given.Seams.size() * 2 >= interior && !given.Seams.empty() &&
      hasFaceNormals(points, this->InputTriangles, normals);
  }
  given.Use = normals.size() == n && !given.FlatShaded;
  return given;
}

std::unique_ptr<PreparedMesh> WeldedSurface::prepareGeometry(std::vector<glm::dvec3> points,
  const std::vector<glm::dvec3>& normals, const GivenNormals& given,
  const std::vector<FeatureEdge>& markedFeatures, const SurfaceOptions& options,
  SurfaceStatistics& statistics, const ParallelFor& parallelFor, PreparedMesh* reusable,
  bool* reused)
{
  statistics.FlatShadedNormals = given.FlatShaded;
  const std::vector<Triangle>& welded = this->Welded;
  // Prepared corner k of triangle t is input corner inputCorner(t, k).
  auto inputCorner = [this](std::size_t t, std::size_t k) -> std::size_t {
    return this->Reversed[t] && k != 0 ? 3 - k : k;
  };
  // The given normal at prepared corner k of triangle t (read in place: a
  // per-corner copy is made only when the prepared mesh needs one, below).
  auto givenCornerNormal = [&](std::size_t t, std::size_t k) -> const glm::dvec3& {
    return normals[static_cast<std::size_t>(this->InputTriangles[t][inputCorner(t, k)])];
  };
  // Per component: whether its given normals are reversed; and whether
  // triangle t's are.
  std::vector<unsigned char> reversedComponent;
  auto reversedAt = [&](std::size_t t) {
    return !reversedComponent.empty() && this->Components[t] >= 0 &&
      reversedComponent[static_cast<std::size_t>(this->Components[t])] != 0;
  };
  bool normalsReversed = false;
  if (options.Orient && given.Use && !this->Components.empty())
  {
    // A given normal is a direction to shade with, its sign the exporter's
    // choice: where a component's given normals point into its oriented
    // surface on the whole (summed against the area normals), reverse them
    // all. Decided per component, not per point: a normal nearly in the
    // plane of its triangles says little about the side.
    // Each corner's term in parallel (the points and normals are read at
    // random), then summed per component in triangle order, the same sums
    // on any split; a skipped corner's term is exactly zero, which leaves a
    // sum as it was.
    std::vector<double> ownTerms;
    std::vector<double>& terms = reusable ? this->MovedAgreementTerms : ownTerms;
    terms.resize(3 * welded.size());
    parallelFor(welded.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
      {
        if (this->Components[t] < 0)
        {
          continue;
        }
        const glm::dvec3& a = points[static_cast<std::size_t>(welded[t][0])];
        const glm::dvec3 areaNormal = glm::cross(points[static_cast<std::size_t>(welded[t][1])] - a,
          points[static_cast<std::size_t>(welded[t][2])] - a);
        for (std::size_t k = 0; k < 3; ++k)
        {
          const glm::dvec3& normal = givenCornerNormal(t, k);
          terms[3 * t + k] = isFinite(normal) ? glm::dot(areaNormal, normal) : 0.0;
        }
      }
    });
    std::vector<double> agreement(statistics.ComponentCount, 0.0);
    for (std::size_t t = 0; t < welded.size(); ++t)
    {
      if (this->Components[t] >= 0)
      {
        double& sum = agreement[static_cast<std::size_t>(this->Components[t])];
        sum += terms[3 * t];
        sum += terms[3 * t + 1];
        sum += terms[3 * t + 2];
      }
    }
    reversedComponent.resize(agreement.size(), 0);
    for (std::size_t c = 0; c < agreement.size(); ++c)
    {
      reversedComponent[c] = agreement[c] < 0.0 ? 1 : 0;
    }
    for (std::size_t t = 0; t < welded.size() && !normalsReversed; ++t)
    {
      normalsReversed = reversedAt(t);
    }
  }

  std::vector<FeatureEdge> features;
  for (const FeatureEdge& f : markedFeatures)
  {
    features.emplace_back(this->Vertex[static_cast<std::size_t>(f.first)],
      this->Vertex[static_cast<std::size_t>(f.second)]);
  }
  statistics.NormalSeamEdgeCount = 0;
  if (options.NormalSeams && given.Use)
  {
    statistics.NormalSeamEdgeCount = given.Seams.size();
    features.insert(features.end(), given.Seams.begin(), given.Seams.end());
  }
  statistics.FlatCreaseEdgeCount = 0;
  // Both tests read the dihedral angles: computed once (a sixth of a
  // deforming mesh's frame at 1.3M triangles when computed for each).
  std::vector<double> ownCosines;
  std::vector<double>& cosines = reusable ? this->MovedCosines : ownCosines;
  if (options.DetectFlatCreases || options.DetectFeatures)
  {
    std::vector<glm::dvec3> ownFaceNormals;
    dihedralCosines(points, welded, this->Sides, parallelFor,
      reusable ? this->MovedFaceNormals : ownFaceNormals, cosines);
  }
  if (options.DetectFlatCreases)
  {
    const std::vector<FeatureEdge> creases = flatSidedCreases(
      cosines, this->Sides, this->Table, options.FlatCreaseAngleDegrees, parallelFor);
    statistics.FlatCreaseEdgeCount = creases.size();
    features.insert(features.end(), creases.begin(), creases.end());
  }
  if (options.DetectFeatures)
  {
    const std::vector<FeatureEdge> sharp =
      featureEdgesByAngle(cosines, this->Table, options.FeatureAngleDegrees);
    features.insert(features.end(), sharp.begin(), sharp.end());
  }
  const bool cornersMatter = given.Use &&
    (statistics.WeldedPointCount > 0 || statistics.ReversedTriangleCount > 0 || normalsReversed);
  // The given normals per prepared corner, read in place (a copy would be
  // three per triangle: at 1.3M triangles 94 MB of fresh memory every frame
  // of a deforming mesh).
  CornerNormals cornerNormals;
  if (cornersMatter)
  {
    cornerNormals = CornerNormals(
      [&](std::size_t t, std::size_t k) {
        const glm::dvec3& normal = givenCornerNormal(t, k);
        return reversedAt(t) ? -normal : normal;
      },
      welded.size());
  }
  // Nothing welded or reversed: the per-point normals are the corners'.
  const std::vector<glm::dvec3> none;
  const std::vector<glm::dvec3>& pointNormals = given.Use && !cornersMatter ? normals : none;
  if (reusable)
  {
    std::unique_ptr<PreparedMesh> moved = PreparedMesh::moved(*reusable, std::move(points),
      pointNormals, features, cornerNormals, this->Table, options.Normals);
    *reused = moved != nullptr;
    if (moved)
    {
      return moved;
    }
  }
  return std::make_unique<PreparedMesh>(std::move(points), welded, pointNormals,
    std::move(features), cornerNormals, &this->Table, options.Normals);
}

bool WeldedSurface::movePoints(std::vector<glm::dvec3> points,
  const std::vector<glm::dvec3>& normals, const std::vector<FeatureEdge>& markedFeatures,
  const SurfaceOptions& options, const ParallelFor& parallelFor)
{
  const std::size_t n = this->InputPointCount;
  if (points.size() != n || (!normals.empty() && normals.size() != n) ||
    (options.Weld && options.WeldTolerance > 0.0))
  {
    return false;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    // Welded points must still be one position (and the unwelded are
    // assumed not to have come together).
    if (points[i] != points[static_cast<std::size_t>(this->Vertex[i])])
    {
      return false;
    }
  }
  // The seams' own edge table (this one's sides are turned for the
  // orientation): only for meshes with welded points and normals.
  const GivenNormals given = this->examineNormals(points, normals, nullptr, nullptr);
  SurfaceStatistics statistics = this->Statistics;
  bool reused = false;
  std::unique_ptr<PreparedMesh> prepared = this->prepareGeometry(std::move(points), normals, given,
    markedFeatures, options, statistics, parallelFor, this->Prepared.get(), &reused);
  // The output's points and their copies follow from the prepared
  // triangles; where the features moved, so did they: build anew.
  if (!reused &&
    (prepared->triangles() != this->Prepared->triangles() ||
      prepared->points().size() != this->Prepared->points().size()))
  {
    return false;
  }
  // The fold guard's grid of the triangles' boxes serves again while the
  // points move little (PreparedMesh::adoptTriangleGrid; a reused mesh has
  // done so).
  if (!reused)
  {
    prepared->adoptTriangleGrid(*this->Prepared);
  }
  this->Prepared = std::move(prepared);
  this->Statistics = statistics;
  return true;
}

Id WeldedSurface::outputOfPreparedCorner(std::size_t t, Id preparedPoint) const
{
  const Triangle& tri = this->Prepared->triangles()[t];
  for (std::size_t k = 0; k < 3; ++k)
  {
    if (tri[k] == preparedPoint)
    {
      const std::size_t c = this->Reversed[t] && k != 0 ? 3 - k : k;
      return this->CornerOutput[t * 3 + c];
    }
  }
  return this->PreparedHome[static_cast<std::size_t>(preparedPoint)];
}

std::size_t WeldedSurface::outputTriangleCount(const SmoothingResult& result) const
{
  return this->Prepared->triangles().size() - result.RemeshedTriangles.size() +
    result.Replacements.size();
}

namespace
{

// An added point as one triangle sees it: the new point and the input points
// it is interpolated from there.
struct AddedKey
{
  std::size_t NewPoint;
  std::array<Id, 3> Sources;
  bool operator==(const AddedKey& o) const
  {
    return NewPoint == o.NewPoint && Sources == o.Sources;
  }
};

struct AddedKeyHash
{
  std::size_t operator()(const AddedKey& k) const
  {
    std::size_t h = k.NewPoint * 0x9E3779B97F4A7C15ULL;
    for (const Id s : k.Sources)
    {
      h = (h ^ static_cast<std::size_t>(s)) * 0x100000001B3ULL;
    }
    return h;
  }
};

} // namespace

template<typename IdType>
SurfaceFrame WeldedSurface::assemble(const SmoothingResult& result, IdType* triangles,
  IdType* sourceTriangle, unsigned char* kind) const
{
  return this->assembleSome(result, nullptr, triangles, sourceTriangle, kind);
}

void WeldedSurface::addPolylinesAndMoves(
  const SmoothingResult& result, std::vector<Id>& firstCopy, SurfaceFrame& frame) const
{
  const Id preparedCount = static_cast<Id>(this->Prepared->points().size());
  const Id outputBase = static_cast<Id>(this->outputPointCount());
  // Silhouette polylines: any copy of a point will do (same position).
  frame.Polylines.reserve(result.Polylines.size());
  for (const std::vector<Id>& chain : result.Polylines)
  {
    std::vector<Id> out;
    out.reserve(chain.size());
    for (const Id v : chain)
    {
      if (v < preparedCount)
      {
        out.push_back(this->PreparedHome[static_cast<std::size_t>(v)]);
        continue;
      }
      const std::size_t np = static_cast<std::size_t>(v - preparedCount);
      if (firstCopy[np] < 0)
      {
        // On no output triangle (cannot happen for a sampled segment): keep
        // the point anyway, from its prepared sources.
        SurfaceFrame::AddedPoint point{ np, {} };
        for (std::size_t k = 0; k < 3; ++k)
        {
          point.Sources[k] = this->outputSource(
            this->PreparedHome[static_cast<std::size_t>(result.NewPoints[np].Sources[k])]);
        }
        firstCopy[np] = outputBase + static_cast<Id>(frame.Added.size());
        frame.Added.push_back(point);
      }
      out.push_back(firstCopy[np]);
    }
    frame.Polylines.push_back(std::move(out));
  }

  for (const auto& moved : result.MovedPoints)
  {
    const std::size_t p = static_cast<std::size_t>(moved.first);
    for (Id k = this->OutputsOffsets[p]; k < this->OutputsOffsets[p + 1]; ++k)
    {
      frame.Moved.emplace_back(this->OutputsOf[static_cast<std::size_t>(k)], moved.second);
    }
  }
  std::sort(frame.Moved.begin(), frame.Moved.end(),
    [](const std::pair<Id, glm::dvec3>& a, const std::pair<Id, glm::dvec3>& b) {
      return a.first < b.first;
    });
}

template<typename IdType>
SurfaceFrame WeldedSurface::assembleSome(const SmoothingResult& result, const std::vector<Id>* only,
  IdType* triangles, IdType* sourceTriangle, unsigned char* kind) const
{
  SurfaceFrame frame;
  const std::vector<Triangle>& prepared = this->Prepared->triangles();
  const Id preparedCount = static_cast<Id>(this->Prepared->points().size());
  const Id outputBase = static_cast<Id>(this->outputPointCount());
  auto keyOf = [&](std::size_t t, Id v) {
    const std::size_t np = static_cast<std::size_t>(v - preparedCount);
    AddedKey key{ np, {} };
    const NewPoint& point = result.NewPoints[np];
    for (std::size_t k = 0; k < 3; ++k)
    {
      key.Sources[k] = this->outputSource(this->outputOfPreparedCorner(t, point.Sources[k]));
    }
    return key;
  };

  // Pass 1, over the re-meshed triangles only: every distinct added point,
  // numbered in the order of the new points it copies (then of first use),
  // so that without seams the output is the SmoothingResult's own order.
  std::unordered_map<AddedKey, Id, AddedKeyHash> added;
  for (std::size_t i = 0; i < result.RemeshedTriangles.size(); ++i)
  {
    const std::size_t t = static_cast<std::size_t>(result.RemeshedTriangles[i]);
    for (std::size_t r = result.ReplacementOffsets[i]; r < result.ReplacementOffsets[i + 1]; ++r)
    {
      for (const Id v : result.Replacements[r])
      {
        if (v >= preparedCount)
        {
          const AddedKey key = keyOf(t, v);
          if (added.emplace(key, static_cast<Id>(frame.Added.size())).second)
          {
            frame.Added.push_back({ key.NewPoint, key.Sources });
          }
        }
      }
    }
  }
  std::vector<Id> firstCopy(result.NewPoints.size(), -1);
  {
    std::vector<std::size_t> order(frame.Added.size());
    for (std::size_t i = 0; i < order.size(); ++i)
    {
      order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return frame.Added[a].NewPoint < frame.Added[b].NewPoint;
    });
    std::vector<Id> number(order.size());
    std::vector<SurfaceFrame::AddedPoint> sorted(order.size());
    for (std::size_t i = 0; i < order.size(); ++i)
    {
      number[order[i]] = outputBase + static_cast<Id>(i);
      sorted[i] = frame.Added[order[i]];
      if (firstCopy[sorted[i].NewPoint] < 0)
      {
        firstCopy[sorted[i].NewPoint] = outputBase + static_cast<Id>(i);
      }
    }
    for (auto& entry : added)
    {
      entry.second = number[static_cast<std::size_t>(entry.second)];
    }
    frame.Added = std::move(sorted);
  }

  // Pass 2: every output triangle, in input order, re-meshed ones replaced in
  // place, wound as their part is written (chooseWrittenWinding).
  std::size_t next = 0;
  std::size_t written = 0;
  auto emit = [&](const Triangle& tri, std::size_t t, unsigned char k) {
    for (std::size_t k = 0; k < 3; ++k)
    {
      triangles[written * 3 + k] = static_cast<IdType>(tri[k]);
    }
    sourceTriangle[written] = static_cast<IdType>(t);
    kind[written] = k;
    ++written;
  };
  const std::size_t visited = only ? only->size() : prepared.size();
  for (std::size_t i = 0; i < visited; ++i)
  {
    const std::size_t t = only ? static_cast<std::size_t>((*only)[i]) : i;
    while (
      next < result.RemeshedTriangles.size() && result.RemeshedTriangles[next] < static_cast<Id>(t))
    {
      ++next; // only when `only` skips a re-meshed triangle
    }
    if (next < result.RemeshedTriangles.size() &&
      result.RemeshedTriangles[next] == static_cast<Id>(t))
    {
      const auto remeshKind = static_cast<unsigned char>(result.RemeshKinds[next]);
      for (std::size_t r = result.ReplacementOffsets[next]; r < result.ReplacementOffsets[next + 1];
           ++r)
      {
        Triangle out;
        for (std::size_t k = 0; k < 3; ++k)
        {
          const Id v = result.Replacements[r][k];
          out[k] = v < preparedCount ? this->outputOfPreparedCorner(t, v) : added.at(keyOf(t, v));
        }
        emit(oriented(out, this->Written[t] != 0), t, remeshKind);
      }
      ++next;
      continue;
    }
    // The input triangle's points, turned over when its part is written
    // the other way round.
    const Triangle kept{ { this->CornerOutput[t * 3], this->CornerOutput[t * 3 + 1],
      this->CornerOutput[t * 3 + 2] } };
    emit(oriented(kept, this->Written[t] != this->Reversed[t]), t, 0);
  }

  this->addPolylinesAndMoves(result, firstCopy, frame);
  return frame;
}

template SurfaceFrame WeldedSurface::assemble<Id>(
  const SmoothingResult&, Id*, Id*, unsigned char*) const;
template SurfaceFrame WeldedSurface::assemble<long long>(
  const SmoothingResult&, long long*, long long*, unsigned char*) const;

SurfaceFrame WeldedSurface::assembleChanges(const SmoothingResult& result) const
{
  const std::vector<Triangle>& prepared = this->Prepared->triangles();
  std::vector<Id> replaced = result.RemeshedTriangles;
  if (!result.MovedPoints.empty())
  {
    std::call_once(this->TrianglesOfBuilt, [&]() {
      const std::size_t points = this->Prepared->points().size();
      this->TrianglesOffsets.assign(points + 1, 0);
      for (const Triangle& tri : prepared)
      {
        for (const Id v : tri)
        {
          ++this->TrianglesOffsets[static_cast<std::size_t>(v) + 1];
        }
      }
      for (std::size_t p = 0; p < points; ++p)
      {
        this->TrianglesOffsets[p + 1] += this->TrianglesOffsets[p];
      }
      this->TrianglesOf.resize(static_cast<std::size_t>(this->TrianglesOffsets[points]));
      std::vector<Id> fill(this->TrianglesOffsets.begin(), this->TrianglesOffsets.end() - 1);
      for (std::size_t t = 0; t < prepared.size(); ++t)
      {
        for (const Id v : prepared[t])
        {
          this->TrianglesOf[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] =
            static_cast<Id>(t);
        }
      }
    });
    for (const auto& moved : result.MovedPoints)
    {
      const std::size_t p = static_cast<std::size_t>(moved.first);
      replaced.insert(replaced.end(), this->TrianglesOf.begin() + this->TrianglesOffsets[p],
        this->TrianglesOf.begin() + this->TrianglesOffsets[p + 1]);
    }
    std::sort(replaced.begin(), replaced.end());
    replaced.erase(std::unique(replaced.begin(), replaced.end()), replaced.end());
  }
  // Replacements of the re-meshed ones, one triangle for each kept one.
  const std::size_t count =
    replaced.size() - result.RemeshedTriangles.size() + result.Replacements.size();
  SurfaceFrame frame = this->assembleInto(result, &replaced, count);
  frame.ReplacedTriangles = std::move(replaced);
  return frame;
}

SurfaceFrame WeldedSurface::assemble(const SmoothingResult& result) const
{
  return this->assembleInto(result, nullptr, this->outputTriangleCount(result));
}

SurfaceFrame WeldedSurface::assembleInto(
  const SmoothingResult& result, const std::vector<Id>* only, std::size_t count) const
{
  std::vector<Id> connectivity(count * 3);
  std::vector<Id> source(count);
  std::vector<unsigned char> kind(count);
  SurfaceFrame frame =
    this->assembleSome(result, only, connectivity.data(), source.data(), kind.data());
  frame.Triangles.resize(count);
  for (std::size_t t = 0; t < count; ++t)
  {
    frame.Triangles[t] = { { connectivity[t * 3], connectivity[t * 3 + 1],
      connectivity[t * 3 + 2] } };
  }
  frame.SourceTriangle = std::move(source);
  frame.Kind = std::move(kind);
  return frame;
}

} // namespace silsmooth
