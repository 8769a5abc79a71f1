#include "VertexHierarchy.h"

#include "ClosestPoint.h"
#include "ShadingNormals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace silsmooth
{

namespace
{

constexpr double Pi = 3.14159265358979323846;

// Distance from p to triangle (a, b, c).
double pointTriangleDistance(
  const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  return glm::length(p - closestPointOnTriangle(p, a, b, c));
}

} // namespace

void BoundingSphere::add(const glm::dvec3& point)
{
  if (this->Radius < 0.0)
  {
    this->Center = point;
    this->Radius = 0.0;
    return;
  }
  const double distance = glm::length(point - this->Center);
  if (distance <= this->Radius)
    return;
  // Grow towards the point just enough to hold it and the old sphere.
  const double radius = 0.5 * (this->Radius + distance);
  this->Center += (point - this->Center) * ((radius - this->Radius) / distance);
  this->Radius = radius;
}

void BoundingSphere::add(const BoundingSphere& other)
{
  if (other.Radius < 0.0)
    return;
  if (this->Radius < 0.0)
  {
    *this = other;
    return;
  }
  const double distance = glm::length(other.Center - this->Center);
  if (distance + other.Radius <= this->Radius)
    return;
  if (distance + this->Radius <= other.Radius)
  {
    *this = other;
    return;
  }
  const double radius = 0.5 * (distance + this->Radius + other.Radius);
  this->Center += (other.Center - this->Center) * ((radius - this->Radius) / distance);
  this->Radius = radius;
}

void NormalCone::add(const glm::dvec3& unitNormal)
{
  NormalCone single;
  single.Axis = unitNormal;
  single.HalfAngle = 0.0;
  this->add(single);
}

void NormalCone::add(const NormalCone& other)
{
  if (other.HalfAngle < 0.0 || this->HalfAngle >= Pi)
    return;
  if (this->HalfAngle < 0.0 || other.HalfAngle >= Pi)
  {
    *this = other;
    return;
  }
  const double between = std::acos(std::clamp(glm::dot(this->Axis, other.Axis), -1.0, 1.0));
  if (between + other.HalfAngle <= this->HalfAngle)
    return;
  if (between + this->HalfAngle <= other.HalfAngle)
  {
    *this = other;
    return;
  }
  const double halfAngle = 0.5 * (between + this->HalfAngle + other.HalfAngle);
  const glm::dvec3 across = other.Axis - glm::dot(other.Axis, this->Axis) * this->Axis;
  const double acrossLength = glm::length(across);
  if (halfAngle >= Pi || !(acrossLength > 1e-12))
  {
    this->HalfAngle = Pi; // opposite axes: every direction
    return;
  }
  // Turn the axis towards the other cone's by what the half-angle grew.
  const double turn = halfAngle - this->HalfAngle;
  this->Axis =
    glm::normalize(std::cos(turn) * this->Axis + std::sin(turn) * (across / acrossLength));
  // A little slack so that rounding never leaves a merged cone short.
  this->HalfAngle = std::min(Pi, halfAngle + 1e-9);
}

// Clusters whose normals are further apart than this (45 degrees) lie on two
// sides of a crease: their normals are not summed.
constexpr float CreaseCosine = 0.70710678f;

// Replays the collapse sequence on the input, fine to coarse, recording for
// each collapse the split that undoes it.
class VertexHierarchyBuilder
{
public:
  using Index = VertexHierarchy::Index;

  VertexHierarchyBuilder(VertexHierarchy& out, const std::vector<glm::dvec3>& points,
    const std::vector<Triangle>& triangles, std::vector<glm::dvec3> pointNormals)
    : Out(out)
    , Positions(points)
    , PointNormals(std::move(pointNormals))
    , Corners(triangles)
    , FacesOf(points.size())
    , LastSplitOf(points.size(), VertexHierarchy::None)
    , NeighbourUsers(triangles.size())
  {
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      if (hasRepeatedCorner(triangles[t]))
        continue;
      for (const Id v : triangles[t])
      {
        if (v < 0 || static_cast<std::size_t>(v) >= points.size())
          throw std::invalid_argument("triangle " + std::to_string(t) + " names a missing point");
        this->FacesOf[static_cast<std::size_t>(v)].push_back(static_cast<Index>(t));
      }
    }
    if (this->PointNormals.size() != points.size())
      this->PointNormals = angleWeightedNormals(points, triangles);
    this->NormalSums = this->PointNormals;
  }

  void collapse(const CollapseRecord& record)
  {
    const Index j = static_cast<Index>(this->Out.Nodes.size());
    this->checkRecord(record);
    VertexHierarchy::Node node;
    node.Kept = record.Kept;
    node.Removed = record.Removed;
    node.KeptFine = this->position(record.Kept);
    node.KeptCoarse = record.Position;
    node.RemovedFine = this->position(record.Removed);
    node.KeptFineNormal = this->clusterNormal(record.Kept);
    node.RemovedFineNormal = this->clusterNormal(record.Removed);
    // Across a crease (the two sides' normals more than 45 degrees apart)
    // the kept vertex keeps its side's normal: a sum of both would shade
    // each side as the other.
    if (glm::dot(node.KeptFineNormal, node.RemovedFineNormal) >= CreaseCosine)
    {
      this->NormalSums[static_cast<std::size_t>(record.Kept)] +=
        this->NormalSums[static_cast<std::size_t>(record.Removed)];
    }
    node.KeptCoarseNormal = this->clusterNormal(record.Kept);
    this->findFaces(node);
    for (const Id end : { node.Kept, node.Removed })
    {
      for (const Index face : this->FacesOf[static_cast<std::size_t>(end)])
        this->addToBounds(node, face);
    }
    std::vector<Index> children = this->childrenOf(node);
    for (const Index face : node.Neighbours)
      this->NeighbourUsers[static_cast<std::size_t>(face)].push_back(j);

    this->applyCollapse(node, record.Position);
    for (const Index face : this->FacesOf[static_cast<std::size_t>(node.Kept)])
      this->addToBounds(node, face);
    node.NextSplitOfKept = this->LastSplitOf[static_cast<std::size_t>(node.Kept)];
    node.FirstSplitOfRemoved = this->LastSplitOf[static_cast<std::size_t>(node.Removed)];
    this->LastSplitOf[static_cast<std::size_t>(node.Kept)] = j;
    this->finishNode(node);
    appendRow(this->Out.Children, children);
    this->Out.Nodes.push_back(node);
  }

  void finish()
  {
    VertexHierarchy& out = this->Out;
    out.BaseCorners = this->Corners;
    for (std::size_t v = 0; v < this->FacesOf.size(); ++v)
    {
      for (const Index face : this->FacesOf[v])
      {
        if (this->Corners[static_cast<std::size_t>(face)][0] == static_cast<Id>(v))
          out.BaseFaces.push_back(face);
      }
      if (this->LastSplitOf[v] >= 0 && !this->FacesOf[v].empty())
        out.Roots.push_back(this->LastSplitOf[v]);
    }
    std::sort(out.BaseFaces.begin(), out.BaseFaces.end());
    out.BasePositions = this->Positions;
    out.BaseNormals.resize(this->NormalSums.size());
    for (std::size_t v = 0; v < this->NormalSums.size(); ++v)
      out.BaseNormals[v] = this->clusterNormal(static_cast<Id>(v));
    out.PointNormals = std::move(this->PointNormals);
    buildParents(out);
  }

private:
  const glm::dvec3& position(Id v) const { return this->Positions[static_cast<std::size_t>(v)]; }
  // The unit sum of the input normals of the points v stands for now: the
  // surface's normal about where the collapses placed v (a merged vertex
  // keeps no input point's position, so no input point's normal suits it;
  // on a sphere those were up to 16 degrees off). A sum that cancels keeps
  // v's own input normal.
  glm::vec3 clusterNormal(Id v) const
  {
    const glm::dvec3& sum = this->NormalSums[static_cast<std::size_t>(v)];
    const double length = glm::length(sum);
    return glm::vec3(length > 1e-12 && std::isfinite(length)
        ? sum / length
        : this->PointNormals[static_cast<std::size_t>(v)]);
  }
  const Triangle& corners(Index face) const
  {
    return this->Corners[static_cast<std::size_t>(face)];
  }
  bool has(Index face, Id v) const
  {
    const Triangle& t = this->corners(face);
    return t[0] == v || t[1] == v || t[2] == v;
  }

  void checkRecord(const CollapseRecord& record) const
  {
    const auto valid = [this](Id v) {
      return v >= 0 && static_cast<std::size_t>(v) < this->Positions.size() &&
        !this->FacesOf[static_cast<std::size_t>(v)].empty();
    };
    if (record.Kept == record.Removed || !valid(record.Kept) || !valid(record.Removed))
    {
      throw std::invalid_argument("collapse " + std::to_string(this->Out.Nodes.size()) +
        " does not join two points of the mesh");
    }
  }

  [[noreturn]] void notAnInteriorEdge() const
  {
    throw std::invalid_argument("collapse " + std::to_string(this->Out.Nodes.size()) +
      " is not along an edge of exactly two triangles with neighbours");
  }

  // The face at `end` other than `face` that also has `wedge`: across the edge (end, wedge).
  Index across(Index face, Id end, Id wedge) const
  {
    for (const Index other : this->FacesOf[static_cast<std::size_t>(end)])
    {
      if (other != face && this->has(other, wedge))
        return other;
    }
    this->notAnInteriorEdge();
  }

  // The edge's two faces (the left one has the edge from Kept to Removed in its
  // corner order), their corner roles, and their four neighbours.
  void findFaces(VertexHierarchy::Node& node) const
  {
    std::vector<Index> onEdge;
    for (const Index face : this->FacesOf[static_cast<std::size_t>(node.Kept)])
    {
      if (this->has(face, node.Removed))
        onEdge.push_back(face);
    }
    if (onEdge.size() != 2)
      this->notAnInteriorEdge();
    const Triangle& first = this->corners(onEdge[0]);
    bool firstIsLeft = false;
    for (std::size_t k = 0; k < 3; ++k)
      firstIsLeft = firstIsLeft || (first[k] == node.Kept && first[(k + 1) % 3] == node.Removed);
    node.LeftFace = firstIsLeft ? onEdge[0] : onEdge[1];
    node.RightFace = firstIsLeft ? onEdge[1] : onEdge[0];
    const Id left = this->wedgeOf(node.LeftFace, node, node.LeftRoles);
    const Id right = this->wedgeOf(node.RightFace, node, node.RightRoles);
    if (left == right)
      this->notAnInteriorEdge();
    node.Neighbours = { this->across(node.LeftFace, node.Kept, left),
      this->across(node.LeftFace, node.Removed, left),
      this->across(node.RightFace, node.Kept, right),
      this->across(node.RightFace, node.Removed, right) };
  }

  Id wedgeOf(Index face, const VertexHierarchy::Node& node,
    std::array<VertexHierarchy::CornerRole, 3>& roles) const
  {
    Id wedge = node.Kept;
    const Triangle& t = this->corners(face);
    for (std::size_t k = 0; k < 3; ++k)
    {
      roles[k] = t[k] == node.Kept ? VertexHierarchy::KeptCorner
        : t[k] == node.Removed     ? VertexHierarchy::RemovedCorner
                                   : VertexHierarchy::WedgeCorner;
      wedge = roles[k] == VertexHierarchy::WedgeCorner ? t[k] : wedge;
    }
    return wedge;
  }

  // In the tree: the previous splits of both points; and every split that
  // needs one of the two faces as a neighbour.
  std::vector<Index> childrenOf(const VertexHierarchy::Node& node) const
  {
    std::vector<Index> children;
    for (const Id end : { node.Kept, node.Removed })
    {
      if (this->LastSplitOf[static_cast<std::size_t>(end)] >= 0)
        children.push_back(this->LastSplitOf[static_cast<std::size_t>(end)]);
    }
    for (const Index face : { node.LeftFace, node.RightFace })
    {
      const std::vector<Index>& users = this->NeighbourUsers[static_cast<std::size_t>(face)];
      children.insert(children.end(), users.begin(), users.end());
    }
    std::sort(children.begin(), children.end());
    children.erase(std::unique(children.begin(), children.end()), children.end());
    return children;
  }

  void eraseFace(Id v, Index face)
  {
    std::vector<Index>& list = this->FacesOf[static_cast<std::size_t>(v)];
    list.erase(std::remove(list.begin(), list.end(), face), list.end());
  }

  void applyCollapse(const VertexHierarchy::Node& node, const glm::dvec3& position)
  {
    for (const Index face : { node.LeftFace, node.RightFace })
    {
      for (const Id v : this->corners(face))
      {
        if (v != node.Removed)
          this->eraseFace(v, face);
      }
    }
    for (const Index face : this->FacesOf[static_cast<std::size_t>(node.Removed)])
    {
      if (face == node.LeftFace || face == node.RightFace)
        continue;
      for (Id& v : this->Corners[static_cast<std::size_t>(face)])
        v = v == node.Removed ? node.Kept : v;
      this->FacesOf[static_cast<std::size_t>(node.Kept)].push_back(face);
    }
    this->FacesOf[static_cast<std::size_t>(node.Removed)].clear();
    this->Positions[static_cast<std::size_t>(node.Kept)] = position;
  }

  void addToBounds(VertexHierarchy::Node& node, Index face)
  {
    const Triangle& t = this->corners(face);
    const glm::dvec3& a = this->position(t[0]);
    const glm::dvec3& b = this->position(t[1]);
    const glm::dvec3& c = this->position(t[2]);
    node.Bound.add(a);
    node.Bound.add(b);
    node.Bound.add(c);
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    const double length = glm::length(normal);
    if (length > 0.0 && std::isfinite(length))
      node.Normals.add(normal / length);
    for (const Id p : t)
    {
      const glm::dvec3& pointNormal = this->PointNormals[static_cast<std::size_t>(p)];
      const double pointLength = glm::length(pointNormal);
      if (pointLength > 0.0 && std::isfinite(pointLength))
        node.Normals.add(pointNormal / pointLength);
    }
  }

  // The split's own error (its two fine points against the coarse star of
  // Kept) plus its tree children's, and their bounds.
  void finishNode(VertexHierarchy::Node& node) const
  {
    double own = 0.0;
    for (const glm::dvec3& fine : { node.KeptFine, node.RemovedFine })
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Index face : this->FacesOf[static_cast<std::size_t>(node.Kept)])
      {
        const Triangle& t = this->corners(face);
        nearest = std::min(nearest,
          pointTriangleDistance(
            fine, this->position(t[0]), this->position(t[1]), this->position(t[2])));
      }
      own = std::max(own, std::isfinite(nearest) ? nearest : 0.0);
    }
    double childError = 0.0;
    for (const Index child : { node.NextSplitOfKept, node.FirstSplitOfRemoved })
    {
      if (child < 0)
        continue;
      const VertexHierarchy::Node& c = this->Out.Nodes[static_cast<std::size_t>(child)];
      node.Bound.add(c.Bound);
      node.Normals.add(c.Normals);
      childError = std::max(childError, c.Error);
    }
    node.Error = own + childError;
  }

  static void appendRow(VertexHierarchy::Table& table, const std::vector<Index>& row)
  {
    table.Items.insert(table.Items.end(), row.begin(), row.end());
    table.Offsets.push_back(table.Items.size());
  }

  static void buildParents(VertexHierarchy& out)
  {
    const std::size_t n = out.Nodes.size();
    out.Parents.Offsets.assign(n + 1, 0);
    for (std::size_t j = 0; j < n; ++j)
    {
      for (auto c = out.childrenBegin(Index(j)); c != out.childrenEnd(Index(j)); ++c)
        ++out.Parents.Offsets[static_cast<std::size_t>(*c) + 1];
    }
    for (std::size_t j = 0; j < n; ++j)
      out.Parents.Offsets[j + 1] += out.Parents.Offsets[j];
    out.Parents.Items.assign(out.Parents.Offsets[n], 0);
    std::vector<std::size_t> next(out.Parents.Offsets.begin(), out.Parents.Offsets.end() - 1);
    for (std::size_t j = 0; j < n; ++j)
    {
      for (auto c = out.childrenBegin(Index(j)); c != out.childrenEnd(Index(j)); ++c)
        out.Parents.Items[next[static_cast<std::size_t>(*c)]++] = Index(j);
    }
  }

  VertexHierarchy& Out;
  std::vector<glm::dvec3> Positions;
  std::vector<glm::dvec3> PointNormals;
  std::vector<glm::dvec3> NormalSums; // per point: its cluster's input normals summed
  std::vector<Triangle> Corners;
  std::vector<std::vector<Index>> FacesOf; // per point: the live faces at it
  std::vector<Index> LastSplitOf;          // per point: the last collapse that kept it, so far
  std::vector<std::vector<Index>> NeighbourUsers; // per face: splits with it as a neighbour
};

VertexHierarchy::VertexHierarchy(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<CollapseRecord>& sequence,
  std::vector<glm::dvec3> pointNormals, const ProgressCallback& progress)
{
  VertexHierarchyBuilder builder(*this, points, triangles, std::move(pointNormals));
  this->Nodes.reserve(sequence.size());
  for (std::size_t j = 0; j < sequence.size(); ++j)
  {
    if (j % 4096 == 0 &&
      !reportProgress(progress, static_cast<double>(j) / static_cast<double>(sequence.size())))
    {
      *this = VertexHierarchy();
      this->Aborted = true;
      return;
    }
    builder.collapse(sequence[j]);
  }
  builder.finish();
}

} // namespace silsmooth
