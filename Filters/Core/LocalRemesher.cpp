#include "LocalRemesher.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace silsmooth
{

namespace
{

// Appends (a, b, c) unless it repeats a point id (see the header: a
// silhouette point given as a vertex's id collapses these triangles).
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

// Shape quality 4 sqrt(3) area / (sum of squared sides): 1 for an equilateral
// triangle, 0 for a degenerate one. Triangles that repeat an id are dropped
// by emit(), so they do not count (infinite quality).
double shapeQuality(
  Id ia, Id ib, Id ic, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  if (ia == ib || ib == ic || ic == ia)
  {
    return std::numeric_limits<double>::infinity();
  }
  const double sides = glm::dot(b - a, b - a) + glm::dot(c - b, c - b) + glm::dot(a - c, a - c);
  if (!(sides > 0.0))
  {
    return 0.0;
  }
  return 2.0 * std::sqrt(3.0) * glm::length(glm::cross(b - a, c - a)) / sides;
}

// The k whose triangulation has the best worst triangle, in O(n) with
// prefix minima of B's fan and suffix minima of C's fan.
std::size_t chooseBaseSplit(const SilhouetteTriangleLayout& layout)
{
  const std::vector<Id>& s = layout.Chain;
  const std::vector<glm::dvec3>& x = layout.ChainPositions;
  const glm::dvec3& pb = layout.BaseFirstPosition;
  const glm::dvec3& pc = layout.BaseSecondPosition;
  const Id b = layout.BaseFirst;
  const Id c = layout.BaseSecond;
  const std::size_t n = s.size() - 1;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> bFanBefore(n + 1, inf); // worst of (B, s[i+1], s[i]) for i < k
  for (std::size_t k = 1; k <= n; ++k)
  {
    bFanBefore[k] =
      std::min(bFanBefore[k - 1], shapeQuality(b, s[k], s[k - 1], pb, x[k], x[k - 1]));
  }
  std::vector<double> cFanFrom(n + 1, inf); // worst of (C, s[i+1], s[i]) for i >= k
  for (std::size_t k = n; k-- > 0;)
  {
    cFanFrom[k] = std::min(cFanFrom[k + 1], shapeQuality(c, s[k + 1], s[k], pc, x[k + 1], x[k]));
  }
  std::size_t best = 0;
  double bestQuality = -1.0;
  for (std::size_t k = 0; k <= n; ++k)
  {
    const double worst =
      std::min({ bFanBefore[k], cFanFrom[k], shapeQuality(b, c, s[k], pb, pc, x[k]) });
    if (worst > bestQuality)
    {
      bestQuality = worst;
      best = k;
    }
  }
  return best;
}

} // namespace

std::size_t remeshSilhouetteTriangle(
  const SilhouetteTriangleLayout& layout, std::vector<Triangle>& out)
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

int chooseFanApex(const std::vector<Id>& ids, const std::vector<glm::dvec3>& flat,
  const std::vector<unsigned char>& isCandidate, const glm::dvec3& centre)
{
  const std::size_t n = ids.size();
  if (n < 3)
  {
    return 0;
  }
  // A fan from v makes (v, j, j + 1) for every side not touching v.
  int best = -1;
  double bestQuality = 0.0;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (!isCandidate[v])
    {
      continue;
    }
    double worst = std::numeric_limits<double>::infinity();
    for (std::size_t step = 1; step + 1 < n; ++step)
    {
      const std::size_t j = (v + step) % n;
      const std::size_t k = (v + step + 1) % n;
      worst = std::min(worst, shapeQuality(ids[v], ids[j], ids[k], flat[v], flat[j], flat[k]));
    }
    if (best < 0 || worst > bestQuality)
    {
      best = static_cast<int>(v);
      bestQuality = worst;
    }
  }
  double centreQuality = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n; ++j)
  {
    const std::size_t k = (j + 1) % n;
    centreQuality =
      std::min(centreQuality, shapeQuality(-1, ids[j], ids[k], centre, flat[j], flat[k]));
  }
  // Below this a vertex fan has a triangle standing on edge in the domain.
  const double proper = 1e-6;
  if (best < 0 || bestQuality < proper || 0.5 * centreQuality > bestQuality)
  {
    return -1;
  }
  return best;
}

std::size_t emitFan(const std::vector<Id>& ids, int apex, Id centreId, std::vector<Triangle>& out)
{
  const std::size_t n = ids.size();
  std::size_t count = 0;
  if (apex < 0)
  {
    for (std::size_t j = 0; j < n; ++j)
    {
      count += emit(centreId, ids[j], ids[(j + 1) % n], out);
    }
    return count;
  }
  const std::size_t v = static_cast<std::size_t>(apex);
  for (std::size_t step = 1; step + 1 < n; ++step)
  {
    count += emit(ids[v], ids[(v + step) % n], ids[(v + step + 1) % n], out);
  }
  return count;
}

} // namespace silsmooth
