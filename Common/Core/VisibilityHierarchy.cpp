#include "VisibilityHierarchy.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace silsmooth
{

namespace
{

using namespace visibility_cones;

} // namespace

VisibilityHierarchy::VisibilityHierarchy(
  const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& normals)
  : PointCount(points.size())
{
  // Which vertices the trees can decide, and the bounding box of those.
  glm::dvec3 lo(0.0);
  glm::dvec3 hi(0.0);
  std::vector<std::uint32_t> clustered;
  clustered.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const glm::dvec3 normal = i < normals.size() ? normals[i] : glm::dvec3(0.0);
    if (!clusterable(points[i], normal))
    {
      this->Direct.push_back(static_cast<std::uint32_t>(i));
      this->DirectPoints.push_back(points[i]);
      this->DirectNormals.push_back(normal);
      continue;
    }
    if (clustered.empty())
    {
      lo = hi = points[i];
    }
    lo = glm::min(lo, points[i]);
    hi = glm::max(hi, points[i]);
    clustered.push_back(static_cast<std::uint32_t>(i));
  }
  this->Map = Conditioning::ofBox(lo, hi);
  const Conditioning& conditioning = this->Map;

  for (Tree* tree : { &this->Parallel, &this->Perspective })
  {
    const bool perspective = tree == &this->Perspective;
    tree->Order = clustered;
    tree->Normals.reserve(clustered.size());
    if (perspective)
    {
      tree->Points.reserve(clustered.size());
    }
    std::vector<glm::dvec4> vectors;
    vectors.reserve(clustered.size());
    for (const std::uint32_t i : clustered)
    {
      tree->Normals.push_back(normals[i]);
      if (perspective)
      {
        tree->Points.push_back(points[i]);
      }
      vectors.push_back(conditioning.vectorOf(points[i], normals[i], perspective));
    }
    if (!perspective || conditioning.PerspectiveUsable)
    {
      buildTree(*tree, vectors);
    }
  }
}

void VisibilityHierarchy::buildTree(Tree& tree, const std::vector<glm::dvec4>& vectors)
{
  ConeTree cones = buildConeTree(vectors);
  tree.Nodes = std::move(cones.Nodes);
  tree.Tasks = std::move(cones.Tasks);
  // Store the vertices in tree order.
  const std::size_t n = cones.Items.size();
  std::vector<std::uint32_t> order(n);
  std::vector<glm::dvec3> normals(n);
  std::vector<glm::dvec3> points(tree.Points.empty() ? 0 : n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::uint32_t slot = cones.Items[k];
    order[k] = tree.Order[slot];
    normals[k] = tree.Normals[slot];
    if (!points.empty())
    {
      points[k] = tree.Points[slot];
    }
  }
  tree.Order = std::move(order);
  tree.Normals = std::move(normals);
  tree.Points = std::move(points);
}

void VisibilityHierarchy::classifySubtree(const Tree& tree, std::int32_t root,
  const ViewGeometry& view, const glm::dvec4& query, double* g, Statistics& statistics)
{
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = root;
  while (top > 0)
  {
    const ConeNode& node = tree.Nodes[static_cast<std::size_t>(stack[--top])];
    ++statistics.VisitedNodes;
    const double decided = decide(node.Axis, node.HalfAngle, query);
    if (decided != 0.0)
    {
      for (std::uint32_t k = node.Begin; k < node.End; ++k)
      {
        g[tree.Order[k]] = decided;
      }
      statistics.DecidedVertices += node.End - node.Begin;
    }
    else if (node.FirstChild < 0)
    {
      // For parallel projection visibility() reads only the normal.
      const bool hasPoints = !tree.Points.empty();
      for (std::uint32_t k = node.Begin; k < node.End; ++k)
      {
        g[tree.Order[k]] =
          view.visibility(hasPoints ? tree.Points[k] : glm::dvec3(0.0), tree.Normals[k]);
      }
      statistics.ExactVertices += node.End - node.Begin;
    }
    else
    {
      // Depth is below 64: a node has more than twice as many vertices as
      // each child, and counts fit 32 bits.
      stack[top++] = node.FirstChild + 1;
      stack[top++] = node.FirstChild;
    }
  }
}

void VisibilityHierarchy::classify(const ViewGeometry& view, std::vector<double>& g,
  const ParallelForFunction& parallelFor, Statistics* statistics) const
{
  g.resize(this->PointCount);
  const auto forEach = [&parallelFor](std::size_t count,
                         const std::function<void(std::size_t, std::size_t)>& body) {
    if (parallelFor)
    {
      parallelFor(count, body);
    }
    else if (count > 0)
    {
      body(0, count);
    }
  };
  Statistics total;

  for (std::size_t k = 0; k < this->Direct.size(); ++k)
  {
    g[this->Direct[k]] = view.visibility(this->DirectPoints[k], this->DirectNormals[k]);
  }
  total.ExactVertices += this->Direct.size();

  // The query direction on the sphere, when the view allows one.
  const Tree& tree = view.Parallel ? this->Parallel : this->Perspective;
  glm::dvec4 query(0.0);
  const bool useTree = !tree.Nodes.empty() && this->Map.queryOf(view, query);

  double* out = g.data();
  if (!useTree)
  {
    const bool hasPoints = !tree.Points.empty();
    forEach(tree.Order.size(), [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
      {
        out[tree.Order[k]] =
          view.visibility(hasPoints ? tree.Points[k] : glm::dvec3(0.0), tree.Normals[k]);
      }
    });
    total.ExactVertices += tree.Order.size();
  }
  else
  {
    std::vector<Statistics> perTask(statistics ? tree.Tasks.size() : 0);
    forEach(tree.Tasks.size(), [&](std::size_t begin, std::size_t end) {
      Statistics local;
      for (std::size_t t = begin; t < end; ++t)
      {
        Statistics& s = statistics ? perTask[t] : local;
        classifySubtree(tree, tree.Tasks[t], view, query, out, s);
      }
    });
    for (const Statistics& s : perTask)
    {
      total.DecidedVertices += s.DecidedVertices;
      total.ExactVertices += s.ExactVertices;
      total.VisitedNodes += s.VisitedNodes;
    }
  }
  if (statistics)
  {
    *statistics = total;
  }
}

} // namespace silsmooth
