// Uniform tessellation of a triangle mesh by a smooth patch per triangle: the
// part PN triangles (PNTriangles.h) and Phong tessellation
// (PhongTessellation.h) share. A patch is given by its position and normal at
// barycentric coordinates of one triangle, from the corners' positions and
// normals only, and by the same on an edge, from the edge's two ends only.
//
// Rules and invariants of the result:
// - Level k inserts k points on every edge, so every input triangle becomes
//   (k + 1)^2 triangles, oriented as the input triangle.
// - Points: the input points first (same ids, same positions, normals given or
//   computed), then the edge points, then the interior points.
// - Edge points are computed once per undirected edge, walking from its lower
//   id: the triangles of an edge use the same point ids, so a closed input
//   gives a closed (watertight) output whatever rounding the patch does.
// - Normals that are missing (a short `normals`) or zero are replaced by
//   angle-weighted normals (ShadingNormals.h); the patches see unit normals.
// - Triangles that repeat a corner (and every triangle at level 0) are copied
//   unchanged.
// - Each output point is also a barycentric combination of the corners of a
//   triangle it lies on (SourcePoints, SourceWeights), for point data.
#pragma once

#include "MeshTopology.h"
#include "Progress.h"

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <vector>

namespace silsmooth
{

struct TessellationResult
{
  /// Input points first (same ids, same positions), then the edge points,
  /// then the interior points.
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Normals;
  /// For point data: each output point as a barycentric combination of the
  /// corners of a triangle it lies on (input points: themselves, weight 1).
  std::vector<std::array<Id, 3>> SourcePoints;
  std::vector<glm::dvec3> SourceWeights;
  std::vector<Triangle> Triangles;
  /// The input triangle of each output triangle.
  std::vector<Id> TriangleSource;
  /// Stopped by the progress callback: everything above is empty.
  bool Aborted = false;
};

/// One triangle's corner positions or normals, in its corner order.
using CornerVectors = std::array<glm::dvec3, 3>;

/// A smooth patch over each triangle, as functions of its corners.
struct TessellationPatch
{
  /// Position or normal at barycentric (a, b, c), a + b + c = 1, of the
  /// triangle with corners `p` and unit corner normals `n`.
  using PatchFunction = std::function<glm::dvec3(
    const CornerVectors& p, const CornerVectors& n, double a, double b, double c)>;
  /// Position or normal on the edge from (p0, n0) to (p1, n1) at t (the weight
  /// of p1). Must equal the patch of either triangle of the edge there, and
  /// use the edge's data only.
  using EdgeFunction = std::function<glm::dvec3(const glm::dvec3& p0, const glm::dvec3& p1,
    const glm::dvec3& n0, const glm::dvec3& n1, double t)>;

  PatchFunction Position;
  PatchFunction Normal;
  EdgeFunction EdgePosition;
  EdgeFunction EdgeNormal;
};

/// Tessellates every triangle at `level` (k >= 0, less is 0) points per edge
/// on `patch`, by the rules above. `progress` hears the fraction of the
/// edges and triangles done, every 4,096 of them; when it returns false the
/// result is empty and Aborted.
TessellationResult tessellateUniformly(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals, int level,
  const TessellationPatch& patch, const ProgressCallback& progress = {});

} // namespace silsmooth
