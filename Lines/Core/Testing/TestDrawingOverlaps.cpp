// Lines of a drawing that run over each other (Lines/Core/DrawingOverlaps.h):
// straight lines in the image whose answers are exact.
#include "DrawingOverlaps.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace silsmooth;

namespace
{

using Line = std::vector<glm::dvec2>;

std::vector<PolylineSpan> spansOf(const std::vector<Line>& lines,
  const DrawingOverlapParameters& parameters = DrawingOverlapParameters())
{
  std::vector<std::size_t> order(lines.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  return spansNotOverlapping(lines, order, parameters);
}

bool isWhole(const PolylineSpan& span, std::size_t line, const Line& points)
{
  return span.Line == line && span.First == 0.0 &&
    span.Last == static_cast<double>(points.size() - 1);
}

// The distance from p to the nearest point of a polyline.
double distanceTo(const glm::dvec2& p, const Line& line)
{
  double nearest = INFINITY;
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
  {
    const glm::dvec2 ab = line[i + 1] - line[i];
    const double t = std::clamp(glm::dot(p - line[i], ab) / glm::dot(ab, ab), 0.0, 1.0);
    nearest = std::min(nearest, glm::distance(p, line[i] + ab * t));
  }
  return nearest;
}

glm::dvec2 along(double degrees, double length)
{
  const double radians = degrees * M_PI / 180.0;
  return { length * std::cos(radians), length * std::sin(radians) };
}

} // namespace

TEST(DrawingOverlaps, ALineDrawnTwiceIsKeptOnceForwardsOrBackwards)
{
  const Line a{ { 0, 0 }, { 40, 0 }, { 40, 30 } };
  const Line back{ { 40, 30 }, { 40, 0 }, { 0, 0 } };
  const std::vector<PolylineSpan> spans = spansOf({ a, a, back });
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_TRUE(isWhole(spans[0], 0, a));
}

TEST(DrawingOverlaps, ALineWithinTheWidthBesideAnotherIsLeftOutAndOneBeyondItIsKept)
{
  const Line a{ { 0, 0 }, { 100, 0 } };
  const Line near{ { 0, 0.9 }, { 100, 0.9 } };
  const Line far{ { 0, 1.2 }, { 100, 1.2 } };
  const std::vector<PolylineSpan> nearSpans = spansOf({ a, near });
  ASSERT_EQ(nearSpans.size(), 1u);
  EXPECT_EQ(nearSpans[0].Line, 0u);
  const std::vector<PolylineSpan> farSpans = spansOf({ a, far });
  ASSERT_EQ(farSpans.size(), 2u);
  EXPECT_TRUE(isWhole(farSpans[1], 1, far));
}

TEST(DrawingOverlaps, LinesThatCrossAreKeptWhole)
{
  // At right angles, and at 25 degrees (outside the 20 degrees of
  // AlongCosine): each point of the second line near the first runs across it.
  for (const double degrees : { 90.0, 25.0 })
  {
    const Line a{ { -50, 0 }, { 50, 0 } };
    const Line b{ -along(degrees, 50), along(degrees, 50) };
    const std::vector<PolylineSpan> spans = spansOf({ a, b });
    ASSERT_EQ(spans.size(), 2u) << degrees;
    EXPECT_TRUE(isWhole(spans[1], 1, b)) << degrees;
  }
}

TEST(DrawingOverlaps, AShallowCrossingIsKeptUnlessItsStretchReachesTheShortestGap)
{
  // At 15 degrees the second line lies within 1 px of the first over
  // 2 / sin(15 degrees) = 7.7 px.
  const Line a{ { -50, 0 }, { 50, 0 } };
  const Line b{ -along(15, 50), along(15, 50) };
  DrawingOverlapParameters parameters;
  parameters.ShortestGap = 10.0;
  const std::vector<PolylineSpan> kept = spansOf({ a, b }, parameters);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_TRUE(isWhole(kept[1], 1, b));

  parameters.ShortestGap = 4.0;
  const std::vector<PolylineSpan> split = spansOf({ a, b }, parameters);
  ASSERT_EQ(split.size(), 3u);
  // Two spans, each ending where the first line covers it (within a
  // sample's step of 1 px from it), about 7.7 px apart.
  const glm::dvec2 end = valuesAlong(b, split[1].First, split[1].Last).back();
  const glm::dvec2 start = valuesAlong(b, split[2].First, split[2].Last).front();
  EXPECT_LE(distanceTo(end, a), 1.0);
  EXPECT_LE(distanceTo(start, a), 1.0);
  EXPECT_NEAR(glm::distance(start, end), 2.0 / std::sin(15 * M_PI / 180), 0.6);
}

TEST(DrawingOverlaps, APartlyCoveredLineKeepsTheRestJoinedToTheLineThatCoversIt)
{
  const Line a{ { 0, 0 }, { 100, 0 } };
  const Line b{ { 50, 0.3 }, { 150, 0.3 } };
  const std::vector<PolylineSpan> spans = spansOf({ a, b });
  ASSERT_EQ(spans.size(), 2u);
  const Line kept = valuesAlong(b, spans[1].First, spans[1].Last);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept.back(), b.back());
  // It starts where the first line stops covering it: at most a quarter
  // of the width before the first line's end, and within the width of it.
  EXPECT_GE(kept.front().x, 100.0 - 0.25);
  EXPECT_LE(kept.front().x, 100.0 + 1.0);
  EXPECT_LE(distanceTo(kept.front(), a), 1.0);
}

