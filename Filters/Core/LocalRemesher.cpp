#include "LocalRemesher.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace silsmooth {

namespace {

// Appends (a, b, c) unless it repeats a point id (see the header: a
// silhouette point snapped onto a vertex collapses these triangles).
std::size_t emit(Id a, Id b, Id c, std::vector<Triangle>& out)
{
  const Triangle t{ a, b, c };
  if (hasRepeatedCorner(t))
  {
    return 0;
  }
  out.push_back(t);
  return 1;
}

std::size_t chooseBaseSplit(const SilhouetteTriangleLayout& layout)
{
  std::size_t best = 0;
  double bestImbalance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < layout.ChainPositions.size(); ++k)
  {
    const double imbalance = std::abs(glm::distance(layout.ChainPositions[k], layout.BaseFirstPosition) -
      glm::distance(layout.ChainPositions[k], layout.BaseSecondPosition));
    if (imbalance < bestImbalance)
    {
      bestImbalance = imbalance;
      best = k;
    }
  }
  return best;
}

} // namespace

std::size_t remeshSilhouetteTriangle(const SilhouetteTriangleLayout& layout, std::vector<Triangle>& out)
{
  const std::vector<Id>& s = layout.Chain;
  const Id a = layout.Lone;
  const Id b = layout.BaseFirst;
  const Id c = layout.BaseSecond;
  if (s.size() < 2 || s.front() == s.back())
  {
    // Both silhouette points on one vertex: the silhouette only touches the
    // triangle there, and the triangle stays as it was.
    return emit(a, b, c, out);
  }
  std::size_t count = 0;
  const std::size_t n = s.size() - 1;
  // Lone side: fan from A over P ... Q.
  for (std::size_t i = 0; i < n; ++i)
  {
    count += emit(a, s[i], s[i + 1], out);
  }
  // Base side: polygon P B C Q s(n-1) ... s1 in the triangle's orientation.
  const std::size_t k = chooseBaseSplit(layout);
  count += emit(b, c, s[k], out);
  for (std::size_t i = 0; i < k; ++i)
  {
    count += emit(b, s[i + 1], s[i], out);
  }
  for (std::size_t i = k; i < n; ++i)
  {
    count += emit(c, s[i + 1], s[i], out);
  }
  return count;
}

} // namespace silsmooth
