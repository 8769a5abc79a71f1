#include "SurfaceWelding.h"

#include "FiniteVector.h"

#include "DisjointSets.h"
#include "ShadingNormals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace silsmooth
{

namespace
{

std::vector<Id> weldExactly(const std::vector<glm::dvec3>& points)
{
  std::vector<Id> order(points.size());
  std::iota(order.begin(), order.end(), Id{ 0 });
  auto key = [&](Id i) {
    const glm::dvec3& p = points[static_cast<std::size_t>(i)];
    return std::make_tuple(p.x, p.y, p.z, i);
  };
  std::sort(order.begin(), order.end(), [&](Id a, Id b) { return key(a) < key(b); });
  std::vector<Id> vertex(points.size());
  std::iota(vertex.begin(), vertex.end(), Id{ 0 });
  // In sorted order equal positions are adjacent, lowest id first.
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    const glm::dvec3& a = points[static_cast<std::size_t>(order[k - 1])];
    const glm::dvec3& b = points[static_cast<std::size_t>(order[k])];
    if (isFinite(b) && a == b)
    {
      vertex[static_cast<std::size_t>(order[k])] = vertex[static_cast<std::size_t>(order[k - 1])];
    }
  }
  return vertex;
}

// Points within `tolerance`: a hash grid of cells `tolerance` wide, each point
// compared with the points of its own and the 26 neighbouring cells.
std::vector<Id> weldWithin(const std::vector<glm::dvec3>& points, double tolerance)
{
  struct CellKey
  {
    long long x, y, z;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct CellHash
  {
    std::size_t operator()(const CellKey& k) const
    {
      // Unsigned: the cells of a small tolerance number 1e14 and more, and a
      // signed product would overflow.
      const auto u = [](long long v) {
        return static_cast<std::uint64_t>(v);
      };
      return static_cast<std::size_t>(
        u(k.x) * 73856093ULL ^ u(k.y) * 19349663ULL ^ u(k.z) * 83492791ULL);
    }
  };
  auto cellOf = [&](const glm::dvec3& p, CellKey& key) {
    const glm::dvec3 c = glm::floor(p / tolerance);
    // Coordinates too large for the grid at this tolerance are not welded.
    const double limit = 4.0e18;
    if (!(std::abs(c.x) < limit && std::abs(c.y) < limit && std::abs(c.z) < limit))
    {
      return false;
    }
    key = { static_cast<long long>(c.x), static_cast<long long>(c.y), static_cast<long long>(c.z) };
    return true;
  };
  std::unordered_map<CellKey, std::vector<Id>, CellHash> grid;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    CellKey key{};
    if (isFinite(points[i]) && cellOf(points[i], key))
    {
      grid[key].push_back(static_cast<Id>(i));
    }
  }
  DisjointSets sets(points.size());
  const double limit2 = tolerance * tolerance;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    CellKey key{};
    if (!isFinite(points[i]) || !cellOf(points[i], key))
    {
      continue;
    }
    for (long long dx = -1; dx <= 1; ++dx)
    {
      for (long long dy = -1; dy <= 1; ++dy)
      {
        for (long long dz = -1; dz <= 1; ++dz)
        {
          const auto it = grid.find({ key.x + dx, key.y + dy, key.z + dz });
          if (it == grid.end())
          {
            continue;
          }
          for (const Id j : it->second)
          {
            const glm::dvec3 d = points[static_cast<std::size_t>(j)] - points[i];
            if (static_cast<std::size_t>(j) > i && glm::dot(d, d) <= limit2)
            {
              sets.unite(i, static_cast<std::size_t>(j));
            }
          }
        }
      }
    }
  }
  std::vector<Id> vertex(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    vertex[i] = static_cast<Id>(sets.find(i)); // the lowest member
  }
  return vertex;
}

} // namespace

