#include "LineVisibility.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace silsmooth
{
namespace
{

bool finite(const glm::dvec3& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Where the ray origin + t dir (dir a unit vector) meets triangle (a, b, c):
// t, or -1 when it misses (Moller and Trumbore). Edges count as inside,
// with a margin of 1e-12 in the barycentric coordinates, so that a ray
// through an edge shared by two triangles cannot slip between them.
double rayHit(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec3& c)
{
  constexpr double margin = 1e-12;
  const glm::dvec3 e1 = b - a;
  const glm::dvec3 e2 = c - a;
  const glm::dvec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (!(std::abs(det) > 0.0))
  {
    return -1.0; // the ray runs in the triangle's plane, or no triangle
  }
  const double inverse = 1.0 / det;
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) * inverse;
  if (!(u >= -margin && u <= 1.0 + margin))
  {
    return -1.0;
  }
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(dir, q) * inverse;
  if (!(v >= -margin && u + v <= 1.0 + margin))
  {
    return -1.0;
  }
  return glm::dot(e2, q) * inverse;
}

// The range [enter, leave] of t where origin + t dir lies in the box.
std::pair<double, double> rayInBox(
  const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& low, const glm::dvec3& high)
{
  double enter = -std::numeric_limits<double>::infinity();
  double leave = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (dir[axis] == 0.0)
    {
      if (origin[axis] < low[axis] || origin[axis] > high[axis])
      {
        return { 1.0, 0.0 }; // parallel to the slab and outside it: empty
      }
      continue;
    }
    double t0 = (low[axis] - origin[axis]) / dir[axis];
    double t1 = (high[axis] - origin[axis]) / dir[axis];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return { enter, leave };
}

} // namespace

LineVisibilityParameters LineVisibilityParameters::forMesh(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles)
{
  LineVisibilityParameters parameters;
  double sum = 0.0;
  std::size_t sides = 0;
  glm::dvec3 low(std::numeric_limits<double>::infinity());
  glm::dvec3 high(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const glm::dvec3& a = points[static_cast<std::size_t>(t[k])];
      const glm::dvec3& b = points[static_cast<std::size_t>(t[(k + 1) % 3])];
      const double length = glm::length(b - a);
      if (std::isfinite(length))
      {
        sum += length;
        ++sides;
      }
      if (finite(a))
      {
        low = glm::min(low, a);
        high = glm::max(high, a);
      }
    }
  }
  if (sides > 0)
  {
    parameters.Tolerance = sum / static_cast<double>(sides);
    parameters.Precision = 1e-6 * glm::length(high - low);
  }
  return parameters;
}

OcclusionMesh::OcclusionMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , Grid(this->Points, this->Triangles)
{
  this->Low = glm::dvec3(std::numeric_limits<double>::infinity());
  this->High = glm::dvec3(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : this->Triangles)
  {
    for (const Id corner : t)
    {
      const glm::dvec3& p = this->Points[static_cast<std::size_t>(corner)];
      if (finite(p))
      {
        this->Low = glm::min(this->Low, p);
        this->High = glm::max(this->High, p);
      }
    }
  }
  this->Step = this->Grid.cellSize();
}

bool OcclusionMesh::hides(const ViewGeometry& view, const glm::dvec3& point, double tolerance) const
{
  if (this->Grid.empty() || !finite(point) || !(this->Step > 0.0))
  {
    return false;
  }
  const glm::dvec3 toward = view.towardViewerFrom(point);
  const double reach = glm::length(toward); // to the eye; parallel: no end
  if (!(reach > 0.0) || !std::isfinite(reach))
  {
    return false;
  }
  const glm::dvec3 dir = toward / reach;
  const double end = view.Parallel ? std::numeric_limits<double>::infinity() : reach;
  // Only where the ray is inside the surface's box can it meet a triangle.
  const auto [enter, leave] = rayInBox(point, dir, this->Low, this->High);
  const double first = std::max(enter, tolerance);
  const double last = std::min(leave, end);
  if (!(first <= last))
  {
    return false;
  }
  // The ray in pieces about a grid cell long, near to far: the triangles
  // whose boxes meet a piece's box include every triangle the piece crosses.
  std::vector<Id> candidates;
  for (double t = first; t <= last; t += this->Step)
  {
    const double next = std::min(t + this->Step, last);
    const glm::dvec3 a = point + t * dir;
    const glm::dvec3 b = point + next * dir;
    this->Grid.query(glm::min(a, b), glm::max(a, b), candidates);
    for (const Id c : candidates)
    {
      const Triangle& tri = this->Triangles[static_cast<std::size_t>(c)];
      const double hit = rayHit(point, dir, this->Points[static_cast<std::size_t>(tri[0])],
        this->Points[static_cast<std::size_t>(tri[1])],
        this->Points[static_cast<std::size_t>(tri[2])]);
      if (hit > tolerance && hit <= end)
      {
        return true;
      }
    }
    if (next >= last || !(t + this->Step > t))
    {
      break; // the end, or a step too short to advance at this distance
    }
  }
  return false;
}

