#include "TriangleIntersection.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{
namespace
{

// Relative tolerances: of the plane distance to the triangles' size, and of
// the barycentric coordinates of a crossing. Negative ones make the lenient
// test of trianglesTouch.
struct Tolerances
{
  double Plane;
  double Interior;
};
constexpr Tolerances Strict{ 1e-9, 1e-7 };
constexpr Tolerances Lenient{ -TouchTolerance, -TouchTolerance };

double longestSide(const TriangleCorners& t)
{
  return std::max(
    { glm::length(t.P[1] - t.P[0]), glm::length(t.P[2] - t.P[1]), glm::length(t.P[0] - t.P[2]) });
}

// The largest coordinate difference along any side: at most longestSide.
double longestAxisSpan(const TriangleCorners& t)
{
  const glm::dvec3 d0 = glm::abs(t.P[1] - t.P[0]);
  const glm::dvec3 d1 = glm::abs(t.P[2] - t.P[1]);
  const glm::dvec3 d2 = glm::abs(t.P[0] - t.P[2]);
  const glm::dvec3 m = glm::max(d0, glm::max(d1, d2));
  return std::max({ m.x, m.y, m.z });
}

// A triangle's plane: unit normal and twice its area (0: degenerate).
struct Plane
{
  glm::dvec3 Unit{ 0.0 };
  double Area2 = 0.0;
};

Plane planeOf(const TriangleCorners& t)
{
  const glm::dvec3 normal = glm::cross(t.P[1] - t.P[0], t.P[2] - t.P[0]);
  Plane plane;
  plane.Area2 = glm::length(normal);
  if (plane.Area2 > 0.0)
  {
    plane.Unit = normal / plane.Area2;
  }
  return plane;
}

// Whether the segment (u, v), whose ends are du and dv from t's plane,
// crosses t's interior.
bool crossesAt(const glm::dvec3& u, const glm::dvec3& v, double du, double dv,
  const TriangleCorners& t, const Plane& plane, double scale, const Tolerances& tolerances)
{
  if (!(plane.Area2 > 0.0) || !(scale > 0.0))
  {
    return false;
  }
  const double tolerance = tolerances.Plane * scale;
  if (!((du > tolerance && dv < -tolerance) || (du < -tolerance && dv > tolerance)))
  {
    return false;
  }
  // Lenient: an end within the tolerance of the plane counts as on it.
  const double along = du == dv ? 0.0 : std::clamp(du / (du - dv), 0.0, 1.0);
  const glm::dvec3 x = u + along * (v - u);
  // Barycentric coordinates of x from the sub-triangle areas, signed along
  // the normal.
  const double b0 = glm::dot(plane.Unit, glm::cross(t.P[1] - x, t.P[2] - x)) / plane.Area2;
  const double b1 = glm::dot(plane.Unit, glm::cross(t.P[2] - x, t.P[0] - x)) / plane.Area2;
  const double b2 = 1.0 - b0 - b1;
  return b0 > tolerances.Interior && b1 > tolerances.Interior && b2 > tolerances.Interior;
}

bool crosses(const glm::dvec3& u, const glm::dvec3& v, const TriangleCorners& t, double scale,
  const Tolerances& tolerances = Strict)
{
  const Plane plane = planeOf(t);
  return crossesAt(u, v, glm::dot(plane.Unit, u - t.P[0]), glm::dot(plane.Unit, v - t.P[0]), t,
    plane, scale, tolerances);
}

struct SharedCorners
{
  int Count = 0;
  int A = -1; // a corner of a that b has too
  int B = -1;
};

SharedCorners sharedCorners(const TriangleCorners& a, const TriangleCorners& b)
{
  SharedCorners shared;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (a.P[i] == b.P[j])
      {
        ++shared.Count;
        shared.A = i;
        shared.B = j;
      }
    }
  }
  return shared;
}

