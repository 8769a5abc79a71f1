#include "VisibilityHierarchy.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace silsmooth
{

namespace
{

constexpr std::size_t LeafSize = 32;
/// Subtrees of about this many nodes' depth become the parallel tasks.
constexpr int TaskDepth = 6;
/// Angular margin of a decision (radians). A decided vertex has
/// |g| >= sin(Margin) |N| |E - V| / (1 + sqrt 3) (the 4D map scales by at
/// most 1 + |v|, |v| <= sqrt 3), about 3.7e-8 |N| |E - V|, against a rounding
/// error of the direct dot product below 1e-15 |N| |E - V| and angle errors of
/// the tree's own arithmetic of the same order.
constexpr double Margin = 1e-7;
/// Normals and positions outside these magnitudes are evaluated directly (no
/// overflow or underflow can reach the margin's scale inside them).
constexpr double SmallestNormal = 1e-100;
constexpr double LargestNormal = 1e100;
constexpr double LargestCoordinate = 1e140;
constexpr double SmallestHalfExtent = 1e-140;
constexpr double HalfPi = 1.57079632679489661923;

bool isFinite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

double maxAbs(const glm::dvec3& v)
{
  return std::max({ std::abs(v.x), std::abs(v.y), std::abs(v.z) });
}

// Unit vector of a non-zero finite 4D vector, without overflow or underflow.
glm::dvec4 unit(glm::dvec4 v)
{
  const double m = std::max({ std::abs(v.x), std::abs(v.y), std::abs(v.z), std::abs(v.w) });
  v /= m;
  return v / std::sqrt(glm::dot(v, v));
}

// The angle between unit vectors, accurate near 0 and pi too.
double angleBetween(const glm::dvec4& a, const glm::dvec4& b)
{
  const double d = glm::dot(a, b);
  const glm::dvec4 p = b - d * a;
  return std::atan2(std::sqrt(glm::dot(p, p)), d);
}

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
    const double length = isFinite(normal) ? maxAbs(normal) : 0.0;
    if (!isFinite(points[i]) || maxAbs(points[i]) > LargestCoordinate ||
      !(length >= SmallestNormal && length <= LargestNormal))
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

  // Perspective conditioning: centre on the box, scale by a power of two
  // (exact) at least half its largest side, so that |v| <= sqrt 3.
  this->Centre = 0.5 * lo + 0.5 * hi;
  const double halfExtent = 0.5 * std::max({ hi.x - lo.x, hi.y - lo.y, hi.z - lo.z });
  int exponent = 0;
  if (halfExtent > 0.0)
  {
    std::frexp(halfExtent, &exponent); // halfExtent < 2^exponent
  }
  this->InverseScale = std::ldexp(1.0, -exponent);
  const bool perspectiveTree = halfExtent == 0.0 || halfExtent >= SmallestHalfExtent;

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
      const glm::dvec3 n = normals[i] / maxAbs(normals[i]);
      const glm::dvec3 unitNormal = n / std::sqrt(glm::dot(n, n));
      tree->Normals.push_back(normals[i]);
      if (perspective)
      {
        tree->Points.push_back(points[i]);
        const glm::dvec3 v = (points[i] - this->Centre) * this->InverseScale;
        vectors.push_back(unit(glm::dvec4(unitNormal, -glm::dot(unitNormal, v))));
      }
      else
      {
        vectors.emplace_back(unitNormal, 0.0);
      }
    }
    if (!perspective || perspectiveTree)
    {
      buildTree(*tree, vectors);
    }
  }
}