TEST(DrawingOverlaps, TheOrderGivenDecidesWhichLineIsKept)
{
  const Line longer{ { 0, 0 }, { 100, 0 } };
  const Line shorter{ { 20, 0 }, { 60, 0 } };
  const std::vector<std::vector<glm::dvec2>> lines{ longer, shorter };
  const std::vector<PolylineSpan> longerFirst =
    spansNotOverlapping(lines, { 0, 1 }, DrawingOverlapParameters());
  ASSERT_EQ(longerFirst.size(), 1u);
  EXPECT_EQ(longerFirst[0].Line, 0u);
  // The shorter first keeps the longer's two ends beyond it.
  const std::vector<PolylineSpan> shorterFirst =
    spansNotOverlapping(lines, { 1, 0 }, DrawingOverlapParameters());
  ASSERT_EQ(shorterFirst.size(), 3u);
  EXPECT_TRUE(isWhole(shorterFirst[0], 1, shorter));
  EXPECT_EQ(shorterFirst[1].Line, 0u);
  EXPECT_EQ(shorterFirst[1].First, 0.0);
  EXPECT_EQ(shorterFirst[2].Last, 1.0);
}

TEST(DrawingOverlaps, AWaverBetweenTwoCoveredStretchesIsLeftOut)
{
  // The second line leaves the first by at most 1.1 px, over 10 px, and
  // comes back: beyond 1 px for 0.9 px of its length.
  const Line a{ { 0, 0 }, { 100, 0 } };
  const Line b{ { 10, 0 }, { 50, 0 }, { 55, 1.1 }, { 60, 0 }, { 90, 0 } };
  const std::vector<PolylineSpan> spans = spansOf({ a, b });
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].Line, 0u);
}

TEST(DrawingOverlaps, ALineDoesNotCoverItself)
{
  // A hairpin: the way back runs 0.5 px beside the way out.
  const Line hairpin{ { 0, 0 }, { 100, 0 }, { 100, 0.5 }, { 0, 0.5 } };
  const std::vector<PolylineSpan> spans = spansOf({ hairpin });
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_TRUE(isWhole(spans[0], 0, hairpin));
}

TEST(DrawingOverlaps, ValuesAlongASpanAreInterpolatedAtItsEnds)
{
  const std::vector<double> depths{ 1.0, 2.0, 4.0, 8.0 };
  EXPECT_EQ(valuesAlong(depths, 0.5, 2.25), (std::vector<double>{ 1.5, 2.0, 4.0, 5.0 }));
  EXPECT_EQ(valuesAlong(depths, 1.0, 2.0), (std::vector<double>{ 2.0, 4.0 }));
  EXPECT_EQ(valuesAlong(depths, 0.0, 3.0), depths);
}

