// Cubic Hermite curves with circle-preserving end tangents (Wang et al. 2008,
// III-C, eqs. 2-5). Used for silhouette bridges (over a mesh edge) and
// silhouette segments (between two silhouette points).
#pragma once

#include <glm/vec3.hpp>

namespace silsmooth
{

struct HermiteCurve
{
  glm::dvec3 P0{ 0.0 };
  glm::dvec3 P1{ 0.0 };
  glm::dvec3 T0{ 0.0 };
  glm::dvec3 T1{ 0.0 };

  /// Eq. 5: S(u) = (2P0 - 2P1 + T0 + T1)u^3 - (3P0 - 3P1 + 2T0 + T1)u^2 + T0 u + P0.
  glm::dvec3 evaluate(double u) const;
};

/// The end tangent of a curve along `chord` at an end with unit normal
/// `normal`: the chord projected on the end's tangent plane (eqs. 2-3), scaled to
/// L = 2|chord| / (1 + cos(theta)) (eq. 4) so that end data sampled from a
/// circular arc give the standard cubic approximation of that arc.
/// Where the projection vanishes (the chord is parallel to the normal, or the
/// normal is zero) the chord itself is used, which makes the curve straight at
/// that end instead of dividing by ~0.
glm::dvec3 circleTangent(const glm::dvec3& normal, const glm::dvec3& chord);

/// The Hermite curve from p0 to p1 with unit normals n0, n1 at the ends.
///
/// No overshoot (the bulge invariant). Write c = p1 - p0 and T_perp for the
/// part of an end tangent across the chord; eq. 4 gives
/// |T_perp| = 2|c| tan(theta / 2) with theta <= 90 degrees. Then every point of
/// the curve
/// - projects onto the chord's line between p0 and p1 (the curve never runs
///   past its ends), and
/// - lies within chordDeviationBound(curve) = max |T_perp| / 4
///   = (|c| / 2) tan(theta_max / 2) of the chord.
/// For end data taken from a circular arc, that bound is the arc's own
/// sagitta: a bridge or segment never bulges beyond the circle its ends'
/// normals imply, and whatever the normals never beyond half its chord (a
/// semicircle). Frustum culling (SilhouettePass::cullOutsideFrustum) relies on it.
HermiteCurve makeCircleApproximatingCurve(
  const glm::dvec3& p0, const glm::dvec3& n0, const glm::dvec3& p1, const glm::dvec3& n1);

/// The largest distance of `curve` from its chord that the bulge invariant
/// above allows: a quarter of the larger end tangent's part across the chord.
double chordDeviationBound(const HermiteCurve& curve);

/// The largest distance between C(u) and the point at the same parameter on
/// the chord, P0 + u (P1 - P0), for u in [0, 1]: a quarter of the larger of
/// |T0 - c| and |T1 - c|, c = P1 - P0. (C(u) minus that point is
/// h10(u) (T0 - c) + h11(u) (T1 - c), and |h10(u)| + |h11(u)| = u (1 - u).)
/// Unlike chordDeviationBound it also bounds the slide along the chord: a
/// re-meshing that puts C(u) where the flat triangle has the chord's point
/// moves that point by at most this much.
double parametricDeviationBound(const HermiteCurve& curve);

} // namespace silsmooth
