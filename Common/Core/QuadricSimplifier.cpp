#include "QuadricSimplifier.h"

#include "FiniteVector.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

namespace silsmooth
{

namespace
{

// A symmetric 4x4 quadric: v^T A v + 2 b . v + c.
struct Quadric
{
  glm::dmat3 A{ 0.0 };
  glm::dvec3 B{ 0.0 };
  double C = 0.0;

  static Quadric plane(const glm::dvec3& n, double d)
  {
    Quadric q;
    q.A = glm::outerProduct(n, n);
    q.B = d * n;
    q.C = d * d;
    return q;
  }
  Quadric& operator+=(const Quadric& o)
  {
    this->A += o.A;
    this->B += o.B;
    this->C += o.C;
    return *this;
  }
  double operator()(const glm::dvec3& v) const
  {
    return std::max(0.0, glm::dot(v, this->A * v) + 2.0 * glm::dot(this->B, v) + this->C);
  }
};

struct Candidate
{
  double Rank;
  double Cost;
  Id A;
  Id B;
  std::uint64_t StampA;
  std::uint64_t StampB;
  glm::dvec3 Position;
  bool operator>(const Candidate& o) const
  {
    if (this->Rank != o.Rank)
      return this->Rank > o.Rank;
    if (this->A != o.A)
      return this->A > o.A;
    return this->B > o.B;
  }
};

class Simplifier
{
public:
  Simplifier(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
    const SimplificationParameters& parameters)
    : Points(points)
    , Parameters(parameters)
  {
    for (const Triangle& t : triangles)
    {
      if (!hasRepeatedCorner(t))
      {
        this->Faces.push_back(t);
      }
    }
    const std::size_t n = points.size();
    this->Quadrics.assign(n, Quadric());
    this->FacesOf.assign(n, {});
    this->Stamp.assign(n, 0);
    this->Alive.assign(n, 1);
    this->Locked.assign(n, 0);
    this->Near.assign(n, 0);
    for (std::size_t i = 0; i < n && i < parameters.Near.size(); ++i)
    {
      this->Near[i] = parameters.Near[i] ? 1 : 0;
    }
    this->FaceAlive.assign(this->Faces.size(), 1);
    for (std::size_t f = 0; f < this->Faces.size(); ++f)
    {
      const Triangle& t = this->Faces[f];
      const glm::dvec3 cross =
        glm::cross(this->P(t[1]) - this->P(t[0]), this->P(t[2]) - this->P(t[0]));
      const double length = glm::length(cross);
      if (length > 0.0 && std::isfinite(length))
      {
        const glm::dvec3 normal = cross / length;
        const Quadric q = Quadric::plane(normal, -glm::dot(normal, this->P(t[0])));
        for (const Id v : t)
        {
          this->Quadrics[static_cast<std::size_t>(v)] += q;
        }
      }
      for (const Id v : t)
      {
        this->FacesOf[static_cast<std::size_t>(v)].push_back(static_cast<Id>(f));
      }
    }
    // Boundary and non-manifold edges lock their points. The edges, sorted,
    // each as often as triangles have it (the same order a map gave).
    std::vector<std::pair<Id, Id>> sides;
    sides.reserve(3 * this->Faces.size());
    for (const Triangle& t : this->Faces)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Id a = t[static_cast<std::size_t>(k)];
        const Id b = t[static_cast<std::size_t>((k + 1) % 3)];
        sides.emplace_back(std::min(a, b), std::max(a, b));
      }
    }
    std::sort(sides.begin(), sides.end());
    for (std::size_t i = 0; i < sides.size();)
    {
      std::size_t j = i;
      while (j < sides.size() && sides[j] == sides[i])
        ++j;
      if (j - i != 2)
      {
        this->Locked[static_cast<std::size_t>(sides[i].first)] = 1;
        this->Locked[static_cast<std::size_t>(sides[i].second)] = 1;
      }
      i = j;
    }
    this->lockPinchedPoints();
    sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
    for (const auto& [a, b] : sides)
    {
      this->push(a, b);
    }
    this->FaceCount = this->Faces.size();
    this->RoundOf.assign(n, 0);
    this->Error.assign(n, 0.0);
  }

