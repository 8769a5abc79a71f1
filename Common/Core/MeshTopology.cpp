#include "MeshTopology.h"

#include <utility>

#include <algorithm>

namespace silsmooth
{

EdgeTable::EdgeTable(const std::vector<Triangle>& triangles)
{
  // Order the 3T sides by their (low, high) key and number the distinct
  // keys: deterministic edge ids, no hashing. Where the low ids are point
  // ids of a sensible range (not negative, below a few per side), the sides
  // are placed in buckets per low id in one counting pass and each small
  // bucket is sorted by its high ids: a third of the time of sorting them
  // all at 1.3M triangles. Otherwise all are sorted. Both give the same order.
  struct Side
  {
    Id Low;
    Id High;
    std::size_t Index;
  };
  auto byKey = [](const Side& x, const Side& y) {
    return x.Low != y.Low ? x.Low < y.Low
                          : (x.High != y.High ? x.High < y.High : x.Index < y.Index);
  };
  const std::size_t sideCount = triangles.size() * 3;
  auto sideOf = [&triangles](std::size_t t, int k) {
    const Id a = triangles[t][static_cast<std::size_t>(k)];
    const Id b = triangles[t][static_cast<std::size_t>((k + 1) % 3)];
    return Side{ std::min(a, b), std::max(a, b), t * 3 + static_cast<std::size_t>(k) };
  };
  Id lowest = 0;
  Id highest = -1;
  for (const Triangle& t : triangles)
  {
    for (const Id v : t)
    {
      lowest = std::min(lowest, v);
      highest = std::max(highest, v);
    }
  }
  std::vector<Side> sides(sideCount);
  if (lowest >= 0 && static_cast<std::size_t>(highest) < 4 * sideCount + 1024)
  {
    std::vector<std::size_t> start(static_cast<std::size_t>(highest) + 2, 0);
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        ++start[static_cast<std::size_t>(sideOf(t, k).Low) + 1];
      }
    }
    for (std::size_t v = 1; v < start.size(); ++v)
    {
      start[v] += start[v - 1];
    }
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Side side = sideOf(t, k);
        sides[next[static_cast<std::size_t>(side.Low)]++] = side;
      }
    }
    for (std::size_t v = 0; v + 1 < start.size(); ++v)
    {
      std::sort(sides.begin() + static_cast<std::ptrdiff_t>(start[v]),
        sides.begin() + static_cast<std::ptrdiff_t>(start[v + 1]), byKey);
    }
  }
  else
  {
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        sides[t * 3 + static_cast<std::size_t>(k)] = sideOf(t, k);
      }
    }
    std::sort(sides.begin(), sides.end(), byKey);
  }

  this->SideEdges.assign(sideCount, -1);
  for (const Side& side : sides)
  {
    if (this->Edges.empty() || this->Edges.back().low != side.Low ||
      this->Edges.back().high != side.High)
    {
      this->Edges.push_back({ side.Low, side.High });
    }
    this->SideEdges[side.Index] = static_cast<Id>(this->Edges.size() - 1);
  }
}

EdgeTable EdgeTable::withSidesReversed(const std::vector<unsigned char>& reversed) const
{
  EdgeTable table = *this;
  for (std::size_t t = 0; t < reversed.size(); ++t)
  {
    if (reversed[t])
    {
      std::swap(table.SideEdges[t * 3], table.SideEdges[t * 3 + 2]);
    }
  }
  return table;
}

} // namespace silsmooth
