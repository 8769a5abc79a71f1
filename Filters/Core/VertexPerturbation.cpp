#include "VertexPerturbation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

namespace silsmooth
{

bool isConcaveSegment(
  const glm::dvec3& s1, const glm::dvec3& n1, const glm::dvec3& s2, const glm::dvec3& n2)
{
  const glm::dvec3 f = s2 - s1;
  return glm::dot(n1, f) > 0.0 && glm::dot(n2, f) < 0.0;
}

namespace
{

// Whether `point` lies alongside the segment (its position along the chord
// within the chord's extent, widened by half a chord at each end) and in
// front of it, where it could hide it from the eye. "In front" allows a
// quarter chord behind the midpoint, because the vertices of a rim sit at
// about the midpoint's depth. Measured when this rule chose every
// neighbouring vertex (deviation ratios of the evaluation):
// strictly in front, torus 0.34 and knot 0.57; a quarter chord, 0.29 and 0.67;
// half a chord, 0.28 and 0.73; no depth test, 0.28 and 0.75.
bool isAlongside(const glm::dvec3& point, const ConcaveSegment& segment)
{
  const glm::dvec3 chord = segment.End - segment.Start;
  const double length2 = glm::dot(chord, chord);
  if (!(length2 > 0.0))
  {
    return false;
  }
  const double t = glm::dot(point - segment.Start, chord) / length2;
  return t >= -0.5 && t <= 1.5 &&
    glm::dot(point - segment.Midpoint, segment.TowardViewer) > -0.25 * std::sqrt(length2);
}

using Move = std::pair<Id, glm::dvec3>;

std::ptrdiff_t IndexOf(const std::vector<Move>& moved, Id v)
{
  const auto it = std::lower_bound(
    moved.begin(), moved.end(), v, [](const Move& m, Id id) { return m.first < id; });
  return it != moved.end() && it->first == v ? it - moved.begin() : -1;
}

// Distance along the unit `direction` from `origin` to the triangle (a, b,
// c) (Moller and Trumbore), or -1 when the ray misses it.
double RayToTriangle(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 e1 = b - a;
  const glm::dvec3 e2 = c - a;
  const glm::dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (!(std::abs(det) > std::numeric_limits<double>::min()))
  {
    return -1.0;
  }
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  if (!(u >= 0.0 && u <= 1.0))
  {
    return -1.0;
  }
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (!(v >= 0.0 && u + v <= 1.0))
  {
    return -1.0;
  }
  return glm::dot(e2, q) / det;
}

// A few points of a concave segment and their lines of sight, to find the
// triangles that hide it. The quadratic through S(0), S(1/2) and S(1) stands
// in for the curve, and the lines of sight run along the midpoint's direction
// to the viewer (the segment is small beside its distance to the eye).
// Triangles whose projection along that direction misses the points' bounding
// box, or that lie wholly behind the points, are rejected before any ray test.
class SegmentProbes
{
public:
  explicit SegmentProbes(const ConcaveSegment& segment)
    : Direction(segment.TowardViewer)
    , Margin(1e-6 * glm::distance(segment.Start, segment.End))
  {
    // A frame across the lines of sight.
    const glm::dvec3 helper =
      std::abs(this->Direction.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    this->Across1 = glm::normalize(glm::cross(this->Direction, helper));
    this->Across2 = glm::cross(this->Direction, this->Across1);
    const glm::dvec3 control = 2.0 * segment.Midpoint - 0.5 * (segment.Start + segment.End);
    for (int k = 0; k < OcclusionProbes; ++k)
    {
      const double s = static_cast<double>(k + 1) / (OcclusionProbes + 1);
      this->Points[k] =
        (1.0 - s) * (1.0 - s) * segment.Start + 2.0 * s * (1.0 - s) * control + s * s * segment.End;
      this->include(this->Points[k], this->Low, this->High);
      this->NearestDepth = std::min(this->NearestDepth, glm::dot(this->Points[k], this->Direction));
    }
  }

  bool hiddenBy(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) const
  {
    if (!(glm::dot(this->Direction, this->Direction) > 0.5))
    {
      return false; // no direction to the viewer (the eye on the segment)
    }
    glm::dvec3 low(std::numeric_limits<double>::infinity());
    glm::dvec3 high(-std::numeric_limits<double>::infinity());
    this->include(a, low, high);
    this->include(b, low, high);
    this->include(c, low, high);
    if (high.x < this->Low.x || low.x > this->High.x || high.y < this->Low.y ||
      low.y > this->High.y || high.z <= this->NearestDepth)
    {
      return false;
    }
    for (const glm::dvec3& x : this->Points)
    {
      if (RayToTriangle(x, this->Direction, a, b, c) > this->Margin)
      {
        return true;
      }
    }
    return false;
  }

private:
  // Grows the box (across, across, depth) by a point.
  void include(const glm::dvec3& x, glm::dvec3& low, glm::dvec3& high) const
  {
    const glm::dvec3 q(
      glm::dot(x, this->Across1), glm::dot(x, this->Across2), glm::dot(x, this->Direction));
    low = glm::min(low, q);
    high = glm::max(high, q);
  }

  glm::dvec3 Direction;
  glm::dvec3 Across1;
  glm::dvec3 Across2;
  double Margin;
  glm::dvec3 Points[OcclusionProbes];
  glm::dvec3 Low{ std::numeric_limits<double>::infinity() };
  glm::dvec3 High{ -std::numeric_limits<double>::infinity() };
  double NearestDepth = std::numeric_limits<double>::infinity();
};

// Whether v and w are joined by an edge.
bool AreNeighbours(
  Id v, Id w, const std::vector<Id>& neighbourOffsets, const std::vector<Id>& neighbours)
{
  const auto begin = neighbours.begin() + neighbourOffsets[static_cast<std::size_t>(v)];
  const auto end = neighbours.begin() + neighbourOffsets[static_cast<std::size_t>(v) + 1];
  return std::find(begin, end, w) != end;
}

} // namespace

std::vector<Move> perturbVerticesBelowConcaveSegments(const std::vector<ConcaveSegment>& segments,
  const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals,
  const std::vector<Triangle>& triangles, const std::vector<Id>& neighbourOffsets,
  const std::vector<Id>& neighbours)
{
  // (vertex, segment) pairs: the vertices that must clear the segment's
  // plane. The corners of the segment's own triangle that lie alongside it
  // (its re-meshed fans reach the curve from them), and every corner of a
  // triangle near the segment that actually hides part of it from the eye.
  // Near: a corner in the segment triangle's corners or their edge
  // neighbours (the paper's neighbouring vertices). The triangles around a
  // vertex are found as pairs of its neighbours that are neighbours of each
  // other (a 3-cycle that is not a face can only add a test).
  std::vector<std::pair<Id, std::size_t>> constraints;
  std::vector<Id> nearby;
  // The triangles around a vertex, found once per call (neighbouring
  // segments share most of their nearby vertices).
  std::unordered_map<Id, std::pair<std::size_t, std::size_t>> around;
  std::vector<Triangle> aroundTriangles;
  auto trianglesAround = [&](Id v) {
    const auto found = around.find(v);
    if (found != around.end())
    {
      return found->second;
    }
    const std::size_t first = aroundTriangles.size();
    const Id begin = neighbourOffsets[static_cast<std::size_t>(v)];
    const Id end = neighbourOffsets[static_cast<std::size_t>(v) + 1];
    for (Id i = begin; i < end; ++i)
    {
      for (Id j = i + 1; j < end; ++j)
      {
        const Id a = neighbours[static_cast<std::size_t>(i)];
        const Id b = neighbours[static_cast<std::size_t>(j)];
        if (AreNeighbours(a, b, neighbourOffsets, neighbours))
        {
          aroundTriangles.push_back({ v, a, b });
        }
      }
    }
    const auto range = std::make_pair(first, aroundTriangles.size());
    around.emplace(v, range);
    return range;
  };
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    const ConcaveSegment& segment = segments[s];
    const Triangle& own = triangles[static_cast<std::size_t>(segment.Triangle)];
    nearby.clear();
    for (const Id corner : own)
    {
      if (isAlongside(points[static_cast<std::size_t>(corner)], segment))
      {
        constraints.emplace_back(corner, s);
      }
      nearby.push_back(corner);
      for (Id k = neighbourOffsets[static_cast<std::size_t>(corner)];
           k < neighbourOffsets[static_cast<std::size_t>(corner) + 1]; ++k)
      {
        nearby.push_back(neighbours[static_cast<std::size_t>(k)]);
      }
    }
    std::sort(nearby.begin(), nearby.end());
    nearby.erase(std::unique(nearby.begin(), nearby.end()), nearby.end());
    // A triangle with every corner below the segment's plane cannot hide it
    // (the eye is on the plane, the segment above it): only the triangles
    // around the nearby vertices above the plane are tested (a triangle
    // around two of them is tested twice; the constraints are made unique
    // below).
    const SegmentProbes probes(segment);
    auto isOwn = [&own](const Triangle& t) {
      return std::find(own.begin(), own.end(), t[0]) != own.end() &&
        std::find(own.begin(), own.end(), t[1]) != own.end() &&
        std::find(own.begin(), own.end(), t[2]) != own.end();
    };
    for (const Id v : nearby)
    {
      if (!(glm::dot(segment.Normal, points[static_cast<std::size_t>(v)] - segment.Midpoint) > 0.0))
      {
        continue;
      }
      const auto range = trianglesAround(v);
      for (std::size_t k = range.first; k < range.second; ++k)
      {
        const Triangle t = aroundTriangles[k];
        if (!isOwn(t) &&
          probes.hiddenBy(points[static_cast<std::size_t>(t[0])],
            points[static_cast<std::size_t>(t[1])], points[static_cast<std::size_t>(t[2])]))
        {
          for (const Id corner : t)
          {
            constraints.emplace_back(corner, s);
          }
        }
      }
    }
  }
  std::sort(constraints.begin(), constraints.end());
  constraints.erase(std::unique(constraints.begin(), constraints.end()), constraints.end());

