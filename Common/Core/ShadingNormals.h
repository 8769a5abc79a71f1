// Shading normals at mesh vertices (Wang et al. 2008, III-B): the
// angle-weighted average of the incident triangles' normals (Thuermer and
// Wuethrich), which does not depend on how a fan is triangulated.
#pragma once

#include "MeshTopology.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <vector>

namespace silsmooth
{

/// Unit angle-weighted vertex normals. A vertex with no incident triangle of
/// non-zero area gets the zero vector: callers treat it as having no defined
/// normal (see VertexVisibility).
std::vector<glm::dvec3> angleWeightedNormals(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles);

/// How vertex normals are estimated from the triangles around a vertex
/// (measured against the truth in docs/fidelity.md).
enum class NormalWeighting
{
  /// Face normals weighted by the corner angle (Thuermer and Wuethrich).
  Angle,
  /// Face normals weighted by the face area.
  Area,
  /// N. Max, "Weights for computing vertex normals from facet normals",
  /// JGT 4(2), 1999: cross products of the corner's edges over the product
  /// of their squared lengths; exact for vertices on a sphere.
  Max,
  /// A height field z = a x^2 + b x y + c y^2 + d x + e y through the vertex,
  /// fitted by least squares to the vertex's neighbours in the frame of its
  /// angle-weighted normal; the normal is the field's at the vertex.
  /// Fewer than five neighbours, or a near-singular fit: the angle normal.
  QuadricFit
};

/// Unit vertex normals by `weighting` (zero where undefined, as above).
std::vector<glm::dvec3> vertexNormals(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, NormalWeighting weighting);

/// Triangle t's area vector: its normal as its corners wind, twice its area
/// long.
inline glm::dvec3 areaVector(const std::vector<glm::dvec3>& points, const Triangle& t)
{
  const glm::dvec3& a = points[static_cast<std::size_t>(t[0])];
  return glm::cross(
    points[static_cast<std::size_t>(t[1])] - a, points[static_cast<std::size_t>(t[2])] - a);
}

/// Normalises `normal`, or returns the zero vector when it is too short to
/// have a direction (zero, denormal, or not finite). Inline: the hot loops
/// (face and vertex normals, dihedral angles) call it per triangle.
inline glm::dvec3 safeNormalize(const glm::dvec3& normal)
{
  const double length = glm::length(normal);
  if (!(length > 1e-300) || !std::isfinite(length))
  {
    return glm::dvec3(0.0);
  }
  return normal / length;
}

} // namespace silsmooth
