#include "UniformTessellation.h"

#include "ShadingNormals.h"

#include <algorithm>

namespace silsmooth
{

namespace
{

constexpr std::size_t ProgressEvery = 4096; // edges or triangles between reports

TessellationResult aborted()
{
  TessellationResult result;
  result.Aborted = true;
  return result;
}

} // namespace

TessellationResult tessellateUniformly(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals, int level,
  const TessellationPatch& patch, const ProgressCallback& progress)
{
  TessellationResult result;
  const int k = std::max(0, level);
  const int n = k + 1; // pieces per edge
  const std::vector<glm::dvec3> computed = angleWeightedNormals(points, triangles);
  result.Points = points;
  result.Normals.resize(points.size());
  result.SourcePoints.resize(points.size());
  result.SourceWeights.assign(points.size(), glm::dvec3(1.0, 0.0, 0.0));
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    glm::dvec3 normal = i < normals.size() ? safeNormalize(normals[i]) : glm::dvec3(0.0);
    result.Normals[i] = normal == glm::dvec3(0.0) ? computed[i] : normal;
    const auto id = static_cast<Id>(i);
    result.SourcePoints[i] = { { id, id, id } };
  }
  const std::vector<glm::dvec3>& nrm = result.Normals;

  // Edge points, once per undirected edge, from its lower id: both triangles
  // of the edge then name the same points (no cracks from rounding).
  const EdgeTable edges(triangles);
  std::vector<Id> edgeFirst(edges.edgeCount(), -1); // id of the edge's first inner point
  // The work: each edge once (at level 0 there is none), then each triangle.
  const std::size_t edgeSteps = k > 0 ? edges.edgeCount() : 0;
  const double steps = static_cast<double>(edgeSteps + triangles.size()) + 1.0;
  for (std::size_t e = 0; e < edges.edgeCount() && k > 0; ++e)
  {
    if (e % ProgressEvery == 0 && !reportProgress(progress, static_cast<double>(e) / steps))
    {
      return aborted();
    }
    const Edge& edge = edges.edge(static_cast<Id>(e));
    if (edge.low == edge.high)
    {
      continue;
    }
    const auto lo = static_cast<std::size_t>(edge.low);
    const auto hi = static_cast<std::size_t>(edge.high);
    edgeFirst[e] = static_cast<Id>(result.Points.size());
    for (int m = 1; m <= k; ++m)
    {
      const double t = static_cast<double>(m) / n;
      result.Points.push_back(patch.EdgePosition(points[lo], points[hi], nrm[lo], nrm[hi], t));
      result.Normals.push_back(patch.EdgeNormal(points[lo], points[hi], nrm[lo], nrm[hi], t));
      result.SourcePoints.push_back({ { edge.low, edge.high, edge.high } });
      result.SourceWeights.emplace_back(1.0 - t, t, 0.0);
    }
  }

  result.Triangles.reserve(triangles.size() * static_cast<std::size_t>(n * n));
  std::vector<Id> lattice;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (t % ProgressEvery == 0 &&
      !reportProgress(progress, static_cast<double>(edgeSteps + t) / steps))
    {
      return aborted();
    }
    const Triangle& tri = triangles[t];
    if (hasRepeatedCorner(tri) || k == 0)
    {
      result.Triangles.push_back(tri);
      result.TriangleSource.push_back(static_cast<Id>(t));
      continue;
    }
    const CornerVectors p{ { points[static_cast<std::size_t>(tri[0])],
      points[static_cast<std::size_t>(tri[1])], points[static_cast<std::size_t>(tri[2])] } };
    const CornerVectors nn{ { nrm[static_cast<std::size_t>(tri[0])],
      nrm[static_cast<std::size_t>(tri[1])], nrm[static_cast<std::size_t>(tri[2])] } };
    // The point of side s (corner s to corner s+1) `steps` pieces from corner s.
    auto sidePoint = [&](int s, int steps) -> Id {
      const Id from = tri[static_cast<std::size_t>(s)];
      const Id e = edges.sideEdge(static_cast<Id>(t), s);
      const Edge& edge = edges.edge(e);
      const int m = edge.low == from ? steps : n - steps;
      return edgeFirst[static_cast<std::size_t>(e)] + (m - 1);
    };
    // Lattice (i, j) with barycentric (a, b, c) = ((n - i - j) / n, i / n, j / n).
    lattice.assign(static_cast<std::size_t>((n + 1) * (n + 1)), -1);
    auto at = [&](int i, int j) -> Id& {
      return lattice[static_cast<std::size_t>(i * (n + 1) + j)];
    };
    for (int i = 0; i <= n; ++i)
    {
      for (int j = 0; i + j <= n; ++j)
      {
        const int l = n - i - j; // weight of corner 0, in pieces
        Id id = -1;
        if (l == n)
        {
          id = tri[0];
        }
        else if (i == n)
        {
          id = tri[1];
        }
        else if (j == n)
        {
          id = tri[2];
        }
        else if (j == 0)
        {
          id = sidePoint(0, i); // side 0 -> 1
        }
        else if (l == 0)
        {
          id = sidePoint(1, j); // side 1 -> 2
        }
        else if (i == 0)
        {
          id = sidePoint(2, l); // side 2 -> 0
        }
        else
        {
          const double a = static_cast<double>(l) / n;
          const double b = static_cast<double>(i) / n;
          const double c = static_cast<double>(j) / n;
          id = static_cast<Id>(result.Points.size());
          result.Points.push_back(patch.Position(p, nn, a, b, c));
          result.Normals.push_back(patch.Normal(p, nn, a, b, c));
          result.SourcePoints.push_back(tri);
          result.SourceWeights.emplace_back(a, b, c);
        }
        at(i, j) = id;
      }
    }
    // Triangles of the lattice, oriented as (corner 0, corner 1, corner 2).
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; i + j < n; ++j)
      {
        result.Triangles.push_back({ { at(i, j), at(i + 1, j), at(i, j + 1) } });
        result.TriangleSource.push_back(static_cast<Id>(t));
        if (i + j + 1 < n)
        {
          result.Triangles.push_back({ { at(i + 1, j), at(i + 1, j + 1), at(i, j + 1) } });
          result.TriangleSource.push_back(static_cast<Id>(t));
        }
      }
    }
  }
  return result;
}

} // namespace silsmooth
