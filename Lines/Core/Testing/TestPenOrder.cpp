// The order a pen plotter draws lines in (Lines/Core/PenOrder.h), against
// the plain greedy scan it must reproduce step for step.
#include "PenOrder.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <tuple>

using namespace silsmooth;

namespace
{

using Ends = std::vector<std::array<glm::dvec2, 2>>;

// Each step scans every line left: the rule itself, quadratic. A line with
// points in `loops` is a loop entered at any of them.
std::vector<PenStep> scannedOrder(const Ends& ends, glm::dvec2 pen, bool backToEntry = false,
  const std::vector<std::vector<glm::dvec2>>& loops = {})
{
  const auto isLoop = [&](std::size_t i) {
    return i < loops.size() && !loops[i].empty();
  };
  std::vector<PenStep> order;
  std::vector<bool> used(ends.size(), false);
  for (std::size_t k = 0; k < ends.size(); ++k)
  {
    auto best =
      std::make_tuple(std::numeric_limits<double>::infinity(), std::size_t(0), std::size_t(0));
    for (std::size_t i = 0; i < ends.size(); ++i)
    {
      const std::size_t count = isLoop(i) ? loops[i].size() : 2;
      for (std::size_t e = 0; e < count && !used[i]; ++e)
      {
        const glm::dvec2& end = isLoop(i) ? loops[i][e] : ends[i][e];
        best = std::min(best, std::make_tuple(glm::distance(pen, end), i, e));
      }
    }
    const auto [distance, line, point] = best;
    used[line] = true;
    if (isLoop(line))
    {
      order.push_back({ line, false, point });
      pen = loops[line][point];
      continue;
    }
    const bool last = point == 1;
    order.push_back({ line, last, 0 });
    pen = backToEntry ? ends[line][last ? 1 : 0] : ends[line][last ? 0 : 1];
  }
  return order;
}

bool sameOrder(const std::vector<PenStep>& a, const std::vector<PenStep>& b)
{
  return a.size() == b.size() &&
    std::equal(a.begin(), a.end(), b.begin(), [](const PenStep& x, const PenStep& y) {
      return x.Line == y.Line && x.Reversed == y.Reversed && x.Entry == y.Entry;
    });
}

Ends randomLines(std::size_t count, double width, double height, double length, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(0.0, width), y(0.0, height), step(-length, length);
  Ends ends(count);
  for (auto& line : ends)
  {
    line[0] = { x(random), y(random) };
    line[1] = line[0] + glm::dvec2(step(random), step(random));
  }
  return ends;
}

} // namespace

TEST(PenOrder, TakesTheNearestEndEachStepAsAScanOfEveryLineDoes)
{
  // Short strokes over a page, long lines across it, a row of lines on one
  // line (a grid one cell high), starts inside and outside the ends' box.
  const std::vector<Ends> drawings{ randomLines(3000, 800, 600, 10, 1),
    randomLines(500, 800, 600, 400, 2), randomLines(200, 1000, 0, 5, 3) };
  for (const Ends& ends : drawings)
  {
    for (const glm::dvec2 start : { glm::dvec2(0.0), glm::dvec2(400, 300), glm::dvec2(-1e4, 5e3) })
    {
      EXPECT_TRUE(sameOrder(penOrder(ends, start), scannedOrder(ends, start)))
        << ends.size() << " lines from " << start.x << ", " << start.y;
    }
  }
}

TEST(PenOrder, AnOutlineBringsThePenBackToTheEndItEnteredBy)
{
  // Outlines of lines from x to x + 100: the pen comes back where it went
  // in, so it takes the lines in the order of their left ends' distance
  // chain, each entered at its left end.
  const Ends ends{ { glm::dvec2(300, 0), glm::dvec2(400, 0) },
    { glm::dvec2(0, 10), glm::dvec2(100, 10) }, { glm::dvec2(20, 30), glm::dvec2(120, 30) } };
  const std::vector<PenStep> loops = penOrder(ends, glm::dvec2(0.0), true);
  EXPECT_TRUE(sameOrder(loops, scannedOrder(ends, glm::dvec2(0.0), true)));
  ASSERT_EQ(loops.size(), 3u);
  EXPECT_EQ(loops[0].Line, 1u);
  EXPECT_EQ(loops[1].Line, 2u);
  EXPECT_FALSE(loops[1].Reversed);
  // Drawn as strokes, the pen leaves line 1 at x = 100, nearer line 2's
  // right end.
  const std::vector<PenStep> strokes = penOrder(ends, glm::dvec2(0.0));
  EXPECT_EQ(strokes[1].Line, 2u);
  EXPECT_TRUE(strokes[1].Reversed);
  // And on many lines, step for step as the scan.
  const Ends many = randomLines(2000, 800, 600, 40, 5);
  EXPECT_TRUE(
    sameOrder(penOrder(many, glm::dvec2(0.0), true), scannedOrder(many, glm::dvec2(0.0), true)));
}

