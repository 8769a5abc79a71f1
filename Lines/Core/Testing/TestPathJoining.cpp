// A drawing's lines joined end to end (Lines/Core/PathJoining.h).
#include "PathJoining.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace silsmooth;

namespace
{

using Line = std::vector<glm::dvec2>;

std::pair<std::int64_t, std::int64_t> hundredths(const glm::dvec2& p)
{
  return { std::llround(p.x * 100.0), std::llround(p.y * 100.0) };
}

// Each path as its line ids, negative (minus one) where a line is turned round.
std::vector<std::vector<long>> idsOf(const std::vector<std::vector<JoinedLine>>& paths)
{
  std::vector<std::vector<long>> ids;
  for (const auto& path : paths)
  {
    ids.emplace_back();
    for (const JoinedLine& line : path)
    {
      ids.back().push_back(line.Reversed ? -long(line.Line) - 1 : long(line.Line));
    }
  }
  return ids;
}

} // namespace

TEST(PathJoining, TheFourSidesOfASquareAreOnePath)
{
  // Written in any order and direction, within rounding of each other.
  const std::vector<Line> sides{ { { 0, 0 }, { 10, 0 } }, { { 10, 10 }, { 0, 10 } },
    { { 10, 10.001 }, { 10, 0 } }, { { 0, 0 }, { 0, 10 } } };
  const auto paths = joinedPaths(sides, { 0, 0, 0, 0 }, hundredths);
  ASSERT_EQ(paths.size(), 1u);
  // A closed chain starts at its lowest line: 0, then on round the square.
  EXPECT_EQ(idsOf(paths), (std::vector<std::vector<long>>{ { 0, -3, 1, -4 } }));
}

TEST(PathJoining, AtACornerOfThreeTheStraightestTwoAreJoined)
{
  // A T: the bar's two halves continue each other, the stem starts a path.
  const std::vector<Line> t{ { { 0, 0 }, { 10, 0 } }, { { 10, 0 }, { 10, -10 } },
    { { 20, 0 }, { 10, 0 } } };
  EXPECT_EQ(idsOf(joinedPaths(t, { 0, 0, 0 }, hundredths)),
    (std::vector<std::vector<long>>{ { 0, -3 }, { 1 } }));
  // A cube's corner seen from outside: three edges 120 degrees apart, any
  // two as straight as the others; the first pair in order is joined.
  const double c = std::cos(2.0 * M_PI / 3.0), s = std::sin(2.0 * M_PI / 3.0);
  const std::vector<Line> corner{ { { 0, 0 }, { 10, 0 } }, { { 0, 0 }, { 10 * c, 10 * s } },
    { { 0, 0 }, { 10 * c, -10 * s } } };
  const auto paths = joinedPaths(corner, { 0, 0, 0 }, hundredths);
  EXPECT_EQ(paths.size(), 2u);
}

TEST(PathJoining, LinesOfOtherGroupsAndLinesApartAreNotJoined)
{
  const std::vector<Line> lines{ { { 0, 0 }, { 10, 0 } }, { { 10, 0 }, { 20, 0 } },
    { { 20.02, 0 }, { 30, 0 } } };
  // Different groups at the shared point; the third line's end is 0.02 away.
  EXPECT_EQ(idsOf(joinedPaths(lines, { 0, 1, 1 }, hundredths)),
    (std::vector<std::vector<long>>{ { 0 }, { 1 }, { 2 } }));
  // One group: the first two join.
  EXPECT_EQ(idsOf(joinedPaths(lines, { 0, 0, 0 }, hundredths)),
    (std::vector<std::vector<long>>{ { 0, 1 }, { 2 } }));
}

TEST(PathJoining, AClosedLoopStaysOnePathAndEveryLineIsUsedOnce)
{
  const std::vector<Line> lines{ { { 0, 0 }, { 5, 5 }, { 0, 5 }, { 0, 0 } },
    { { 0, 0 }, { -5, 0 } }, { { 7, 7 }, { 8, 8 } } };
  const auto paths = joinedPaths(lines, { 0, 0, 0 }, hundredths);
  std::vector<int> seen(lines.size(), 0);
  for (const auto& path : paths)
  {
    for (const JoinedLine& line : path)
    {
      ++seen[line.Line];
    }
  }
  EXPECT_EQ(seen, (std::vector<int>{ 1, 1, 1 }));
  // The loop's two ends meet at the tail's end: one of them takes the tail.
  EXPECT_EQ(paths.size(), 2u);
}

TEST(PathJoining, LinesInSpaceMeetWhereTheirEndsLieWithinTheTolerance)
{
  // A square's sides in the plane z = 1, each corner's two ends up to 1e-6
  // apart (as a line visibility filter's pieces come), in any order and
  // direction: one closed path within 1e-5; with ends equal only (the
  // wrong variant), the corners apart stay apart. An end 1e-3 away is not
  // joined: the chain is open there.
  using Line3 = std::vector<glm::dvec3>;
  const std::vector<Line3> sides{ { { 0, 0, 1 }, { 1, 0, 1 } }, { { 1, 1, 1 }, { 1e-6, 1, 1 } },
    { { 1 + 4e-7, 1 - 6e-7, 1 }, { 1, 1e-6, 1 } }, { { 0, 0, 1 }, { 0, 1, 1 } } };
  EXPECT_EQ(idsOf(joinedPaths(sides, 1e-5)), (std::vector<std::vector<long>>{ { 0, -3, 1, -4 } }));
  EXPECT_GT(joinedPaths(sides, 0.0).size(), 1u);
  Line3 apart = sides[3];
  apart.back().x += 1e-3;
  const std::vector<Line3> open{ sides[0], sides[1], sides[2], apart };
  EXPECT_EQ(joinedPaths(open, 1e-5).size(), 1u) << "an open chain, one path";
  EXPECT_EQ(idsOf(joinedPaths(open, 1e-5)).front().size(), 4u);
  const auto ends = joinedPaths(open, 1e-5).front();
  EXPECT_TRUE(ends.front().Line == 3 || ends.back().Line == 3) << "the line apart ends the path";
}
