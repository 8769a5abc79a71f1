#include "PNTriangles.h"

#include "ShadingNormals.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace silsmooth
{

namespace
{

// The edge control point next to `from` on the edge towards `to`.
glm::dvec3 edgeControl(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& normal)
{
  const double w = glm::dot(to - from, normal);
  return (2.0 * from + to - w * normal) / 3.0;
}

// The mid-edge normal n110 of the quadratic normal field.
glm::dvec3 edgeNormal(
  const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& n0, const glm::dvec3& n1)
{
  const glm::dvec3 d = p1 - p0;
  const double dd = glm::dot(d, d);
  const double v = dd > 0.0 ? 2.0 * glm::dot(d, n0 + n1) / dd : 0.0;
  return safeNormalize(n0 + n1 - v * d);
}

// A point of the edge's cubic at t from p0 (uses the edge's data only).
glm::dvec3 edgePosition(
  const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& n0, const glm::dvec3& n1, double t)
{
  const double s = 1.0 - t;
  return s * s * s * p0 + 3.0 * s * s * t * edgeControl(p0, p1, n0) +
    3.0 * s * t * t * edgeControl(p1, p0, n1) + t * t * t * p1;
}

glm::dvec3 edgeNormalAt(
  const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& n0, const glm::dvec3& n1, double t)
{
  const double s = 1.0 - t;
  return safeNormalize(s * s * n0 + t * t * n1 + s * t * edgeNormal(p0, p1, n0, n1));
}

} // namespace

glm::dvec3 pnPosition(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
  double a, double b, double c)
{
  const glm::dvec3 b210 = edgeControl(p[0], p[1], n[0]);
  const glm::dvec3 b120 = edgeControl(p[1], p[0], n[1]);
  const glm::dvec3 b021 = edgeControl(p[1], p[2], n[1]);
  const glm::dvec3 b012 = edgeControl(p[2], p[1], n[2]);
  const glm::dvec3 b102 = edgeControl(p[2], p[0], n[2]);
  const glm::dvec3 b201 = edgeControl(p[0], p[2], n[0]);
  const glm::dvec3 e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
  const glm::dvec3 v = (p[0] + p[1] + p[2]) / 3.0;
  const glm::dvec3 b111 = e + 0.5 * (e - v);
  return a * a * a * p[0] + b * b * b * p[1] + c * c * c * p[2] + 3.0 * a * a * b * b210 +
    3.0 * a * b * b * b120 + 3.0 * b * b * c * b021 + 3.0 * b * c * c * b012 +
    3.0 * c * c * a * b102 + 3.0 * c * a * a * b201 + 6.0 * a * b * c * b111;
}

glm::dvec3 pnNormal(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
  double a, double b, double c)
{
  const glm::dvec3 n110 = edgeNormal(p[0], p[1], n[0], n[1]);
  const glm::dvec3 n011 = edgeNormal(p[1], p[2], n[1], n[2]);
  const glm::dvec3 n101 = edgeNormal(p[2], p[0], n[2], n[0]);
  return safeNormalize(
    a * a * n[0] + b * b * n[1] + c * c * n[2] + a * b * n110 + b * c * n011 + c * a * n101);
}

PNTriangleResult tessellatePNTriangles(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals, int level)
{
  PNTriangleResult result;
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

  // Edge points, once per undirected edge, from its lower id.
  const EdgeTable edges(triangles);
  std::vector<Id> edgeFirst(edges.edgeCount(), -1); // id of the edge's first inner point
  for (std::size_t e = 0; e < edges.edgeCount() && k > 0; ++e)
  {
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
      result.Points.push_back(edgePosition(points[lo], points[hi], nrm[lo], nrm[hi], t));
      result.Normals.push_back(edgeNormalAt(points[lo], points[hi], nrm[lo], nrm[hi], t));
      result.SourcePoints.push_back({ { edge.low, edge.high, edge.high } });
      result.SourceWeights.emplace_back(1.0 - t, t, 0.0);
    }
  }

  result.Triangles.reserve(triangles.size() * static_cast<std::size_t>(n * n));
  std::vector<Id> lattice;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = triangles[t];
    if (hasRepeatedCorner(tri) || k == 0)
    {
      result.Triangles.push_back(tri);
      result.TriangleSource.push_back(static_cast<Id>(t));
      continue;
    }
    const std::array<glm::dvec3, 3> p{ { points[static_cast<std::size_t>(tri[0])],
      points[static_cast<std::size_t>(tri[1])], points[static_cast<std::size_t>(tri[2])] } };
    const std::array<glm::dvec3, 3> nn{ { nrm[static_cast<std::size_t>(tri[0])],
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
          result.Points.push_back(pnPosition(p, nn, a, b, c));
          result.Normals.push_back(pnNormal(p, nn, a, b, c));
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
