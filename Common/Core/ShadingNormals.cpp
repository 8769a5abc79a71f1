#include "ShadingNormals.h"

#include "FiniteVector.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace silsmooth
{

namespace
{

// `v` divided by its largest component's magnitude: the direction survives
// where the cross product of two tiny edges (a model at 1e-150 scale) would
// underflow to zero.
glm::dvec3 rescaled(const glm::dvec3& v)
{
  const double largest = std::max({ std::abs(v.x), std::abs(v.y), std::abs(v.z) });
  return largest > 0.0 && std::isfinite(largest) ? v / largest : v;
}

// Interior angle at `corner` between the directions to `a` and `b`; zero when
// either direction is degenerate. atan2 of |cross| and dot is accurate for
// angles near 0 and pi, where acos of a dot product loses digits.
double cornerAngle(const glm::dvec3& corner, const glm::dvec3& a, const glm::dvec3& b)
{
  const glm::dvec3 u = rescaled(a - corner);
  const glm::dvec3 v = rescaled(b - corner);
  const double sine = glm::length(glm::cross(u, v));
  const double cosine = glm::dot(u, v);
  if (sine == 0.0 && cosine == 0.0)
  {
    return 0.0;
  }
  return std::atan2(sine, cosine);
}

} // namespace

std::vector<glm::dvec3> angleWeightedNormals(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles)
{
  std::vector<glm::dvec3> sums(points.size(), glm::dvec3(0.0));
  for (const Triangle& t : triangles)
  {
    if (hasRepeatedCorner(t))
    {
      continue;
    }
    const glm::dvec3& p0 = points[static_cast<std::size_t>(t[0])];
    const glm::dvec3& p1 = points[static_cast<std::size_t>(t[1])];
    const glm::dvec3& p2 = points[static_cast<std::size_t>(t[2])];
    const glm::dvec3 faceNormal = safeNormalize(glm::cross(rescaled(p1 - p0), rescaled(p2 - p0)));
    if (faceNormal == glm::dvec3(0.0))
    {
      continue; // zero area: no direction to contribute
    }
    sums[static_cast<std::size_t>(t[0])] += cornerAngle(p0, p1, p2) * faceNormal;
    sums[static_cast<std::size_t>(t[1])] += cornerAngle(p1, p2, p0) * faceNormal;
    sums[static_cast<std::size_t>(t[2])] += cornerAngle(p2, p0, p1) * faceNormal;
  }
  for (glm::dvec3& n : sums)
  {
    n = safeNormalize(n);
  }
  return sums;
}

namespace
{

// Face normals weighted by area (the plain cross product) or by Max's weights
// (the cross product of the corner's edges over their squared lengths). Edges
// are measured in units of the mesh's extent, one unit for the whole mesh so
// the weights keep their ratios: at 1e-150 scale the cross products of raw
// edges would underflow, at 1e150 overflow.
std::vector<glm::dvec3> crossWeightedNormals(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles, bool max)
{
  glm::dvec3 low(std::numeric_limits<double>::infinity());
  glm::dvec3 high(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : triangles)
  {
    for (const Id v : t)
    {
      low = glm::min(low, points[static_cast<std::size_t>(v)]);
      high = glm::max(high, points[static_cast<std::size_t>(v)]);
    }
  }
  const glm::dvec3 extent = high - low;
  double unit = std::max({ extent.x, extent.y, extent.z });
  unit = unit > 0.0 && std::isfinite(unit) ? unit : 1.0;
  std::vector<glm::dvec3> sums(points.size(), glm::dvec3(0.0));
  for (const Triangle& t : triangles)
  {
    if (hasRepeatedCorner(t))
    {
      continue;
    }
    for (std::size_t k = 0; k < 3; ++k)
    {
      const glm::dvec3& p = points[static_cast<std::size_t>(t[k])];
      const glm::dvec3 a = (points[static_cast<std::size_t>(t[(k + 1) % 3])] - p) / unit;
      const glm::dvec3 b = (points[static_cast<std::size_t>(t[(k + 2) % 3])] - p) / unit;
      glm::dvec3 c = glm::cross(a, b);
      if (max)
      {
        const double scale = glm::dot(a, a) * glm::dot(b, b);
        c = scale > 0.0 && std::isfinite(scale) ? c / scale : glm::dvec3(0.0);
      }
      if (isFinite(c))
      {
        sums[static_cast<std::size_t>(t[k])] += c;
      }
    }
  }
  for (glm::dvec3& n : sums)
  {
    n = safeNormalize(n);
  }
  return sums;
}

// Solves the 5x5 normal equations by Gaussian elimination with partial
// pivoting; false when a pivot is negligible against the matrix's scale.
bool solve5(std::array<std::array<double, 6>, 5>& m, std::array<double, 5>& x)
{
  double scale = 0.0;
  for (const auto& row : m)
  {
    for (int c = 0; c < 5; ++c)
    {
      scale = std::max(scale, std::abs(row[static_cast<std::size_t>(c)]));
    }
  }
  if (!(scale > 0.0))
  {
    return false;
  }
  for (int col = 0; col < 5; ++col)
  {
    int pivot = col;
    for (int r = col + 1; r < 5; ++r)
    {
      if (std::abs(m[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)]) >
        std::abs(m[static_cast<std::size_t>(pivot)][static_cast<std::size_t>(col)]))
      {
        pivot = r;
      }
    }
    if (std::abs(m[static_cast<std::size_t>(pivot)][static_cast<std::size_t>(col)]) < 1e-9 * scale)
    {
      return false;
    }
    std::swap(m[static_cast<std::size_t>(col)], m[static_cast<std::size_t>(pivot)]);
    for (int r = col + 1; r < 5; ++r)
    {
      const double f = m[static_cast<std::size_t>(r)][static_cast<std::size_t>(col)] /
        m[static_cast<std::size_t>(col)][static_cast<std::size_t>(col)];
      for (int c = col; c < 6; ++c)
      {
        m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] -=
          f * m[static_cast<std::size_t>(col)][static_cast<std::size_t>(c)];
      }
    }
  }
  for (int r = 4; r >= 0; --r)
  {
    double v = m[static_cast<std::size_t>(r)][5];
    for (int c = r + 1; c < 5; ++c)
    {
      v -= m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] *
        x[static_cast<std::size_t>(c)];
    }
    x[static_cast<std::size_t>(r)] =
      v / m[static_cast<std::size_t>(r)][static_cast<std::size_t>(r)];
  }
  return std::isfinite(x[3]) && std::isfinite(x[4]);
}

