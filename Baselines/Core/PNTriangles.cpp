#include "PNTriangles.h"

#include "ShadingNormals.h"

#include <glm/geometric.hpp>

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
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals, int level,
  const ProgressCallback& progress)
{
  TessellationPatch patch;
  patch.Position = pnPosition;
  patch.Normal = pnNormal;
  // The edge's own cubic, not pnPosition at c = 0: the same curve, but this
  // one reads only the edge's data (and keeps the output as it always was).
  patch.EdgePosition = edgePosition;
  patch.EdgeNormal = edgeNormalAt;
  return tessellateUniformly(points, triangles, normals, level, patch, progress);
}

} // namespace silsmooth