  SimplificationResult run()
  {
    SimplificationResult result;
    const std::size_t target = std::max<std::size_t>(this->Parameters.TargetTriangles, 4);
    const std::size_t start = this->FaceCount;
    std::size_t nextReport = 0; // in collapses
    while (this->FaceCount > target && this->nextRoundIfNeeded())
    {
      if (result.Collapses >= nextReport)
      {
        nextReport = result.Collapses + 256;
        if (!reportProgress(this->Parameters.Progress,
              static_cast<double>(start - this->FaceCount) / static_cast<double>(start - target)))
        {
          result = SimplificationResult();
          result.Aborted = true;
          return result;
        }
      }
      const Candidate c = this->Heap.top();
      this->Heap.pop();
      if (!std::isfinite(c.Rank))
      {
        break; // only forbidden collapses are left
      }
      const std::size_t a = static_cast<std::size_t>(c.A);
      const std::size_t b = static_cast<std::size_t>(c.B);
      if (!this->Alive[a] || !this->Alive[b] || this->Stamp[a] != c.StampA ||
        this->Stamp[b] != c.StampB)
      {
        continue;
      }
      if (this->Parameters.IndependentRounds && this->touchedThisRound(c.A, c.B))
      {
        this->Deferred.push_back(c);
        continue;
      }
      if (!this->canCollapse(c.A, c.B, c.Position))
      {
        continue;
      }
      this->collapse(c.A, c.B, c.Position);
      if (this->Parameters.IndependentRounds)
      {
        this->markRound(c.A);
      }
      if (this->Parameters.RecordSequence)
      {
        result.Sequence.push_back({ c.A, c.B, c.Position, c.Cost });
      }
      result.Threshold = std::max(result.Threshold, c.Rank);
      ++result.Collapses;
      this->Error[static_cast<std::size_t>(c.A)] = c.Cost;
    }
    result.ReachedTarget = this->FaceCount <= target;

    std::vector<Id> newId(this->Points.size(), -1);
    for (std::size_t f = 0; f < this->Faces.size(); ++f)
    {
      if (!this->FaceAlive[f])
      {
        continue;
      }
      Triangle t = this->Faces[f];
      for (Id& v : t)
      {
        Id& id = newId[static_cast<std::size_t>(v)];
        if (id < 0)
        {
          id = static_cast<Id>(result.Points.size());
          result.Points.push_back(this->Points[static_cast<std::size_t>(v)]);
          result.SourcePoint.push_back(v);
          result.PointError.push_back(this->Error[static_cast<std::size_t>(v)]);
          result.PointNear.push_back(this->Near[static_cast<std::size_t>(v)]);
        }
        v = id;
      }
      result.Triangles.push_back(t);
    }
    return result;
  }

private:
  const glm::dvec3& P(Id v) const { return this->Points[static_cast<std::size_t>(v)]; }

  // Points whose triangles form more than one fan around them (triangles
  // around the point joined through the edges at it): a collapse there would
  // need a disk around the point.
  void lockPinchedPoints()
  {
    std::vector<std::size_t> parent;
    std::unordered_map<Id, std::size_t> faceAcross; // other corner -> first face index here
    for (std::size_t v = 0; v < this->FacesOf.size(); ++v)
    {
      const std::vector<Id>& faces = this->FacesOf[v];
      if (faces.size() < 2 || this->Locked[v])
        continue;
      parent.resize(faces.size());
      for (std::size_t i = 0; i < faces.size(); ++i)
        parent[i] = i;
      const auto root = [&parent](std::size_t i) {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      };
      faceAcross.clear();
      for (std::size_t i = 0; i < faces.size(); ++i)
      {
        for (const Id w : this->Faces[static_cast<std::size_t>(faces[i])])
        {
          if (w == static_cast<Id>(v))
            continue;
          const auto [it, added] = faceAcross.emplace(w, i);
          if (!added)
            parent[root(i)] = root(it->second);
        }
      }
      std::size_t fans = 0;
      for (std::size_t i = 0; i < faces.size(); ++i)
        fans += root(i) == i ? 1 : 0;
      if (fans > 1)
        this->Locked[v] = 1;
    }
  }

  // Whether there is a candidate left; with IndependentRounds, an empty heap
  // starts the next round with the collapses this one deferred.
  bool nextRoundIfNeeded()
  {
    if (this->Heap.empty() && !this->Deferred.empty())
    {
      ++this->Round;
      for (const Candidate& c : this->Deferred)
        this->Heap.push(c);
      this->Deferred.clear();
    }
    return !this->Heap.empty();
  }

