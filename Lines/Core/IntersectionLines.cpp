#include "IntersectionLines.h"

#include "SurfaceWelding.h"
#include "TriangleGrid.h"
#include "TriangleIntersection.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>
#include <utility>

namespace silsmooth
{
namespace
{

/// A segment's end: side (Low, High) of one triangle (welded ids, Low <
/// High) crossing the interior of triangle Crossed.
struct CrossingName
{
  Id Low = 0;
  Id High = 0;
  Id Crossed = 0;
  bool operator<(const CrossingName& o) const
  {
    return std::tie(this->Low, this->High, this->Crossed) < std::tie(o.Low, o.High, o.Crossed);
  }
  bool operator==(const CrossingName& o) const
  {
    return this->Low == o.Low && this->High == o.High && this->Crossed == o.Crossed;
  }
};

struct Crossing
{
  CrossingName Name;
  glm::dvec3 Point{ 0.0 };
  Id OnTriangle = 0; // the triangle whose side it is
};

struct Segment
{
  Crossing End[2];
};

/// How far outside a triangle's sides (relative to its longest side) a
/// crossing still counts as in it: a point on a side, computed from another
/// triangle, lands on either side of it by a rounding error.
constexpr double SideTolerance = 1e-9;

/// Whether `at`, on t's plane, lies in t, its sides included (within
/// SideTolerance).
bool inTriangle(const glm::dvec3& at, const TriangleShape& t)
{
  for (int k = 0; k < 3; ++k)
  {
    const glm::dvec3& from = t.Corners.P[k];
    const glm::dvec3& to = t.Corners.P[(k + 1) % 3];
    // The distance from the side's line, times the side's length.
    const double inside = glm::dot(glm::cross(to - from, at - from), t.UnitNormal);
    if (inside < -SideTolerance * t.LongestSide * glm::length(to - from))
    {
      return false;
    }
  }
  return true;
}

/// Whether `t` has corners on both sides of the plane of `other`, each
/// farther from it than a rounding error.
bool straddles(const TriangleShape& t, const TriangleShape& other)
{
  const double near = 1e-12 * std::max(t.LongestSide, other.LongestSide);
  bool above = false;
  bool below = false;
  for (const glm::dvec3& p : t.Corners.P)
  {
    const double d = glm::dot(other.UnitNormal, p - other.Corners.P[0]);
    above = above || d > near;
    below = below || d < -near;
  }
  return above && below;
}

/// Where side (p, q) crosses triangle `t`: its ends on opposite sides of
/// t's plane and the crossing in t, its sides included (where a side of one
/// part crosses a side of the other, as on the plane of symmetry of two
/// parts, the pairs around the point find it). The same side and triangle
/// always give the same answer and point.
bool sideCrossing(const glm::dvec3& p, const glm::dvec3& q, const TriangleShape& t, glm::dvec3& at)
{
  const glm::dvec3& n = t.UnitNormal;
  const glm::dvec3& a = t.Corners.P[0];
  const double dp = glm::dot(n, p - a);
  const double dq = glm::dot(n, q - a);
  if (!((dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0)))
  {
    return false;
  }
  at = p + (dp / (dp - dq)) * (q - p);
  return inTriangle(at, t);
}

class IntersectionFinder
{
public:
  IntersectionFinder(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
    double weldTolerance)
    : Points(points)
    , Welded(weldCoincidentPoints(points, weldTolerance))
  {
    this->Corners.reserve(triangles.size());
    this->Shapes.reserve(triangles.size());
    for (const Triangle& raw : triangles)
    {
      Triangle corner;
      TriangleCorners at;
      for (int k = 0; k < 3; ++k)
      {
        corner[k] = this->Welded[static_cast<std::size_t>(raw[k])];
        at.P[k] = points[static_cast<std::size_t>(corner[k])];
      }
      this->Corners.push_back(corner);
      this->Shapes.push_back(shapeOf(at));
    }
  }