TEST(DrawingOverlaps, AWidthOfZeroCoversNothingAndATinyOneStaysCheap)
{
  const Line a{ { 0, 0 }, { 1000, 0 } };
  DrawingOverlapParameters parameters;
  parameters.Width = 0.0;
  EXPECT_EQ(spansOf({ a, a }, parameters).size(), 2u);
  // Sampled every hundredth of a pixel and filed in cells of a pixel at
  // least (a cell of 4e-9 px filed this line in 2.5e11 pieces).
  parameters.Width = 1e-9;
  const std::vector<PolylineSpan> spans = spansOf({ a, a }, parameters);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_TRUE(isWhole(spans[0], 0, a));
}

TEST(DrawingOverlaps, SpansInsideTheImageAreClippedWhereTheLinesCrossItsSides)
{
  const glm::dvec2 low(0, 0);
  const glm::dvec2 high(100, 50);
  const std::vector<Line> lines{
    { { 10, 10 }, { 90, 40 } },                         // inside
    { { -100, 25 }, { 200, 25 } },                      // across
    { { 50, 25 }, { 50, 80 }, { 70, 80 }, { 70, 25 } }, // out and back in
    { { 0, -10 }, { 0, -1 } },                          // outside
    { { -10, 40 }, { 10, 60 } },                        // through a corner only
    { { 50, 25 }, { 5e9, 25 } },                        // to a point far away
  };
  const std::vector<PolylineSpan> spans = spansInside(lines, low, high);
  ASSERT_EQ(spans.size(), 5u);
  EXPECT_TRUE(isWhole(spans[0], 0, lines[0]));
  EXPECT_EQ(spans[1].Line, 1u);
  EXPECT_DOUBLE_EQ(spans[1].First, 100.0 / 300.0);
  EXPECT_DOUBLE_EQ(spans[1].Last, 200.0 / 300.0);
  EXPECT_EQ(spans[2].Line, 2u);
  EXPECT_DOUBLE_EQ(spans[2].First, 0.0);
  EXPECT_DOUBLE_EQ(spans[2].Last, 25.0 / 55.0);
  EXPECT_EQ(spans[3].Line, 2u);
  EXPECT_DOUBLE_EQ(spans[3].First, 2.0 + 30.0 / 55.0);
  EXPECT_DOUBLE_EQ(spans[3].Last, 3.0);
  EXPECT_EQ(spans[4].Line, 5u);
  EXPECT_DOUBLE_EQ(valuesAlong(lines[5], spans[4].First, spans[4].Last).back().x, 100.0);
}

TEST(DrawingOverlaps, ASpanInsideRunsOnAcrossThePointsOfItsLine)
{
  const Line zigzag{ { -10, 5 }, { 20, 10 }, { 40, 5 }, { 60, 10 }, { 120, 5 } };
  const std::vector<PolylineSpan> spans = spansInside({ zigzag }, { 0, 0 }, { 100, 50 });
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_NEAR(spans[0].First, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(spans[0].Last, 3.0 + 2.0 / 3.0, 1e-12);
  EXPECT_EQ(valuesAlong(zigzag, spans[0].First, spans[0].Last).size(), 5u);
}

TEST(DrawingOverlaps, ASpeckOnInkAlreadyThereIsLeftOutAndOneOnItsOwnIsKept)
{
  // A stub 1.5 px long across a line's end (a corner), and the same stub
  // 5 px away from any line.
  const Line a{ { 0, 0 }, { 100, 0 } };
  const Line onInk{ { 100, -0.7 }, { 100, 0.8 } };
  const Line alone{ { 50, 5 }, { 50, 6.5 } };
  const std::vector<PolylineSpan> spans = spansOf({ a, onInk, alone });
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].Line, 0u);
  EXPECT_TRUE(isWhole(spans[1], 2, alone));
  // A speck taken before the line it lies on is left out too.
  const std::vector<PolylineSpan> speckFirst =
    spansNotOverlapping({ a, onInk, alone }, { 1, 2, 0 }, DrawingOverlapParameters());
  ASSERT_EQ(speckFirst.size(), 2u);
  EXPECT_TRUE(isWhole(speckFirst[0], 2, alone));
  EXPECT_TRUE(isWhole(speckFirst[1], 0, a));
  // Longer than LongestSpeck, the stub is a line of its own.
  DrawingOverlapParameters parameters;
  parameters.LongestSpeck = 1.0;
  EXPECT_EQ(spansOf({ a, onInk, alone }, parameters).size(), 3u);
}
