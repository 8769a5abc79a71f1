#include "MeshTopology.h"

#include <algorithm>
#include <numeric>

namespace silsmooth
{

EdgeTable::EdgeTable(const std::vector<Triangle>& triangles)
{
  // Sort the 3T sides by their (low, high) key and number the distinct keys:
  // O(T log T), no hashing, and deterministic edge ids.
  const std::size_t sideCount = triangles.size() * 3;
  std::vector<Edge> sideKeys(sideCount);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Id a = triangles[t][k];
      const Id b = triangles[t][(k + 1) % 3];
      sideKeys[t * 3 + k] = { std::min(a, b), std::max(a, b) };
    }
  }
  std::vector<std::size_t> order(sideCount);
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const Edge& a = sideKeys[i];
    const Edge& b = sideKeys[j];
    return a.low != b.low ? a.low < b.low : (a.high != b.high ? a.high < b.high : i < j);
  });

  this->SideEdges.assign(sideCount, -1);
  for (std::size_t i = 0; i < sideCount; ++i)
  {
    const Edge& key = sideKeys[order[i]];
    if (this->Edges.empty() || this->Edges.back().low != key.low ||
      this->Edges.back().high != key.high)
    {
      this->Edges.push_back(key);
    }
    this->SideEdges[order[i]] = static_cast<Id>(this->Edges.size() - 1);
  }
}

} // namespace silsmooth
