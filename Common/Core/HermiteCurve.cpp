#include "HermiteCurve.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace silsmooth
{

glm::dvec3 HermiteCurve::evaluate(double u) const
{
  // Horner form of eq. 5.
  const glm::dvec3 a = 2.0 * this->P0 - 2.0 * this->P1 + this->T0 + this->T1;
  const glm::dvec3 b = -3.0 * this->P0 + 3.0 * this->P1 - 2.0 * this->T0 - this->T1;
  return ((a * u + b) * u + this->T0) * u + this->P0;
}

glm::dvec3 circleTangent(const glm::dvec3& normal, const glm::dvec3& chord)
{
  const double chordLength = glm::length(chord);
  if (!(chordLength > 0.0))
  {
    return glm::dvec3(0.0);
  }
  const glm::dvec3 projected = chord - glm::dot(chord, normal) * normal;
  const double projectedLength = glm::length(projected);
  // Relative threshold: below it the direction of `projected` is noise.
  if (!(projectedLength > 1e-9 * chordLength))
  {
    return chord; // straight end: cos(theta) = 1, so L = |chord|
  }
  const double cosTheta =
    std::clamp(glm::dot(chord, projected) / (chordLength * projectedLength), 0.0, 1.0);
  const double length = 2.0 * chordLength / (1.0 + cosTheta);
  return projected * (length / projectedLength);
}

HermiteCurve makeCircleApproximatingCurve(
  const glm::dvec3& p0, const glm::dvec3& n0, const glm::dvec3& p1, const glm::dvec3& n1)
{
  const glm::dvec3 chord = p1 - p0;
  HermiteCurve curve;
  curve.P0 = p0;
  curve.P1 = p1;
  curve.T0 = circleTangent(n0, chord);
  curve.T1 = circleTangent(n1, chord);
  return curve;
}

double chordDeviationBound(const HermiteCurve& curve)
{
  const glm::dvec3 chord = curve.P1 - curve.P0;
  const double chordSquared = glm::dot(chord, chord);
  if (!(chordSquared > 0.0))
  {
    return 0.0;
  }
  const auto across = [&](const glm::dvec3& tangent) {
    return glm::length(tangent - (glm::dot(tangent, chord) / chordSquared) * chord);
  };
  // The across-chord deviation is h10(u) T0_perp + h11(u) T1_perp, and
  // |h10(u)| + |h11(u)| = u (1 - u) <= 1/4.
  return 0.25 * std::max(across(curve.T0), across(curve.T1));
}

double parametricDeviationBound(const HermiteCurve& curve)
{
  const glm::dvec3 chord = curve.P1 - curve.P0;
  return 0.25 * std::max(glm::length(curve.T0 - chord), glm::length(curve.T1 - chord));
}

} // namespace silsmooth
