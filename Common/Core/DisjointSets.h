// Union-find over 0..n-1 whose root is always the lowest member of its set,
// so what callers derive from roots does not depend on the order of unions.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace silsmooth
{

class DisjointSets
{
public:
  explicit DisjointSets(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), std::size_t{ 0 });
  }
  std::size_t find(std::size_t x)
  {
    while (this->Parent[x] != x)
    {
      this->Parent[x] = this->Parent[this->Parent[x]];
      x = this->Parent[x];
    }
    return x;
  }
  void unite(std::size_t a, std::size_t b)
  {
    a = this->find(a);
    b = this->find(b);
    if (a != b)
    {
      this->Parent[std::max(a, b)] = std::min(a, b);
    }
  }

private:
  std::vector<std::size_t> Parent;
};

} // namespace silsmooth