// No interior: two corners at one position (a needle, as asset files hold),
// or all three on a line up to rounding (twice the area at most 1e-12 of
// the longest side squared; a re-meshed piece of a needle is such a line).
bool hasNoInterior(const TriangleCorners& t)
{
  if (t.P[0] == t.P[1] || t.P[1] == t.P[2] || t.P[2] == t.P[0])
  {
    return true;
  }
  const double side = longestSide(t);
  return !(glm::length(glm::cross(t.P[1] - t.P[0], t.P[2] - t.P[0])) > 1e-12 * side * side);
}

bool meet(const TriangleShape& shapeA, const TriangleShape& shapeB, const Tolerances& tolerances)
{
  const TriangleCorners& a = shapeA.Corners;
  const TriangleCorners& b = shapeB.Corners;
  const Plane planeA{ shapeA.UnitNormal, shapeA.Area2 };
  const Plane planeB{ shapeB.UnitNormal, shapeB.Area2 };
  // Each corner's distance to the other's plane, once; a triangle whose
  // corners all lie on one side of the other's plane (beyond the tolerance)
  // has no side that crosses the other.
  double toA[3];
  double toB[3];
  for (int k = 0; k < 3; ++k)
  {
    toA[k] = glm::dot(planeA.Unit, b.P[k] - a.P[0]);
    toB[k] = glm::dot(planeB.Unit, a.P[k] - b.P[0]);
  }
  auto straddles = [](const double d[3], double tolerance) {
    const bool below = d[0] < -tolerance || d[1] < -tolerance || d[2] < -tolerance;
    const bool above = d[0] > tolerance || d[1] > tolerance || d[2] > tolerance;
    return below && above;
  };
  // Most pairs a fold check meets lie side by side. With a tolerance of at
  // least zero, a smaller one that needs no square root (the largest
  // coordinate difference along a side is at most the side's length) decides
  // "no" for them before the tests below, which would find the same.
  if (tolerances.Plane >= 0.0)
  {
    const double below =
      tolerances.Plane * (1.0 - 1e-12) * std::max(shapeA.AxisSpan, shapeB.AxisSpan);
    if (!straddles(toA, below) && !straddles(toB, below))
    {
      return false;
    }
  }
  if (shapeA.NoInterior || shapeB.NoInterior)
  {
    return false; // a needle, a line or a point: no interior to cut or be cut
  }
  const SharedCorners shared = sharedCorners(a, b);
  if (shared.Count >= 2)
  {
    return false;
  }
  const double scale = std::max(shapeA.LongestSide, shapeB.LongestSide);
  const double tolerance = tolerances.Plane * scale;
  const bool aSides = straddles(toB, tolerance); // a's sides may cross b
  const bool bSides = straddles(toA, tolerance);
  if (!aSides && !bSides)
  {
    return false;
  }
  auto sideOfACrossesB = [&](int k) {
    const int l = (k + 1) % 3;
    return crossesAt(a.P[k], a.P[l], toB[k], toB[l], b, planeB, scale, tolerances);
  };
  auto sideOfBCrossesA = [&](int k) {
    const int l = (k + 1) % 3;
    return crossesAt(b.P[k], b.P[l], toA[k], toA[l], a, planeA, scale, tolerances);
  };
  if (shared.Count == 1)
  {
    // The sides opposite the shared corner: from corner A + 1 to A + 2.
    return (aSides && sideOfACrossesB((shared.A + 1) % 3)) ||
      (bSides && sideOfBCrossesA((shared.B + 1) % 3));
  }
  for (int k = 0; k < 3; ++k)
  {
    if ((aSides && sideOfACrossesB(k)) || (bSides && sideOfBCrossesA(k)))
    {
      return true;
    }
  }
  return false;
}

} // namespace

