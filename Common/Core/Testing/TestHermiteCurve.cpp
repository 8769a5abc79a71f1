// The silhouette bridges and segments rely on eq. 4 making a Hermite curve
// that hugs a circular arc when the end data come from one.
#include "HermiteCurve.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

namespace
{

struct ChordDeviation
{
  double Excess = -1.0;   // largest (distance from the chord) - chordDeviationBound
  bool PastAnEnd = false; // some point projects outside [p0, p1] on the chord's line
};

ChordDeviation measureChordDeviation(const HermiteCurve& curve)
{
  const glm::dvec3 chord = curve.P1 - curve.P0;
  const double chordSquared = glm::dot(chord, chord);
  const double bound = silsmooth::chordDeviationBound(curve);
  // Rounding of points far from the origin, relative to the chord.
  const double slack = 1e-14 *
    (glm::length(curve.P0) + glm::length(curve.T0) + glm::length(curve.T1) +
      std::sqrt(chordSquared));
  const double alongSlack = slack / std::sqrt(chordSquared);
  ChordDeviation result;
  for (int i = 0; i <= 200; ++i)
  {
    const glm::dvec3 offset = curve.evaluate(i / 200.0) - curve.P0;
    const double along = glm::dot(offset, chord) / chordSquared;
    result.PastAnEnd = result.PastAnEnd || along < -alongSlack || along > 1.0 + alongSlack;
    const double across = glm::length(offset - along * chord);
    result.Excess = std::max(result.Excess, across - bound - slack);
  }
  return result;
}

glm::dvec3 randomUnitVector(std::mt19937& random)
{
  std::normal_distribution<double> gauss;
  glm::dvec3 v(gauss(random), gauss(random), gauss(random));
  return glm::normalize(v);
}

} // namespace

TEST(HermiteCurve, NeverBulgesBeyondTheCircleItsEndsImply)
{
  // The bulge invariant of HermiteCurve.h, over arbitrary normals and chords:
  // within the bound, never past the ends, and the bound at most half the chord.
  std::mt19937 random(2008);
  std::uniform_real_distribution<double> scale(1e-3, 1e3);
  int curved = 0;
  for (int i = 0; i < 20000; ++i)
  {
    const glm::dvec3 p0 = scale(random) * randomUnitVector(random);
    const glm::dvec3 p1 = p0 + scale(random) * randomUnitVector(random);
    const HermiteCurve curve =
      makeCircleApproximatingCurve(p0, randomUnitVector(random), p1, randomUnitVector(random));
    const ChordDeviation deviation = measureChordDeviation(curve);
    ASSERT_LE(deviation.Excess, 0.0) << "curve " << i;
    ASSERT_FALSE(deviation.PastAnEnd) << "curve " << i;
    const double half = 0.5 * glm::distance(p0, p1);
    ASSERT_LE(silsmooth::chordDeviationBound(curve), half * (1.0 + 1e-12)) << "curve " << i;
    curved += silsmooth::chordDeviationBound(curve) > 0.1 * half;
  }
  EXPECT_GT(curved, 10000); // the draws exercise the bound, not straight chords
}

TEST(HermiteCurve, ChordDeviationBoundIsTheArcsSagitta)
{
  // For an arc of angle phi of the unit circle the sagitta is 1 - cos(phi / 2),
  // and the cubic's largest distance from the chord lies within 3e-4 of it.
  for (double phi : { 0.3, 1.0, M_PI / 2.0, 2.5 })
  {
    const glm::dvec3 n0(1.0, 0.0, 0.0);
    const glm::dvec3 n1(std::cos(phi), std::sin(phi), 0.0);
    const HermiteCurve curve = makeCircleApproximatingCurve(n0, n0, n1, n1);
    EXPECT_NEAR(silsmooth::chordDeviationBound(curve), 1.0 - std::cos(phi / 2.0), 1e-12) << phi;
    EXPECT_LE(measureChordDeviation(curve).Excess, 0.0);
    EXPECT_GT(measureChordDeviation(curve).Excess, -3e-4 * (phi > 2.0 ? 10.0 : 1.0)) << phi;
  }
}

TEST(HermiteCurve, OtherTangentsBreakTheBulgeInvariant)
{
  // The checks above can fail. Tangents as long as the chord's run along them
  // (L = |c| / cos(theta)) bulge without bound; tangents whose direction lost
  // its sign (pointing away from the other end) run past the ends.
  const glm::dvec3 p0(0.0), p1(1.0, 0.0, 0.0);
  const glm::dvec3 steep = glm::normalize(glm::dvec3(-1.0, 0.0, 0.05)); // theta near 90 degrees
  HermiteCurve tooLong = makeCircleApproximatingCurve(p0, steep, p1, steep);
  ASSERT_LE(measureChordDeviation(tooLong).Excess, 0.0);
  const double along = glm::dot(glm::normalize(tooLong.T0), p1 - p0);
  tooLong.T0 = glm::normalize(tooLong.T0) / along;
  tooLong.T1 = glm::normalize(tooLong.T1) / along;
  EXPECT_GT(silsmooth::chordDeviationBound(tooLong), 0.5);

  const glm::dvec3 gentle = glm::normalize(glm::dvec3(-0.2, 0.0, 1.0));
  HermiteCurve reversed = makeCircleApproximatingCurve(p0, gentle, p1, gentle);
  ASSERT_FALSE(measureChordDeviation(reversed).PastAnEnd);
  reversed.T0 = -reversed.T0;
  reversed.T1 = -reversed.T1;
  EXPECT_TRUE(measureChordDeviation(reversed).PastAnEnd);
}

TEST(HermiteCurve, ParametricDeviationBoundHoldsAndIsReached)
{
  // parametricDeviationBound bounds |C(u) - (P0 + u c)|, the move of a point
  // that a re-meshing puts on the curve instead of the chord, and is reached:
  // a bound a tenth lower fails.
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> scale(1e-3, 1e3);
  double tightest = 0.0; // largest measured / bound
  for (int i = 0; i < 20000; ++i)
  {
    const glm::dvec3 p0 = scale(random) * randomUnitVector(random);
    const glm::dvec3 p1 = p0 + scale(random) * randomUnitVector(random);
    const HermiteCurve curve =
      makeCircleApproximatingCurve(p0, randomUnitVector(random), p1, randomUnitVector(random));
    const double bound = silsmooth::parametricDeviationBound(curve);
    const double slack = 1e-14 *
      (glm::length(curve.P0) + glm::length(curve.T0) + glm::length(curve.T1) +
        glm::length(p1 - p0));
    double largest = 0.0;
    for (int k = 0; k <= 200; ++k)
    {
      const double u = k / 200.0;
      largest =
        std::max(largest, glm::length(curve.evaluate(u) - (curve.P0 + u * (curve.P1 - curve.P0))));
    }
    ASSERT_LE(largest, bound + slack) << "curve " << i;
    tightest = std::max(tightest, largest / std::max(bound, 1e-300));
  }
  EXPECT_GT(tightest, 0.9) << "the bound is reached (equal end tangents, u = 1/2)";
}
