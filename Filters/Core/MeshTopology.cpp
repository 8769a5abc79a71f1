#include "MeshTopology.h"

#include <utility>

#include <algorithm>

namespace silsmooth
{

EdgeTable::EdgeTable(const std::vector<Triangle>& triangles)
{
  // Sort the 3T sides by their (low, high) key and number the distinct keys:
  // O(T log T), no hashing, deterministic edge ids. The keys are sorted in
  // place with their side index (not through an index array), which halves
  // the time on large meshes.
  struct Side
  {
    Id Low;
    Id High;
    std::size_t Index;
  };
  const std::size_t sideCount = triangles.size() * 3;
  std::vector<Side> sides(sideCount);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Id a = triangles[t][k];
      const Id b = triangles[t][(k + 1) % 3];
      sides[t * 3 + k] = { std::min(a, b), std::max(a, b), t * 3 + static_cast<std::size_t>(k) };
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return x.Low != y.Low ? x.Low < y.Low
                          : (x.High != y.High ? x.High < y.High : x.Index < y.Index);
  });

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
