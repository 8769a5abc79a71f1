#include "PathJoining.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
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

// joinedPaths for points of either dimension; keyOf(point) gives an end's
// position key.
template<typename Point, typename KeyOf>
std::vector<std::vector<JoinedLine>> joinLines(
  const std::vector<std::vector<Point>>& lines, const std::vector<int>& groups, KeyOf keyOf)
{
  // The ends at each point of each group.
  std::map<EndKey, std::vector<std::size_t>> meeting;
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    for (int last = 0; last < 2; ++last)
    {
      const auto [x, y, z] = keyOf(last ? lines[i].back() : lines[i].front());
      meeting[{ groups[i], x, y, z }].push_back(endOf(i, last));
    }
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
  return joinLines(lines, groups, [keyOf](const glm::dvec2& point) {
    const auto [x, y] = keyOf(point);
    return std::array<std::int64_t, 3>{ x, y, 0 };
  });
}

std::vector<std::vector<JoinedLine>> joinedPaths(
  const std::vector<std::vector<glm::dvec3>>& lines, double tolerance)
{
  // The ends, clustered: ends within `tolerance` of each other (directly or
  // through others) are one cluster, found through a grid of cells as wide
  // as the tolerance (a pair within it lies in the same or a neighbouring
  // cell).
  std::vector<glm::dvec3> ends;
  ends.reserve(2 * lines.size());
  for (const std::vector<glm::dvec3>& line : lines)
  {
    ends.push_back(line.front());
    ends.push_back(line.back());
  }
  std::vector<std::size_t> parent(ends.size());
  for (std::size_t i = 0; i < parent.size(); ++i)
  {
    parent[i] = i;
  }
  const auto root = [&](std::size_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  const double cell = tolerance > 0.0 ? tolerance : 1.0;
  const auto cellOf = [&](const glm::dvec3& p) {
    return std::array<std::int64_t, 3>{ static_cast<std::int64_t>(std::floor(p.x / cell)),
      static_cast<std::int64_t>(std::floor(p.y / cell)),
      static_cast<std::int64_t>(std::floor(p.z / cell)) };
  };
  std::map<std::array<std::int64_t, 3>, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < ends.size(); ++i)
  {
    const std::array<std::int64_t, 3> c = cellOf(ends[i]);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
    {
      for (std::int64_t dy = -1; dy <= 1; ++dy)
      {
        for (std::int64_t dz = -1; dz <= 1; ++dz)
        {
          const auto near = grid.find({ c[0] + dx, c[1] + dy, c[2] + dz });
          if (near == grid.end())
          {
            continue;
          }
          for (const std::size_t j : near->second)
          {
            if (glm::distance(ends[i], ends[j]) <= tolerance)
            {
              parent[root(i)] = root(j);
            }
          }
        }
      }
    }
    grid[c].push_back(i);
  }
  // An end's key: its cluster. The keys are looked up by the end's exact
  // position, which the lines hand back.
  std::map<std::array<double, 3>, std::int64_t> clusterAt;
  for (std::size_t i = 0; i < ends.size(); ++i)
  {
    clusterAt.emplace(
      std::array<double, 3>{ ends[i].x, ends[i].y, ends[i].z }, static_cast<std::int64_t>(root(i)));
  }
  return joinLines(lines, std::vector<int>(lines.size(), 0), [&](const glm::dvec3& point) {
    return std::array<std::int64_t, 3>{
      clusterAt.at(std::array<double, 3>{ point.x, point.y, point.z }), 0, 0
    };
  });
}

} // namespace silsmooth
