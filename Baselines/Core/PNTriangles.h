// Curved PN triangles (A. Vlachos, J. Peters, C. Boyd, J. L. Mitchell, "Curved
// PN Triangles", I3D 2001): each triangle becomes a cubic Bezier triangle
// built from its corners' positions and normals only, with a quadratic normal
// field, tessellated uniformly. The 2008 paper's Table I compares with it.
//
// Level k inserts k points on every edge, so every input triangle becomes
// (k + 1)^2 triangles. The corners stay where they were (and keep their ids);
// points on an edge depend only on that edge's two ends and normals and are
// computed once per undirected edge (from the lower id), so the triangles of
// an edge share them: a closed input gives a closed (watertight) output. The
// tessellation itself is UniformTessellation's, shared with Phong
// tessellation (PhongTessellation.h).
// Control points: b210 = (2 P0 + P1 - w01 N0) / 3 with w01 = (P1 - P0) . N0,
// b111 = E + (E - V) / 2 (E the mean of the six edge control points, V of the
// corners). Normals: n110 = normalize(N0 + N1 - v01 (P1 - P0)) with
// v01 = 2 (P1 - P0) . (N0 + N1) / |P1 - P0|^2, and
// n = N0 a^2 + N1 b^2 + N2 c^2 + n110 a b + n011 b c + n101 c a, normalised.
// A flat triangle whose corner normals are its face normal stays flat.
#pragma once

#include "MeshTopology.h"
#include "UniformTessellation.h"

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace silsmooth
{

/// The layout and guarantees of UniformTessellation.h.
using PNTriangleResult = TessellationResult;

/// The cubic PN patch of one triangle at barycentric (a, b, c), a + b + c = 1.
glm::dvec3 pnPosition(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
  double a, double b, double c);
/// Its quadratic normal there (unit, or zero when undefined).
glm::dvec3 pnNormal(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
  double a, double b, double c);

/// Tessellates every triangle at `level` (k >= 0) points per edge. `normals`
/// may be empty or hold zero vectors: those are replaced by angle-weighted
/// normals. Triangles that repeat a corner are copied unchanged. `progress`
/// as in tessellateUniformly.
PNTriangleResult tessellatePNTriangles(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals, int level,
  const ProgressCallback& progress = {});

} // namespace silsmooth
