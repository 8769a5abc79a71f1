#include "AdaptiveSampling.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{

double projectedSagittaPixels(const HermiteCurve& segment, const ViewGeometry& view)
{
  glm::dvec2 middle;
  glm::dvec2 chordMiddle;
  if (!view.toPixels(segment.evaluate(0.5), middle) ||
    !view.toPixels(0.5 * (segment.P0 + segment.P1), chordMiddle))
  {
    return -1.0;
  }
  return glm::length(middle - chordMiddle);
}

int silhouetteSampleCount(const HermiteCurve& segment, const glm::dvec3& n0, const glm::dvec3& n1,
  const ViewGeometry& view, const SamplingParameters& parameters)
{
  const int minimum = std::max(2, parameters.MinimumSamples);
  const int maximum = std::max(minimum, parameters.MaximumSamples);
  const double h = projectedSagittaPixels(segment, view);
  if (h < 0.0)
  {
    return maximum;
  }
  const double tolerance = std::max(parameters.TolerancePixels, 1e-6);
  double samples = 0.0;
  if (parameters.Rule == SamplingRule::ArcBound)
  {
    // h / k^2 underestimates the chord error of an arc (1 - cos x < x^2 / 2)
    // and the Hermite curve's speed is not quite uniform; a 25% margin on h
    // covers both for segments up to a half circle (see TestAdaptiveSampling).
    samples = std::ceil(std::sqrt(ArcBoundMargin * h / tolerance)) + 1.0;
  }
  else
  {
    const double cosAlpha = std::clamp(glm::dot(n0, n1), -1.0, 1.0);
    const double r = std::sqrt(0.5 * (1.0 - cosAlpha));
    samples = std::ceil(0.5 * std::sqrt(h * r / tolerance));
  }
  if (!std::isfinite(samples))
  {
    return maximum;
  }
  return static_cast<int>(
    std::clamp(samples, static_cast<double>(minimum), static_cast<double>(maximum)));
}

} // namespace silsmooth