std::vector<glm::dvec3> quadricFitNormals(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles)
{
  std::vector<glm::dvec3> normals = angleWeightedNormals(points, triangles);
  // The neighbours of every vertex through its triangles (compressed rows).
  std::vector<std::size_t> offsets(points.size() + 1, 0);
  for (const Triangle& t : triangles)
  {
    if (!hasRepeatedCorner(t))
    {
      for (const Id v : t)
      {
        offsets[static_cast<std::size_t>(v) + 1] += 2;
      }
    }
  }
  for (std::size_t v = 1; v < offsets.size(); ++v)
  {
    offsets[v] += offsets[v - 1];
  }
  std::vector<Id> around(offsets.back());
  std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
  for (const Triangle& t : triangles)
  {
    if (hasRepeatedCorner(t))
    {
      continue;
    }
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t v = static_cast<std::size_t>(t[k]);
      around[fill[v]++] = t[(k + 1) % 3];
      around[fill[v]++] = t[(k + 2) % 3];
    }
  }
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    std::vector<Id> ring(around.begin() + static_cast<std::ptrdiff_t>(offsets[v]),
      around.begin() + static_cast<std::ptrdiff_t>(offsets[v + 1]));
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    if (ring.size() < 5 || normals[v] == glm::dvec3(0.0))
    {
      continue;
    }
    double unit = 0.0;
    for (const Id q : ring)
    {
      unit += glm::length(points[static_cast<std::size_t>(q)] - points[v]);
    }
    unit /= static_cast<double>(ring.size());
    if (!(unit > 0.0) || !std::isfinite(unit))
    {
      continue;
    }
    // One fit, in the frame (u, w, n) of the angle-weighted normal, lengths in
    // units of the mean neighbour distance. (A second fit in the frame of the
    // fitted normal was tried: on a paraboloid with a wide ring it came out
    // farther, 2.5e-2 against 1.5e-2 rad.)
    const glm::dvec3 n = normals[v];
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(n, helper));
    const glm::dvec3 w = glm::cross(n, u);
    std::array<std::array<double, 6>, 5> m{};
    for (const Id q : ring)
    {
      const glm::dvec3 d = (points[static_cast<std::size_t>(q)] - points[v]) / unit;
      const double x = glm::dot(d, u);
      const double y = glm::dot(d, w);
      const double z = glm::dot(d, n);
      const std::array<double, 5> basis{ { x * x, x * y, y * y, x, y } };
      for (std::size_t r = 0; r < 5; ++r)
      {
        for (std::size_t c = 0; c < 5; ++c)
        {
          m[r][c] += basis[r] * basis[c];
        }
        m[r][5] += basis[r] * z;
      }
    }
    std::array<double, 5> coefficients{};
    if (!solve5(m, coefficients))
    {
      continue;
    }
    // The height field's normal at the vertex: (-dz/dx, -dz/dy, 1).
    const glm::dvec3 fitted = safeNormalize(-coefficients[3] * u - coefficients[4] * w + n);
    if (fitted != glm::dvec3(0.0))
    {
      normals[v] = fitted;
    }
  }
  return normals;
}

} // namespace

std::vector<glm::dvec3> vertexNormals(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, NormalWeighting weighting)
{
  switch (weighting)
  {
    case NormalWeighting::Area:
      return crossWeightedNormals(points, triangles, false);
    case NormalWeighting::Max:
      return crossWeightedNormals(points, triangles, true);
    case NormalWeighting::QuadricFit:
      return quadricFitNormals(points, triangles);
    case NormalWeighting::Angle:
    default:
      return angleWeightedNormals(points, triangles);
  }
}

} // namespace silsmooth