  std::vector<Segment> segments() const
  {
    std::vector<Segment> found;
    const TriangleGrid grid(this->Points, this->Corners);
    std::vector<Id> candidates;
    for (std::size_t t = 0; t < this->Corners.size(); ++t)
    {
      glm::dvec3 low, high;
      if (this->Shapes[t].NoInterior ||
        !TriangleGrid::boxOf(this->Points, this->Corners[t], low, high))
      {
        continue;
      }
      grid.query(low, high, candidates);
      for (const Id u : candidates)
      {
        Segment segment;
        if (static_cast<std::size_t>(u) <= t)
        {
          continue;
        }
        const Id a = static_cast<Id>(t);
        if (this->segmentOf(a, u, segment) || this->sideSegmentOf(a, u, segment) ||
          this->sideSegmentOf(u, a, segment))
        {
          found.push_back(segment);
        }
      }
    }
    return found;
  }

private:
  bool shareAVertex(const Triangle& a, const Triangle& b) const
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        if (a[i] == b[j])
        {
          return true;
        }
      }
    }
    return false;
  }

  // The crossings of triangle `from` through triangle `into`: its corners
  // that lie in `into` (within a rounding error of its plane), then its
  // sides. A corner is named by itself alone (Low == High): where the curve
  // passes through a corner, the two pairs on either side of it along the
  // curve both find it, so they chain by that name; its sides' crossings
  // there, within rounding of it, are the same point and are dropped.
  void crossingsOf(Id from, Id into, std::vector<Crossing>& out) const
  {
    const Triangle& corner = this->Corners[static_cast<std::size_t>(from)];
    const TriangleShape& target = this->Shapes[static_cast<std::size_t>(into)];
    const double near = 1e-12 *
      std::max(this->Shapes[static_cast<std::size_t>(from)].LongestSide, target.LongestSide);
    for (int k = 0; k < 3; ++k)
    {
      const glm::dvec3& p = this->Points[static_cast<std::size_t>(corner[k])];
      if (std::abs(glm::dot(target.UnitNormal, p - target.Corners.P[0])) <= near &&
        inTriangle(p, target))
      {
        Crossing crossing;
        crossing.Name.Low = corner[k];
        crossing.Name.High = corner[k];
        crossing.Name.Crossed = into;
        crossing.OnTriangle = from;
        crossing.Point = p;
        out.push_back(crossing);
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      Crossing crossing;
      crossing.Name.Low = std::min(corner[k], corner[(k + 1) % 3]);
      crossing.Name.High = std::max(corner[k], corner[(k + 1) % 3]);
      crossing.Name.Crossed = into;
      crossing.OnTriangle = from;
      if (sideCrossing(this->Points[static_cast<std::size_t>(crossing.Name.Low)],
            this->Points[static_cast<std::size_t>(crossing.Name.High)],
            this->Shapes[static_cast<std::size_t>(into)], crossing.Point))
      {
        out.push_back(crossing);
      }
    }
  }

  bool segmentOf(Id a, Id b, Segment& segment) const
  {
    const TriangleShape& sa = this->Shapes[static_cast<std::size_t>(a)];
    const TriangleShape& sb = this->Shapes[static_cast<std::size_t>(b)];
    // Not trianglesIntersect's test, which wants a side through the other's
    // interior: where parts are laid out alike (two copies of a UV sphere
    // side by side, boxes whose faces line up) the curve runs from side to
    // side, crossing sides only. The surfaces cross where each triangle has
    // corners on both sides of the other's plane; a triangle that touches the
    // other along its side, or lies in its plane, does not cross it.
    if (sb.NoInterior || !straddles(sa, sb) || !straddles(sb, sa) ||
      this->neighboursOnOneSheet(a, b))
    {
      return false;
    }
    std::vector<Crossing> crossings;
    this->crossingsOf(a, b, crossings);
    this->crossingsOf(b, a, crossings);
    // A crossing on a side of the other triangle is found from both: one
    // point, up to rounding.
    const double close = 1e-9 * std::max(sa.LongestSide, sb.LongestSide);
    for (std::size_t i = 0; i < crossings.size(); ++i)
    {
      for (std::size_t j = crossings.size(); j-- > i + 1;)
      {
        if (glm::length(crossings[j].Point - crossings[i].Point) <= close)
        {
          crossings.erase(crossings.begin() + static_cast<std::ptrdiff_t>(j));
        }
      }
    }
    if (crossings.size() != 2)
    {
      return false;
    }
    segment.End[0] = crossings[0];
    segment.End[1] = crossings[1];
    return true;
  }

  // Where a side of triangle `a` lies in the plane of triangle `b` (both
  // ends within a rounding error of it) and the surface crosses `b` there:
  // `a`'s third corner is on b's front and the third corner of the other
  // triangle at that side is on its back (both clearly; on one side, the
  // surface only touches b). The curve is then the part of that side in `b`
  // (a sphere centred on a box's face, its equator's ring in the face). Only
  // the triangle in front gives it, so it is found once. Its ends: a corner
  // of the side in `b`, named by the corner as in crossingsOf (the next side
  // along the curve ends there too); or where a side of `b` crosses it,
  // named by that side of `b` and by `a` (the pair of `a` with b's
  // neighbour across that side finds the same point under the same name).
  bool sideSegmentOf(Id a, Id b, Segment& segment) const
  {
    const TriangleShape& sa = this->Shapes[static_cast<std::size_t>(a)];
    const TriangleShape& sb = this->Shapes[static_cast<std::size_t>(b)];
    const Triangle& ca = this->Corners[static_cast<std::size_t>(a)];
    if (sa.NoInterior || sb.NoInterior)
    {
      return false;
    }
    const double near = 1e-12 * std::max(sa.LongestSide, sb.LongestSide);
    const auto height = [&](Id point) {
      return glm::dot(
        sb.UnitNormal, this->Points[static_cast<std::size_t>(point)] - sb.Corners.P[0]);
    };
    int third = -1;
    for (int k = 0; k < 3; ++k)
    {
      if (std::abs(height(ca[k])) > near)
      {
        if (third >= 0)
        {
          return false; // two corners off the plane: no side in it
        }
        third = k;
      }
    }
    if (third < 0 || height(ca[third]) <= near)
    {
      return false; // a lies in b's plane, or behind it (its neighbour gives the curve)
    }
    const Id p = ca[(third + 1) % 3];
    const Id q = ca[(third + 2) % 3];
    const Id across = this->otherTriangleAt(a, (third + 1) % 3); // side (p, q)
    if (across < 0 || this->neighboursOnOneSheet(a, b) || this->neighboursOnOneSheet(across, b))
    {
      return false;
    }
    const Triangle& cx = this->Corners[static_cast<std::size_t>(across)];
    const Id opposite =
      cx[0] != p && cx[0] != q ? cx[0] : (cx[1] != p && cx[1] != q ? cx[1] : cx[2]);
    if (height(opposite) >= -near)
    {
      return false;
    }
    return this->sidePartIn(a, std::min(p, q), std::max(p, q), b, segment);
  }

  // The part of side (low, high) of `a`, lying in b's plane, that lies in
  // `b` (its sides included, as inTriangle): false when that part is a
  // point or nothing.
  bool sidePartIn(Id a, Id low, Id high, Id b, Segment& segment) const
  {
    const TriangleShape& sb = this->Shapes[static_cast<std::size_t>(b)];
    const Triangle& cb = this->Corners[static_cast<std::size_t>(b)];
    const glm::dvec3& from = this->Points[static_cast<std::size_t>(low)];
    const glm::dvec3& to = this->Points[static_cast<std::size_t>(high)];
    // The side from `from` (0) to `to` (1), clipped by b's sides exactly;
    // an end clipped off by less than inTriangle's tolerance is the corner
    // itself (so the part of a neighbouring side in a neighbouring triangle
    // meets it at that point, not a rounding error beyond it).
    double enter = 0.0;
    double leave = 1.0;
    int enterSide = -1;
    int leaveSide = -1;
    for (int k = 0; k < 3; ++k)
    {
      const glm::dvec3& s0 = sb.Corners.P[k];
      const glm::dvec3& s1 = sb.Corners.P[(k + 1) % 3];
      const double f = glm::dot(glm::cross(s1 - s0, from - s0), sb.UnitNormal);
      const double g = glm::dot(glm::cross(s1 - s0, to - s0), sb.UnitNormal);
      if (f < 0.0 && g < 0.0)
      {
        return false;
      }
      if (f < 0.0)
      {
        const double at = f / (f - g);
        if (at > enter)
        {
          enter = at;
          enterSide = k;
        }
      }
      else if (g < 0.0)
      {
        const double at = f / (f - g);
        if (at < leave)
        {
          leave = at;
          leaveSide = k;
        }
      }
    }
    if (enterSide >= 0 && inTriangle(from, sb))
    {
      enter = 0.0;
      enterSide = -1;
    }
    if (leaveSide >= 0 && inTriangle(to, sb))
    {
      leave = 1.0;
      leaveSide = -1;
    }
    const double close = 1e-9;
    if (leave - enter <= close)
    {
      return false;
    }
    const auto end = [&](double at, int side, Id corner, Crossing& c) {
      c.OnTriangle = a;
      if (side < 0)
      {
        c.Name = { corner, corner, b };
        c.Point = this->Points[static_cast<std::size_t>(corner)];
        return;
      }
      c.Name.Low = std::min(cb[side], cb[(side + 1) % 3]);
      c.Name.High = std::max(cb[side], cb[(side + 1) % 3]);
      c.Name.Crossed = a;
      c.Point = from + at * (to - from);
    };
    end(enter, enterSide, low, segment.End[0]);
    end(leave, leaveSide, high, segment.End[1]);
    return true;
  }

  // The triangle other than `a` at its side k, when exactly two share it;
  // -1 otherwise.
  Id otherTriangleAt(Id a, int k) const
  {
    const Topology& topology = this->topology();
    const auto e = static_cast<std::size_t>(topology.Table.sideEdge(a, k));
    if (topology.Sides.Count[e] != 2)
    {
      return -1;
    }
    const Id first = topology.Sides.First[e][0] / 3;
    const Id second = topology.Sides.First[e][1] / 3;
    const Id other = first == a ? second : first;
    return other == a ? -1 : other;
  }

  // Whether a and b share a vertex and lie on one sheet (sheetsOf). Such
  // neighbours are not tested (a surface that folds onto its neighbour has
  // no curve to draw there); parts that only touch at a point (two solids
  // with a corner in common, which welding makes one vertex) are sheets of
  // their own, and where they cross there the curve is drawn.
  bool neighboursOnOneSheet(Id a, Id b) const
  {
    if (!this->shareAVertex(
          this->Corners[static_cast<std::size_t>(a)], this->Corners[static_cast<std::size_t>(b)]))
    {
      return false;
    }
    const std::vector<std::size_t>& sheet = this->topology().Sheet;
    return sheet[static_cast<std::size_t>(a)] == sheet[static_cast<std::size_t>(b)];
  }

  // The welded triangles' edges, their sides and sheets: made when first
  // asked (by a pair that passed the geometric tests), which most pairs of
  // most surfaces never are.
  struct Topology
  {
    EdgeTable Table;
    EdgeSides Sides;
    std::vector<std::size_t> Sheet;
  };
  const Topology& topology() const
  {
    if (!this->Built)
    {
      this->Built = std::make_unique<Topology>();
      this->Built->Table = EdgeTable(this->Corners);
      this->Built->Sides = edgeSidesOf(this->Corners, this->Built->Table);
      this->Built->Sheet = sheetsOf(this->Corners, this->Built->Table);
    }
    return *this->Built;
  }

  const std::vector<glm::dvec3>& Points;
  std::vector<Id> Welded;
  std::vector<Triangle> Corners;
  std::vector<TriangleShape> Shapes;
  mutable std::unique_ptr<Topology> Built; ///< topology(), when asked
};

