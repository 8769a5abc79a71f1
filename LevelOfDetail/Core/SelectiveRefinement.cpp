#include "SelectiveRefinement.h"

#include <algorithm>
#include <stdexcept>

namespace silsmooth
{

void SelectiveRefinement::IndexSet::insert(Index i)
{
  Index& where = this->Where[static_cast<std::size_t>(i)];
  if (where >= 0)
    return;
  where = static_cast<Index>(this->Items.size());
  this->Items.push_back(i);
}

void SelectiveRefinement::IndexSet::erase(Index i)
{
  Index& where = this->Where[static_cast<std::size_t>(i)];
  if (where < 0)
    return;
  const Index last = this->Items.back();
  this->Items[static_cast<std::size_t>(where)] = last;
  this->Where[static_cast<std::size_t>(last)] = where;
  this->Items.pop_back();
  where = -1;
}

SelectiveRefinement::SelectiveRefinement(const VertexHierarchy& hierarchy)
  : Hierarchy(hierarchy)
  , Positions(hierarchy.basePositions())
  , Normals(hierarchy.baseNormals())
  , Corners(hierarchy.baseCorners())
  , FacesOf(hierarchy.basePositions().size())
  , Applied(hierarchy.nodeCount(), 0)
  , UnappliedParents(hierarchy.nodeCount(), 0)
  , AppliedChildren(hierarchy.nodeCount(), 0)
  , Active(hierarchy.faceCount())
  , NextSplits(hierarchy.nodeCount())
  , Undoable(hierarchy.nodeCount())
{
  for (const Index face : hierarchy.baseFaces())
    this->addFace(face);
  for (std::size_t j = 0; j < hierarchy.nodeCount(); ++j)
  {
    const Index node = static_cast<Index>(j);
    this->UnappliedParents[j] =
      static_cast<Index>(hierarchy.parentsEnd(node) - hierarchy.parentsBegin(node));
  }
  for (const Index root : hierarchy.rootSplits())
    this->NextSplits.insert(root);
}

void SelectiveRefinement::addFace(Index face)
{
  this->Active.insert(face);
  for (const Id v : this->Corners[static_cast<std::size_t>(face)])
    this->FacesOf[static_cast<std::size_t>(v)].push_back(face);
}

void SelectiveRefinement::removeFace(Index face)
{
  this->Active.erase(face);
  for (const Id v : this->Corners[static_cast<std::size_t>(face)])
  {
    std::vector<Index>& list = this->FacesOf[static_cast<std::size_t>(v)];
    list.erase(std::find(list.begin(), list.end(), face));
  }
}

void SelectiveRefinement::renameCorner(Index face, Id from, Id to)
{
  for (Id& v : this->Corners[static_cast<std::size_t>(face)])
    v = v == from ? to : v;
  std::vector<Index>& list = this->FacesOf[static_cast<std::size_t>(from)];
  list.erase(std::find(list.begin(), list.end(), face));
  this->FacesOf[static_cast<std::size_t>(to)].push_back(face);
}

Id SelectiveRefinement::sharedPoint(Index a, Index b, Id kept) const
{
  const Triangle& ta = this->corners(a);
  const Triangle& tb = this->corners(b);
  for (const Id v : ta)
  {
    if (v != kept && (tb[0] == v || tb[1] == v || tb[2] == v))
      return v;
  }
  throw std::logic_error("a split's neighbour faces do not meet");
}

void SelectiveRefinement::fanBetween(
  Id kept, Index first, Index last, Id wedge, std::vector<Index>& fan) const
{
  const std::vector<Index>& around = this->FacesOf[static_cast<std::size_t>(kept)];
  fan.clear();
  Index face = first;
  Id previous = wedge;
  while (true)
  {
    fan.push_back(face);
    if (face == last)
      return;
    if (fan.size() > around.size())
      throw std::logic_error("a split's fan does not close");
    // Step across the face's other edge at `kept`.
    const Triangle& t = this->corners(face);
    Id next = kept;
    for (const Id v : t)
      next = (v != kept && v != previous) ? v : next;
    Index following = VertexHierarchy::None;
    for (const Index other : around)
    {
      const Triangle& o = this->corners(other);
      if (other != face && (o[0] == next || o[1] == next || o[2] == next))
        following = other;
    }
    if (following == VertexHierarchy::None)
      throw std::logic_error("a split's fan is open");
    previous = next;
    face = following;
  }
}

void SelectiveRefinement::apply(Index node)
{
  const VertexHierarchy& h = this->Hierarchy;
  const VertexHierarchy::Node& n = h.node(node);
  const std::array<Index, 4>& fn = n.Neighbours;
  const Id left = this->sharedPoint(fn[0], fn[1], n.Kept);
  const Id right = this->sharedPoint(fn[2], fn[3], n.Kept);
  this->fanBetween(n.Kept, fn[1], fn[3], left, this->Fan);
  for (const Index face : this->Fan)
    this->renameCorner(face, n.Kept, n.Removed);
  const Id roleLeft[3] = { n.Kept, n.Removed, left };
  const Id roleRight[3] = { n.Kept, n.Removed, right };
  for (std::size_t k = 0; k < 3; ++k)
  {
    this->Corners[static_cast<std::size_t>(n.LeftFace)][k] = roleLeft[n.LeftRoles[k]];
    this->Corners[static_cast<std::size_t>(n.RightFace)][k] = roleRight[n.RightRoles[k]];
  }
  this->addFace(n.LeftFace);
  this->addFace(n.RightFace);
  this->Positions[static_cast<std::size_t>(n.Kept)] = n.KeptFine;
  this->Positions[static_cast<std::size_t>(n.Removed)] = n.RemovedFine;
  this->Normals[static_cast<std::size_t>(n.Kept)] = n.KeptFineNormal;
  this->Normals[static_cast<std::size_t>(n.Removed)] = n.RemovedFineNormal;
  this->Applied[static_cast<std::size_t>(node)] = 1;
  ++this->AppliedNodes;
  this->NextSplits.erase(node);
  for (const Index next : { n.NextSplitOfKept, n.FirstSplitOfRemoved })
  {
    if (next >= 0)
      this->NextSplits.insert(next);
  }
  this->Undoable.insert(node);
  for (auto p = h.parentsBegin(node); p != h.parentsEnd(node); ++p)
  {
    if (this->AppliedChildren[static_cast<std::size_t>(*p)]++ == 0)
      this->Undoable.erase(*p);
  }
  for (auto c = h.childrenBegin(node); c != h.childrenEnd(node); ++c)
    --this->UnappliedParents[static_cast<std::size_t>(*c)];
}

void SelectiveRefinement::undo(Index node)
{
  const VertexHierarchy& h = this->Hierarchy;
  const VertexHierarchy::Node& n = h.node(node);
  this->removeFace(n.LeftFace);
  this->removeFace(n.RightFace);
  this->Fan = this->FacesOf[static_cast<std::size_t>(n.Removed)];
  for (const Index face : this->Fan)
    this->renameCorner(face, n.Removed, n.Kept);
  this->Positions[static_cast<std::size_t>(n.Kept)] = n.KeptCoarse;
  this->Normals[static_cast<std::size_t>(n.Kept)] = n.KeptCoarseNormal;
  this->Applied[static_cast<std::size_t>(node)] = 0;
  --this->AppliedNodes;
  this->Undoable.erase(node);
  for (const Index next : { n.NextSplitOfKept, n.FirstSplitOfRemoved })
  {
    if (next >= 0)
      this->NextSplits.erase(next);
  }
  this->NextSplits.insert(node);
  for (auto p = h.parentsBegin(node); p != h.parentsEnd(node); ++p)
  {
    if (--this->AppliedChildren[static_cast<std::size_t>(*p)] == 0)
      this->Undoable.insert(*p);
  }
  for (auto c = h.childrenBegin(node); c != h.childrenEnd(node); ++c)
    ++this->UnappliedParents[static_cast<std::size_t>(*c)];
}

AdaptStatistics SelectiveRefinement::adapt(const RefinementTest& test)
{
  const VertexHierarchy& h = this->Hierarchy;
  AdaptStatistics statistics;
  // 1. Coarsen: the worklist starts as the undoable front; undoing a node may
  // make its parents undoable.
  std::vector<Index> work(this->Undoable.items());
  while (!work.empty())
  {
    const Index node = work.back();
    work.pop_back();
    if (!this->Undoable.contains(node))
      continue;
    ++statistics.Evaluated;
    if (test.keeps(node))
      continue;
    this->undo(node);
    ++statistics.Undone;
    for (auto p = h.parentsBegin(node); p != h.parentsEnd(node); ++p)
    {
      if (this->Undoable.contains(*p))
        work.push_back(*p);
    }
  }
  // 2. Refine: the worklist starts as every point's next split; applying a
  // node (and each parent it needed) adds the next splits of its two points.
  work = this->NextSplits.items();
  std::vector<Index> applied;
  while (!work.empty())
  {
    const Index node = work.back();
    work.pop_back();
    if (this->isApplied(node))
      continue;
    ++statistics.Evaluated;
    if (!test.needs(node))
      continue;
    applied.clear();
    this->applyWithParents(node, applied);
    statistics.Applied += applied.size();
    statistics.Forced += applied.size() - 1;
    for (const Index a : applied)
    {
      const VertexHierarchy::Node& n = h.node(a);
      for (const Index next : { n.NextSplitOfKept, n.FirstSplitOfRemoved })
      {
        if (next >= 0)
          work.push_back(next);
      }
    }
  }
  return statistics;
}

void SelectiveRefinement::applyWithParents(Index node, std::vector<Index>& applied)
{
  const VertexHierarchy& h = this->Hierarchy;
  std::vector<Index> stack{ node };
  while (!stack.empty())
  {
    const Index top = stack.back();
    if (this->isApplied(top))
    {
      stack.pop_back();
      continue;
    }
    if (this->UnappliedParents[static_cast<std::size_t>(top)] > 0)
    {
      for (auto p = h.parentsBegin(top); p != h.parentsEnd(top); ++p)
      {
        if (!this->isApplied(*p))
          stack.push_back(*p);
      }
      continue;
    }
    this->apply(top);
    applied.push_back(top);
    stack.pop_back();
  }
}

void SelectiveRefinement::applyAll()
{
  struct Everything : RefinementTest
  {
    bool needs(Index) const override { return true; }
  };
  this->adapt(Everything());
}

void SelectiveRefinement::undoAll()
{
  struct Nothing : RefinementTest
  {
    bool needs(Index) const override { return false; }
  };
  this->adapt(Nothing());
}

void SelectiveRefinement::extract(ExtractedMesh& mesh) const
{
  std::vector<glm::dvec3>& points = mesh.Points;
  std::vector<glm::vec3>& normals = mesh.Normals;
  std::vector<Triangle>& triangles = mesh.Triangles;
  std::vector<Id>& pointIds = mesh.PointIds;
  std::vector<Id>& triangleIds = mesh.TriangleIds;
  points.clear();
  normals.clear();
  triangles.clear();
  pointIds.clear();
  triangleIds.clear();
  if (this->PointStamp.size() != this->Positions.size())
    this->PointStamp.assign(this->Positions.size(), -1);
  triangles.reserve(this->triangleCount());
  triangleIds.reserve(this->triangleCount());
  for (const Index face : this->Active.items())
  {
    const Triangle& corners = this->corners(face);
    Triangle t;
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t p = static_cast<std::size_t>(corners[k]);
      if (this->PointStamp[p] < 0)
      {
        this->PointStamp[p] = static_cast<Id>(points.size());
        points.push_back(this->Positions[p]);
        normals.push_back(this->Normals[p]);
        pointIds.push_back(corners[k]);
      }
      t[k] = this->PointStamp[p];
    }
    triangles.push_back(t);
    triangleIds.push_back(face);
  }
  // Clean the stamps it set, so the next call costs its mesh, not every point.
  for (const Id p : pointIds)
    this->PointStamp[static_cast<std::size_t>(p)] = -1;
}

} // namespace silsmooth