  std::vector<Move> moved;
  for (std::size_t first = 0; first < constraints.size();)
  {
    const Id v = constraints[first].first;
    std::size_t last = first;
    glm::dvec3 sum(0.0);
    while (last < constraints.size() && constraints[last].first == v)
    {
      sum += segments[constraints[last].second].Normal;
      ++last;
    }
    const double length = glm::length(sum);
    const glm::dvec3& position = points[static_cast<std::size_t>(v)];
    if (length > 1e-12 &&
      glm::dot(normals[static_cast<std::size_t>(v)], sum / length) >= MinimumNormalAlignment)
    {
      const glm::dvec3 r = sum / length;
      // The step along r that puts v on or below every plane it must clear:
      // N . (v + step r - M) <= 0, so step <= -N . (v - M) / (N . r).
      double step = 0.0;
      double largestBulge = 0.0;
      for (std::size_t c = first; c < last; ++c)
      {
        const ConcaveSegment& segment = segments[constraints[c].second];
        largestBulge = std::max(
          largestBulge, glm::distance(segment.Midpoint, 0.5 * (segment.Start + segment.End)));
        const double alignment = glm::dot(segment.Normal, r);
        if (alignment < MinimumPlaneAlignment)
        {
          continue;
        }
        step = std::min(step, -glm::dot(segment.Normal, position - segment.Midpoint) / alignment);
      }
      // A vertex that blocks a segment only needs to clear its bulge; one
      // that needs more is not in front of it (e.g. across a thin tube).
      step = std::max(step, -MaximumStepInBulges * largestBulge);
      if (step < 0.0)
      {
        moved.emplace_back(v, position + step * r);
      }
    }
    first = last;
  }
  return moved;
}

void keepTrianglesFacingOut(std::vector<Move>& moved, const std::vector<Triangle>& triangles,
  const std::function<glm::dvec3(Id)>& position, const std::function<glm::dvec3(Id)>& normal)
{
  auto facesOut = [&](const Triangle& t, bool afterMove) {
    glm::dvec3 p[3];
    glm::dvec3 normalSum(0.0);
    for (int k = 0; k < 3; ++k)
    {
      const std::ptrdiff_t m = afterMove ? IndexOf(moved, t[k]) : -1;
      p[k] = m >= 0 ? moved[static_cast<std::size_t>(m)].second : position(t[k]);
      normalSum += normal(t[k]);
    }
    return glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), normalSum) >= 0.0;
  };
  // Only triangles that faced out before the moves are held to it.
  std::vector<Triangle> watched;
  for (const Triangle& t : triangles)
  {
    if (!hasRepeatedCorner(t) && facesOut(t, false))
    {
      watched.push_back(t);
    }
  }
  constexpr int halvings = 8;
  for (int round = 0; round <= halvings; ++round)
  {
    std::vector<Id> offenders;
    for (const Triangle& t : watched)
    {
      if (!facesOut(t, true))
      {
        for (const Id v : t)
        {
          if (IndexOf(moved, v) >= 0)
          {
            offenders.push_back(v);
          }
        }
      }
    }
    if (offenders.empty())
    {
      break;
    }
    std::sort(offenders.begin(), offenders.end());
    offenders.erase(std::unique(offenders.begin(), offenders.end()), offenders.end());
    for (const Id v : offenders)
    {
      Move& m = moved[static_cast<std::size_t>(IndexOf(moved, v))];
      const glm::dvec3 from = position(v);
      m.second = round < halvings ? from + 0.5 * (m.second - from) : from;
    }
  }
  // Cancelled moves are no moves.
  moved.erase(std::remove_if(moved.begin(), moved.end(),
                [&](const Move& m) { return m.second == position(m.first); }),
    moved.end());
}

} // namespace silsmooth
