// The sample count must keep the sampled silhouette within the pixel
// tolerance (docs/methods.md, "How the open choices were closed": sampling). Measured here on circular arcs
// seen head-on in an orthographic view where one model unit is one pixel.
#include "AdaptiveSampling.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace silsmooth;

namespace
{

ViewGeometry unitPixelView()
{
  // Clip = model / 500, viewport 1000 px: one model unit is one pixel.
  ViewGeometry view;
  view.Parallel = true;
  view.ModelToClip = glm::dmat4(1.0 / 500.0);
  view.ModelToClip[3][3] = 1.0;
  view.ViewportWidth = 1000;
  view.ViewportHeight = 1000;
  return view;
}

// Largest distance between the curve and the polyline through `samples`
// evenly spaced parameter values, in model units (= pixels here).
double polylineError(const HermiteCurve& curve, int samples)
{
  double worst = 0.0;
  for (int piece = 0; piece + 1 < samples; ++piece)
  {
    const double t0 = static_cast<double>(piece) / (samples - 1);
    const double t1 = static_cast<double>(piece + 1) / (samples - 1);
    const glm::dvec3 a = curve.evaluate(t0);
    const glm::dvec3 b = curve.evaluate(t1);
    for (int i = 1; i < 50; ++i)
    {
      const glm::dvec3 p = curve.evaluate(t0 + (t1 - t0) * i / 50.0);
      const glm::dvec3 ab = b - a;
      const double s = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
      worst = std::max(worst, glm::distance(p, a + s * ab));
    }
  }
  return worst;
}

struct Arc
{
  HermiteCurve Curve;
  glm::dvec3 N0;
  glm::dvec3 N1;
};

Arc circleArc(double radius, double angle)
{
  const glm::dvec3 n0(std::cos(-angle / 2), std::sin(-angle / 2), 0.0);
  const glm::dvec3 n1(std::cos(angle / 2), std::sin(angle / 2), 0.0);
  return { makeCircleApproximatingCurve(radius * n0, n0, radius * n1, n1), n0, n1 };
}

} // namespace

TEST(AdaptiveSampling, SagittaOfAnArc)
{
  const Arc arc = circleArc(400.0, 1.0);
  // Sagitta of a circular arc: R (1 - cos(angle / 2)).
  EXPECT_NEAR(
    projectedSagittaPixels(arc.Curve, unitPixelView()), 400.0 * (1.0 - std::cos(0.5)), 0.05);
}

TEST(AdaptiveSampling, KeepsTheToleranceOnArcs)
{
  const ViewGeometry view = unitPixelView();
  for (double tolerance : { 0.25, 0.5, 1.0, 2.0 })
  {
    for (double radius : { 20.0, 100.0, 400.0 })
    {
      for (double angle : { 0.2, 0.6, 1.1, 1.6 })
      {
        SamplingParameters parameters;
        parameters.TolerancePixels = tolerance;
        const Arc arc = circleArc(radius, angle);
        const int samples = silhouetteSampleCount(arc.Curve, arc.N0, arc.N1, view, parameters);
        EXPECT_LE(polylineError(arc.Curve, samples), tolerance)
          << "tolerance " << tolerance << " radius " << radius << " angle " << angle << " samples "
          << samples;
        // And it is not wasteful: one sample fewer would leave at least a
        // quarter of the tolerance (the bound is within a factor of about 2
        // of the true error on arcs).
        if (samples > parameters.MinimumSamples)
        {
          EXPECT_GT(polylineError(arc.Curve, samples - 1), 0.25 * tolerance);
        }
      }
    }
  }
}

TEST(AdaptiveSampling, KeepsTheToleranceOnAnyCubic)
{
  // Asymmetric and S-shaped segments are not circular arcs: a rule that
  // measured only the sagitta at S(1/2) missed the tolerance on 31% of the
  // coarse bunny's segments. The bound holds for every cubic.
  const ViewGeometry view = unitPixelView();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
  SamplingParameters parameters;
  parameters.MaximumSamples = 100000;
  for (int i = 0; i < 2000; ++i)
  {
    HermiteCurve curve;
    curve.P0 = { coordinate(rng), coordinate(rng), 0.0 };
    curve.P1 = { coordinate(rng), coordinate(rng), 0.0 };
    curve.T0 = { 2.0 * coordinate(rng), 2.0 * coordinate(rng), 0.0 };
    curve.T1 = { 2.0 * coordinate(rng), 2.0 * coordinate(rng), 0.0 };
    const int samples = silhouetteSampleCount(curve, {}, {}, view, parameters);
    ASSERT_LE(polylineError(curve, samples), parameters.TolerancePixels) << "curve " << i;
  }
}

TEST(AdaptiveSampling, Equation8UnderSamples)
{
  // The measurement behind the choice of default sampling rule: the paper's
  // eq. 8 leaves errors well beyond the tolerance on arcs like those of a
  // coarse sphere's silhouette.
  SamplingParameters paper;
  paper.Rule = SamplingRule::WangEquation8;
  const Arc arc = circleArc(390.0, 1.1); // 80-triangle sphere, 780 px across
  const int samples = silhouetteSampleCount(arc.Curve, arc.N0, arc.N1, unitPixelView(), paper);
  EXPECT_GT(polylineError(arc.Curve, samples), 4.0 * paper.TolerancePixels);
}

TEST(AdaptiveSampling, ClampsAndHandlesPointsBehindTheEye)
{
  SamplingParameters parameters;
  parameters.MinimumSamples = 4;
  parameters.MaximumSamples = 9;
  const Arc tiny = circleArc(0.01, 0.1);
  EXPECT_EQ(silhouetteSampleCount(tiny.Curve, tiny.N0, tiny.N1, unitPixelView(), parameters), 4);
  const Arc huge = circleArc(1e6, 1.0);
  EXPECT_EQ(silhouetteSampleCount(huge.Curve, huge.N0, huge.N1, unitPixelView(), parameters), 9);
  ViewGeometry behind = unitPixelView();
  behind.ModelToClip[3][3] = 0.0; // w = 0 everywhere: nothing projects, nothing is seen
  EXPECT_EQ(silhouetteSampleCount(huge.Curve, huge.N0, huge.N1, behind, parameters), 4);
}
