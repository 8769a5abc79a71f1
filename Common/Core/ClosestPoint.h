// The point of a triangle nearest a point: shared by the line visibility's
// local sheet (Lines/Core) and the level of detail's split errors
// (LevelOfDetail/Core). Inline: both call it in loops over many triangles.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace silsmooth
{

// The point of triangle (a, b, c) nearest p (Ericson, Real-Time Collision
// Detection, 5.1.5: the Voronoi regions of the vertices, edges and face).
inline glm::dvec3 closestPointOnTriangle(
  const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 ab = b - a;
  const glm::dvec3 ac = c - a;
  const glm::dvec3 ap = p - a;
  const double d1 = glm::dot(ab, ap);
  const double d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return a;
  }
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp);
  const double d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return a + (d1 / (d1 - d3)) * ab;
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp);
  const double d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double denominator = va + vb + vc;
  if (!(std::abs(denominator) > 0.0))
  {
    return a; // a degenerate triangle: its first corner
  }
  const double v = vb / denominator;
  const double w = vc / denominator;
  return a + v * ab + w * ac;
}

} // namespace silsmooth