TEST(PenOrder, TiesGoToTheLowerLineAndToItsFirstPoint)
{
  // Lines 1 and 2 have ends at the same distance from the pen; line 3 is
  // a loop whose two ends are one point.
  const Ends ends{ { glm::dvec2(100, 100), glm::dvec2(110, 100) },
    { glm::dvec2(0, 5), glm::dvec2(0, 20) }, { glm::dvec2(20, 0), glm::dvec2(5, 0) },
    { glm::dvec2(50, 50), glm::dvec2(50, 50) } };
  const std::vector<PenStep> order = penOrder(ends, glm::dvec2(0.0));
  ASSERT_EQ(order.size(), 4u);
  EXPECT_EQ(order[0].Line, 1u);
  EXPECT_FALSE(order[0].Reversed);
  EXPECT_TRUE(sameOrder(order, scannedOrder(ends, glm::dvec2(0.0))));
  EXPECT_FALSE(order[2].Reversed); // the loop, from its first point
}

TEST(PenOrder, OrdersFiftyThousandLinesAndAllAtOnePoint)
{
  const Ends ends = randomLines(50000, 16384, 12288, 20, 4);
  const std::vector<PenStep> order = penOrder(ends, glm::dvec2(0.0));
  ASSERT_EQ(order.size(), ends.size());
  std::vector<bool> seen(ends.size(), false);
  for (const PenStep& step : order)
  {
    EXPECT_FALSE(seen[step.Line]);
    seen[step.Line] = true;
  }
  const Ends onePoint(100, { glm::dvec2(3, 4), glm::dvec2(3, 4) });
  EXPECT_TRUE(
    sameOrder(penOrder(onePoint, glm::dvec2(0.0)), scannedOrder(onePoint, glm::dvec2(0.0))));
  EXPECT_TRUE(penOrder({}, glm::dvec2(0.0)).empty());
}

TEST(PenOrder, ALoopIsEnteredAtItsPointNearestThePenAndLeftThere)
{
  // A square loop through (110, 10), (210, 10), (210, 110), (110, 110).
  // From the origin the pen draws the stroke to (120, 0); there the loop's
  // point (110, 10) is the nearest end (14.1, against 20.6 for the last
  // stroke's (100, 5)), so the loop is entered at it, and the pen, back
  // there after going round, takes the stroke from (100, 5) next.
  const Ends ends{ { glm::dvec2(0, 0), glm::dvec2(120, 0) },
    { glm::dvec2(110, 10), glm::dvec2(110, 10) }, { glm::dvec2(215, 10), glm::dvec2(300, 10) },
    { glm::dvec2(100, 5), glm::dvec2(60, 5) } };
  const std::vector<std::vector<glm::dvec2>> loops{ {},
    { glm::dvec2(110, 10), glm::dvec2(210, 10), glm::dvec2(210, 110), glm::dvec2(110, 110) }, {},
    {} };
  const std::vector<PenStep> order = penOrder(ends, glm::dvec2(0.0), false, loops);
  EXPECT_TRUE(sameOrder(order, scannedOrder(ends, glm::dvec2(0.0), false, loops)));
  ASSERT_EQ(order.size(), 4u);
  EXPECT_EQ(order[0].Line, 0u); // the stroke from the origin, to (120, 0)
  EXPECT_EQ(order[1].Line, 1u); // the loop, entered at (110, 10)
  EXPECT_EQ(order[1].Entry, 0u);
  EXPECT_FALSE(order[1].Reversed);
  EXPECT_EQ(order[2].Line, 3u); // from (110, 10), the nearest end is (100, 5)
  EXPECT_FALSE(order[2].Reversed);
  EXPECT_EQ(order[3].Line, 2u);
  // From another start the loop is entered elsewhere: from (215, 120) its
  // nearest point is (210, 110).
  const std::vector<PenStep> fromRight = penOrder(ends, glm::dvec2(215, 120), false, loops);
  EXPECT_TRUE(sameOrder(fromRight, scannedOrder(ends, glm::dvec2(215, 120), false, loops)));
  EXPECT_EQ(fromRight[0].Line, 1u);
  EXPECT_EQ(fromRight[0].Entry, 2u);
  // And many loops and strokes, step for step as the scan.
  Ends many = randomLines(1500, 800, 600, 30, 6);
  std::vector<std::vector<glm::dvec2>> manyLoops(many.size());
  for (std::size_t i = 0; i < many.size(); i += 3)
  {
    const glm::dvec2 c = many[i][0];
    for (int k = 0; k < 6; ++k)
    {
      manyLoops[i].push_back(c + 8.0 * glm::dvec2(std::cos(k), std::sin(k)));
    }
  }
  for (const bool back : { false, true })
  {
    EXPECT_TRUE(sameOrder(penOrder(many, glm::dvec2(0.0), back, manyLoops),
      scannedOrder(many, glm::dvec2(0.0), back, manyLoops)));
  }
}
