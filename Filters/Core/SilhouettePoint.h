// The silhouette point on a silhouette bridge (Wang et al. 2008, III-D).
//
// Along an edge V0 -> V1 the normal and the direction to the viewer are both
// interpolated linearly (eqs. 6-7), so h(u) = D(u) . N(u) is a quadratic in u
// (linear for parallel projection, where D is constant). h(0) = g(V0) and
// h(1) = g(V1) differ in sign on a silhouette bridge, so h has exactly one
// root in [0, 1]; this unit finds it robustly.
#pragma once

#include <glm/vec3.hpp>

namespace silsmooth
{

/// Coefficients of h(u) = a u^2 + b u + c.
struct VisibilityQuadratic
{
  double A = 0.0;
  double B = 0.0;
  double C = 0.0;

  double operator()(double u) const { return (this->A * u + this->B) * u + this->C; }
};

/// h(u) for the edge from (p0, n0, d0) to (p1, n1, d1), where d is the
/// direction to the viewer at each end. C equals n0 . d0 and A + B + C equals
/// n1 . d1 up to rounding.
VisibilityQuadratic visibilityAlongEdge(
  const glm::dvec3& n0, const glm::dvec3& d0, const glm::dvec3& n1, const glm::dvec3& d1);

/// The root of h in [0, 1], given h(0) = h0 and h(1) = h1 of opposite visibility
/// (h0 >= 0 > h1 or h1 >= 0 > h0; the values passed are those the visibility
/// pass computed, so the bracket is the one that classified the edge). Uses the
/// numerically stable closed form and falls back to bisection when rounding
/// puts the closed-form root outside the bracket. Always returns a value in
/// [0, 1]; returns 0 when h0 == 0 and 1 when h1 == 0.
double silhouetteParameter(const VisibilityQuadratic& h, double h0, double h1);

} // namespace silsmooth