bool triangleMeetsBox(const TriangleCorners& t, const glm::dvec3& low, const glm::dvec3& high)
{
  // Most candidates have a corner in the box (a neighbour shares one).
  for (const glm::dvec3& p : t.P)
  {
    if (p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y && p.z >= low.z &&
      p.z <= high.z)
    {
      return true;
    }
  }
  const glm::dvec3 centre = 0.5 * (low + high);
  const glm::dvec3 half = 0.5 * (high - low);
  const glm::dvec3 p[3] = { t.P[0] - centre, t.P[1] - centre, t.P[2] - centre };
  const glm::dvec3 extent = glm::max(glm::abs(p[0]), glm::max(glm::abs(p[1]), glm::abs(p[2])));
  const double slack = 1e-9 * std::max({ half.x, half.y, half.z, extent.x, extent.y, extent.z });
  // Separated along `axis` when the corners' projections all lie beyond the
  // box's projected half-width (a zero axis separates nothing).
  auto separates = [&](const glm::dvec3& axis) {
    const double a = glm::dot(p[0], axis);
    const double b = glm::dot(p[1], axis);
    const double c = glm::dot(p[2], axis);
    const double radius = glm::dot(half, glm::abs(axis));
    const double reach = radius + slack * (std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z));
    return std::min({ a, b, c }) > reach || std::max({ a, b, c }) < -reach;
  };
  const glm::dvec3 sides[3] = { p[1] - p[0], p[2] - p[1], p[0] - p[2] };
  const glm::dvec3 axes[3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
  for (const glm::dvec3& axis : axes)
  {
    if (separates(axis))
    {
      return false;
    }
  }
  if (separates(glm::cross(sides[0], sides[1])))
  {
    return false;
  }
  for (const glm::dvec3& side : sides)
  {
    for (const glm::dvec3& axis : axes)
    {
      if (separates(glm::cross(side, axis)))
      {
        return false;
      }
    }
  }
  return true;
}

bool segmentCrossesTriangle(const glm::dvec3& u, const glm::dvec3& v, const TriangleCorners& t)
{
  return crosses(u, v, t, std::max(longestSide(t), glm::length(v - u)));
}

TriangleShape shapeOf(const TriangleCorners& t)
{
  TriangleShape shape;
  shape.Corners = t;
  const Plane plane = planeOf(t);
  shape.UnitNormal = plane.Unit;
  shape.Area2 = plane.Area2;
  shape.AxisSpan = longestAxisSpan(t);
  shape.LongestSide = longestSide(t);
  // hasNoInterior's rule, from the plane's area and the side already at hand.
  shape.NoInterior = t.P[0] == t.P[1] || t.P[1] == t.P[2] || t.P[2] == t.P[0] ||
    !(shape.Area2 > 1e-12 * shape.LongestSide * shape.LongestSide);
  return shape;
}

bool trianglesIntersect(const TriangleShape& a, const TriangleShape& b)
{
  return meet(a, b, Strict);
}

bool trianglesIntersect(const TriangleCorners& a, const TriangleCorners& b)
{
  return meet(shapeOf(a), shapeOf(b), Strict);
}

bool trianglesTouch(const TriangleCorners& a, const TriangleCorners& b)
{
  return meet(shapeOf(a), shapeOf(b), Lenient);
}

bool turnedOverAgainst(
  const TriangleCorners& piece, const TriangleCorners& input, const glm::dvec3& normalSum)
{
  auto facing = [&normalSum](const TriangleCorners& t) {
    const glm::dvec3 normal = glm::cross(t.P[1] - t.P[0], t.P[2] - t.P[0]);
    const double scale = glm::length(normal) * glm::length(normalSum);
    const double dot = glm::dot(normal, normalSum);
    // -1, 0 (edge-on or degenerate) or +1.
    return !(scale > 0.0) || !(std::abs(dot) > FacingTolerance * scale) ? 0 : (dot > 0.0 ? 1 : -1);
  };
  if (hasNoInterior(piece) || hasNoInterior(input))
  {
    return false; // a line or a point faces no way: rounding picks its normal
  }
  const int a = facing(piece);
  const int b = facing(input);
  return a != 0 && b != 0 && a != b;
}

} // namespace silsmooth
