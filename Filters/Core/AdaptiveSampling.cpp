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

double projectedSecondDifferencePixels(const HermiteCurve& segment, const ViewGeometry& view)
{
  const glm::dvec3 control[4] = { segment.P0, segment.P0 + segment.T0 / 3.0,
    segment.P1 - segment.T1 / 3.0, segment.P1 };
  glm::dvec2 q[4];
  for (int i = 0; i < 4; ++i)
  {
    if (!view.toPixels(control[i], q[i]))
    {
      return -1.0;
    }
  }
  return std::max(glm::length(q[0] - 2.0 * q[1] + q[2]), glm::length(q[1] - 2.0 * q[2] + q[3]));
}

int silhouetteSampleCount(const HermiteCurve& segment, const glm::dvec3& n0, const glm::dvec3& n1,
  const ViewGeometry& view, const SamplingParameters& parameters)
{
  const int minimum = std::max(2, parameters.MinimumSamples);
  const int maximum = std::max(minimum, parameters.MaximumSamples);
  const double tolerance = std::max(parameters.TolerancePixels, 1e-6);
  double samples = 0.0;
  if (parameters.Rule == SamplingRule::SecondDifference)
  {
    const double m = projectedSecondDifferencePixels(segment, view);
    if (m < 0.0)
    {
      return minimum;
    }
    samples = std::ceil(std::sqrt(0.75 * m / tolerance)) + 1.0;
  }
  else
  {
    const double h = projectedSagittaPixels(segment, view);
    if (h < 0.0)
    {
      return minimum;
    }
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
