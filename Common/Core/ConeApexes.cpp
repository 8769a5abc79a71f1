#include "ConeApexes.h"

#include "ShadingNormals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{
namespace
{

// A triangle seen from one of its corners: the corner, the other end of one
// of its sides there, and the triangle's unit normal.
struct SideAtPoint
{
  Id Point = 0;
  Id Other = 0;
  glm::dvec3 Normal{ 0.0 };
};

} // namespace

std::vector<Id> coneApexes(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles)
{
  const double pi = 3.14159265358979323846;
  const double spreadCosine = std::cos(ApexSpreadDegrees * pi / 180.0);
  // False for a triangle with no area (or not finite).
  auto faceNormal = [&](const Triangle& t, glm::dvec3& normal) {
    const glm::dvec3 n = areaVector(points, t);
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length))
    {
      return false;
    }
    normal = n / length;
    return true;
  };
  // Pass 1: the mean of each point's triangles' unit normals; a point whose
  // mean is shorter than cos(ApexSpreadDegrees) is a candidate (few are).
  std::vector<glm::dvec3> sum(points.size(), glm::dvec3(0.0));
  std::vector<unsigned> count(points.size(), 0);
  for (const Triangle& t : triangles)
  {
    glm::dvec3 n;
    if (!faceNormal(t, n))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      sum[static_cast<std::size_t>(t[k])] += n;
      ++count[static_cast<std::size_t>(t[k])];
    }
  }
  std::vector<unsigned char> candidate(points.size(), 0);
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    candidate[p] = count[p] > 0 && glm::length(sum[p]) < count[p] * spreadCosine ? 1 : 0;
  }
  // Pass 2, for the candidates only: their triangles by the other end of
  // each side at the candidate, so that two triangles that share a side
  // there come together when sorted.
  std::vector<SideAtPoint> sides;
  for (const Triangle& t : triangles)
  {
    glm::dvec3 n;
    if (!(candidate[static_cast<std::size_t>(t[0])] | candidate[static_cast<std::size_t>(t[1])] |
          candidate[static_cast<std::size_t>(t[2])]) ||
      !faceNormal(t, n))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (candidate[static_cast<std::size_t>(t[k])])
      {
        sides.push_back({ t[k], t[(k + 1) % 3], n });
        sides.push_back({ t[k], t[(k + 2) % 3], n });
      }
    }
  }
  std::sort(sides.begin(), sides.end(), [](const SideAtPoint& a, const SideAtPoint& b) {
    return a.Point != b.Point ? a.Point < b.Point : a.Other < b.Other;
  });
  std::vector<Id> apexes;
  for (std::size_t begin = 0; begin < sides.size();)
  {
    const Id p = sides[begin].Point;
    std::size_t end = begin;
    double turnCosine = 1.0; // the largest turn across a side at p
    glm::dvec3 mean(0.0);    // the sum of the unit normals (each twice)
    for (; end < sides.size() && sides[end].Point == p; ++end)
    {
      mean += sides[end].Normal;
      if (end > begin && sides[end].Other == sides[end - 1].Other)
      {
        turnCosine = std::min(turnCosine, glm::dot(sides[end].Normal, sides[end - 1].Normal));
      }
    }
    const double length = glm::length(mean);
    double nearest = 1.0; // the smallest cosine of a normal to the mean
    for (std::size_t i = begin; i < end && length > 0.0; ++i)
    {
      nearest = std::min(nearest, glm::dot(sides[i].Normal, mean / length));
    }
    const double spread = std::acos(std::clamp(nearest, -1.0, 1.0));
    const double turn = std::acos(std::clamp(turnCosine, -1.0, 1.0));
    if (turn * ApexSpreadPerTurn < spread)
    {
      apexes.push_back(p);
    }
    begin = end;
  }
  return apexes;
}

} // namespace silsmooth