/// Chains segments whose ends share a name: through names that two ends
/// have; polylines stop at the others.
class SegmentChainer
{
public:
  explicit SegmentChainer(const std::vector<Segment>& segments)
    : Segments(segments)
    , Used(segments.size(), false)
  {
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      for (int e = 0; e < 2; ++e)
      {
        this->Ends.push_back({ segments[s].End[e].Name, s, e });
      }
    }
    std::sort(this->Ends.begin(), this->Ends.end(),
      [](const EndRef& x, const EndRef& y) { return x.Name < y.Name; });
    this->Partner.assign(2 * segments.size(), NoPartner);
    for (std::size_t i = 0; i < this->Ends.size();)
    {
      std::size_t j = i;
      while (j < this->Ends.size() && this->Ends[j].Name == this->Ends[i].Name)
      {
        ++j;
      }
      if (j - i == 2)
      {
        const std::size_t x = 2 * this->Ends[i].Segment + this->Ends[i].End;
        const std::size_t y = 2 * this->Ends[i + 1].Segment + this->Ends[i + 1].End;
        this->Partner[x] = y;
        this->Partner[y] = x;
      }
      i = j;
    }
  }

  std::vector<IntersectionLine> polylines()
  {
    std::vector<IntersectionLine> lines;
    // Open polylines from their free ends, then the loops.
    for (std::size_t s = 0; s < this->Segments.size(); ++s)
    {
      for (int e = 0; e < 2 && !this->Used[s]; ++e)
      {
        if (this->Partner[2 * s + e] == NoPartner)
        {
          lines.push_back(this->walk(s, e));
        }
      }
    }
    for (std::size_t s = 0; s < this->Segments.size(); ++s)
    {
      if (!this->Used[s])
      {
        lines.push_back(this->walk(s, 0));
      }
    }
    return lines;
  }

