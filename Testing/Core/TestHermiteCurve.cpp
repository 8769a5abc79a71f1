// The silhouette bridges and segments rely on eq. 4 making a Hermite curve
// that hugs a circular arc when the end data come from one.
#include "HermiteCurve.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using silsmooth::HermiteCurve;
using silsmooth::makeCircleApproximatingCurve;

namespace
{

// Largest |radius - 1| along the curve for an arc of the unit circle in the
// XY plane spanning `angle` radians, end normals radial.
double maxRadialError(double angle)
{
  const glm::dvec3 n0(1.0, 0.0, 0.0);
  const glm::dvec3 n1(std::cos(angle), std::sin(angle), 0.0);
  const HermiteCurve curve = makeCircleApproximatingCurve(n0, n0, n1, n1);
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i)
  {
    worst = std::max(worst, std::abs(glm::length(curve.evaluate(i / 1000.0)) - 1.0));
  }
  return worst;
}

} // namespace

TEST(HermiteCurve, InterpolatesItsEnds)
{
  const glm::dvec3 p0(0.3, -1.0, 2.0);
  const glm::dvec3 p1(1.5, 0.25, -0.5);
  const HermiteCurve curve =
    makeCircleApproximatingCurve(p0, glm::normalize(glm::dvec3(0, 1, 1)), p1, glm::dvec3(1, 0, 0));
  EXPECT_EQ(curve.evaluate(0.0), p0);
  EXPECT_LT(glm::distance(curve.evaluate(1.0), p1), 1e-14);
}

TEST(HermiteCurve, ApproximatesCircularArcs)
{
  // The standard cubic approximation of a quarter circle is off by 2.7e-4 of
  // the radius, and the error scales with the sixth power of the angle.
  EXPECT_LT(maxRadialError(M_PI / 2.0), 3.0e-4);
  EXPECT_LT(maxRadialError(M_PI / 3.0), 3.0e-5);
  EXPECT_LT(maxRadialError(M_PI / 6.0), 5.0e-7);
  EXPECT_LT(maxRadialError(M_PI / 6.0), maxRadialError(M_PI / 3.0) / 32.0);
}

TEST(HermiteCurve, TangentLengthFollowsEquation4)
{
  // For an arc of angle phi the end tangent makes theta = phi / 2 with the
  // chord, and L = 2|chord| / (1 + cos theta) = 4 R tan(phi / 4).
  const double phi = 1.1;
  const glm::dvec3 n0(1.0, 0.0, 0.0);
  const glm::dvec3 n1(std::cos(phi), std::sin(phi), 0.0);
  const HermiteCurve curve = makeCircleApproximatingCurve(n0, n0, n1, n1);
  EXPECT_NEAR(glm::length(curve.T0), 4.0 * std::tan(phi / 4.0), 1e-12);
  EXPECT_NEAR(glm::length(curve.T1), 4.0 * std::tan(phi / 4.0), 1e-12);
  // Tangent to the circle: perpendicular to the radius.
  EXPECT_NEAR(glm::dot(curve.T0, n0), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(curve.T1, n1), 0.0, 1e-12);
}

TEST(HermiteCurve, FlatNormalsGiveTheStraightChord)
{
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const HermiteCurve curve = makeCircleApproximatingCurve({ 0, 0, 0 }, up, { 2, 0, 0 }, up);
  for (double u : { 0.1, 0.5, 0.9 })
  {
    const glm::dvec3 p = curve.evaluate(u);
    EXPECT_NEAR(p.x, 2.0 * u, 1e-14);
    EXPECT_EQ(p.y, 0.0);
    EXPECT_EQ(p.z, 0.0);
  }
}

TEST(HermiteCurve, ChordAlongTheNormalFallsBackToTheChord)
{
  // The projected tangent vanishes: no division by ~0, a finite straight end.
  const glm::dvec3 n(0.0, 0.0, 1.0);
  const HermiteCurve curve = makeCircleApproximatingCurve({ 0, 0, 0 }, n, { 0, 0, 1 }, n);
  EXPECT_EQ(curve.T0, glm::dvec3(0, 0, 1));
  EXPECT_EQ(curve.T1, glm::dvec3(0, 0, 1));
  const glm::dvec3 mid = curve.evaluate(0.5);
  EXPECT_TRUE(std::isfinite(mid.x) && std::isfinite(mid.y) && std::isfinite(mid.z));
  // Zero normals and a zero chord stay finite too.
  const HermiteCurve none = makeCircleApproximatingCurve({ 1, 1, 1 }, {}, { 1, 1, 1 }, {});
  EXPECT_EQ(none.evaluate(0.5), glm::dvec3(1, 1, 1));
}
