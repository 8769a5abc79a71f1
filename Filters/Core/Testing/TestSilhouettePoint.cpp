// The silhouette point is the root of h(u) = D(u) . N(u) in [0, 1] (III-D).
#include "SilhouettePoint.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using silsmooth::silhouetteParameter;
using silsmooth::visibilityAlongEdge;
using silsmooth::VisibilityQuadratic;

namespace
{

VisibilityQuadratic quadratic(double a, double b, double c)
{
  VisibilityQuadratic h;
  h.A = a;
  h.B = b;
  h.C = c;
  return h;
}

double solve(const VisibilityQuadratic& h)
{
  return silhouetteParameter(h, h(0.0), h(1.0));
}

} // namespace

TEST(SilhouettePoint, CoefficientsMatchTheEnds)
{
  const glm::dvec3 n0 = glm::normalize(glm::dvec3(1, 0.2, 0));
  const glm::dvec3 n1 = glm::normalize(glm::dvec3(-0.3, 1, 0.1));
  const glm::dvec3 d0(0.5, -2, 3);
  const glm::dvec3 d1(-1, 0.7, 2);
  const VisibilityQuadratic h = visibilityAlongEdge(n0, d0, n1, d1);
  EXPECT_NEAR(h(0.0), glm::dot(n0, d0), 1e-14);
  EXPECT_NEAR(h(1.0), glm::dot(n1, d1), 1e-14);
  const double u = 0.37;
  EXPECT_NEAR(h(u), glm::dot((1 - u) * n0 + u * n1, (1 - u) * d0 + u * d1), 1e-14);
}

TEST(SilhouettePoint, ExactRoots)
{
  EXPECT_DOUBLE_EQ(solve(quadratic(0.0, -2.0, 1.0)), 0.5);    // linear (parallel projection)
  EXPECT_NEAR(solve(quadratic(1.0, 0.0, -0.25)), 0.5, 1e-15); // u^2 - 1/4
  EXPECT_NEAR(solve(quadratic(-1.0, 0.0, 0.09)), 0.3, 1e-15); // roots +-0.3
  EXPECT_NEAR(solve(quadratic(1.0, -2.2, 0.4)), 0.2, 1e-14);  // roots 0.2 and 2
  EXPECT_NEAR(solve(quadratic(1.0, 1.8, -0.4)), 0.2, 1e-14);  // roots 0.2 and -2
}

TEST(SilhouettePoint, EndsOnTheSurfaceOfVisibility)
{
  // g = 0 counts as visible: the silhouette point is that end exactly.
  EXPECT_EQ(silhouetteParameter(quadratic(0.3, -1.0, 0.0), 0.0, -0.7), 0.0);
  EXPECT_EQ(silhouetteParameter(quadratic(0.3, 1.0, -1.3), -1.3, 0.0), 1.0);
}

TEST(SilhouettePoint, NearDegenerateCases)
{
  // Nearly linear: A tiny against B and C.
  EXPECT_NEAR(solve(quadratic(1e-17, -1.0, 0.5)), 0.5, 1e-15);
  // Root extremely close to an end.
  const double nearZero = solve(quadratic(0.0, -1.0, 1e-13));
  EXPECT_GE(nearZero, 0.0);
  EXPECT_NEAR(nearZero, 1e-13, 1e-20);
  const double nearOne = solve(quadratic(0.0, -1.0, 1.0 - 1e-13));
  EXPECT_LE(nearOne, 1.0);
  EXPECT_NEAR(nearOne, 1.0 - 1e-13, 1e-15);
  // Nearly a double root at the far end: roots 1 - eps (inside) and 1 + eps.
  const double eps = 1e-6;
  const VisibilityQuadratic nearDouble = quadratic(1.0, -2.0, 1.0 - eps * eps);
  const double u = solve(nearDouble);
  // A near-double root is ill-conditioned (a rounding of C moves it by about
  // sqrt(C's rounding)), so the test is on h(u), with a loose bound on u.
  EXPECT_LT(std::abs(nearDouble(u)), 1e-15);
  EXPECT_NEAR(u, 1.0 - eps, 1e-9);
  // Tiny magnitudes everywhere.
  EXPECT_NEAR(solve(quadratic(1e-300, -2e-300, 5e-301)), 0.29289321881345254, 1e-12);
}

TEST(SilhouettePoint, RandomQuadraticsWithASignChange)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coefficient(-10.0, 10.0);
  int solved = 0;
  while (solved < 20000)
  {
    const VisibilityQuadratic h = quadratic(coefficient(rng), coefficient(rng), coefficient(rng));
    const double h0 = h(0.0);
    const double h1 = h(1.0);
    if ((h0 >= 0.0) == (h1 >= 0.0))
    {
      continue;
    }
    ++solved;
    const double u = silhouetteParameter(h, h0, h1);
    ASSERT_GE(u, 0.0);
    ASSERT_LE(u, 1.0);
    // |h(u)| is at rounding level of the coefficients.
    const double scale = std::abs(h.A) + std::abs(h.B) + std::abs(h.C);
    ASSERT_LT(std::abs(h(u)), 1e-12 * scale) << h.A << " " << h.B << " " << h.C;
  }
}
