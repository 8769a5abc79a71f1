#include "SilhouettePoint.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{

VisibilityQuadratic visibilityAlongEdge(
  const glm::dvec3& n0, const glm::dvec3& d0, const glm::dvec3& n1, const glm::dvec3& d1)
{
  // h(u) = (d0 + u dd) . (n0 + u dn)
  const glm::dvec3 dd = d1 - d0;
  const glm::dvec3 dn = n1 - n0;
  VisibilityQuadratic h;
  h.A = glm::dot(dd, dn);
  h.B = glm::dot(d0, dn) + glm::dot(dd, n0);
  h.C = glm::dot(d0, n0);
  return h;
}

namespace
{

bool isVisible(double g)
{
  return g >= 0.0;
}

// Bisection on the visibility status; 64 halvings reach the spacing of doubles
// in [0, 1]. Used only when the closed form is not trustworthy.
double bisect(const VisibilityQuadratic& h, bool visibleAtZero)
{
  double lo = 0.0;
  double hi = 1.0;
  for (int i = 0; i < 64 && hi - lo > 0.0; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi)
    {
      break;
    }
    if (isVisible(h(mid)) == visibleAtZero)
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

} // namespace

double silhouetteParameter(const VisibilityQuadratic& h, double h0, double h1)
{
  if (h0 == 0.0)
  {
    return 0.0;
  }
  if (h1 == 0.0)
  {
    return 1.0;
  }
  const bool visibleAtZero = isVisible(h0);
  // Roots this far outside [0, 1] are rounding of a root at an end.
  constexpr double slack = 1e-9;
  const double scale = std::abs(h.A) + std::abs(h.B) + std::abs(h.C);

  double candidates[2];
  int candidateCount = 0;
  if (std::abs(h.A) <= 1e-12 * scale)
  {
    if (h.B != 0.0)
    {
      candidates[candidateCount++] = -h.C / h.B;
    }
  }
  else
  {
    const double discriminant = std::max(0.0, h.B * h.B - 4.0 * h.A * h.C);
    // Stable form: no cancellation between -B and the square root.
    const double q = -0.5 * (h.B + std::copysign(std::sqrt(discriminant), h.B));
    candidates[candidateCount++] = q / h.A;
    if (q != 0.0)
    {
      candidates[candidateCount++] = h.C / q;
    }
  }

  int inside = 0;
  double root = 0.0;
  for (int i = 0; i < candidateCount; ++i)
  {
    if (std::isfinite(candidates[i]) && candidates[i] >= -slack && candidates[i] <= 1.0 + slack)
    {
      root = candidates[i];
      ++inside;
    }
  }
  // A lone root that does not make h small is a casualty of underflow or
  // cancellation in the coefficients.
  if (inside == 1 && !(std::abs(h(std::clamp(root, 0.0, 1.0))) <= 1e-9 * scale))
  {
    inside = 0;
  }
  if (inside != 1)
  {
    // None or two in range: rounding has blurred the picture; the sign change
    // still brackets exactly one crossing, so bisection is safe.
    return bisect(h, visibleAtZero);
  }
  return std::clamp(root, 0.0, 1.0);
}

} // namespace silsmooth
