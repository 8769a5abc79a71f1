#include "EdgeClassification.h"

#include "ShadingNormals.h"
#include "SilhouettePolylines.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace silsmooth
{

std::vector<FlaggedEdge> classifyEdges(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const EdgeView& view, double creaseAngleDegrees)
{
  const Id n = static_cast<Id>(points.size());
  std::map<std::pair<Id, Id>, std::vector<std::size_t>> edgeTriangles;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = triangles[t];
    bool valid = !hasRepeatedCorner(tri);
    for (Id v : tri)
    {
      valid = valid && v >= 0 && v < n;
    }
    if (!valid)
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      edgeTriangles[std::minmax(tri[k], tri[(k + 1) % 3])].push_back(t);
    }
  }
  const double cosCrease = std::cos(creaseAngleDegrees * 3.14159265358979323846 / 180.0);
  const auto normal = [&](std::size_t t) {
    return areaVector(points, triangles[t]);
  };
  std::vector<FlaggedEdge> out;
  out.reserve(edgeTriangles.size());
  for (const auto& [edge, faces] : edgeTriangles)
  {
    FlaggedEdge e;
    e.a = edge.first;
    e.b = edge.second;
    if (faces.size() == 1)
    {
      e.flags |= BorderEdge;
    }
    else if (faces.size() == 2)
    {
      const glm::dvec3 n1 = normal(faces[0]);
      const glm::dvec3 n2 = normal(faces[1]);
      const double l1 = glm::length(n1);
      const double l2 = glm::length(n2);
      if (l1 > 0.0 && l2 > 0.0)
      {
        const glm::dvec3 v =
          view.parallel ? -view.direction : view.eye - 0.5 * (points[e.a] + points[e.b]);
        if ((glm::dot(n1, v) / l1) * (glm::dot(n2, v) / l2) <= 0.0)
        {
          e.flags |= SilhouetteEdge;
        }
        if (glm::dot(n1, n2) / (l1 * l2) < cosCrease)
        {
          e.flags |= CreaseEdge;
        }
      }
    }
    out.push_back(e);
  }
  return out;
}

std::vector<std::vector<Id>> chainFlaggedEdges(const std::vector<FlaggedEdge>& edges, unsigned mask)
{
  std::vector<std::vector<Id>> segments;
  for (const FlaggedEdge& e : edges)
  {
    if (e.flags & mask)
    {
      segments.push_back({ e.a, e.b });
    }
  }
  return chainSegments(segments);
}

} // namespace silsmooth
