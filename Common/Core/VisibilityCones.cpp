#include "VisibilityCones.h"

#include <algorithm>
#include <cmath>

namespace silsmooth
{
namespace visibility_cones
{
namespace
{

constexpr std::size_t LeafSize = 32;
/// Subtrees of about this many nodes' depth become the parallel tasks.
constexpr int TaskDepth = 6;

// The keys travel with their item through the splits (sequential memory).
// 48 bytes without padding: with a 4-byte index the swaps of the splits
// copied the struct in overlapping pieces that stalled on the stack.
struct Item
{
  glm::dvec4 U;
  double Radius;
  std::uint64_t Index;
};

// Median splits along the widest coordinate, breadth first, down to leaves
// of at most LeafSize items; the depth of every node.
std::vector<int> splitNodes(std::vector<Item>& items, ConeTree& tree)
{
  tree.Nodes.emplace_back();
  tree.Nodes[0].Begin = 0;
  tree.Nodes[0].End = static_cast<std::uint32_t>(items.size());
  std::vector<int> depth{ 0 };
  for (std::size_t index = 0; index < tree.Nodes.size(); ++index)
  {
    const std::uint32_t begin = tree.Nodes[index].Begin;
    const std::uint32_t end = tree.Nodes[index].End;

    // The extent of a large node from about 1024 of its items: the split
    // only needs a wide coordinate, not the widest exactly (the cones below
    // bound every member whatever the split), and a pass over every item
    // at every level was most of the build.
    const std::uint32_t stride = std::max<std::uint32_t>(1, (end - begin) / 1024);
    glm::dvec4 low = items[begin].U;
    glm::dvec4 high = low;
    for (std::uint32_t k = begin; k < end; k += stride)
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
    ConeNode left;
    left.Begin = begin;
    left.End = middle;
    ConeNode right;
    right.Begin = middle;
    right.End = end;
    tree.Nodes.push_back(left);
    tree.Nodes.push_back(right);
    depth.push_back(depth[index] + 1);
    depth.push_back(depth[index] + 1);
  }
  return depth;
}

// Bounding cones, bottom-up (children follow their parent): the axis is the
// mean direction. A leaf's half-angle is the largest angle to a member's
// cap; a parent's bounds the children's cones (angles obey the triangle
// inequality on the sphere), looser than from the members but linear time.
void boundCones(const std::vector<Item>& items, ConeTree& tree)
{
  std::vector<glm::dvec4> sums(tree.Nodes.size(), glm::dvec4(0.0));
  for (std::size_t index = tree.Nodes.size(); index-- > 0;)
  {
    ConeNode& node = tree.Nodes[index];
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
        halfAngle = std::max(halfAngle, angleBetween(node.Axis, items[k].U) + items[k].Radius);
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
}

} // namespace

ConeTree buildConeTree(const std::vector<glm::dvec4>& keys, const std::vector<double>& radii)
{
  ConeTree tree;
  const std::size_t n = keys.size();
  if (n == 0)
  {
    return tree;
  }
  std::vector<Item> items(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    items[k] = { keys[k], radii.empty() ? 0.0 : radii[k], k };
  }
  const std::vector<int> depth = splitNodes(items, tree);
  boundCones(items, tree);
  // Nodes are in breadth-first order: the tasks are the nodes at TaskDepth
  // and the leaves above it.
  for (std::size_t index = 0; index < tree.Nodes.size(); ++index)
  {
    if (depth[index] == TaskDepth || (depth[index] < TaskDepth && tree.Nodes[index].FirstChild < 0))
    {
      tree.Tasks.push_back(static_cast<std::int32_t>(index));
    }
  }
  tree.Items.resize(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    tree.Items[k] = static_cast<std::uint32_t>(items[k].Index);
  }
  return tree;
}

} // namespace visibility_cones
} // namespace silsmooth
