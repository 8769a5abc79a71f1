#include "SurfaceOrientation.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <deque>

namespace silsmooth
{

namespace
{

// +1 when side k of t runs from the edge's low vertex to its high one.
int sideDirection(const Triangle& t, int k)
{
  return t[static_cast<std::size_t>(k)] < t[static_cast<std::size_t>((k + 1) % 3)] ? 1 : -1;
}

} // namespace

Orientation orientConsistently(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& cornerNormals,
  const EdgeTable* given)
{
  Orientation result;
  const std::size_t n = triangles.size();
  result.Reversed.assign(n, 0);
  const EdgeTable built = given ? EdgeTable() : EdgeTable(triangles);
  const EdgeTable& table = given ? *given : built;
  // The sides of each edge: the first two, and how many in all.
  std::vector<std::array<Id, 2>> sides(table.edgeCount(), { { -1, -1 } });
  std::vector<int> uses(table.edgeCount(), 0);
  for (std::size_t t = 0; t < n; ++t)
  {
    if (hasRepeatedCorner(triangles[t]))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t e = static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k));
      if (uses[e] < 2)
      {
        sides[e][static_cast<std::size_t>(uses[e])] = static_cast<Id>(t * 3) + k;
      }
      ++uses[e];
    }
  }

  std::vector<Id> component(n, -1);
  std::vector<Id> members;
  std::deque<Id> queue;
  for (std::size_t seed = 0; seed < n; ++seed)
  {
    if (component[seed] >= 0 || hasRepeatedCorner(triangles[seed]))
    {
      continue;
    }
    const Id c = static_cast<Id>(result.ComponentCount++);
    members.clear();
    bool closed = true;
    component[seed] = c;
    queue.push_back(static_cast<Id>(seed));
    while (!queue.empty())
    {
      const Id t = queue.front();
      queue.pop_front();
      members.push_back(t);
      const Triangle& tri = triangles[static_cast<std::size_t>(t)];
      for (int k = 0; k < 3; ++k)
      {
        const std::size_t e = static_cast<std::size_t>(table.sideEdge(t, k));
        if (uses[e] != 2)
        {
          closed = false;
          continue;
        }
        const Id other = sides[e][0] / 3 == t ? sides[e][1] : sides[e][0];
        const Id u = other / 3;
        const int ku = static_cast<int>(other % 3);
        // Consistent when the two run along the edge in opposite directions
        // once both have their chosen orientation.
        const int dt =
          sideDirection(tri, k) * (result.Reversed[static_cast<std::size_t>(t)] ? -1 : 1);
        const int du = sideDirection(triangles[static_cast<std::size_t>(u)], ku);
        if (component[static_cast<std::size_t>(u)] < 0)
        {
          component[static_cast<std::size_t>(u)] = c;
          result.Reversed[static_cast<std::size_t>(u)] = dt == du ? 1 : 0;
          queue.push_back(u);
        }
        else if (t < u && dt == du * (result.Reversed[static_cast<std::size_t>(u)] ? -1 : 1))
        {
          ++result.InconsistentEdgeCount;
          closed = false;
        }
      }
    }

    // Which side is out.
    double volume = 0.0;
    double agreement = 0.0;
    double reversedArea = 0.0;
    double keptArea = 0.0;
    glm::dvec3 origin = points[static_cast<std::size_t>(triangles[seed][0])];
    for (const Id t : members)
    {
      const Triangle tri = oriented(
        triangles[static_cast<std::size_t>(t)], result.Reversed[static_cast<std::size_t>(t)] != 0);
      const glm::dvec3 a = points[static_cast<std::size_t>(tri[0])] - origin;
      const glm::dvec3 b = points[static_cast<std::size_t>(tri[1])] - origin;
      const glm::dvec3 d = points[static_cast<std::size_t>(tri[2])] - origin;
      volume += glm::dot(a, glm::cross(b, d));
      const glm::dvec3 areaNormal = glm::cross(b - a, d - a);
      const double area = glm::length(areaNormal);
      (result.Reversed[static_cast<std::size_t>(t)] ? reversedArea : keptArea) += area;
      if (!cornerNormals.empty())
      {
        for (std::size_t k = 0; k < 3; ++k)
        {
          const glm::dvec3& given = cornerNormals[static_cast<std::size_t>(t) * 3 + k];
          if (std::isfinite(given.x) && std::isfinite(given.y) && std::isfinite(given.z))
          {
            agreement += glm::dot(areaNormal, given);
          }
        }
      }
    }
    bool flipAll = false;
    if (closed)
    {
      flipAll = volume < 0.0;
    }
    else if (!cornerNormals.empty() && agreement != 0.0)
    {
      flipAll = agreement < 0.0;
    }
    else
    {
      flipAll = reversedArea > keptArea;
    }
    if (flipAll)
    {
      for (const Id t : members)
      {
        result.Reversed[static_cast<std::size_t>(t)] ^= 1;
      }
    }
  }
  for (const unsigned char r : result.Reversed)
  {
    result.ReversedCount += r;
  }
  result.Component = std::move(component);
  return result;
}

} // namespace silsmooth
