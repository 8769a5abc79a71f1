#include "SurfaceEdgeLines.h"

#include "EdgeClassification.h"
#include "SurfaceWelding.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{
namespace
{

constexpr double DegreesToRadians = 3.14159265358979323846 / 180.0;

/// One side of an edge: the triangle and the point ids it uses at the
/// edge's welded ends.
struct EdgeSide
{
  Id Low = 0;
  Id High = 0;
  Id Triangle = 0;
  Id LowCopy = 0;
  Id HighCopy = 0;
};

bool normalsJump(const std::vector<glm::dvec3>& normals, Id a, Id b, double cosine)
{
  if (a == b)
  {
    return false;
  }
  const glm::dvec3& m = normals[static_cast<std::size_t>(a)];
  const glm::dvec3& n = normals[static_cast<std::size_t>(b)];
  const double scale = glm::length(m) * glm::length(n);
  // A zero or broken normal says nothing about a jump.
  return scale > 0.0 && std::isfinite(scale) && glm::dot(m, n) < cosine * scale;
}

} // namespace

std::vector<SurfaceEdgeLine> surfaceEdgeLines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals,
  const SurfaceEdgeLineParameters& parameters)
{
  const std::vector<Id> welded = weldCoincidentPoints(points, parameters.WeldTolerance);
  const bool withNormals = !normals.empty() && normals.size() == points.size();

  std::vector<EdgeSide> sides;
  sides.reserve(3 * triangles.size());
  std::vector<glm::dvec3> faceNormals(triangles.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& raw = triangles[t];
    Triangle corner;
    for (int k = 0; k < 3; ++k)
    {
      corner[k] = welded[static_cast<std::size_t>(raw[k])];
    }
    if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0])
    {
      continue;
    }
    const glm::dvec3& p0 = points[static_cast<std::size_t>(corner[0])];
    faceNormals[t] = glm::cross(points[static_cast<std::size_t>(corner[1])] - p0,
      points[static_cast<std::size_t>(corner[2])] - p0);
    for (int k = 0; k < 3; ++k)
    {
      const int next = (k + 1) % 3;
      EdgeSide side;
      const bool ordered = corner[k] < corner[next];
      side.Low = ordered ? corner[k] : corner[next];
      side.High = ordered ? corner[next] : corner[k];
      side.LowCopy = ordered ? raw[k] : raw[next];
      side.HighCopy = ordered ? raw[next] : raw[k];
      side.Triangle = static_cast<Id>(t);
      sides.push_back(side);
    }
  }
  std::sort(sides.begin(), sides.end(), [](const EdgeSide& x, const EdgeSide& y) {
    return std::tie(x.Low, x.High, x.Triangle) < std::tie(y.Low, y.High, y.Triangle);
  });

  const double jumpCosine = std::cos(parameters.NormalJumpDegrees * DegreesToRadians);
  const double creaseCosine = std::cos(parameters.CreaseAngleDegrees * DegreesToRadians);
  std::vector<FlaggedEdge> edges;
  for (std::size_t begin = 0; begin < sides.size();)
  {
    std::size_t end = begin + 1;
    while (end < sides.size() && sides[end].Low == sides[begin].Low &&
      sides[end].High == sides[begin].High)
    {
      ++end;
    }
    const EdgeSide& one = sides[begin];
    unsigned flags = 0;
    if (end - begin == 1)
    {
      flags = BorderEdge;
    }
    else if (end - begin > 2)
    {
      flags = CreaseEdge;
    }
    else
    {
      const EdgeSide& other = sides[begin + 1];
      if (withNormals)
      {
        if (normalsJump(normals, one.LowCopy, other.LowCopy, jumpCosine) ||
          normalsJump(normals, one.HighCopy, other.HighCopy, jumpCosine))
        {
          flags = CreaseEdge;
        }
      }
      else
      {
        const glm::dvec3& m = faceNormals[static_cast<std::size_t>(one.Triangle)];
        const glm::dvec3& n = faceNormals[static_cast<std::size_t>(other.Triangle)];
        if (glm::dot(m, n) < creaseCosine * glm::length(m) * glm::length(n))
        {
          flags = CreaseEdge;
        }
      }
    }
    if (flags != 0)
    {
      edges.push_back({ one.Low, one.High, flags });
    }
    begin = end;
  }

  std::vector<SurfaceEdgeLine> lines;
  const auto add = [&](bool wanted, unsigned mask, LineKind kind) {
    if (!wanted)
    {
      return;
    }
    for (std::vector<Id>& chain : chainFlaggedEdges(edges, mask))
    {
      lines.push_back({ std::move(chain), kind });
    }
  };
  add(parameters.Creases, CreaseEdge, LineKind::Crease);
  add(parameters.Borders, BorderEdge, LineKind::Border);
  return lines;
}

} // namespace silsmooth