namespace
{

double pieceLength(const LinePiece& piece)
{
  double length = 0.0;
  for (std::size_t k = 1; k < piece.Points.size(); ++k)
  {
    length += glm::length(piece.Points[k] - piece.Points[k - 1]);
  }
  return length;
}

// Appends `next` to `piece` (they share the change point at the joint).
void appendPiece(LinePiece& piece, const LinePiece& next)
{
  piece.Points.insert(piece.Points.end(), next.Points.begin() + 1, next.Points.end());
  piece.Along.insert(piece.Along.end(), next.Along.begin() + 1, next.Along.end());
}

} // namespace

std::vector<LinePiece> mergeShortPieces(std::vector<LinePiece> pieces, double minimumLength)
{
  if (!(minimumLength > 0.0))
  {
    return pieces;
  }
  // The shortest piece below the limit takes its neighbours' state and
  // joins them, until none is left or one piece remains; alternation keeps
  // both neighbours of a piece in the other state.
  while (pieces.size() > 1)
  {
    std::size_t shortest = pieces.size();
    double shortestLength = minimumLength;
    for (std::size_t i = 0; i < pieces.size(); ++i)
    {
      const double length = pieceLength(pieces[i]);
      if (length < shortestLength)
      {
        shortest = i;
        shortestLength = length;
      }
    }
    if (shortest == pieces.size())
    {
      break;
    }
    const std::size_t first = shortest > 0 ? shortest - 1 : 0;
    const std::size_t last = std::min(shortest + 1, pieces.size() - 1);
    LinePiece merged = std::move(pieces[first]);
    merged.Visible = !pieces[shortest].Visible;
    for (std::size_t i = first + 1; i <= last; ++i)
    {
      appendPiece(merged, pieces[i]);
    }
    pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(first) + 1,
      pieces.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    pieces[first] = std::move(merged);
  }
  return pieces;
}

std::vector<LinePiece> splitByVisibility(const OcclusionMesh& surface, const ViewGeometry& view,
  const std::vector<glm::dvec3>& polyline, const LineVisibilityParameters& parameters)
{
  std::vector<LinePiece> pieces;
  if (polyline.empty())
  {
    return pieces;
  }
  auto visible = [&](const glm::dvec3& p) {
    return !surface.hides(view, p, parameters.Tolerance);
  };
  LinePiece current;
  current.Visible = visible(polyline.front());
  current.Points.push_back(polyline.front());
  current.Along.push_back(0.0);
  for (std::size_t i = 1; i < polyline.size(); ++i)
  {
    const glm::dvec3& a = polyline[i - 1];
    const glm::dvec3& b = polyline[i];
    const bool state = visible(b);
    if (state != current.Visible)
    {
      // Bisection on the segment: a keeps the current state, b the new one.
      const double length = glm::length(b - a);
      double low = 0.0;
      double high = 1.0;
      for (int step = 0; step < 64 && (high - low) * length > parameters.Precision; ++step)
      {
        const double middle = 0.5 * (low + high);
        (visible(a + middle * (b - a)) == current.Visible ? low : high) = middle;
      }
      const double fraction = 0.5 * (low + high);
      const glm::dvec3 change = a + fraction * (b - a);
      const double along = static_cast<double>(i - 1) + fraction;
      current.Points.push_back(change);
      current.Along.push_back(along);
      pieces.push_back(std::move(current));
      current = LinePiece();
      current.Visible = state;
      current.Points.push_back(change);
      current.Along.push_back(along);
    }
    current.Points.push_back(b);
    current.Along.push_back(static_cast<double>(i));
  }
  pieces.push_back(std::move(current));
  return mergeShortPieces(std::move(pieces), parameters.MinimumPieceLength);
}

} // namespace silsmooth
