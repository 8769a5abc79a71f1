#include "SilhouettePolylines.h"

#include <algorithm>
#include <unordered_map>

namespace silsmooth
{

std::vector<std::vector<Id>> chainSegments(const std::vector<std::vector<Id>>& segments)
{
  std::unordered_map<Id, std::vector<std::size_t>> byEnd;
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    byEnd[segments[i].front()].push_back(i);
    byEnd[segments[i].back()].push_back(i);
  }
  std::vector<bool> used(segments.size(), false);
  std::vector<std::vector<Id>> chains;

  auto walk = [&](std::size_t first, Id start) {
    std::vector<Id> chain{ start };
    std::size_t current = first;
    Id at = start;
    while (true)
    {
      used[current] = true;
      const std::vector<Id>& s = segments[current];
      if (s.front() == at)
      {
        chain.insert(chain.end(), s.begin() + 1, s.end());
      }
      else
      {
        chain.insert(chain.end(), s.rbegin() + 1, s.rend());
      }
      at = chain.back();
      const std::vector<std::size_t>& next = byEnd[at];
      if (next.size() != 2)
      {
        break; // chain end or branch point
      }
      const std::size_t other = next[0] == current ? next[1] : next[0];
      if (used[other])
      {
        break; // loop closed
      }
      current = other;
    }
    chains.push_back(std::move(chain));
  };

  // Open chains first, from their ends, then the closed loops.
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    for (const Id end : { segments[i].front(), segments[i].back() })
    {
      if (!used[i] && byEnd[end].size() != 2)
      {
        walk(i, end);
      }
    }
  }
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    if (!used[i])
    {
      walk(i, segments[i].front());
    }
  }
  return chains;
}

} // namespace silsmooth