private:
  static constexpr std::size_t NoPartner = static_cast<std::size_t>(-1);

  struct EndRef
  {
    CrossingName Name;
    std::size_t Segment;
    int End;
  };

  // From end `e` of segment `s` through the segments chained to it.
  IntersectionLine walk(std::size_t s, int e)
  {
    IntersectionLine line;
    const auto add = [&line](const Crossing& c) {
      line.Points.push_back(c.Point);
      line.Triangles.push_back(c.OnTriangle);
    };
    add(this->Segments[s].End[e]);
    while (true)
    {
      // A loop ends where it began: its last point is its first, to the bit.
      this->Used[s] = true;
      const int other = 1 - e;
      add(this->Segments[s].End[other]);
      const std::size_t next = this->Partner[2 * s + static_cast<std::size_t>(other)];
      if (next == NoPartner || this->Used[next / 2])
      {
        return line;
      }
      s = next / 2;
      e = static_cast<int>(next % 2);
    }
  }

  const std::vector<Segment>& Segments;
  std::vector<bool> Used;
  std::vector<EndRef> Ends;
  std::vector<std::size_t> Partner;
};

/// An end of an open polyline.
struct LineEnd
{
  std::size_t Line;
  bool Front;
  glm::dvec3 Point;
};

/// Joins open polylines whose ends meet within `close` where exactly two
/// ends meet (where a side of one part crosses a side of the other the point
/// is found under two names), then closes those whose own ends meet. Ends
/// are matched after sorting them along x.
void joinTouchingEnds(std::vector<IntersectionLine>& lines, double close)
{
  constexpr std::size_t None = static_cast<std::size_t>(-1);
  std::vector<LineEnd> ends;
  std::vector<std::size_t> frontEnd(lines.size(), None);
  std::vector<std::size_t> backEnd(lines.size(), None);
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    const IntersectionLine& l = lines[i];
    if (l.Points.size() > 1 && !(l.Points.front() == l.Points.back()))
    {
      ends.push_back({ i, true, l.Points.front() });
      ends.push_back({ i, false, l.Points.back() });
    }
  }
  std::sort(ends.begin(), ends.end(),
    [](const LineEnd& x, const LineEnd& y) { return x.Point.x < y.Point.x; });
  // Each end's partner: the other end within `close`, when it is the only one
  // either way.
  std::vector<std::size_t> partner(ends.size(), None);
  std::vector<int> meeting(ends.size(), 0);
  for (std::size_t i = 0; i < ends.size(); ++i)
  {
    (ends[i].Front ? frontEnd : backEnd)[ends[i].Line] = i;
    for (std::size_t j = i + 1; j < ends.size() && ends[j].Point.x - ends[i].Point.x <= close; ++j)
    {
      if (glm::length(ends[j].Point - ends[i].Point) <= close)
      {
        ++meeting[i];
        ++meeting[j];
        partner[i] = j;
        partner[j] = i;
      }
    }
  }
  const auto linked = [&](std::size_t e) {
    return e != None && meeting[e] == 1 && meeting[partner[e]] == 1 ? partner[e] : None;
  };
  std::vector<bool> used(lines.size(), false);
  // From one end of `line` through the linked ends, each line once.
  const auto follow = [&](std::size_t line, bool forward) {
    IntersectionLine out;
    std::size_t at = line;
    while (true)
    {
      used[at] = true;
      IntersectionLine& l = lines[at];
      if (!forward)
      {
        std::reverse(l.Points.begin(), l.Points.end());
        std::reverse(l.Triangles.begin(), l.Triangles.end());
      }
      const std::ptrdiff_t skip = out.Points.empty() ? 0 : 1;
      out.Points.insert(out.Points.end(), l.Points.begin() + skip, l.Points.end());
      out.Triangles.insert(out.Triangles.end(), l.Triangles.begin() + skip, l.Triangles.end());
      const std::size_t next = linked(forward ? backEnd[at] : frontEnd[at]);
      if (next == None || used[ends[next].Line])
      {
        return out;
      }
      at = ends[next].Line;
      forward = ends[next].Front;
    }
  };
  std::vector<IntersectionLine> joined;
  // Chains from an end linked to nothing first, then the rings left.
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    if (!used[i] && frontEnd[i] != None && linked(frontEnd[i]) == None)
    {
      joined.push_back(follow(i, true));
    }
    else if (!used[i] && frontEnd[i] != None && linked(backEnd[i]) == None)
    {
      joined.push_back(follow(i, false));
    }
  }
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    if (!used[i])
    {
      used[i] = true;
      joined.push_back(frontEnd[i] == None ? std::move(lines[i]) : follow(i, true));
    }
  }
  for (IntersectionLine& line : joined)
  {
    if (line.Points.size() > 2 && !(line.Points.front() == line.Points.back()) &&
      glm::length(line.Points.front() - line.Points.back()) <= close)
    {
      line.Points.back() = line.Points.front();
      line.Triangles.back() = line.Triangles.front();
    }
  }
  lines = std::move(joined);
}
} // namespace

std::vector<IntersectionLine> intersectionLines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, double weldTolerance)
{
  const std::vector<Segment> segments =
    IntersectionFinder(points, triangles, weldTolerance).segments();
  std::vector<IntersectionLine> lines = SegmentChainer(segments).polylines();
  glm::dvec3 low(HUGE_VAL), high(-HUGE_VAL);
  for (const IntersectionLine& line : lines)
  {
    for (const glm::dvec3& p : line.Points)
    {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  if (!lines.empty())
  {
    joinTouchingEnds(lines, 1e-9 * glm::length(high - low));
  }
  return lines;
}

} // namespace silsmooth
