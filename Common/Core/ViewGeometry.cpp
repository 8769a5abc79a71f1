#include "ViewGeometry.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace silsmooth
{

bool ViewGeometry::toPixels(const glm::dvec3& point, glm::dvec2& pixel) const
{
  const glm::dvec4 clip = this->ModelToClip * glm::dvec4(point, 1.0);
  // w is the distance along the view axis for perspective and 1 for parallel.
  // Any positive w projects (a model at 1e-150 scale has w near 1e-150).
  if (!(clip.w > 0.0))
  {
    return false;
  }
  pixel.x = (clip.x / clip.w + 1.0) * 0.5 * this->ViewportWidth;
  pixel.y = (clip.y / clip.w + 1.0) * 0.5 * this->ViewportHeight;
  return std::isfinite(pixel.x) && std::isfinite(pixel.y);
}

double ViewGeometry::pixelShiftBound(
  const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double distance) const
{
  const glm::dvec4 rows[3] = { this->clipRow(0), this->clipRow(1), this->clipRow(3) };
  double norm[3];
  double largest[3] = { 0.0, 0.0, HUGE_VAL }; // |x| and |y| at most, w at least
  for (int i = 0; i < 3; ++i)
  {
    const glm::dvec3 linear(rows[i]);
    norm[i] = glm::length(linear);
    for (const glm::dvec3* p : { &a, &b, &c })
    {
      const double value = glm::dot(linear, *p) + rows[i].w;
      largest[i] = i < 2 ? std::max(largest[i], std::abs(value)) : std::min(largest[i], value);
    }
  }
  // Over the region: w >= wLeast, |x| <= xMost, |y| <= yMost, since each
  // is a corner's combination plus a move of at most `distance`.
  const double wLeast = largest[2] - norm[2] * distance;
  if (!(wLeast > 0.0))
  {
    return std::numeric_limits<double>::infinity();
  }
  // d(x / w) = (dx - (x / w) dw) / w, per unit of the move.
  auto slope = [&](int i) {
    const double most = largest[i] + norm[i] * distance;
    return (norm[i] + most / wLeast * norm[2]) / wLeast;
  };
  const double sx = slope(0) * 0.5 * this->ViewportWidth;
  const double sy = slope(1) * 0.5 * this->ViewportHeight;
  const double bound = distance * std::sqrt(sx * sx + sy * sy);
  return std::isfinite(bound) ? bound : std::numeric_limits<double>::infinity();
}

} // namespace silsmooth