  // A collapse of this round changed a triangle at a, at b or next to them.
  bool touchedThisRound(Id a, Id b) const
  {
    for (const Id end : { a, b })
    {
      for (const Id f : this->FacesOf[static_cast<std::size_t>(end)])
      {
        if (!this->FaceAlive[static_cast<std::size_t>(f)])
          continue;
        for (const Id w : this->Faces[static_cast<std::size_t>(f)])
        {
          if (this->RoundOf[static_cast<std::size_t>(w)] == this->Round)
            return true;
        }
      }
    }
    return false;
  }

  // After a collapse into `kept`: its star's points were touched this round.
  void markRound(Id kept)
  {
    for (const Id f : this->FacesOf[static_cast<std::size_t>(kept)])
    {
      for (const Id w : this->Faces[static_cast<std::size_t>(f)])
        this->RoundOf[static_cast<std::size_t>(w)] = this->Round;
    }
  }

  void push(Id a, Id b)
  {
    if (a > b)
    {
      std::swap(a, b);
    }
    const std::size_t ia = static_cast<std::size_t>(a);
    const std::size_t ib = static_cast<std::size_t>(b);
    if (this->Locked[ia] || this->Locked[ib])
    {
      return;
    }
    Quadric q = this->Quadrics[ia];
    q += this->Quadrics[ib];
    glm::dvec3 best = 0.5 * (this->P(a) + this->P(b));
    double cost = q(best);
    const double det = glm::determinant(q.A);
    const double scale = std::pow(
      std::max(glm::length(q.A[0]) + glm::length(q.A[1]) + glm::length(q.A[2]), 1e-300), 3.0);
    bool solved = false;
    if (std::abs(det) > 1e-10 * scale)
    {
      const glm::dvec3 v = -(glm::inverse(q.A) * q.B);
      // Trust the optimum only near the edge (a far optimum of a nearly
      // flat region makes spikes).
      const double edgeLength = glm::length(this->P(b) - this->P(a));
      if (isFinite(v) && glm::length(v - best) <= 2.0 * edgeLength)
      {
        best = v;
        cost = q(v);
        solved = true;
      }
    }
    if (!solved)
    {
      for (const glm::dvec3& v : { this->P(a), this->P(b) })
      {
        const double c = q(v);
        if (c < cost)
        {
          cost = c;
          best = v;
        }
      }
    }
    const bool near = this->Near[ia] || this->Near[ib];
    double rank = cost;
    if (near)
    {
      rank = this->Parameters.NearFactor > 0.0 ? cost / this->Parameters.NearFactor
                                               : std::numeric_limits<double>::infinity();
    }
    this->Heap.push({ rank, cost, a, b, this->Stamp[ia], this->Stamp[ib], best });
  }

  std::vector<Id> neighbours(Id v) const
  {
    std::vector<Id> result;
    for (const Id f : this->FacesOf[static_cast<std::size_t>(v)])
    {
      if (!this->FaceAlive[static_cast<std::size_t>(f)])
      {
        continue;
      }
      for (const Id w : this->Faces[static_cast<std::size_t>(f)])
      {
        if (w != v)
        {
          result.push_back(w);
        }
      }
    }
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }

