#include "SilhouetteSmoother.h"

#include "HermiteCurve.h"
#include "LocalRemesher.h"
#include "ShadingNormals.h"
#include "SilhouettePoint.h"
#include "SilhouettePolylines.h"
#include "VertexPerturbation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

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
  const std::vector<glm::dvec3>& normals)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , Edges(this->Triangles)
{
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

  std::vector<glm::dvec3> computed;
  bool needComputed = normals.size() != this->Points.size();
  if (!needComputed)
  {
    this->Normals.resize(normals.size());
    for (std::size_t i = 0; i < normals.size(); ++i)
    {
      this->Normals[i] = safeNormalize(normals[i]);
      needComputed = needComputed || this->Normals[i] == glm::dvec3(0.0);
    }
  }
  if (needComputed)
  {
    computed = angleWeightedNormals(this->Points, this->Triangles);
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
    this->computeSilhouettePoints();
    std::vector<std::vector<Id>> segments;
    segments.reserve(this->Result.SilhouetteTriangles.size());
    for (const Id t : this->Result.SilhouetteTriangles)
    {
      this->remeshTriangle(t, segments);
    }
    this->Result.Polylines = chainSegments(segments);
    this->Result.ConcaveSegmentCount = this->Concave.size();
    if (this->Parameters.PerturbConcaveSilhouettes && !this->Concave.empty())
    {
      this->Result.MovedPoints = perturbVerticesBelowConcaveSegments(this->Concave,
        this->Mesh.points(), this->Mesh.normals(), this->Mesh.triangles(),
        this->Mesh.neighbourOffsets(), this->Mesh.neighbours());
      this->keepOutputFacingOut();
    }
    return std::move(this->Result);
  }

private:
  void findSilhouetteTriangles()
  {
    const std::vector<Triangle>& triangles = this->Mesh.triangles();
    std::vector<unsigned char> isSilhouette(triangles.size(), 0);
    this->For(triangles.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
      {
        const Triangle& tri = triangles[t];
        if (hasRepeatedCorner(tri))
        {
          continue;
        }
        const bool v0 = isVisible(this->G[static_cast<std::size_t>(tri[0])]);
        const bool v1 = isVisible(this->G[static_cast<std::size_t>(tri[1])]);
        const bool v2 = isVisible(this->G[static_cast<std::size_t>(tri[2])]);
        isSilhouette[t] = (v0 != v1 || v1 != v2) ? 1 : 0;
      }
    });
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      if (isSilhouette[t])
      {
        this->Result.SilhouetteTriangles.push_back(static_cast<Id>(t));
      }
    }
  }

  // One silhouette point per mixed edge, in ascending edge order, so both
  // triangles of an edge use the same point (DESIGN 3.2).
  void computeSilhouettePoints()
  {
    const EdgeTable& edges = this->Mesh.edges();
    std::vector<Id> mixedEdges;
    for (const Id t : this->Result.SilhouetteTriangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Id e = edges.sideEdge(t, k);
        const Edge& edge = edges.edge(e);
        if (isVisible(this->G[static_cast<std::size_t>(edge.low)]) !=
          isVisible(this->G[static_cast<std::size_t>(edge.high)]))
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
      const VisibilityQuadratic h =
        visibilityAlongEdge(normals[lo], this->View.towardViewerFrom(points[lo]), normals[hi],
          this->View.towardViewerFrom(points[hi]));
      // G holds only signs for hierarchically decided vertices: the values here.
      const double u =
        std::clamp(silhouetteParameter(h, this->View.visibility(points[lo], normals[lo]),
                     this->View.visibility(points[hi], normals[hi])),
          EdgeParameterMargin, 1.0 - EdgeParameterMargin);
      const HermiteCurve bridge =
        makeCircleApproximatingCurve(points[lo], normals[lo], points[hi], normals[hi]);
      NewPoint p;
      p.Position = bridge.evaluate(u);
      p.Normal = safeNormalize((1.0 - u) * normals[lo] + u * normals[hi]);
      if (p.Normal == glm::dvec3(0.0))
      {
        // Opposite normals at the ends: no interpolated direction exists.
        p.Normal = u < 0.5 ? normals[lo] : normals[hi];
      }
      p.Sources = { edge.low, edge.high, edge.high };
      p.Weights = { 1.0 - u, u, 0.0 };
      EdgeSilhouettePoint sp;
      sp.Edge = e;
      sp.Point = pointCount + static_cast<Id>(this->Result.NewPoints.size());
      sp.HighWeight = u;
      this->Result.NewPoints.push_back(p);
      this->EdgePoints.push_back(sp);
    }
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

  void remeshTriangle(Id t, std::vector<std::vector<Id>>& segments)
  {
    const Triangle& tri = this->Mesh.triangles()[static_cast<std::size_t>(t)];
    const EdgeTable& edges = this->Mesh.edges();
    const bool v0 = isVisible(this->G[static_cast<std::size_t>(tri[0])]);
    const bool v1 = isVisible(this->G[static_cast<std::size_t>(tri[1])]);
    const int lone =
      (v0 == v1) ? 2 : (isVisible(this->G[static_cast<std::size_t>(tri[2])]) == v0 ? 1 : 0);
    const Id a = tri[lone];
    const Id b = tri[(lone + 1) % 3];
    const Id c = tri[(lone + 2) % 3];
    const EdgeSilhouettePoint& p = this->silhouettePointOf(edges.sideEdge(t, lone));
    const EdgeSilhouettePoint& q = this->silhouettePointOf(edges.sideEdge(t, (lone + 2) % 3));

    // Weight of the far corner (B for P, C for Q) in the point's combination.
    const double pTowardB = (b > a) ? p.HighWeight : 1.0 - p.HighWeight;
    const double qTowardC = (c > a) ? q.HighWeight : 1.0 - q.HighWeight;

    // The re-meshing works in the flat triangle, where P and Q sit on their
    // edges and the samples on the chord between them.
    const glm::dvec3 flatA = this->positionOf(a);
    const glm::dvec3 flatB = this->positionOf(b);
    const glm::dvec3 flatC = this->positionOf(c);
    const glm::dvec3 flatP = flatA + pTowardB * (flatB - flatA);
    const glm::dvec3 flatQ = flatA + qTowardC * (flatC - flatA);
    SilhouetteTriangleLayout layout;
    layout.Lone = a;
    layout.BaseFirst = b;
    layout.BaseSecond = c;
    layout.BaseFirstPosition = flatB;
    layout.BaseSecondPosition = flatC;
    layout.Chain.push_back(p.Point);
    layout.ChainPositions.push_back(flatP);

    if (p.Point != q.Point)
    {
      const glm::dvec3 nP = this->normalOf(p.Point);
      const glm::dvec3 nQ = this->normalOf(q.Point);
      const HermiteCurve segment =
        makeCircleApproximatingCurve(this->positionOf(p.Point), nP, this->positionOf(q.Point), nQ);
      const int samples = silhouetteSampleCount(segment, nP, nQ, this->View, this->Sampling);
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
      const Id pointCount = static_cast<Id>(this->Mesh.points().size());
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
        sample.Sources = { a, b, c };
        sample.Weights = { (1.0 - s) * (1.0 - pTowardB) + s * (1.0 - qTowardC),
          (1.0 - s) * pTowardB, s * qTowardC };
        layout.Chain.push_back(pointCount + static_cast<Id>(this->Result.NewPoints.size()));
        layout.ChainPositions.push_back((1.0 - s) * flatP + s * flatQ);
        this->Result.NewPoints.push_back(sample);
      }
    }
    layout.Chain.push_back(q.Point);
    layout.ChainPositions.push_back(flatQ);

    remeshSilhouetteTriangle(layout, this->Result.Replacements);
    this->Result.ReplacementOffsets.push_back(this->Result.Replacements.size());
    if (layout.Chain.front() != layout.Chain.back())
    {
      segments.push_back(layout.Chain);
    }
  }

  // The output triangles around the moved points (kept input triangles and
  // replacements alike) must not turn over.
  void keepOutputFacingOut()
  {
    const std::vector<std::pair<Id, glm::dvec3>>& moved = this->Result.MovedPoints;
    auto isMoved = [&moved](Id v) {
      const auto it = std::lower_bound(moved.begin(), moved.end(), v,
        [](const std::pair<Id, glm::dvec3>& m, Id id) { return m.first < id; });
      return it != moved.end() && it->first == v;
    };
    auto touchesMoved = [&isMoved](const Triangle& t) {
      return isMoved(t[0]) || isMoved(t[1]) || isMoved(t[2]);
    };
    std::vector<Triangle> around;
    const std::vector<Triangle>& triangles = this->Mesh.triangles();
    std::size_t next = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      if (next < this->Result.SilhouetteTriangles.size() &&
        this->Result.SilhouetteTriangles[next] == static_cast<Id>(t))
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
    keepTrianglesFacingOut(
      this->Result.MovedPoints, around, [this](Id id) { return this->positionOf(id); },
      [this](Id id) { return this->normalOf(id); });
  }

  const PreparedMesh& Mesh;
  const ViewGeometry& View;
  const SmoothingParameters& Parameters;
  const SamplingParameters& Sampling;
  const ParallelFor& For;
  std::vector<double> G;
  std::vector<EdgeSilhouettePoint> EdgePoints;
  std::vector<ConcaveSegment> Concave;
  SmoothingResult Result;
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
    if (next < result.SilhouetteTriangles.size() &&
      result.SilhouetteTriangles[next] == static_cast<Id>(t))
    {
      for (std::size_t r = result.ReplacementOffsets[next]; r < result.ReplacementOffsets[next + 1];
           ++r)
      {
        triangles.push_back(result.Replacements[r]);
        sourceTriangle.push_back(static_cast<Id>(t));
        isNew.push_back(1);
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
