// Shading normals at mesh vertices (Wang et al. 2008, III-B): the
// angle-weighted average of the incident triangles' normals (Thuermer and
// Wuethrich), which does not depend on how a fan is triangulated.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>
#include <vector>

namespace silsmooth
{

/// Unit angle-weighted vertex normals. A vertex with no incident triangle of
/// non-zero area gets the zero vector: callers treat it as having no defined
/// normal (see VertexVisibility).
std::vector<glm::dvec3> angleWeightedNormals(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles);

/// Normalises `normal`, or returns the zero vector when it is too short to
/// have a direction (zero, denormal, or not finite).
glm::dvec3 safeNormalize(const glm::dvec3& normal);

} // namespace silsmooth
