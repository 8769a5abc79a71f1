// Edge extraction of Kim and Choe (3.3, Algorithms 1 and 2): every edge of a
// triangle mesh is flagged as
// - silhouette: between two triangles with (N1 . V)(N2 . V) <= 0 (eq. 2),
//   N the (unnormalised) face normals and V the view vector: eye minus the
//   edge's midpoint in perspective, minus the direction of projection in
//   parallel projection;
// - crease: between two triangles whose normals turn by more than the
//   crease angle (the dihedral test of Algorithm 1);
// - border: in exactly one triangle.
// An edge can carry several flags. Edges in more than two triangles, and
// triangles with a repeated corner or zero area, take no part (their edges
// get no silhouette or crease flag from them).
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

enum EdgeFlag : unsigned
{
  SilhouetteEdge = 1u,
  CreaseEdge = 2u,
  BorderEdge = 4u
};

struct FlaggedEdge
{
  Id a = 0; ///< lower point id
  Id b = 0; ///< higher point id
  unsigned flags = 0;
};

struct EdgeView
{
  bool parallel = false;
  glm::dvec3 eye{ 0.0, 0.0, 1.0 };
  glm::dvec3 direction{ 0.0, 0.0, -1.0 };
};

/// Every edge of the mesh with its flags (possibly 0), sorted by (a, b).
std::vector<FlaggedEdge> classifyEdges(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const EdgeView& view, double creaseAngleDegrees);

/// The edges with any of `mask`'s flags chained into polylines (point ids;
/// a closed loop repeats its first id at the end).
std::vector<std::vector<Id>> chainFlaggedEdges(
  const std::vector<FlaggedEdge>& edges, unsigned mask);

} // namespace silsmooth
