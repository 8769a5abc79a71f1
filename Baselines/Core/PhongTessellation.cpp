#include "PhongTessellation.h"

#include "ShadingNormals.h"

#include <glm/geometric.hpp>

namespace silsmooth
{

glm::dvec3 phongPosition(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
  double u, double v, double w, double shapeFactor)
{
  const glm::dvec3 flat = u * p[0] + v * p[1] + w * p[2];
  // pi_m(flat) - flat: the move onto corner m's tangent plane, along n_m.
  auto lift = [&](std::size_t m) {
    return -glm::dot(flat - p[m], n[m]) * n[m];
  };
  return flat + shapeFactor * (u * lift(0) + v * lift(1) + w * lift(2));
}

glm::dvec3 phongNormal(const std::array<glm::dvec3, 3>& n, double u, double v, double w)
{
  return safeNormalize(u * n[0] + v * n[1] + w * n[2]);
}

PhongTessellationResult tessellatePhong(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals, int level,
  double shapeFactor, const ProgressCallback& progress)
{
  TessellationPatch patch;
  patch.Position = [shapeFactor](
                     const CornerVectors& p, const CornerVectors& n, double u, double v, double w) {
    return phongPosition(p, n, u, v, w, shapeFactor);
  };
  patch.Normal = [](const CornerVectors&, const CornerVectors& n, double u, double v, double w) {
    return phongNormal(n, u, v, w);
  };
  // On an edge the patch is the triangle's with the third corner's weight
  // zero; any third corner will do, so repeating p1 keeps to the edge's data.
  patch.EdgePosition = [shapeFactor](const glm::dvec3& p0, const glm::dvec3& p1,
                         const glm::dvec3& n0, const glm::dvec3& n1, double t) {
    return phongPosition({ { p0, p1, p1 } }, { { n0, n1, n1 } }, 1.0 - t, t, 0.0, shapeFactor);
  };
  patch.EdgeNormal = [](const glm::dvec3&, const glm::dvec3&, const glm::dvec3& n0,
                       const glm::dvec3& n1, double t) {
    return phongNormal({ { n0, n1, n1 } }, 1.0 - t, t, 0.0);
  };
  return tessellateUniformly(points, triangles, normals, level, patch, progress);
}

} // namespace silsmooth