std::vector<Id> weldCoincidentPoints(const std::vector<glm::dvec3>& points, double tolerance)
{
  return tolerance > 0.0 && std::isfinite(tolerance) ? weldWithin(points, tolerance)
                                                     : weldExactly(points);
}

NearCopies nearCopyEdges(
  const std::vector<glm::dvec3>& points, const EdgeTable& table, double relative)
{
  NearCopies found;
  glm::dvec3 low(std::numeric_limits<double>::max());
  glm::dvec3 high(std::numeric_limits<double>::lowest());
  for (const glm::dvec3& p : points)
  {
    if (isFinite(p))
    {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  if (!(low.x <= high.x))
  {
    return found; // no finite point
  }
  const double limit = relative * glm::length(high - low);
  if (!std::isfinite(limit))
  {
    return found; // a size past the doubles' range: no edge is small against it
  }
  for (std::size_t e = 0; e < table.edgeCount(); ++e)
  {
    const Edge& edge = table.edge(static_cast<Id>(e));
    const glm::dvec3& a = points[static_cast<std::size_t>(edge.low)];
    const glm::dvec3& b = points[static_cast<std::size_t>(edge.high)];
    if (!isFinite(a) || !isFinite(b) || a == b)
    {
      continue;
    }
    const double length = glm::length(b - a);
    if (length <= limit)
    {
      ++found.EdgeCount;
      found.LongestEdge = std::max(found.LongestEdge, length);
    }
  }
  return found;
}

std::vector<Triangle> weldTriangles(
  const std::vector<Triangle>& triangles, const std::vector<Id>& vertex)
{
  std::vector<Triangle> welded(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      welded[t][k] = vertex[static_cast<std::size_t>(triangles[t][k])];
    }
  }
  return welded;
}

namespace
{
std::array<Id, 3> sortedCorners(const Triangle& c)
{
  std::array<Id, 3> sorted{ { c[0], c[1], c[2] } };
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

} // namespace

std::vector<unsigned char> backToBackTwins(
  const std::vector<Triangle>& triangles, const EdgeTable& table)
{
  std::vector<unsigned char> twinned(triangles.size(), 0);
  // A twin's sides lie on edges of its twin's too, so each of its edges
  // has at least three sides unless the pair is alone: only triangles on
  // such an edge are looked at (none on a manifold mesh).
  std::vector<unsigned char> sides(table.edgeCount(), 0);
  for (std::size_t side = 0; side < table.sideCount(); ++side)
  {
    unsigned char& count = sides[static_cast<std::size_t>(
      table.sideEdge(static_cast<Id>(side / 3), static_cast<int>(side % 3)))];
    count = count < 3 ? count + 1 : count;
  }
  // Sorted corners -> the triangles on them, with their winding's parity.
  std::map<std::array<Id, 3>, std::vector<std::pair<std::size_t, bool>>> byCorners;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& c = triangles[t];
    bool crowded = false;
    for (int k = 0; k < 3; ++k)
    {
      crowded =
        crowded || sides[static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k))] >= 3;
    }
    if (!crowded || hasRepeatedCorner(c))
    {
      continue;
    }
    const std::array<Id, 3> sorted = sortedCorners(c);
    // Even: a rotation of the sorted order.
    const bool even = (c[0] == sorted[0] && c[1] == sorted[1]) ||
      (c[1] == sorted[0] && c[2] == sorted[1]) || (c[2] == sorted[0] && c[0] == sorted[1]);
    byCorners[sorted].emplace_back(t, even);
  }
  for (const auto& entry : byCorners)
  {
    const auto& onCorners = entry.second;
    const auto isEven = [](const std::pair<std::size_t, bool>& x) {
      return x.second;
    };
    const bool both = std::any_of(onCorners.begin(), onCorners.end(), isEven) &&
      !std::all_of(onCorners.begin(), onCorners.end(), isEven);
    for (const auto& x : onCorners)
    {
      twinned[x.first] = both ? 1 : 0;
    }
  }
  return twinned;
}

