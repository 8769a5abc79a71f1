#include "FoldGuard.h"

#include "TriangleIntersection.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace silsmooth
{
namespace
{

class FrameGeometry
{
public:
  FrameGeometry(const FoldGuardMesh& mesh, const FoldGuardFrame& frame)
    : Mesh(mesh)
    , Frame(frame)
    , PointCount(static_cast<Id>(mesh.Points.size()))
  {
  }

  // Where input point p was moved to, or nullptr.
  const glm::dvec3* moveOf(Id p) const
  {
    if (p >= this->PointCount || this->Frame.Moved.empty())
    {
      return nullptr;
    }
    const auto it = std::lower_bound(this->Frame.Moved.begin(), this->Frame.Moved.end(), p,
      [](const std::pair<Id, glm::dvec3>& m, Id id) { return m.first < id; });
    return it != this->Frame.Moved.end() && it->first == p ? &it->second : nullptr;
  }

  glm::dvec3 position(Id p) const
  {
    if (p >= this->PointCount)
    {
      return this->Frame.NewPositions[static_cast<std::size_t>(p - this->PointCount)];
    }
    const glm::dvec3* moved = this->moveOf(p);
    return moved ? *moved : this->Mesh.Points[static_cast<std::size_t>(p)];
  }

  glm::dvec3 normal(Id p) const
  {
    return p >= this->PointCount
      ? this->Frame.NewNormals[static_cast<std::size_t>(p - this->PointCount)]
      : this->Mesh.Normals[static_cast<std::size_t>(p)];
  }

  bool isMoved(Id p) const { return this->moveOf(p) != nullptr; }

  TriangleCorners current(const Triangle& t) const
  {
    return TriangleCorners{ { this->position(t[0]), this->position(t[1]), this->position(t[2]) } };
  }

  TriangleCorners prepared(Id t) const
  {
    const Triangle& tri = this->Mesh.Triangles[static_cast<std::size_t>(t)];
    return TriangleCorners{ { this->Mesh.Points[static_cast<std::size_t>(tri[0])],
      this->Mesh.Points[static_cast<std::size_t>(tri[1])],
      this->Mesh.Points[static_cast<std::size_t>(tri[2])] } };
  }

  // Turned over against its input triangle: on the other side of the sum of
  // its corners' shading normals.
  bool turnedOver(const TriangleCorners& c, const Triangle& ids, const TriangleCorners& input) const
  {
    return turnedOverAgainst(
      c, input, this->normal(ids[0]) + this->normal(ids[1]) + this->normal(ids[2]));
  }

  /// The entry of Remeshed for input triangle t, or -1 when t is kept.
  long remeshedIndex(Id t) const
  {
    const auto it = std::lower_bound(this->Frame.Remeshed.begin(), this->Frame.Remeshed.end(), t);
    return it != this->Frame.Remeshed.end() && *it == t
      ? static_cast<long>(it - this->Frame.Remeshed.begin())
      : -1;
  }

  const FoldGuardMesh& Mesh;
  const FoldGuardFrame& Frame;
  const Id PointCount;
};

// A triangle to check: a replacement (Index into Replacements) or a kept
// input triangle with a moved corner (Index = -1).
struct Item
{
  Id Source = -1;
  long Remeshed = -1; // entry of Remeshed, or -1
  long Index = -1;
};

} // namespace

FoldFindings findFolds(
  const FoldGuardMesh& mesh, const FoldGuardFrame& frame, const FoldGuardParallelFor& parallelFor)
{
  const FrameGeometry geometry(mesh, frame);
  std::vector<Item> items;
  for (std::size_t i = 0; i < frame.Remeshed.size(); ++i)
  {
    for (std::size_t r = frame.ReplacementOffsets[i]; r < frame.ReplacementOffsets[i + 1]; ++r)
    {
      items.push_back({ frame.Remeshed[i], static_cast<long>(i), static_cast<long>(r) });
    }
  }
  // Kept triangles around moved points, and in a partial check around the
  // points whose move changed (a triangle that moved back is changed too).
  std::vector<Id> aroundPoints;
  for (const auto& m : frame.Moved)
  {
    aroundPoints.push_back(m.first);
  }
  if (frame.CheckSources && frame.CheckPoints)
  {
    aroundPoints.insert(aroundPoints.end(), frame.CheckPoints->begin(), frame.CheckPoints->end());
    std::sort(aroundPoints.begin(), aroundPoints.end());
    aroundPoints.erase(std::unique(aroundPoints.begin(), aroundPoints.end()), aroundPoints.end());
  }
  if (!aroundPoints.empty())
  {
    std::vector<Id> around;
    std::vector<Id> candidates;
    for (const Id p : aroundPoints)
    {
      const glm::dvec3& at = mesh.Points[static_cast<std::size_t>(p)];
      mesh.Grid.query(at, at, candidates);
      for (const Id t : candidates)
      {
        const Triangle& tri = mesh.Triangles[static_cast<std::size_t>(t)];
        if ((tri[0] == p || tri[1] == p || tri[2] == p) && geometry.remeshedIndex(t) < 0)
        {
          around.push_back(t);
        }
      }
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (const Id t : around)
    {
      items.push_back({ t, -1, -1 });
    }
  }

  auto idsOf = [&](const Item& item) -> const Triangle& {
    return item.Index >= 0 ? frame.Replacements[static_cast<std::size_t>(item.Index)]
                           : mesh.Triangles[static_cast<std::size_t>(item.Source)];
  };

  // The changed triangles where they are now, and a grid of their boxes
  // made for this frame: the prepared grid knows only the input's boxes,
  // which a lifted new triangle or a moved one may leave.
  std::vector<TriangleCorners> corners(items.size());
  std::vector<glm::dvec3> lows(items.size());
  std::vector<glm::dvec3> highs(items.size());
  for (std::size_t k = 0; k < items.size(); ++k)
  {
    corners[k] = geometry.current(idsOf(items[k]));
    lows[k] = glm::min(corners[k].P[0], glm::min(corners[k].P[1], corners[k].P[2]));
    highs[k] = glm::max(corners[k].P[0], glm::max(corners[k].P[1], corners[k].P[2]));
  }
  auto overlap = [](const glm::dvec3& aLow, const glm::dvec3& aHigh, const glm::dvec3& bLow,
                   const glm::dvec3& bHigh) {
    return aLow.x <= bHigh.x && bLow.x <= aHigh.x && aLow.y <= bHigh.y && bLow.y <= aHigh.y &&
      aLow.z <= bHigh.z && bLow.z <= aHigh.z;
  };
  auto hasMovedCorner = [&](const Triangle& t) {
    return !frame.Moved.empty() &&
      (geometry.isMoved(t[0]) || geometry.isMoved(t[1]) || geometry.isMoved(t[2]));
  };

  // Which items to check (all, unless the caller names what changed).
  std::vector<unsigned char> toCheck(items.size(), 1);
  if (frame.CheckSources && frame.CheckPoints)
  {
    for (std::size_t k = 0; k < items.size(); ++k)
    {
      const Triangle& t = idsOf(items[k]);
      toCheck[k] = std::binary_search(
                     frame.CheckSources->begin(), frame.CheckSources->end(), items[k].Source) ||
          std::binary_search(frame.CheckPoints->begin(), frame.CheckPoints->end(), t[0]) ||
          std::binary_search(frame.CheckPoints->begin(), frame.CheckPoints->end(), t[1]) ||
          std::binary_search(frame.CheckPoints->begin(), frame.CheckPoints->end(), t[2])
        ? 1
        : 0;
    }
  }

  // The grid pays off when many triangles are checked; a few (a partial
  // check after the first round) scan the boxes instead.
  const std::size_t checking =
    static_cast<std::size_t>(std::count(toCheck.begin(), toCheck.end(), 1));
  const bool scan = checking <= 64;
  const TriangleGrid changed = scan ? TriangleGrid() : TriangleGrid(lows, highs);
  auto changedCandidates = [&](std::size_t k, std::vector<Id>& out) {
    if (!scan)
    {
      changed.query(lows[k], highs[k], out);
      return;
    }
    out.clear();
    for (std::size_t j = 0; j < items.size(); ++j)
    {
      if (overlap(lows[k], highs[k], lows[j], highs[j]))
      {
        out.push_back(static_cast<Id>(j));
      }
    }
  };

  // 0: fine, 1: turned over, 2: cuts through another; and per item, the
  // changed triangles it cuts, which fold too.
  std::vector<unsigned char> verdict(items.size(), 0);
  std::vector<std::vector<std::size_t>> cutItems(items.size());
  parallelFor(items.size(), [&](std::size_t begin, std::size_t end) {
    std::vector<Id> candidates;
    for (std::size_t k = begin; k < end; ++k)
    {
      const Item& item = items[k];
      const Triangle& ids = idsOf(item);
      if (!toCheck[k] || hasRepeatedCorner(ids))
      {
        continue;
      }
      const TriangleCorners& x = corners[k];
      const TriangleCorners source = geometry.prepared(item.Source);
      // Turned over or not, the cuts are looked for: the triangles it cuts
      // fold too, and a partial check may not look at them.
      const bool turned = geometry.turnedOver(x, ids, source);
      // Whether y (of input triangle `other`) cuts x where the inputs do
      // not already touch; the touch test, the dearest, comes last.
      auto cutBy = [&](const TriangleCorners& y, Id other) {
        return trianglesIntersect(x, y) &&
          (other == item.Source || !trianglesTouch(source, geometry.prepared(other)));
      };
      bool cuts = false;
      // Kept, unmoved triangles: where the prepared grid has them.
      mesh.Grid.query(lows[k], highs[k], candidates);
      for (std::size_t c = 0; c < candidates.size() && !cuts; ++c)
      {
        const Id other = candidates[c];
        const Triangle& y = mesh.Triangles[static_cast<std::size_t>(other)];
        if (other != item.Source && !hasRepeatedCorner(y) && geometry.remeshedIndex(other) < 0 &&
          !hasMovedCorner(y))
        {
          cuts = cutBy(geometry.current(y), other);
        }
      }
      // Changed triangles (new ones, and kept ones with a moved corner):
      // all of those it cuts, since each of them folds too (a whole check
      // would find that from there; a partial one may not look there).
      changedCandidates(k, candidates);
      for (const Id candidate : candidates)
      {
        const std::size_t j = static_cast<std::size_t>(candidate);
        if (j != k && !hasRepeatedCorner(idsOf(items[j])) &&
          overlap(lows[k], highs[k], lows[j], highs[j]) && cutBy(corners[j], items[j].Source))
        {
          cuts = true;
          cutItems[k].push_back(j);
        }
      }
      verdict[k] = turned ? 1 : (cuts ? 2 : 0);
    }
  });

  FoldFindings findings;
  findings.FoldingRemeshed.assign(frame.Remeshed.size(), 0);
  auto mark = [&](std::size_t k) {
    if (items[k].Remeshed >= 0)
    {
      findings.FoldingRemeshed[static_cast<std::size_t>(items[k].Remeshed)] = 1;
    }
    for (const Id p : idsOf(items[k]))
    {
      if (geometry.isMoved(p))
      {
        findings.FoldingMovedPoints.push_back(p);
      }
    }
  };
  for (std::size_t k = 0; k < items.size(); ++k)
  {
    if (verdict[k] == 0)
    {
      continue;
    }
    ++(verdict[k] == 1 ? findings.Turned : findings.Cutting);
    mark(k);
    for (const std::size_t j : cutItems[k])
    {
      mark(j);
    }
  }
  std::sort(findings.FoldingMovedPoints.begin(), findings.FoldingMovedPoints.end());
  findings.FoldingMovedPoints.erase(
    std::unique(findings.FoldingMovedPoints.begin(), findings.FoldingMovedPoints.end()),
    findings.FoldingMovedPoints.end());
  return findings;
}

} // namespace silsmooth
