// Phong tessellation (T. Boubekeur, M. Alexa, "Phong Tessellation", ACM TOG
// 27(5), SIGGRAPH Asia 2008): the geometric analogue of Phong shading, a peer
// of PN triangles (PNTriangles.h). For a triangle with corners p_i, p_j, p_k
// and unit corner normals n_i, n_j, n_k, at barycentric (u, v, w):
//   p = u p_i + v p_j + w p_k                    the flat point,
//   pi_m(q) = q - ((q - p_m) . n_m) n_m          q onto corner m's tangent plane,
//   p* = (1 - a) p + a (u pi_i(p) + v pi_j(p) + w pi_k(p)),
// a quadratic patch with shape factor a (the paper's 3/4 by default; 0 is the
// flat triangle). p* is evaluated as p + a sum_m u_m (pi_m(p) - p), the same
// point since u + v + w = 1, so that a = 0 or a flat triangle with its face
// normal at the corners gives exactly the flat point. Normals are the Phong
// normals: the corner normals interpolated linearly, normalised (zero when
// they cancel), not the patch's own.
//
// On an edge p* depends only on the edge's two ends and normals, so the two
// triangles of an edge agree there; the tessellation (UniformTessellation.h)
// computes edge points once per undirected edge, so a closed input gives a
// closed (watertight) output. Level k inserts k points on every edge: every
// input triangle becomes (k + 1)^2 triangles. The corners stay where they were
// (and keep their ids).
#pragma once

#include "MeshTopology.h"
#include "UniformTessellation.h"

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace silsmooth
{

/// The layout and guarantees of UniformTessellation.h.
using PhongTessellationResult = TessellationResult;

/// The paper's shape factor.
constexpr double PhongDefaultShapeFactor = 0.75;

/// The Phong patch of one triangle (corners `p`, unit corner normals `n`) at
/// barycentric (u, v, w), u + v + w = 1, with shape factor `shapeFactor`.
glm::dvec3 phongPosition(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
  double u, double v, double w, double shapeFactor = PhongDefaultShapeFactor);
/// The Phong normal there: normalize(u n_i + v n_j + w n_k), or zero when the
/// normals cancel.
glm::dvec3 phongNormal(const std::array<glm::dvec3, 3>& n, double u, double v, double w);

/// Tessellates every triangle at `level` (k >= 0) points per edge on its
/// Phong patch. `normals` may be empty or hold zero vectors: those are
/// replaced by angle-weighted normals. Triangles that repeat a corner are
/// copied unchanged. `shapeFactor` is used as given (the paper keeps it in
/// [0, 1]). `progress` as in tessellateUniformly.
PhongTessellationResult tessellatePhong(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals, int level,
  double shapeFactor = PhongDefaultShapeFactor, const ProgressCallback& progress = {});

} // namespace silsmooth