std::vector<std::size_t> sheetsOf(
  const std::vector<Triangle>& triangles, const EdgeTable& table, bool backToBackApart)
{
  constexpr Id noTriangle = -1;
  const std::vector<unsigned char> twinned =
    backToBackApart ? backToBackTwins(triangles, table) : std::vector<unsigned char>();
  const bool anyTwins = std::find(twinned.begin(), twinned.end(), 1) != twinned.end();
  // Edges with a twinned triangle: their triangles, each with whether it
  // runs along the edge from its low end.
  std::vector<unsigned char> twinnedEdge(anyTwins ? table.edgeCount() : 0, 0);
  for (std::size_t t = 0; anyTwins && t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3 && twinned[t]; ++k)
    {
      twinnedEdge[static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k))] = 1;
    }
  }
  std::map<std::size_t, std::vector<std::pair<std::size_t, bool>>> alongTwinnedEdge;
  std::vector<Id> firstAtEdge(table.edgeCount(), noTriangle);
  DisjointSets sheets(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const auto e = static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k));
      const Edge& edge = table.edge(static_cast<Id>(e));
      if (edge.low == edge.high)
      {
        continue;
      }
      if (anyTwins && twinnedEdge[e])
      {
        alongTwinnedEdge[e].emplace_back(t, triangles[t][k] == edge.low);
      }
      else if (firstAtEdge[e] == noTriangle)
      {
        firstAtEdge[e] = static_cast<Id>(t);
      }
      else
      {
        sheets.unite(static_cast<std::size_t>(firstAtEdge[e]), t);
      }
    }
  }
  for (const auto& entry : alongTwinnedEdge)
  {
    const auto& along = entry.second;
    // Past a few triangles on one edge (a fan's spine), all are joined, as
    // without twins: the pairs would cost their square.
    constexpr std::size_t mostPaired = 16;
    for (std::size_t a = 0; a < along.size() && along.size() > mostPaired; ++a)
    {
      sheets.unite(along[0].first, along[a].first);
    }
    for (std::size_t a = 0; a < along.size() && along.size() <= mostPaired; ++a)
    {
      for (std::size_t b = a + 1; b < along.size(); ++b)
      {
        const std::size_t ta = along[a].first, tb = along[b].first;
        const bool apart = (twinned[ta] || twinned[tb]) &&
          (along[a].second == along[b].second ||
            sortedCorners(triangles[ta]) == sortedCorners(triangles[tb]));
        if (!apart)
        {
          sheets.unite(ta, tb);
        }
      }
    }
  }
  std::vector<std::size_t> sheet(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    sheet[t] = sheets.find(t);
  }
  return sheet;
}

std::vector<Id> weldWithinSheets(
  const std::vector<Triangle>& triangles, std::vector<Id> vertex, const EdgeTable& weldedTable)
{
  const std::size_t n = vertex.size();
  bool anyWelded = false;
  for (std::size_t i = 0; i < n && !anyWelded; ++i)
  {
    anyWelded = vertex[i] != static_cast<Id>(i);
  }
  if (!anyWelded)
  {
    return vertex;
  }
  const std::vector<std::size_t> sheets =
    sheetsOf(weldTriangles(triangles, vertex), weldedTable, true);
  // Each point's sheet; a group with a point on two sheets stays whole.
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> sheetOfPoint(n, none);
  std::vector<unsigned char> keepWhole(n, 0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const std::size_t sheet = sheets[t];
    for (const Id p : triangles[t])
    {
      std::size_t& s = sheetOfPoint[static_cast<std::size_t>(p)];
      if (s != none && s != sheet)
      {
        keepWhole[static_cast<std::size_t>(vertex[static_cast<std::size_t>(p)])] = 1;
      }
      s = sheet;
    }
  }
  // The group's first sheet (in ascending point order) keeps the group's
  // vertex, so a group on one sheet is left as it was; each further sheet's
  // points take the lowest of them (rare: looked up in a small map).
  std::vector<std::size_t> firstSheet(n, none);
  std::map<std::pair<Id, std::size_t>, Id> furtherSheets;
  for (std::size_t i = 0; i < n; ++i)
  {
    const Id group = vertex[i];
    const std::size_t sheet = sheetOfPoint[i];
    if (sheet == none || keepWhole[static_cast<std::size_t>(group)])
    {
      continue; // unused points stay with their group's lowest point
    }
    std::size_t& first = firstSheet[static_cast<std::size_t>(group)];
    if (first == none)
    {
      first = sheet;
    }
    if (first != sheet)
    {
      vertex[i] =
        furtherSheets.emplace(std::make_pair(group, sheet), static_cast<Id>(i)).first->second;
    }
  }
  return vertex;
}