  bool canCollapse(Id a, Id b, const glm::dvec3& position) const
  {
    // Exactly two triangles on the edge, and the link condition.
    std::vector<Id> opposite;
    for (const Id f : this->FacesOf[static_cast<std::size_t>(a)])
    {
      if (!this->FaceAlive[static_cast<std::size_t>(f)])
      {
        continue;
      }
      const Triangle& t = this->Faces[static_cast<std::size_t>(f)];
      if (t[0] == b || t[1] == b || t[2] == b)
      {
        for (const Id w : t)
        {
          if (w != a && w != b)
          {
            opposite.push_back(w);
          }
        }
      }
    }
    if (opposite.size() != 2 || opposite[0] == opposite[1])
    {
      return false;
    }
    std::sort(opposite.begin(), opposite.end());
    const std::vector<Id> na = this->neighbours(a);
    const std::vector<Id> nb = this->neighbours(b);
    std::vector<Id> common;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    if (common != opposite)
    {
      return false;
    }
    // Link condition, edges: the opposite corners c, d must not make a
    // triangle with a and one with b (an edge of a tetrahedron: collapsing it
    // would fold two triangles onto each other).
    int ends = 0;
    for (const Id v : { a, b })
    {
      for (const Id f : this->FacesOf[static_cast<std::size_t>(v)])
      {
        const Triangle& t = this->Faces[static_cast<std::size_t>(f)];
        if (this->FaceAlive[static_cast<std::size_t>(f)] &&
          std::count(t.begin(), t.end(), opposite[0]) == 1 &&
          std::count(t.begin(), t.end(), opposite[1]) == 1)
        {
          ++ends;
          break;
        }
      }
    }
    if (ends == 2)
    {
      return false;
    }
    // No remaining triangle turns over or degenerates.
    for (const Id v : { a, b })
    {
      for (const Id f : this->FacesOf[static_cast<std::size_t>(v)])
      {
        if (!this->FaceAlive[static_cast<std::size_t>(f)])
        {
          continue;
        }
        const Triangle& t = this->Faces[static_cast<std::size_t>(f)];
        if ((t[0] == a || t[1] == a || t[2] == a) && (t[0] == b || t[1] == b || t[2] == b))
        {
          continue; // removed by the collapse
        }
        std::array<glm::dvec3, 3> before;
        std::array<glm::dvec3, 3> after;
        for (int k = 0; k < 3; ++k)
        {
          before[static_cast<std::size_t>(k)] = this->P(t[static_cast<std::size_t>(k)]);
          after[static_cast<std::size_t>(k)] =
            t[static_cast<std::size_t>(k)] == v ? position : before[static_cast<std::size_t>(k)];
        }
        const glm::dvec3 n0 = glm::cross(before[1] - before[0], before[2] - before[0]);
        const glm::dvec3 n1 = glm::cross(after[1] - after[0], after[2] - after[0]);
        const double l0 = glm::length(n0);
        const double l1 = glm::length(n1);
        if (!(l1 > 1e-12 * std::max(l0, 1e-300)) || glm::dot(n0, n1) <= 0.05 * l0 * l1)
        {
          return false;
        }
      }
    }
    return true;
  }

  // b goes into a, which moves to `position`.
  void collapse(Id a, Id b, const glm::dvec3& position)
  {
    const std::size_t ia = static_cast<std::size_t>(a);
    const std::size_t ib = static_cast<std::size_t>(b);
    for (const Id f : this->FacesOf[ib])
    {
      const std::size_t fi = static_cast<std::size_t>(f);
      if (!this->FaceAlive[fi])
      {
        continue;
      }
      Triangle& t = this->Faces[fi];
      if (t[0] == a || t[1] == a || t[2] == a)
      {
        this->FaceAlive[fi] = 0;
        --this->FaceCount;
        continue;
      }
      for (Id& w : t)
      {
        w = w == b ? a : w;
      }
      this->FacesOf[ia].push_back(f);
    }
    this->FacesOf[ib].clear();
    this->Alive[ib] = 0;
    this->Points[ia] = position;
    this->Quadrics[ia] += this->Quadrics[ib];
    this->Near[ia] = this->Near[ia] || this->Near[ib];
    ++this->Stamp[ia];
    // Drop dead faces from a's list, then re-rank a's edges.
    auto& list = this->FacesOf[ia];
    list.erase(std::remove_if(list.begin(), list.end(),
                 [this](Id f) { return !this->FaceAlive[static_cast<std::size_t>(f)]; }),
      list.end());
    for (const Id w : this->neighbours(a))
    {
      this->push(a, w);
    }
  }

  std::vector<glm::dvec3> Points;
  SimplificationParameters Parameters;
  std::vector<Triangle> Faces;
  std::vector<unsigned char> FaceAlive;
  std::size_t FaceCount = 0;
  std::vector<Quadric> Quadrics;
  std::vector<std::vector<Id>> FacesOf;
  std::vector<std::uint64_t> Stamp;
  std::vector<unsigned char> Alive;
  std::vector<unsigned char> Locked;
  std::vector<unsigned char> Near;
  std::vector<double> Error; // per point: the cost of the last collapse into it, else 0
  // IndependentRounds: the round that last touched each point (0: none yet),
  // and the candidates this round put off.
  std::vector<std::uint32_t> RoundOf;
  std::uint32_t Round = 1;
  std::vector<Candidate> Deferred;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> Heap;
};

} // namespace

SimplificationResult simplifyQuadric(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const SimplificationParameters& parameters)
{
  Simplifier simplifier(points, triangles, parameters);
  return simplifier.run();
}

} // namespace silsmooth
