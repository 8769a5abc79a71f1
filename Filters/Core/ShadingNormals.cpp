#include "ShadingNormals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{

glm::dvec3 safeNormalize(const glm::dvec3& normal)
{
  const double length = glm::length(normal);
  if (!(length > 1e-300) || !std::isfinite(length))
  {
    return glm::dvec3(0.0);
  }
  return normal / length;
}

namespace
{

// `v` divided by its largest component's magnitude: the direction survives
// where the cross product of two tiny edges (a model at 1e-150 scale) would
// underflow to zero.
glm::dvec3 rescaled(const glm::dvec3& v)
{
  const double largest = std::max({ std::abs(v.x), std::abs(v.y), std::abs(v.z) });
  return largest > 0.0 && std::isfinite(largest) ? v / largest : v;
}

// Interior angle at `corner` between the directions to `a` and `b`; zero when
// either direction is degenerate. atan2 of |cross| and dot is accurate for
// angles near 0 and pi, where acos of a dot product loses digits.
double cornerAngle(const glm::dvec3& corner, const glm::dvec3& a, const glm::dvec3& b)
{
  const glm::dvec3 u = rescaled(a - corner);
  const glm::dvec3 v = rescaled(b - corner);
  const double sine = glm::length(glm::cross(u, v));
  const double cosine = glm::dot(u, v);
  if (sine == 0.0 && cosine == 0.0)
  {
    return 0.0;
  }
  return std::atan2(sine, cosine);
}

} // namespace

std::vector<glm::dvec3> angleWeightedNormals(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles)
{
  std::vector<glm::dvec3> sums(points.size(), glm::dvec3(0.0));
  for (const Triangle& t : triangles)
  {
    if (hasRepeatedCorner(t))
    {
      continue;
    }
    const glm::dvec3& p0 = points[static_cast<std::size_t>(t[0])];
    const glm::dvec3& p1 = points[static_cast<std::size_t>(t[1])];
    const glm::dvec3& p2 = points[static_cast<std::size_t>(t[2])];
    const glm::dvec3 faceNormal = safeNormalize(glm::cross(rescaled(p1 - p0), rescaled(p2 - p0)));
    if (faceNormal == glm::dvec3(0.0))
    {
      continue; // zero area: no direction to contribute
    }
    sums[static_cast<std::size_t>(t[0])] += cornerAngle(p0, p1, p2) * faceNormal;
    sums[static_cast<std::size_t>(t[1])] += cornerAngle(p1, p2, p0) * faceNormal;
    sums[static_cast<std::size_t>(t[2])] += cornerAngle(p2, p0, p1) * faceNormal;
  }
  for (glm::dvec3& n : sums)
  {
    n = safeNormalize(n);
  }
  return sums;
}

} // namespace silsmooth
