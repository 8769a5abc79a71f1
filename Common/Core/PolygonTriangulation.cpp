#include "PolygonTriangulation.h"

#include "FiniteVector.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{
namespace
{

constexpr double StepBudget = 2e8;

// Twice the signed area of the 2D triangle (a, b, c): positive when it turns
// left (counter-clockwise).
double turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The polygon in its plane: the corners projected onto two axes across the
// Newell normal, so that it winds counter-clockwise. False for no area or a
// corner that is not finite.
bool projectToPlane(const std::vector<glm::dvec3>& points, const Id* corners, std::size_t count,
  std::vector<glm::dvec2>& flat)
{
  glm::dvec3 normal(0.0);
  for (std::size_t k = 0; k < count; ++k)
  {
    const glm::dvec3& p = points[static_cast<std::size_t>(corners[k])];
    const glm::dvec3& q = points[static_cast<std::size_t>(corners[(k + 1) % count])];
    normal +=
      glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  const double length = glm::length(normal);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  const glm::dvec3 n = normal / length;
  // The axis of n's smallest component, made perpendicular to n.
  glm::dvec3 seed(0.0);
  const glm::dvec3 m = glm::abs(n);
  seed[m.x <= m.y && m.x <= m.z ? 0 : (m.y <= m.z ? 1 : 2)] = 1.0;
  const glm::dvec3 u = glm::normalize(seed - glm::dot(seed, n) * n);
  const glm::dvec3 v = glm::cross(n, u);
  const glm::dvec3 origin = points[static_cast<std::size_t>(corners[0])];
  flat.resize(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    const glm::dvec3 d = points[static_cast<std::size_t>(corners[k])] - origin;
    flat[k] = glm::dvec2(glm::dot(d, u), glm::dot(d, v));
    if (!isFinite(points[static_cast<std::size_t>(corners[k])]))
    {
      return false;
    }
  }
  return true;
}

// Ear clipping over a ring of the polygon's corners.
class EarClipper
{
public:
  EarClipper(
    const std::vector<glm::dvec3>& points, const Id* corners, const std::vector<glm::dvec2>& flat)
    : Points(points)
    , Corners(corners)
    , Flat(flat)
    , Next(flat.size())
    , Previous(flat.size())
  {
    const std::size_t n = flat.size();
    double extent = 0.0;
    for (std::size_t k = 0; k < n; ++k)
    {
      this->Next[k] = (k + 1) % n;
      this->Previous[k] = (k + n - 1) % n;
      extent = std::max({ extent, std::abs(flat[k].x), std::abs(flat[k].y) });
    }
    // Turns smaller than this are straight: rounding's size for coordinates
    // of this extent.
    this->Straight = 1e-12 * extent * extent;
  }

  bool clip(std::vector<Triangle>& out)
  {
    std::size_t left = this->Flat.size();
    std::size_t at = 0;
    while (left > 3)
    {
      bool clipped = false;
      for (std::size_t tried = 0; tried < left && !clipped; ++tried)
      {
        if (this->isEar(at, left))
        {
          const std::size_t before = this->Previous[at];
          const std::size_t after = this->Next[at];
          this->emit(before, at, after, out);
          this->Next[before] = after;
          this->Previous[after] = before;
          at = after;
          --left;
          clipped = true;
        }
        else
        {
          at = this->Next[at];
        }
        if (this->Steps > StepBudget)
        {
          return false;
        }
      }
      if (!clipped)
      {
        // No ear: what is left must lie on a line (then its triangles have
        // no area), or the polygon crosses itself.
        return this->finishStraight(at, left, out);
      }
    }
    const std::size_t before = this->Previous[at];
    const std::size_t after = this->Next[at];
    if (turn(this->Flat[before], this->Flat[at], this->Flat[after]) < -this->Straight)
    {
      return false; // the last three turn the wrong way: it crossed itself
    }
    this->emit(before, at, after, out);
    return true;
  }

private:
  const glm::dvec3& position(std::size_t k) const
  {
    return this->Points[static_cast<std::size_t>(this->Corners[k])];
  }

  void emit(std::size_t a, std::size_t b, std::size_t c, std::vector<Triangle>& out) const
  {
    out.push_back({ this->Corners[a], this->Corners[b], this->Corners[c] });
  }

  // Whether corner b, between its neighbours, is an ear: it turns left, and
  // no other corner left lies in or on the triangle (corners at the position
  // of one of its corners aside: a slit's two sides).
  bool isEar(std::size_t b, std::size_t left)
  {
    const std::size_t a = this->Previous[b];
    const std::size_t c = this->Next[b];
    const glm::dvec2& pa = this->Flat[a];
    const glm::dvec2& pb = this->Flat[b];
    const glm::dvec2& pc = this->Flat[c];
    if (!(turn(pa, pb, pc) > this->Straight))
    {
      return false;
    }
    this->Steps += static_cast<double>(left);
    for (std::size_t k = this->Next[c]; k != a; k = this->Next[k])
    {
      const glm::dvec3& p = this->position(k);
      if (p == this->position(a) || p == this->position(b) || p == this->position(c))
      {
        continue;
      }
      const glm::dvec2& q = this->Flat[k];
      if (turn(pa, pb, q) >= -this->Straight && turn(pb, pc, q) >= -this->Straight &&
        turn(pc, pa, q) >= -this->Straight)
      {
        return false;
      }
    }
    return true;
  }

  // The corners left, when none is an ear: if they enclose no area (all on
  // a line), a fan of triangles of no area; otherwise false.
  bool finishStraight(std::size_t at, std::size_t left, std::vector<Triangle>& out) const
  {
    double area = 0.0;
    std::size_t k = at;
    for (std::size_t i = 0; i < left; ++i, k = this->Next[k])
    {
      area += turn(this->Flat[at], this->Flat[k], this->Flat[this->Next[k]]);
    }
    if (!(std::abs(area) <= this->Straight * static_cast<double>(left)))
    {
      return false;
    }
    for (k = this->Next[at]; this->Next[k] != at; k = this->Next[k])
    {
      this->emit(at, k, this->Next[k], out);
    }
    return true;
  }

  const std::vector<glm::dvec3>& Points;
  const Id* Corners;
  const std::vector<glm::dvec2>& Flat;
  std::vector<std::size_t> Next;
  std::vector<std::size_t> Previous;
  double Straight = 0.0;
  double Steps = 0.0;
};

} // namespace

bool triangulatePolygon(const std::vector<glm::dvec3>& points, const Id* corners, std::size_t count,
  std::vector<Triangle>& out)
{
  if (count < 3)
  {
    return false;
  }
  for (std::size_t k = 0; k < count; ++k)
  {
    if (corners[k] < 0 || static_cast<std::size_t>(corners[k]) >= points.size())
    {
      return false;
    }
  }
  std::vector<glm::dvec2> flat;
  if (!projectToPlane(points, corners, count, flat))
  {
    return false;
  }
  const std::size_t first = out.size();
  EarClipper clipper(points, corners, flat);
  if (!clipper.clip(out))
  {
    out.resize(first);
    return false;
  }
  return true;
}

} // namespace silsmooth
