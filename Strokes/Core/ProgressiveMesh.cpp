#include "ProgressiveMesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <stdexcept>
#include <tuple>

namespace silsmooth
{

namespace
{

struct Candidate
{
  double cost = 0.0;
  double length2 = 0.0;
  Id a = 0;
  Id b = 0;
  std::uint64_t stampA = 0;
  std::uint64_t stampB = 0;
  bool operator>(const Candidate& other) const
  {
    return std::tie(this->cost, this->length2, this->a, this->b) >
      std::tie(other.cost, other.length2, other.a, other.b);
  }
};

glm::dvec3 normalOf(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2)
{
  return glm::cross(p1 - p0, p2 - p0);
}

int cornerOf(const Triangle& t, Id v)
{
  for (int k = 0; k < 3; ++k)
  {
    if (t[k] == v)
    {
      return k;
    }
  }
  return -1;
}

// The simplification state: the mesh being coarsened plus the incidence.
class Simplifier
{
public:
  Simplifier(
    std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles, std::vector<char>& active)
    : P(points)
    , T(triangles)
    , Active(active)
    , Incident(points.size())
    , Frozen(points.size(), 0)
    , Stamp(points.size(), 0)
  {
    std::map<std::pair<Id, Id>, int> edgeUse;
    for (std::size_t t = 0; t < T.size(); ++t)
    {
      const Triangle& tri = T[t];
      if (hasRepeatedCorner(tri))
      {
        for (Id v : tri)
        {
          this->Frozen[v] = 1;
        }
      }
      for (Id v : tri)
      {
        if (this->Incident[v].empty() || this->Incident[v].back() != static_cast<Id>(t))
        {
          this->Incident[v].push_back(static_cast<Id>(t));
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        ++edgeUse[std::minmax(tri[k], tri[(k + 1) % 3])];
      }
    }
    for (const auto& [edge, count] : edgeUse)
    {
      if (count > 2)
      {
        this->Frozen[edge.first] = 1;
        this->Frozen[edge.second] = 1;
      }
    }
  }

  std::vector<Id> neighbours(Id v) const
  {
    std::vector<Id> out;
    for (Id t : this->Incident[v])
    {
      for (Id w : T[t])
      {
        if (w != v)
        {
          out.push_back(w);
        }
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  std::vector<Id> edgeTriangles(Id a, Id b) const
  {
    std::vector<Id> out;
    for (Id t : this->Incident[a])
    {
      if (cornerOf(T[t], b) >= 0)
      {
        out.push_back(t);
      }
    }
    return out;
  }

  std::size_t edgeTriangleCount(Id a, Id b) const
  {
    std::size_t count = 0;
    for (Id t : this->Incident[a])
    {
      count += cornerOf(T[t], b) >= 0 ? 1 : 0;
    }
    return count;
  }

  bool onBorder(Id v) const
  {
    for (Id t : this->Incident[v])
    {
      for (Id w : T[t])
      {
        if (w != v && this->edgeTriangleCount(v, w) == 1)
        {
          return true;
        }
      }
    }
    return false;
  }

  // The best collapse of edge (a, b), or false when it is not allowed.
  // Where a collapse of (a, b) may put the kept point: the border end when
  // one end is on the border, else either end or the midpoint.
  struct Placement
  {
    Id kept;
    Id removed;
    glm::dvec3 v;
  };

  // The rules a collapse of (a, b) must keep (ProgressiveMesh.h): one or two
  // triangles on the edge, no pinch between two border points, and the link
  // condition on vertices and on edges. `onEdge` gets the edge's triangles,
  // `na` and `nb` the ends' neighbours.
  bool collapsible(
    Id a, Id b, std::vector<Id>& onEdge, std::vector<Id>& na, std::vector<Id>& nb) const
  {
    if (this->Frozen[a] || this->Frozen[b])
    {
      return false;
    }
    onEdge = this->edgeTriangles(a, b);
    if (onEdge.empty() || onEdge.size() > 2)
    {
      return false;
    }
    if (this->onBorder(a) && this->onBorder(b) && onEdge.size() != 1)
    {
      return false;
    }
    // Link condition, vertices: the common neighbours are the far corners.
    std::vector<Id> far;
    for (Id t : onEdge)
    {
      for (Id w : T[t])
      {
        if (w != a && w != b)
        {
          far.push_back(w);
        }
      }
    }
    std::sort(far.begin(), far.end());
    na = this->neighbours(a);
    nb = this->neighbours(b);
    std::vector<Id> common;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    if (common != far)
    {
      return false;
    }
    // Link condition, edges: no triangle (a, c, d) with c and d both far
    // corners (a tetrahedron would fold onto itself).
    if (far.size() == 2)
    {
      for (Id t : this->Incident[a])
      {
        if (cornerOf(T[t], b) < 0 && cornerOf(T[t], far[0]) >= 0 && cornerOf(T[t], far[1]) >= 0)
        {
          return false;
        }
      }
    }
    return true;
  }

  std::vector<Placement> placements(Id a, Id b) const
  {
    const bool aBorder = this->onBorder(a);
    const bool bBorder = this->onBorder(b);
    if (aBorder && !bBorder)
    {
      return { { a, b, P[a] } };
    }
    if (bBorder && !aBorder)
    {
      return { { b, a, P[b] } };
    }
    return { { a, b, P[a] }, { b, a, P[b] },
      { std::min(a, b), std::max(a, b), 0.5 * (P[a] + P[b]) } };
  }

  // The border edges at a or b among `around`, oriented as in their triangle.
  std::vector<std::pair<Id, Id>> borderEdgesAt(Id a, Id b, const std::vector<Id>& around) const
  {
    std::vector<std::pair<Id, Id>> borderEdges;
    for (Id t : around)
    {
      const Triangle& tri = T[t];
      for (int k = 0; k < 3; ++k)
      {
        const Id u = tri[k];
        const Id w = tri[(k + 1) % 3];
        if ((u == a || u == b || w == a || w == b) && this->edgeTriangleCount(u, w) == 1)
        {
          borderEdges.emplace_back(u, w);
        }
      }
    }
    return borderEdges;
  }

  // F_C of putting the merged point at `placement` (ProgressiveMesh.h), or
  // NaN when a remaining triangle around a or b would turn over.
  double costOf(const Placement& placement, Id a, Id b, const std::vector<Id>& around,
    const std::vector<Id>& onEdge, const std::vector<std::pair<Id, Id>>& borderEdges, double degree,
    double length2) const
  {
    double volume = 0.0;
    for (Id t : around)
    {
      const Triangle& tri = T[t];
      const glm::dvec3& p0 = P[tri[0]];
      const glm::dvec3& p1 = P[tri[1]];
      const glm::dvec3& p2 = P[tri[2]];
      volume += glm::dot(placement.v - p0, glm::cross(p1 - p0, p2 - p0)) / 6.0;
      if (std::find(onEdge.begin(), onEdge.end(), t) != onEdge.end())
      {
        continue;
      }
      glm::dvec3 q[3];
      for (int k = 0; k < 3; ++k)
      {
        q[k] = (tri[k] == a || tri[k] == b) ? placement.v : P[tri[k]];
      }
      if (!(glm::dot(normalOf(p0, p1, p2), normalOf(q[0], q[1], q[2])) > 0.0))
      {
        return std::numeric_limits<double>::quiet_NaN();
      }
    }
    glm::dvec3 area(0.0);
    for (const auto& [u, w] : borderEdges)
    {
      area += 0.5 * glm::cross(P[u] - placement.v, P[w] - placement.v);
    }
    return ProgressiveMesh::Lambda * std::abs(volume) * degree +
      (1.0 - ProgressiveMesh::Lambda) * length2 * glm::length(area);
  }

  // The cheapest allowed collapse of edge (a, b), as the split that undoes
  // it; false when the edge may not collapse.
  bool evaluate(Id a, Id b, VertexSplit& best) const
  {
    std::vector<Id> onEdge;
    std::vector<Id> na;
    std::vector<Id> nb;
    if (!this->collapsible(a, b, onEdge, na, nb))
    {
      return false;
    }
    // Triangles around a and b, each once.
    std::vector<Id> around = this->Incident[a];
    around.insert(around.end(), this->Incident[b].begin(), this->Incident[b].end());
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    const std::vector<std::pair<Id, Id>> borderEdges = this->borderEdgesAt(a, b, around);
    const double length2 = glm::dot(P[a] - P[b], P[a] - P[b]);
    const double degree = static_cast<double>(na.size() + nb.size());
    bool found = false;
    for (const Placement& placement : this->placements(a, b))
    {
      const double cost =
        this->costOf(placement, a, b, around, onEdge, borderEdges, degree, length2);
      if (!std::isfinite(cost))
      {
        continue; // a triangle turns over, or no finite cost
      }
      if (!found || cost < best.cost)
      {
        found = true;
        best = VertexSplit();
        best.kept = placement.kept;
        best.removed = placement.removed;
        best.keptBefore = P[placement.kept];
        best.keptAfter = placement.v;
        best.cost = cost;
        best.removedTriangles = onEdge;
      }
    }
    if (!found)
    {
      return false;
    }
    for (Id t : this->Incident[best.removed])
    {
      if (std::find(onEdge.begin(), onEdge.end(), t) == onEdge.end())
      {
        best.renamedCorners.emplace_back(t, cornerOf(T[t], best.removed));
      }
    }
    return true;
  }

  void push(Id a, Id b)
  {
    VertexSplit split;
    if (this->evaluate(a, b, split))
    {
      Candidate c;
      c.cost = split.cost;
      c.length2 = glm::dot(P[a] - P[b], P[a] - P[b]);
      c.a = std::min(a, b);
      c.b = std::max(a, b);
      c.stampA = this->Stamp[c.a];
      c.stampB = this->Stamp[c.b];
      this->Queue.push(c);
    }
  }

  // Collapses cheapest-first until `minimumTriangles`; returns the collapses.
  /// The collapses, in order; empty with `aborted` set when `progress`
  /// stopped them.
  std::vector<VertexSplit> run(std::size_t activeTriangles, std::size_t minimumTriangles,
    const ProgressCallback& progress, bool& aborted)
  {
    const std::size_t start = activeTriangles;
    for (std::size_t v = 0; v < P.size(); ++v)
    {
      for (Id w : this->neighbours(static_cast<Id>(v)))
      {
        if (static_cast<Id>(v) < w)
        {
          this->push(static_cast<Id>(v), w);
        }
      }
    }
    std::vector<VertexSplit> collapses;
    aborted = false;
    std::size_t nextReport = 0; // in collapses
    while (!this->Queue.empty() && activeTriangles > minimumTriangles)
    {
      if (collapses.size() >= nextReport)
      {
        nextReport = collapses.size() + 256;
        if (!reportProgress(progress,
              static_cast<double>(start - activeTriangles) /
                static_cast<double>(start - minimumTriangles)))
        {
          aborted = true;
          return {};
        }
      }
      const Candidate c = this->Queue.top();
      this->Queue.pop();
      if (this->Stamp[c.a] != c.stampA || this->Stamp[c.b] != c.stampB)
      {
        continue; // stale: a newer entry was pushed when the neighbourhood changed
      }
      VertexSplit split;
      if (!this->evaluate(c.a, c.b, split))
      {
        continue;
      }
      if (activeTriangles < minimumTriangles + split.removedTriangles.size())
      {
        break;
      }
      this->collapse(split);
      activeTriangles -= split.removedTriangles.size();
      collapses.push_back(split);
      // Every vertex whose cost inputs may have changed: kept and its ring.
      std::vector<Id> touched = this->neighbours(split.kept);
      touched.push_back(split.kept);
      for (Id v : touched)
      {
        ++this->Stamp[v];
      }
      for (Id v : touched)
      {
        for (Id w : this->neighbours(v))
        {
          this->push(v, w);
        }
      }
    }
    return collapses;
  }

  void collapse(const VertexSplit& split)
  {
    for (Id t : split.removedTriangles)
    {
      this->Active[t] = 0;
      for (Id w : T[t])
      {
        auto& list = this->Incident[w];
        list.erase(std::remove(list.begin(), list.end(), t), list.end());
      }
    }
    for (const auto& [t, corner] : split.renamedCorners)
    {
      T[t][corner] = split.kept;
      this->Incident[split.kept].push_back(t);
    }
    std::sort(this->Incident[split.kept].begin(), this->Incident[split.kept].end());
    this->Incident[split.removed].clear();
    P[split.kept] = split.keptAfter;
  }

private:
  std::vector<glm::dvec3>& P;
  std::vector<Triangle>& T;
  std::vector<char>& Active;
  std::vector<std::vector<Id>> Incident;
  std::vector<char> Frozen;
  std::vector<std::uint64_t> Stamp;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> Queue;
};

} // namespace

ProgressiveMesh::ProgressiveMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
  std::size_t minimumTriangles, const ProgressCallback& progress)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
{
  const Id n = static_cast<Id>(this->Points.size());
  for (const Triangle& t : this->Triangles)
  {
    for (Id v : t)
    {
      if (v < 0 || v >= n)
      {
        throw std::invalid_argument("ProgressiveMesh: triangle corner out of range");
      }
    }
  }
  this->TriangleActive.assign(this->Triangles.size(), 1);
  this->VertexActive.assign(this->Points.size(), 0);
  for (const Triangle& t : this->Triangles)
  {
    for (Id v : t)
    {
      this->VertexActive[v] = 1;
    }
  }
  this->ActiveVertices =
    static_cast<std::size_t>(std::count(this->VertexActive.begin(), this->VertexActive.end(), 1));
  this->ActiveTriangles = this->Triangles.size();

  std::vector<VertexSplit> collapses;
  {
    Simplifier simplifier(this->Points, this->Triangles, this->TriangleActive);
    collapses = simplifier.run(this->ActiveTriangles, minimumTriangles, progress, this->Aborted);
  }
  if (this->Aborted)
  {
    return; // the caller throws this mesh away
  }
  for (const VertexSplit& c : collapses)
  {
    this->ActiveTriangles -= c.removedTriangles.size();
    this->VertexActive[c.removed] = 0;
    --this->ActiveVertices;
  }
  this->BaseTriangles = this->ActiveTriangles;
  this->Splits.assign(collapses.rbegin(), collapses.rend());
  this->Level = 0;
  this->setLevel(this->Splits.size());
}

void ProgressiveMesh::applySplit(const VertexSplit& split)
{
  this->Points[split.kept] = split.keptBefore;
  for (const auto& [t, corner] : split.renamedCorners)
  {
    this->Triangles[t][corner] = split.removed;
  }
  for (Id t : split.removedTriangles)
  {
    this->TriangleActive[t] = 1;
  }
  this->VertexActive[split.removed] = 1;
  this->ActiveTriangles += split.removedTriangles.size();
  ++this->ActiveVertices;
}

void ProgressiveMesh::applyCollapse(const VertexSplit& split)
{
  this->Points[split.kept] = split.keptAfter;
  for (const auto& [t, corner] : split.renamedCorners)
  {
    this->Triangles[t][corner] = split.kept;
  }
  for (Id t : split.removedTriangles)
  {
    this->TriangleActive[t] = 0;
  }
  this->VertexActive[split.removed] = 0;
  this->ActiveTriangles -= split.removedTriangles.size();
  --this->ActiveVertices;
}

void ProgressiveMesh::setLevel(std::size_t level)
{
  level = std::min(level, this->Splits.size());
  while (this->Level < level)
  {
    this->applySplit(this->Splits[this->Level]);
    ++this->Level;
  }
  while (this->Level > level)
  {
    --this->Level;
    this->applyCollapse(this->Splits[this->Level]);
  }
}

void ProgressiveMesh::refineTo(std::size_t count)
{
  while (this->Level < this->Splits.size() && this->ActiveTriangles < count)
  {
    this->applySplit(this->Splits[this->Level]);
    ++this->Level;
  }
}

void ProgressiveMesh::coarsenTo(std::size_t count)
{
  while (this->Level > 0 && this->ActiveTriangles > count)
  {
    --this->Level;
    this->applyCollapse(this->Splits[this->Level]);
  }
}

void ProgressiveMesh::setTriangleCount(std::size_t count)
{
  // Each split adds one or two triangles, so the count grows strictly with
  // the level: coarsening to <= count then refining to >= count lands on
  // the lowest level with >= count from either side.
  this->coarsenTo(count);
  this->refineTo(count);
}

std::vector<Triangle> ProgressiveMesh::triangles() const
{
  std::vector<Triangle> out;
  out.reserve(this->ActiveTriangles);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    if (this->TriangleActive[t])
    {
      out.push_back(this->Triangles[t]);
    }
  }
  return out;
}

void ProgressiveMesh::compact(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles,
  std::vector<Id>& pointIds, std::vector<Id>& triangleIds) const
{
  points.clear();
  triangles.clear();
  pointIds.clear();
  triangleIds.clear();
  std::vector<Id> newId(this->Points.size(), -1);
  for (std::size_t v = 0; v < this->Points.size(); ++v)
  {
    if (this->VertexActive[v])
    {
      newId[v] = static_cast<Id>(points.size());
      points.push_back(this->Points[v]);
      pointIds.push_back(static_cast<Id>(v));
    }
  }
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    if (this->TriangleActive[t])
    {
      const Triangle& tri = this->Triangles[t];
      triangles.push_back({ newId[tri[0]], newId[tri[1]], newId[tri[2]] });
      triangleIds.push_back(static_cast<Id>(t));
    }
  }
}

} // namespace silsmooth
