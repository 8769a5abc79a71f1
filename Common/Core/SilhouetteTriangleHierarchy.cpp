#include "SilhouetteTriangleHierarchy.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <mutex>
#include <utility>

namespace silsmooth
{

using namespace visibility_cones;

SilhouetteTriangleHierarchy::SilhouetteTriangleHierarchy(const std::vector<glm::dvec3>& points,
  const std::vector<glm::dvec3>& normals, const std::vector<Triangle>& triangles, bool perspective)
  : Perspective(perspective)
{
  if (triangles.size() >= std::numeric_limits<std::uint32_t>::max())
  {
    return;
  }
  // Which points the cones can hold, and the box of those.
  const std::size_t pointCount = points.size();
  std::vector<unsigned char> clustered(pointCount, 0);
  glm::dvec3 lo(0.0);
  glm::dvec3 hi(0.0);
  bool any = false;
  for (std::size_t i = 0; i < pointCount; ++i)
  {
    const glm::dvec3 normal = i < normals.size() ? normals[i] : glm::dvec3(0.0);
    if (clusterable(points[i], normal))
    {
      clustered[i] = 1;
      lo = any ? glm::min(lo, points[i]) : points[i];
      hi = any ? glm::max(hi, points[i]) : points[i];
      any = true;
    }
  }
  this->Map = Conditioning::ofBox(lo, hi);
  if (perspective && !this->Map.PerspectiveUsable)
  {
    return;
  }
  std::vector<glm::dvec4> vectors(pointCount, glm::dvec4(0.0));
  for (std::size_t i = 0; i < pointCount; ++i)
  {
    if (clustered[i])
    {
      vectors[i] = this->Map.vectorOf(points[i], normals[i], perspective);
    }
  }

  // Each triangle is a cap around its corners' mean direction that holds
  // all three corner vectors.
  std::vector<glm::dvec4> keys;
  std::vector<double> radii;
  std::vector<std::uint32_t> members;
  keys.reserve(triangles.size());
  radii.reserve(triangles.size());
  members.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = triangles[t];
    if (hasRepeatedCorner(tri))
    {
      continue; // never a silhouette triangle
    }
    bool inRange = true;
    for (const Id c : tri)
    {
      inRange = inRange && c >= 0 && static_cast<std::size_t>(c) < pointCount &&
        clustered[static_cast<std::size_t>(c)];
    }
    if (!inRange)
    {
      this->Direct.push_back(static_cast<Id>(t));
      continue;
    }
    const glm::dvec4& a = vectors[static_cast<std::size_t>(tri[0])];
    const glm::dvec4& b = vectors[static_cast<std::size_t>(tri[1])];
    const glm::dvec4& c = vectors[static_cast<std::size_t>(tri[2])];
    const glm::dvec4 sum = a + b + c;
    const double length = std::sqrt(glm::dot(sum, sum));
    const glm::dvec4 key = length > 1e-9 ? sum / length : a;
    keys.push_back(key);
    radii.push_back(std::max({ angleBetween(key, a), angleBetween(key, b), angleBetween(key, c) }));
    members.push_back(static_cast<std::uint32_t>(t));
  }
  ConeTree cones = buildConeTree(keys, radii);
  this->Nodes = std::move(cones.Nodes);
  this->Tasks = std::move(cones.Tasks);
  this->Order.resize(cones.Items.size());
  for (std::size_t k = 0; k < cones.Items.size(); ++k)
  {
    this->Order[k] = members[cones.Items[k]];
  }
  this->Built = true;
}

namespace
{

// Whether triangle t's corners do not all lie on one side (g >= 0 or not).
bool isMixedTriangle(const Triangle& tri, const ViewGeometry& view,
  const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals)
{
  bool sides[3];
  for (int k = 0; k < 3; ++k)
  {
    const std::size_t c = static_cast<std::size_t>(tri[k]);
    const glm::dvec3 normal = c < normals.size() ? normals[c] : glm::dvec3(0.0);
    sides[k] = view.visibility(points[c], normal) >= 0.0;
  }
  return sides[0] != sides[1] || sides[1] != sides[2];
}

} // namespace

void SilhouetteTriangleHierarchy::findInSubtree(std::int32_t root, const ViewGeometry& view,
  const glm::dvec4& query, const std::vector<glm::dvec3>& points,
  const std::vector<glm::dvec3>& normals, const std::vector<Triangle>& triangles,
  std::vector<Id>& out, Statistics& statistics) const
{
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = root;
  while (top > 0)
  {
    const ConeNode& node = this->Nodes[static_cast<std::size_t>(stack[--top])];
    ++statistics.VisitedNodes;
    if (decide(node.Axis, node.HalfAngle, query) != 0)
    {
      continue; // every corner below is on one side: no silhouette triangle
    }
    if (node.FirstChild < 0)
    {
      for (std::uint32_t k = node.Begin; k < node.End; ++k)
      {
        const std::uint32_t t = this->Order[k];
        if (isMixedTriangle(triangles[t], view, points, normals))
        {
          out.push_back(static_cast<Id>(t));
        }
      }
      statistics.EvaluatedTriangles += node.End - node.Begin;
    }
    else
    {
      // Depth is below 64: a node has more than twice as many members as
      // each child, and counts fit 32 bits.
      stack[top++] = node.FirstChild + 1;
      stack[top++] = node.FirstChild;
    }
  }
}

bool SilhouetteTriangleHierarchy::find(const ViewGeometry& view,
  const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals,
  const std::vector<Triangle>& triangles, const ParallelFor& parallelFor, std::vector<Id>& out,
  Statistics* statistics) const
{
  glm::dvec4 query(0.0);
  if (!this->Built || view.Parallel == this->Perspective || !this->Map.queryOf(view, query))
  {
    return false;
  }
  // Each task collects its own triangles; the lists are joined and sorted,
  // so the answer does not depend on the split.
  std::mutex joinMutex;
  std::vector<Id> found;
  Statistics total;
  total.EvaluatedTriangles = this->Direct.size();
  for (const Id t : this->Direct)
  {
    if (isMixedTriangle(triangles[static_cast<std::size_t>(t)], view, points, normals))
    {
      found.push_back(t);
    }
  }
  const auto body = [&](std::size_t begin, std::size_t end) {
    std::vector<Id> local;
    Statistics counts;
    for (std::size_t task = begin; task < end; ++task)
    {
      this->findInSubtree(
        this->Tasks[task], view, query, points, normals, triangles, local, counts);
    }
    const std::lock_guard<std::mutex> lock(joinMutex);
    found.insert(found.end(), local.begin(), local.end());
    total.VisitedNodes += counts.VisitedNodes;
    total.EvaluatedTriangles += counts.EvaluatedTriangles;
  };
  if (parallelFor)
  {
    parallelFor(this->Tasks.size(), body);
  }
  else
  {
    serialFor(this->Tasks.size(), body);
  }
  std::sort(found.begin(), found.end());
  out = std::move(found);
  if (statistics)
  {
    *statistics = total;
  }
  return true;
}

} // namespace silsmooth