void VisibilityHierarchy::buildTree(Tree& tree, const std::vector<glm::dvec4>& vectors)
{
  const std::size_t n = vectors.size();
  if (n == 0)
  {
    return;
  }
  // The vectors travel with their slot through the splits (sequential memory).
  struct Item
  {
    glm::dvec4 U;
    std::uint32_t Slot;
  };
  std::vector<Item> items(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    items[k] = { vectors[k], static_cast<std::uint32_t>(k) };
  }
  tree.Nodes.clear();
  tree.Nodes.emplace_back();
  tree.Nodes[0].Begin = 0;
  tree.Nodes[0].End = static_cast<std::uint32_t>(n);
  std::vector<int> depth{ 0 };
  for (std::size_t index = 0; index < tree.Nodes.size(); ++index)
  {
    const std::uint32_t begin = tree.Nodes[index].Begin;
    const std::uint32_t end = tree.Nodes[index].End;

    glm::dvec4 low = items[begin].U;
    glm::dvec4 high = low;
    for (std::uint32_t k = begin; k < end; ++k)
    {
      low = glm::min(low, items[k].U);
      high = glm::max(high, items[k].U);
    }

    // Split at the median of the widest coordinate, unless small or flat.
    const glm::dvec4 extent = high - low;
    int dim = 0;
    for (int d = 1; d < 4; ++d)
    {
      if (extent[d] > extent[dim])
      {
        dim = d;
      }
    }
    if (end - begin <= LeafSize || !(extent[dim] > 0.0))
    {
      continue;
    }
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
      [dim](const Item& a, const Item& b) { return a.U[dim] < b.U[dim]; });
    const std::int32_t first = static_cast<std::int32_t>(tree.Nodes.size());
    tree.Nodes[index].FirstChild = first;
    Node left;
    left.Begin = begin;
    left.End = middle;
    Node right;
    right.Begin = middle;
    right.End = end;
    tree.Nodes.push_back(left);
    tree.Nodes.push_back(right);
    depth.push_back(depth[index] + 1);
    depth.push_back(depth[index] + 1);
  }

  // Bounding cones, bottom-up (children follow their parent): the axis is the
  // mean direction. A leaf's half-angle is the largest angle to a member; a
  // parent's bounds the children's cones (angles obey the triangle
  // inequality on the sphere), looser than from the members but linear time.
  std::vector<glm::dvec4> sums(tree.Nodes.size(), glm::dvec4(0.0));
  for (std::size_t index = tree.Nodes.size(); index-- > 0;)
  {
    Node& node = tree.Nodes[index];
    const bool leaf = node.FirstChild < 0;
    const std::size_t first = static_cast<std::size_t>(node.FirstChild);
    if (leaf)
    {
      for (std::uint32_t k = node.Begin; k < node.End; ++k)
      {
        sums[index] += items[k].U;
      }
    }
    else
    {
      sums[index] = sums[first] + sums[first + 1];
    }
    const double sumLength = std::sqrt(glm::dot(sums[index], sums[index]));
    if (!(sumLength > 1e-9 * (node.End - node.Begin)))
    {
      continue; // no useful axis: never decided (HalfAngle stays > pi)
    }
    node.Axis = sums[index] / sumLength;
    double halfAngle = 0.0;
    if (leaf)
    {
      for (std::uint32_t k = node.Begin; k < node.End; ++k)
      {
        halfAngle = std::max(halfAngle, angleBetween(node.Axis, items[k].U));
      }
    }
    else
    {
      for (std::size_t c = first; c < first + 2; ++c)
      {
        halfAngle = std::max(
          halfAngle, angleBetween(node.Axis, tree.Nodes[c].Axis) + tree.Nodes[c].HalfAngle);
      }
    }
    node.HalfAngle = halfAngle;
  }

  // Nodes are in breadth-first order: the tasks are the nodes at TaskDepth
  // and the leaves above it.
  for (std::size_t index = 0; index < tree.Nodes.size(); ++index)
  {
    if (depth[index] == TaskDepth || (depth[index] < TaskDepth && tree.Nodes[index].FirstChild < 0))
    {
      tree.Tasks.push_back(static_cast<std::int32_t>(index));
    }
  }

  // Store the vertices in tree order.
  std::vector<std::uint32_t> order(n);
  std::vector<glm::dvec3> normals(n);
  std::vector<glm::dvec3> points(tree.Points.empty() ? 0 : n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::uint32_t slot = items[k].Slot;
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
    const Node& node = tree.Nodes[static_cast<std::size_t>(stack[--top])];
    ++statistics.VisitedNodes;
    double decided = 0.0;
    if (node.HalfAngle < HalfPi)
    {
      const double angle = angleBetween(node.Axis, query);
      if (angle + node.HalfAngle < HalfPi - Margin)
      {
        decided = 1.0;
      }
      else if (angle - node.HalfAngle > HalfPi + Margin)
      {
        decided = -1.0;
      }
    }
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
  bool useTree = !tree.Nodes.empty();
  glm::dvec4 query(0.0);
  if (view.Parallel)
  {
    const double m = isFinite(view.TowardViewer) ? maxAbs(view.TowardViewer) : 0.0;
    useTree = useTree && m >= SmallestNormal && m <= LargestNormal;
    if (useTree)
    {
      query = unit(glm::dvec4(view.TowardViewer, 0.0));
    }
  }
  else
  {
    useTree = useTree && isFinite(view.Eye) && maxAbs(view.Eye) <= LargestCoordinate;
    if (useTree)
    {
      query = unit(glm::dvec4((view.Eye - this->Centre) * this->InverseScale, 1.0));
    }
  }

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
