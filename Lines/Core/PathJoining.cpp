#include "PathJoining.h"

#include "SurfaceWelding.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <map>
#include <tuple>

namespace silsmooth
{
namespace
{

constexpr std::size_t none = static_cast<std::size_t>(-1);

// End 2 * line + (0: first point, 1: last point).
std::size_t endOf(std::size_t line, int last)
{
  return 2 * line + static_cast<std::size_t>(last);
}

// The unit direction in which the line leaves its end (towards its nearest
// point at another position); zero for a line of one position.
template<typename Point>
Point leaving(const std::vector<Point>& line, int last)
{
  const std::size_t n = line.size();
  const Point from = last ? line[n - 1] : line[0];
  for (std::size_t k = 1; k < n; ++k)
  {
    const Point to = last ? line[n - 1 - k] : line[k];
    const double length = glm::distance(from, to);
    if (length > 0.0)
    {
      return (to - from) / length;
    }
  }
  return Point(0.0);
}

using EndKey = std::tuple<int, std::int64_t, std::int64_t, std::int64_t>; // group, position

// joinedPaths for points of either dimension; keys[endOf(line, last)] is an
// end's key (its group and position).
template<typename Point>
std::vector<std::vector<JoinedLine>> joinLines(
  const std::vector<std::vector<Point>>& lines, const std::vector<EndKey>& keys)
{
  // The ends at each point of each group.
  std::map<EndKey, std::vector<std::size_t>> meeting;
  for (std::size_t end = 0; end < keys.size(); ++end)
  {
    meeting[keys[end]].push_back(end);
  }
  // Pair the ends at each point, the straightest continuation first.
  std::vector<std::size_t> partner(2 * lines.size(), none);
  for (const auto& point : meeting)
  {
    const std::vector<std::size_t>& ends = point.second;
    std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
    for (std::size_t a = 0; a < ends.size(); ++a)
    {
      for (std::size_t b = a + 1; b < ends.size(); ++b)
      {
        if (ends[a] / 2 == ends[b] / 2)
        {
          continue; // a line's own two ends
        }
        const double straight = glm::dot(leaving(lines[ends[a] / 2], int(ends[a] % 2)),
          leaving(lines[ends[b] / 2], int(ends[b] % 2)));
        pairs.emplace_back(straight, ends[a], ends[b]);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    for (const auto& [straight, a, b] : pairs)
    {
      if (partner[a] == none && partner[b] == none)
      {
        partner[a] = b;
        partner[b] = a;
      }
    }
  }
  // Walk the chains: first those with a free end, from their lowest such
  // line, then the closed ones.
  std::vector<std::vector<JoinedLine>> paths;
  std::vector<unsigned char> used(lines.size(), 0);
  const auto walk = [&](std::size_t line, int startEnd) {
    std::vector<JoinedLine> path;
    std::size_t end = endOf(line, startEnd);
    while (!used[end / 2])
    {
      used[end / 2] = 1;
      path.push_back({ end / 2, end % 2 == 1 });
      const std::size_t far = end ^ 1u; // the line's other end
      if (partner[far] == none)
      {
        break;
      }
      end = partner[far];
    }
    paths.push_back(std::move(path));
  };
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    for (int last = 0; last < 2 && !used[i]; ++last)
    {
      if (partner[endOf(i, last)] == none)
      {
        walk(i, last);
      }
    }
  }
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    if (!used[i])
    {
      walk(i, 0);
    }
  }
  std::sort(paths.begin(), paths.end(),
    [](const std::vector<JoinedLine>& a, const std::vector<JoinedLine>& b) {
      return a.front().Line < b.front().Line;
    });
  return paths;
}

} // namespace

std::vector<std::vector<JoinedLine>> joinedPaths(const std::vector<std::vector<glm::dvec2>>& lines,
  const std::vector<int>& groups, std::pair<std::int64_t, std::int64_t> (*keyOf)(const glm::dvec2&))
{
  std::vector<EndKey> keys;
  keys.reserve(2 * lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    for (const glm::dvec2& end : { lines[i].front(), lines[i].back() })
    {
      const auto [x, y] = keyOf(end);
      keys.emplace_back(groups[i], x, y, 0);
    }
  }
  return joinLines(lines, keys);
}

std::vector<std::vector<JoinedLine>> joinedPaths(
  const std::vector<std::vector<glm::dvec3>>& lines, double tolerance)
{
  // An end's key: the end it is welded with (within the tolerance,
  // transitively), as the surface's points are.
  std::vector<glm::dvec3> ends;
  ends.reserve(2 * lines.size());
  for (const std::vector<glm::dvec3>& line : lines)
  {
    ends.push_back(line.front());
    ends.push_back(line.back());
  }
  const std::vector<Id> welded = weldCoincidentPoints(ends, tolerance);
  std::vector<EndKey> keys;
  keys.reserve(ends.size());
  for (const Id vertex : welded)
  {
    keys.emplace_back(0, vertex, 0, 0);
  }
  return joinLines(lines, keys);
}

} // namespace silsmooth