std::vector<FeatureEdge> normalSeamEdges(const std::vector<Triangle>& triangles,
  const std::vector<Id>& vertex, const std::vector<glm::dvec3>& normals, double angleDegrees,
  std::size_t* interiorEdges, const std::vector<Triangle>* givenWelded, const EdgeTable* givenTable)
{
  if (interiorEdges)
  {
    *interiorEdges = 0;
  }
  std::vector<FeatureEdge> seams;
  if (normals.size() != vertex.size())
  {
    return seams;
  }
  const std::vector<Triangle> weldedHere =
    givenWelded ? std::vector<Triangle>() : weldTriangles(triangles, vertex);
  const std::vector<Triangle>& welded = givenWelded ? *givenWelded : weldedHere;
  const EdgeTable tableHere = givenTable ? EdgeTable() : EdgeTable(welded);
  const EdgeTable& table = givenTable ? *givenTable : tableHere;
  // The two sides of every edge (triangle, side); more than two: not a seam.
  std::vector<std::array<Id, 2>> sides(table.edgeCount(), { { -1, -1 } });
  std::vector<unsigned char> count(table.edgeCount(), 0);
  for (std::size_t t = 0; t < welded.size(); ++t)
  {
    if (hasRepeatedCorner(welded[t]))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t e = static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k));
      if (count[e] < 2)
      {
        sides[e][count[e]] = static_cast<Id>(t) * 3 + k;
      }
      count[e] = static_cast<unsigned char>(std::min(3, count[e] + 1));
    }
  }
  const double cosLimit = std::cos(angleDegrees * 3.14159265358979323846 / 180.0);
  // The input point of triangle t at surface vertex v.
  auto pointAt = [&](Id t, Id v) {
    const Triangle& w = welded[static_cast<std::size_t>(t)];
    const int k = w[0] == v ? 0 : (w[1] == v ? 1 : 2);
    return triangles[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)];
  };
  auto differ = [&](Id p, Id q) {
    if (p == q)
    {
      return false;
    }
    const glm::dvec3 a = safeNormalize(normals[static_cast<std::size_t>(p)]);
    const glm::dvec3 b = safeNormalize(normals[static_cast<std::size_t>(q)]);
    return a != glm::dvec3(0.0) && b != glm::dvec3(0.0) && glm::dot(a, b) < cosLimit;
  };
  for (std::size_t e = 0; e < table.edgeCount(); ++e)
  {
    if (count[e] != 2)
    {
      continue;
    }
    if (interiorEdges)
    {
      ++*interiorEdges;
    }
    const Edge& edge = table.edge(static_cast<Id>(e));
    const Id t0 = sides[e][0] / 3;
    const Id t1 = sides[e][1] / 3;
    if (differ(pointAt(t0, edge.low), pointAt(t1, edge.low)) ||
      differ(pointAt(t0, edge.high), pointAt(t1, edge.high)))
    {
      seams.emplace_back(edge.low, edge.high);
    }
  }
  return seams; // ascending: the edge table is sorted
}

} // namespace silsmooth
