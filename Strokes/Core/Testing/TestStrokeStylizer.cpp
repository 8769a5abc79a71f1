// Brush functions of Kim and Choe (3.5): every offset bounded by the
// amplitude, zero amplitude gives the stroke back, and the noise is repeatable.
#include "StrokeStylizer.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace silsmooth;

namespace
{

std::vector<glm::dvec3> circleStroke(int n)
{
  std::vector<glm::dvec3> points;
  for (int i = 0; i <= n; ++i)
  {
    const double a = 2.0 * 3.14159265358979 * i / n;
    points.emplace_back(std::cos(a), std::sin(a), 0.1 * std::sin(3 * a));
  }
  return points;
}

const Brush allBrushes[] = { Brush::Charcoal, Brush::Lazy, Brush::Hand, Brush::Rough };

} // namespace

TEST(StrokeStylizer, OffsetsAreBoundedByTheAmplitude)
{
  const StrokeView view; // perspective, eye on +z
  for (Brush brush : allBrushes)
  {
    for (double amplitude : { 1e-6, 0.003, 0.05, 2.0 })
    {
      StrokeParameters parameters;
      parameters.brush = brush;
      parameters.amplitude = amplitude;
      parameters.wavelength = 0.07;
      parameters.spacing = 0.01;
      for (std::uint64_t stroke = 0; stroke < 4; ++stroke)
      {
        const StylizedStroke s = stylizeStroke(circleStroke(50), view, parameters, stroke);
        ASSERT_EQ(s.points.size(), s.base.size());
        ASSERT_GT(s.points.size(), 600u); // resampled
        double largestX = 0.0, largestY = 0.0;
        // A stroke shorter than 4 A is drawn with A a quarter of its length
        // (the unit circle's 6.28 caps A = 2 at 1.57).
        const double bound = std::min(amplitude, ShortStrokeAmplitude * s.arcLength.back());
        for (std::size_t i = 0; i < s.points.size(); ++i)
        {
          // Exact bound on the brush values...
          ASSERT_LE(std::abs(s.tangentOffset[i]), bound) << brushName(brush);
          ASSERT_LE(std::abs(s.normalOffset[i]), bound) << brushName(brush);
          largestX = std::max(largestX, std::abs(s.tangentOffset[i]));
          largestY = std::max(largestY, std::abs(s.normalOffset[i]));
          // ... and the moved point is that far from the stroke, along
          // orthonormal directions (up to rounding).
          const double moved = glm::distance(s.points[i], s.base[i]);
          // (1e-15: rounding of coordinates near 1)
          ASSERT_LE(moved, std::hypot(s.tangentOffset[i], s.normalOffset[i]) * (1 + 1e-12) + 1e-15);
          ASSERT_LE(moved, std::sqrt(2.0) * amplitude * (1 + 1e-12) + 1e-15);
        }
        // The brushes use their range: not everything is near zero.
        if (brush == Brush::Rough)
        {
          EXPECT_GT(largestX, 0.9 * bound);
          EXPECT_EQ(largestY, 0.0); // tangent only (Table 1)
        }
        else if (brush == Brush::Hand)
        {
          EXPECT_GT(largestX, 0.3 * bound);
          EXPECT_GT(largestY, 0.3 * bound);
        }
        else
        {
          EXPECT_GT(largestY, 0.9 * bound);
          EXPECT_EQ(largestX, 0.0);
        }
      }
    }
  }
}

TEST(StrokeStylizer, AShortStrokeMovesAQuarterOfItsLengthAtMost)
{
  // A straight stroke 0.08 long, rough brush of amplitude 0.05 (a speck of a
  // tuft at the program's rough settings): its points move along it by at
  // most 0.02, and use that range; the same brush on a stroke 1 long uses
  // the whole 0.05, which the short one would without the cap (the wrong
  // variant: points thrown up to 0.05 past a stroke of 0.08, a spike).
  const StrokeView view;
  StrokeParameters parameters;
  parameters.brush = Brush::Rough;
  parameters.amplitude = 0.05;
  parameters.spacing = 0.004;
  for (double length : { 0.08, 1.0 })
  {
    const StylizedStroke s =
      stylizeStroke({ { 0.0, 0.0, 0.0 }, { length, 0.0, 0.0 } }, view, parameters, 3);
    const double bound = std::min(0.05, 0.25 * length);
    double largest = 0.0;
    for (std::size_t i = 0; i < s.points.size(); ++i)
    {
      ASSERT_LE(std::abs(s.tangentOffset[i]), bound);
      largest = std::max(largest, std::abs(s.tangentOffset[i]));
    }
    EXPECT_GT(largest, 0.9 * bound) << length;
  }
}

TEST(StrokeStylizer, OffsetsLieInTheViewPlane)
{
  StrokeView view;
  view.parallel = true;
  view.direction = glm::normalize(glm::dvec3(0.2, -0.3, -1.0));
  for (Brush brush : allBrushes)
  {
    StrokeParameters parameters;
    parameters.brush = brush;
    parameters.amplitude = 0.02;
    const StylizedStroke s = stylizeStroke(circleStroke(200), view, parameters, 7);
    for (std::size_t i = 0; i < s.points.size(); ++i)
    {
      EXPECT_NEAR(glm::dot(s.points[i] - s.base[i], view.direction), 0.0, 1e-15);
    }
  }
}

TEST(StrokeStylizer, ZeroAmplitudeGivesTheStrokeBack)
{
  const std::vector<glm::dvec3> input = circleStroke(80);
  for (Brush brush : allBrushes)
  {
    StrokeParameters parameters;
    parameters.brush = brush;
    parameters.amplitude = 0.0;
    const StylizedStroke s = stylizeStroke(input, StrokeView(), parameters, 3);
    EXPECT_EQ(s.points, input); // exactly
  }
}

TEST(StrokeStylizer, ResamplingKeepsTheInputPoints)
{
  const std::vector<glm::dvec3> input = circleStroke(10);
  StrokeParameters parameters;
  parameters.amplitude = 0.0;
  parameters.spacing = 0.05;
  const StylizedStroke s = stylizeStroke(input, StrokeView(), parameters, 0);
  std::size_t found = 0;
  for (const glm::dvec3& p : input)
  {
    found += std::count(s.points.begin(), s.points.end(), p) > 0;
  }
  EXPECT_EQ(found, input.size() - 1 + 1); // first and last coincide on the loop
  for (std::size_t i = 1; i < s.base.size(); ++i)
  {
    EXPECT_LE(glm::distance(s.base[i - 1], s.base[i]), 0.05 + 1e-12);
  }
}

TEST(StrokeStylizer, NoiseIsRepeatableAndSeeded)
{
  const std::vector<glm::dvec3> input = circleStroke(300);
  StrokeParameters parameters;
  parameters.brush = Brush::Hand;
  parameters.amplitude = 0.03;
  const StylizedStroke a = stylizeStroke(input, StrokeView(), parameters, 5);
  const StylizedStroke b = stylizeStroke(input, StrokeView(), parameters, 5);
  EXPECT_EQ(a.points, b.points);
  parameters.seed = 2;
  const StylizedStroke c = stylizeStroke(input, StrokeView(), parameters, 5);
  EXPECT_NE(a.points, c.points);
}

TEST(StrokeStylizer, CharcoalIsASawtoothAndLazyAParabola)
{
  StrokeParameters parameters;
  parameters.amplitude = 1.0;
  parameters.wavelength = 4.0;
  double vx = 0.0, vy = 0.0;
  BrushFunction charcoal(parameters, 0);
  charcoal.offsets(1.0, 0, vx, vy);
  EXPECT_EQ(vy, -0.5);
  charcoal.offsets(6.0, 0, vx, vy);
  EXPECT_EQ(vy, 0.0);
  parameters.brush = Brush::Lazy;
  BrushFunction lazy(parameters, 0);
  lazy.offsets(2.0, 0, vx, vy);
  EXPECT_EQ(vy, 1.0);
  lazy.offsets(1.0, 0, vx, vy);
  EXPECT_EQ(vy, 0.75);
  lazy.offsets(0.0, 0, vx, vy);
  EXPECT_EQ(vy, 0.0);
}

TEST(StrokeStylizer, DegenerateStrokesComeBackUnmoved)
{
  StrokeParameters parameters;
  parameters.amplitude = 0.5;
  const std::vector<glm::dvec3> one{ glm::dvec3(1.0) };
  EXPECT_EQ(stylizeStroke(one, StrokeView(), parameters, 0).points, one);
  const std::vector<glm::dvec3> same{ glm::dvec3(1.0), glm::dvec3(1.0) };
  EXPECT_EQ(stylizeStroke(same, StrokeView(), parameters, 0).points, same);
  EXPECT_TRUE(stylizeStroke({}, StrokeView(), parameters, 0).points.empty());
  // Along the line of sight: nothing to offset against.
  const std::vector<glm::dvec3> depth{ glm::dvec3(0, 0, 0), glm::dvec3(0, 0, -1) };
  EXPECT_EQ(stylizeStroke(depth, StrokeView(), parameters, 0).points, depth);
}

TEST(StrokeStylizer, ClosedStrokesCloseWithoutASeam)
{
  std::vector<glm::dvec3> loop = circleStroke(97);
  loop.back() = loop.front(); // exactly closed
  for (Brush brush : allBrushes)
  {
    StrokeParameters parameters;
    parameters.brush = brush;
    parameters.amplitude = 0.02;
    parameters.wavelength = 0.37; // not a divisor of the length
    parameters.spacing = 0.01;
    const StylizedStroke s = stylizeStroke(loop, StrokeView(), parameters, 1);
    const std::size_t n = s.points.size();
    EXPECT_EQ(s.points.front(), s.points.back()) << brushName(brush);
    for (std::size_t i = 0; i < n; ++i)
    {
      ASSERT_LE(std::abs(s.tangentOffset[i]), parameters.amplitude);
      ASSERT_LE(std::abs(s.normalOffset[i]), parameters.amplitude);
    }
    if (brush == Brush::Lazy || brush == Brush::Hand)
    {
      // Continuous brushes: the step across the seam (n-2 -> 0) is no
      // larger than the largest step elsewhere.
      double largest = 0.0;
      for (std::size_t i = 1; i + 1 < n; ++i)
      {
        largest = std::max(largest, std::abs(s.normalOffset[i] - s.normalOffset[i - 1]));
      }
      EXPECT_LE(std::abs(s.normalOffset[n - 2] - s.normalOffset[0]), largest * (1 + 1e-9))
        << brushName(brush);
    }
  }
}
