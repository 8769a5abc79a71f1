#include "FoldGuard.h"

#include "FiniteVector.h"
#include "TriangleIntersection.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>

namespace silsmooth
{
namespace
{

// Input triangle t's corners where the mesh has them.
TriangleCorners inputCorners(const FoldGuardMesh& mesh, Id t)
{
  const Triangle& tri = mesh.Triangles[static_cast<std::size_t>(t)];
  return TriangleCorners{ { mesh.Points[static_cast<std::size_t>(tri[0])],
    mesh.Points[static_cast<std::size_t>(tri[1])],
    mesh.Points[static_cast<std::size_t>(tri[2])] } };
}

class FrameGeometry
{
public:
  FrameGeometry(const FoldGuardMesh& mesh, const FoldGuardFrame& frame)
    : Mesh(mesh)
    , Frame(frame)
    , PointCount(static_cast<Id>(mesh.Points.size()))
    , RemeshedMask(mesh.Triangles.size(), false)
  {
    for (const Id t : frame.Remeshed)
    {
      this->RemeshedMask[static_cast<std::size_t>(t)] = true;
    }
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

  TriangleCorners prepared(Id t) const { return inputCorners(this->Mesh, t); }

  // Turned over against its input triangle: on the other side of the sum of
  // its corners' shading normals.
  bool turnedOver(const TriangleCorners& c, const Triangle& ids, const TriangleCorners& input) const
  {
    return turnedOverAgainst(
      c, input, this->normal(ids[0]) + this->normal(ids[1]) + this->normal(ids[2]));
  }

  /// Whether input triangle t is re-meshed in this frame: a bit per input
  /// triangle, since the check asks it of every candidate near every new
  /// triangle.
  bool isRemeshed(Id t) const { return this->RemeshedMask[static_cast<std::size_t>(t)]; }

  const FoldGuardMesh& Mesh;
  const FoldGuardFrame& Frame;
  const Id PointCount;
  std::vector<bool> RemeshedMask;
};

// A triangle to check: a replacement (Index into Replacements) or a kept
// input triangle with a moved corner (Index = -1).
struct Item
{
  Id Source = -1;
  long Remeshed = -1; // entry of Remeshed, or -1
  long Index = -1;
};

// The triangles of the mesh that meet each of the boxes [lows[b], highs[b]]
// (triangleMeetsBox, where the triangles are now; ascending ids per box; a
// box with a corner that is not finite meets none): from the mesh's grid
// (each box widened by its slack), or by one pass over the triangles
// against a grid of the boxes. A box met by more than `cap` triangles is
// crowded: its list is left empty, and no more than `cap` are ever held for
// it (a fan's triangles all meet a box at its centre). Triangles with a
// repeated or non-finite corner are left out either way
// (TriangleGrid::boxOf).
struct MeetingTriangles
{
  std::vector<std::vector<Id>> Lists;
  std::vector<unsigned char> Crowded;
};

MeetingTriangles trianglesMeeting(const FoldGuardMesh& mesh, const std::vector<glm::dvec3>& lows,
  const std::vector<glm::dvec3>& highs, std::size_t cap, const FoldGuardParallelFor& parallelFor)
{
  const std::size_t count = lows.size();
  MeetingTriangles meeting;
  meeting.Lists.resize(count);
  meeting.Crowded.assign(count, 0);
  if (mesh.Grid)
  {
    const glm::dvec3 slack(mesh.GridSlack);
    parallelFor(count, [&](std::size_t begin, std::size_t end) {
      std::vector<Id> near;
      for (std::size_t b = begin; b < end; ++b)
      {
        if (!isFinite(lows[b]) || !isFinite(highs[b]))
        {
          continue;
        }
        mesh.Grid->query(lows[b] - slack, highs[b] + slack, near);
        std::vector<Id>& list = meeting.Lists[b];
        for (const Id t : near)
        {
          // The grid's boxes may be of earlier positions: tested where the
          // triangle is now, as the pass over the triangles tests it.
          const TriangleCorners corners = inputCorners(mesh, t);
          const glm::dvec3 low = glm::min(corners.P[0], glm::min(corners.P[1], corners.P[2]));
          const glm::dvec3 high = glm::max(corners.P[0], glm::max(corners.P[1], corners.P[2]));
          if (list.size() <= cap && boxesMeet(low, high, lows[b], highs[b]) &&
            triangleMeetsBox(corners, lows[b], highs[b]))
          {
            list.push_back(t);
          }
        }
        if (list.size() > cap)
        {
          meeting.Crowded[b] = 1;
          list = std::vector<Id>();
        }
        std::sort(list.begin(), list.end());
      }
    });
    return meeting;
  }
  if (count == 0)
  {
    return meeting;
  }
  // Leaves out boxes that are not finite. Cells up to one per 8 triangles:
  // few boxes are asked about by every triangle, and smaller cells than 4
  // per box hold fewer boxes that a triangle's query must test.
  const TriangleGrid boxes(lows, highs, mesh.Triangles.size() / 8);
  // The finite boxes' union: most triangles lie well away from it (a
  // silhouette's boxes are a thin ring around the surface) and are dropped
  // by one test instead of a query. triangleMeetsBox's tolerance is 1e-9 of
  // the box's and the corners' spans from its centre, so a triangle whose
  // box lies beyond the union by more than 2e-9 of the two spans meets none
  // of the boxes.
  glm::dvec3 allLow(HUGE_VAL);
  glm::dvec3 allHigh(-HUGE_VAL);
  for (std::size_t b = 0; b < count; ++b)
  {
    if (isFinite(lows[b]) && isFinite(highs[b]))
    {
      allLow = glm::min(allLow, lows[b]);
      allHigh = glm::max(allHigh, highs[b]);
    }
  }
  const glm::dvec3 allSpan = allHigh - allLow;
  const double unionSpan = std::max({ allSpan.x, allSpan.y, allSpan.z });
  const auto beyondEveryBox = [&](const glm::dvec3& low, const glm::dvec3& high) {
    if (!(unionSpan >= 0.0))
    {
      return true; // no finite box
    }
    const glm::dvec3 span = high - low;
    const double reach = 2e-9 * (unionSpan + std::max({ span.x, span.y, span.z }));
    return low.x > allHigh.x + reach || low.y > allHigh.y + reach || low.z > allHigh.z + reach ||
      high.x < allLow.x - reach || high.y < allLow.y - reach || high.z < allLow.z - reach;
  };
  // How many triangles met each box so far; a box is not tested once past
  // its cap, so the count ends above the cap exactly when the box is
  // crowded, however the work is split.
  std::unique_ptr<std::atomic<std::size_t>[]> met(new std::atomic<std::size_t>[count]);
  for (std::size_t b = 0; b < count; ++b)
  {
    met[b].store(0, std::memory_order_relaxed);
  }
  // Fixed blocks, joined in order: the lists do not depend on the split.
  constexpr std::size_t Block = 1 << 14;
  const std::size_t triangleCount = mesh.Triangles.size();
  const std::size_t blocks = (triangleCount + Block - 1) / Block;
  std::vector<std::vector<std::pair<Id, Id>>> pairs(blocks); // (box, triangle)
  parallelFor(blocks, [&](std::size_t begin, std::size_t end) {
    std::vector<Id> near;
    TriangleGrid::TriangleQueryMarks marks;
    for (std::size_t k = begin; k < end; ++k)
    {
      for (std::size_t t = k * Block; t < std::min(triangleCount, (k + 1) * Block); ++t)
      {
        glm::dvec3 low;
        glm::dvec3 high;
        if (!TriangleGrid::boxOf(mesh.Points, mesh.Triangles[t], low, high) ||
          beyondEveryBox(low, high))
        {
          continue;
        }
        const TriangleCorners corners = inputCorners(mesh, static_cast<Id>(t));
        boxes.queryTriangle(corners.P[0], corners.P[1], corners.P[2], near, marks);
        for (const Id box : near)
        {
          const std::size_t b = static_cast<std::size_t>(box);
          if (met[b].load(std::memory_order_relaxed) <= cap &&
            triangleMeetsBox(corners, lows[b], highs[b]) &&
            met[b].fetch_add(1, std::memory_order_relaxed) < cap)
          {
            pairs[k].emplace_back(box, static_cast<Id>(t));
          }
        }
      }
    }
  });
  for (std::size_t b = 0; b < count; ++b)
  {
    meeting.Crowded[b] = met[b].load(std::memory_order_relaxed) > cap ? 1 : 0;
  }
  for (const auto& block : pairs)
  {
    for (const auto& [box, triangle] : block)
    {
      if (!meeting.Crowded[static_cast<std::size_t>(box)])
      {
        meeting.Lists[static_cast<std::size_t>(box)].push_back(triangle);
      }
    }
  }
  return meeting;
}

} // namespace

namespace
{

// More candidates than this for one input triangle's new triangles (of
// kept triangles, or of changed ones) make them crowded: they are taken as
// folding without a test. Ordinary meshes give a few dozen; a fan of
// thousands of triangles around one point gives every one of them to each
// new triangle at its centre, and testing them all would be quadratic.
constexpr std::size_t CandidateCap = 2048;

// Whether triangle c lies in triangle `input`: its corners within 1e-9 of
// the input's longest side from its plane, and inside its sides by the same
// measure (barycentric coordinates of at least -1e-9), as the new triangles
// of a straight re-meshing do up to rounding.
bool liesIn(const TriangleCorners& c, const TriangleCorners& input)
{
  const glm::dvec3 normal = glm::cross(input.P[1] - input.P[0], input.P[2] - input.P[0]);
  const double area2 = glm::length(normal);
  const double side = std::max({ glm::length(input.P[1] - input.P[0]),
    glm::length(input.P[2] - input.P[1]), glm::length(input.P[0] - input.P[2]) });
  if (!(area2 > 1e-12 * side * side))
  {
    return false; // no interior to lie in
  }
  const glm::dvec3 unit = normal / area2;
  constexpr double tolerance = 1e-9;
  for (const glm::dvec3& x : c.P)
  {
    if (!(std::abs(glm::dot(unit, x - input.P[0])) <= tolerance * side))
    {
      return false;
    }
    const double b0 = glm::dot(unit, glm::cross(input.P[1] - x, input.P[2] - x)) / area2;
    const double b1 = glm::dot(unit, glm::cross(input.P[2] - x, input.P[0] - x)) / area2;
    if (!(b0 >= -tolerance && b1 >= -tolerance && 1.0 - b0 - b1 >= -tolerance))
    {
      return false;
    }
  }
  return true;
}

// One check of a frame, in steps: the changed triangles (items), which of
// them to check, their boxes, the verdict of each, and the findings.
class FoldCheck
{
public:
  FoldCheck(const FoldGuardMesh& mesh, const FoldGuardFrame& frame)
    : Mesh(mesh)
    , Frame(frame)
    , Geometry(mesh, frame)
  {
  }

  FoldFindings run(const FoldGuardParallelFor& parallelFor)
  {
    this->collectItems(parallelFor);
    this->placeItems();
    this->chooseItemsToCheck(parallelFor);
    this->judgeItems(parallelFor);
    return this->findings();
  }

private:
  const Triangle& idsOf(const Item& item) const
  {
    return item.Index >= 0 ? this->Frame.Replacements[static_cast<std::size_t>(item.Index)]
                           : this->Mesh.Triangles[static_cast<std::size_t>(item.Source)];
  }

  bool hasMovedCorner(const Triangle& t) const
  {
    return !this->Frame.Moved.empty() &&
      (this->Geometry.isMoved(t[0]) || this->Geometry.isMoved(t[1]) ||
        this->Geometry.isMoved(t[2]));
  }

  // The replacements, and the kept triangles around moved points (in a
  // partial check also around the points whose move changed: a triangle
  // that moved back is changed too).
  void collectItems(const FoldGuardParallelFor& parallelFor)
  {
    const FoldGuardFrame& frame = this->Frame;
    for (std::size_t i = 0; i < frame.Remeshed.size(); ++i)
    {
      for (std::size_t r = frame.ReplacementOffsets[i]; r < frame.ReplacementOffsets[i + 1]; ++r)
      {
        this->Items.push_back({ frame.Remeshed[i], static_cast<long>(i), static_cast<long>(r) });
      }
    }
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
    std::vector<Id> around;
    std::vector<glm::dvec3> at;
    for (const Id p : aroundPoints)
    {
      at.push_back(this->Mesh.Points[static_cast<std::size_t>(p)]);
    }
    // Not capped: every triangle with a corner at the point is needed.
    const std::vector<std::vector<Id>> candidates = aroundPoints.empty()
      ? std::vector<std::vector<Id>>{}
      : trianglesMeeting(this->Mesh, at, at, SIZE_MAX, parallelFor).Lists;
    for (std::size_t i = 0; i < aroundPoints.size(); ++i)
    {
      const Id p = aroundPoints[i];
      for (const Id t : candidates[i])
      {
        const Triangle& tri = this->Mesh.Triangles[static_cast<std::size_t>(t)];
        if ((tri[0] == p || tri[1] == p || tri[2] == p) && !this->Geometry.isRemeshed(t))
        {
          around.push_back(t);
        }
      }
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (const Id t : around)
    {
      this->Items.push_back({ t, -1, -1 });
    }
  }

  // The changed triangles' boxes where they are now.
  void placeItems()
  {
    const std::size_t n = this->Items.size();
    this->Shapes.resize(n);
    this->Flat.assign(n, 0);
    this->Shaped.assign(n, 0);
    this->Lows.resize(n);
    this->Highs.resize(n);
    for (std::size_t k = 0; k < n; ++k)
    {
      const TriangleCorners c = this->Geometry.current(this->idsOf(this->Items[k]));
      this->Lows[k] = glm::min(c.P[0], glm::min(c.P[1], c.P[2]));
      this->Highs[k] = glm::max(c.P[0], glm::max(c.P[1], c.P[2]));
    }
  }

  // The shapes of the items listed (ascending, not yet shaped), and whether
  // each lies in its input triangle: all of them for a whole check, the
  // items to check and their candidates for a partial one.
  void shapeItems(const std::vector<std::size_t>& which, const FoldGuardParallelFor& parallelFor)
  {
    parallelFor(which.size(), [this, &which](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
      {
        const std::size_t k = which[i];
        this->Shapes[k] = shapeOf(this->Geometry.current(this->idsOf(this->Items[k])));
        this->Flat[k] =
          liesIn(this->Shapes[k].Corners, this->Geometry.prepared(this->Items[k].Source)) ? 1 : 0;
      }
    });
    for (const std::size_t k : which)
    {
      this->Shaped[k] = 1;
    }
  }

  // Which items to check (all, unless the caller names what changed), and
  // how to find the changed triangles near one: a grid of their boxes made
  // for this frame (the prepared grid knows only the input's boxes, which a
  // lifted new triangle or a moved one may leave) when many input triangles'
  // items are checked; a few (a partial check after the first round) scan
  // the boxes instead, and only the items they meet are shaped.
  void chooseItemsToCheck(const FoldGuardParallelFor& parallelFor)
  {
    const FoldGuardFrame& frame = this->Frame;
    this->ToCheck.assign(this->Items.size(), 1);
    if (frame.CheckSources && frame.CheckPoints)
    {
      const auto named = [&frame](Id p) {
        return std::binary_search(frame.CheckPoints->begin(), frame.CheckPoints->end(), p);
      };
      for (std::size_t k = 0; k < this->Items.size(); ++k)
      {
        const Triangle& t = this->idsOf(this->Items[k]);
        this->ToCheck[k] = std::binary_search(frame.CheckSources->begin(),
                             frame.CheckSources->end(), this->Items[k].Source) ||
            named(t[0]) || named(t[1]) || named(t[2])
          ? 1
          : 0;
      }
    }
    // Each input triangle's items are checked together (groupItems).
    std::size_t checkedGroups = 0;
    std::vector<std::size_t> checked;
    for (std::size_t k = 0; k < this->Items.size(); ++k)
    {
      if (this->ToCheck[k])
      {
        const bool sameGroup = !checked.empty() && this->Items[k].Remeshed >= 0 &&
          this->Items[checked.back()].Remeshed == this->Items[k].Remeshed;
        checkedGroups += sameGroup ? 0 : 1;
        checked.push_back(k);
      }
    }
    this->Scan = checkedGroups <= 64;
    if (this->Scan)
    {
      this->shapeItems(checked, parallelFor);
      return;
    }
    std::vector<std::size_t> all(this->Items.size());
    for (std::size_t k = 0; k < all.size(); ++k)
    {
      all[k] = k;
    }
    this->shapeItems(all, parallelFor);
    this->Changed = TriangleGrid(this->Lows, this->Highs);
    this->AnyFlat = std::find(this->Flat.begin(), this->Flat.end(), 1) != this->Flat.end();
    if (this->AnyFlat)
    {
      std::vector<glm::dvec3> curvedLows = this->Lows;
      for (std::size_t k = 0; k < this->Items.size(); ++k)
      {
        if (this->Flat[k])
        {
          curvedLows[k] = glm::dvec3(HUGE_VAL); // left out of the grid
        }
      }
      this->CurvedChanged = TriangleGrid(std::move(curvedLows), this->Highs);
    }
  }

  // The changed triangles whose boxes meet the box [low, high] (only the
  // ones that do not lie in their input triangles when `curvedOnly`), from
  // the grids; false, with `out` incomplete, when they are more than
  // CandidateCap.
  bool changedCandidates(
    const glm::dvec3& low, const glm::dvec3& high, bool curvedOnly, std::vector<Id>& out) const
  {
    return (curvedOnly && this->AnyFlat ? this->CurvedChanged : this->Changed)
      .query(low, high, out, CandidateCap);
  }

  // Items in runs that share one query of the prepared grid: the new
  // triangles of one input triangle lie close together, and one query with
  // their joint box, narrowed to each one's box, finds what a query per item
  // would (the grid's query is most of a check's cost).
  void groupItems()
  {
    this->GroupStarts.clear();
    for (std::size_t k = 0; k < this->Items.size(); ++k)
    {
      const bool sameRun = k > 0 && this->Items[k].Remeshed >= 0 &&
        this->Items[k].Remeshed == this->Items[k - 1].Remeshed;
      if (!sameRun)
      {
        this->GroupStarts.push_back(k);
      }
    }
    this->GroupStarts.push_back(this->Items.size());
    this->GroupOf.resize(this->Items.size());
    for (std::size_t g = 0; g + 1 < this->GroupStarts.size(); ++g)
    {
      std::fill(this->GroupOf.begin() + static_cast<std::ptrdiff_t>(this->GroupStarts[g]),
        this->GroupOf.begin() + static_cast<std::ptrdiff_t>(this->GroupStarts[g + 1]), g);
    }
  }

  // Each group's changed candidates (changedCandidates with its joint box),
  // before any group is judged, so that every group knows which others are
  // crowded (testedFromTheOtherSide).
  void findChangedCandidates(const FoldGuardParallelFor& parallelFor)
  {
    const std::size_t groups = this->GroupStarts.size() - 1;
    this->GroupNearChanged.assign(groups, {});
    if (this->Scan)
    {
      this->scanChangedCandidates(parallelFor);
      return;
    }
    parallelFor(groups, [this](std::size_t begin, std::size_t end) {
      for (std::size_t g = begin; g < end; ++g)
      {
        if (this->GroupLows[g].x <= this->GroupHighs[g].x && !this->GroupCrowded[g] &&
          !this->changedCandidates(this->GroupLows[g], this->GroupHighs[g], this->GroupFlat[g] != 0,
            this->GroupNearChanged[g]))
        {
          this->GroupCrowded[g] = 1;
          this->GroupNearChanged[g] = std::vector<Id>();
        }
      }
    });
  }

  // findChangedCandidates by scanning the boxes, for a few groups: the items
  // whose boxes meet a group's are shaped first (the items to check are),
  // then those that lie in their input triangles are left out for a group
  // whose items all do, and the cap applies, as the grids' queries do.
  void scanChangedCandidates(const FoldGuardParallelFor& parallelFor)
  {
    const std::size_t groups = this->GroupStarts.size() - 1;
    std::vector<unsigned char> wanted(this->Items.size(), 0);
    for (std::size_t g = 0; g < groups; ++g)
    {
      if (!(this->GroupLows[g].x <= this->GroupHighs[g].x) || this->GroupCrowded[g])
      {
        continue;
      }
      std::vector<Id>& out = this->GroupNearChanged[g];
      for (std::size_t j = 0; j < this->Items.size(); ++j)
      {
        if (boxesMeet(this->GroupLows[g], this->GroupHighs[g], this->Lows[j], this->Highs[j]))
        {
          out.push_back(static_cast<Id>(j));
          wanted[j] = 1;
        }
      }
    }
    std::vector<std::size_t> unshaped;
    for (std::size_t j = 0; j < this->Items.size(); ++j)
    {
      if (wanted[j] && !this->Shaped[j])
      {
        unshaped.push_back(j);
      }
    }
    this->shapeItems(unshaped, parallelFor);
    for (std::size_t g = 0; g < groups; ++g)
    {
      std::vector<Id>& out = this->GroupNearChanged[g];
      if (this->GroupFlat[g])
      {
        out.erase(std::remove_if(out.begin(), out.end(),
                    [this](Id j) { return this->Flat[static_cast<std::size_t>(j)] != 0; }),
          out.end());
      }
      if (out.size() > CandidateCap)
      {
        this->GroupCrowded[g] = 1;
        out = std::vector<Id>();
      }
    }
  }

  // Whether item j tests its pair with item k (j < k) itself: both are
  // checked, and j's group is not crowded. Then j's group has k among its
  // changed candidates (k's box meets j's, so it meets j's group's box; a
  // group that lies in its input triangles leaves out only candidates that
  // do too, which neither tests against the other), and the test is the
  // same either way round (trianglesIntersect and trianglesTouch are
  // symmetric).
  bool testedFromTheOtherSide(std::size_t k, std::size_t j) const
  {
    return j < k && this->ToCheck[j] && !this->GroupCrowded[this->GroupOf[j]] &&
      !this->Frame.PairsFromBothSides;
  }

  // 0: fine, 1: turned over, 2: cuts through another, 3: not tested
  // (crowded); and per item, the
  // changed triangles it cuts, which fold too.
  void judgeItems(const FoldGuardParallelFor& parallelFor)
  {
    this->Verdict.assign(this->Items.size(), 0);
    this->CutItems.assign(this->Items.size(), {});
    this->groupItems();
    this->findKeptCandidates(parallelFor);
    this->findChangedCandidates(parallelFor);
    parallelFor(this->GroupStarts.size() - 1, [this](std::size_t begin, std::size_t end) {
      GroupScratch scratch;
      for (std::size_t g = begin; g < end; ++g)
      {
        this->judgeGroup(g, scratch);
      }
    });
    // A pair of changed triangles that both check is tested once, from the
    // lower item (testedFromTheOtherSide): the higher one cuts too.
    for (std::size_t k = 0; k < this->Items.size(); ++k)
    {
      for (const std::size_t j : this->CutItems[k])
      {
        if (this->Verdict[j] == 0 && this->ToCheck[j] &&
          !hasRepeatedCorner(this->idsOf(this->Items[j])))
        {
          this->Verdict[j] = 2;
        }
      }
    }
  }

  // A group's candidates from the two grids, and one item's.
  struct GroupScratch
  {
    std::vector<Id> Near; // kept candidates of the group (keptCandidates)
    std::vector<TriangleShape> NearShapes;
    std::vector<glm::dvec3> NearLows; // their boxes where they are now
    std::vector<glm::dvec3> NearHighs;
    std::vector<Id> NearChanged;
    std::vector<Id> Kept;
    std::vector<Id> Changed;
  };

  // An item's own query would find nothing for a box with a corner that is
  // not finite (TriangleGrid::query).
  bool finiteBox(std::size_t k) const
  {
    return isFinite(this->Lows[k]) && isFinite(this->Highs[k]);
  }

  // Each group's joint box (of its items to check, with finite boxes; empty,
  // its low above its high, when there are none), whether all those items
  // lie in their input triangles, and, for the groups with an item that
  // does not, the kept triangles that meet the box, all groups at once
  // (trianglesMeeting).
  void findKeptCandidates(const FoldGuardParallelFor& parallelFor)
  {
    const std::size_t groups = this->GroupStarts.size() - 1;
    this->GroupLows.assign(groups, glm::dvec3(HUGE_VAL));
    this->GroupHighs.assign(groups, glm::dvec3(-HUGE_VAL));
    this->GroupFlat.assign(groups, 1);
    this->GroupCrowded.assign(groups, 0);
    std::vector<glm::dvec3> lows;
    std::vector<glm::dvec3> highs;
    std::vector<std::size_t> asked; // the groups with a box
    for (std::size_t g = 0; g < groups; ++g)
    {
      for (std::size_t k = this->GroupStarts[g]; k < this->GroupStarts[g + 1]; ++k)
      {
        if (this->ToCheck[k] && this->finiteBox(k))
        {
          this->GroupLows[g] = glm::min(this->GroupLows[g], this->Lows[k]);
          this->GroupHighs[g] = glm::max(this->GroupHighs[g], this->Highs[k]);
          this->GroupFlat[g] &= this->Flat[k];
        }
      }
      if (this->GroupLows[g].x <= this->GroupHighs[g].x && !this->GroupFlat[g])
      {
        asked.push_back(g);
        lows.push_back(this->GroupLows[g]);
        highs.push_back(this->GroupHighs[g]);
      }
    }
    MeetingTriangles found = trianglesMeeting(this->Mesh, lows, highs, CandidateCap, parallelFor);
    this->GroupNear.assign(groups, {});
    for (std::size_t i = 0; i < asked.size(); ++i)
    {
      this->GroupNear[asked[i]] = std::move(found.Lists[i]);
      this->GroupCrowded[asked[i]] = found.Crowded[i];
    }
  }

  void judgeGroup(std::size_t g, GroupScratch& scratch)
  {
    const std::size_t begin = this->GroupStarts[g];
    const std::size_t end = this->GroupStarts[g + 1];
    const glm::dvec3& low = this->GroupLows[g];
    const glm::dvec3& high = this->GroupHighs[g];
    scratch.Near.clear();
    scratch.NearShapes.clear();
    scratch.NearLows.clear();
    scratch.NearHighs.clear();
    scratch.NearChanged.clear();
    bool crowded = this->GroupCrowded[g] != 0;
    if (low.x <= high.x && !crowded)
    {
      scratch.Near = std::move(this->GroupNear[g]); // each group is judged once
      this->keptCandidates(scratch.Near, scratch.NearShapes);
      for (const TriangleShape& y : scratch.NearShapes)
      {
        const glm::dvec3* p = y.Corners.P;
        scratch.NearLows.push_back(glm::min(p[0], glm::min(p[1], p[2])));
        scratch.NearHighs.push_back(glm::max(p[0], glm::max(p[1], p[2])));
      }
      scratch.NearChanged = std::move(this->GroupNearChanged[g]); // judged once
    }
    if (crowded)
    {
      // Too many candidates to test (a fan's centre): folding, so that the
      // pass re-meshes it by the chord, which needs no test.
      for (std::size_t k = begin; k < end; ++k)
      {
        this->Verdict[k] =
          this->ToCheck[k] && !hasRepeatedCorner(this->idsOf(this->Items[k])) ? 3 : 0;
      }
      return;
    }
    for (std::size_t k = begin; k < end; ++k)
    {
      scratch.Kept.clear();
      scratch.Changed.clear();
      if (this->ToCheck[k] && this->finiteBox(k))
      {
        // A triangle that lies in its input triangle cuts a kept one only
        // where its input triangle touches that one, which is no fold.
        for (std::size_t c = 0; c < (this->Flat[k] ? 0 : scratch.Near.size()); ++c)
        {
          if (boxesMeet(scratch.NearLows[c], scratch.NearHighs[c], this->Lows[k], this->Highs[k]))
          {
            scratch.Kept.push_back(static_cast<Id>(c));
          }
        }
        for (const Id j : scratch.NearChanged)
        {
          // Two that lie in their input triangles cut each other only where
          // those touch, or not at all (in one plane).
          const std::size_t i = static_cast<std::size_t>(j);
          if (!(this->Flat[k] && this->Flat[i]) && !this->testedFromTheOtherSide(k, i) &&
            boxesMeet(this->Lows[k], this->Highs[k], this->Lows[i], this->Highs[i]))
          {
            scratch.Changed.push_back(j);
          }
        }
      }
      this->judge(k, scratch);
    }
  }

  // Keeps in `near` the kept, unmoved triangles without a repeated corner
  // (the only ones judge() tests), and puts their shapes in `shapes`, once
  // for the whole group. (Dropping here the neighbours that the group's
  // corners lie strictly on one side of was tried: in floating point it can
  // disagree with trianglesIntersect for a sliver nearly in the neighbour's
  // plane, and with the shapes cached it saved nothing measurable.)
  void keptCandidates(std::vector<Id>& near, std::vector<TriangleShape>& shapes) const
  {
    shapes.clear();
    std::size_t kept = 0;
    for (const Id t : near)
    {
      const Triangle& ids = this->Mesh.Triangles[static_cast<std::size_t>(t)];
      if (hasRepeatedCorner(ids) || this->Geometry.isRemeshed(t) || this->hasMovedCorner(ids))
      {
        continue;
      }
      near[kept++] = t;
      shapes.push_back(shapeOf(this->Geometry.prepared(t)));
    }
    near.resize(kept);
  }

  // Judges item k; group.Kept holds the entries of group.Near (the kept
  // candidates) whose boxes meet its box, group.Changed the changed
  // triangles whose boxes meet it.
  void judge(std::size_t k, const GroupScratch& group)
  {
    const Item& item = this->Items[k];
    const Triangle& ids = this->idsOf(item);
    if (!this->ToCheck[k] || hasRepeatedCorner(ids))
    {
      return;
    }
    const FrameGeometry& geometry = this->Geometry;
    const TriangleShape& x = this->Shapes[k];
    const TriangleCorners source = geometry.prepared(item.Source);
    // Turned over or not, the cuts are looked for: the triangles it cuts
    // fold too, and a partial check may not look at them.
    const bool turned = geometry.turnedOver(x.Corners, ids, source);
    // Whether y (of input triangle `other`) cuts x where the inputs do not
    // already touch; the touch test, the dearest, comes last.
    auto cutBy = [&](const TriangleShape& y, Id other) {
      return trianglesIntersect(x, y) &&
        (other == item.Source || !trianglesTouch(source, geometry.prepared(other)));
    };
    bool cuts = false;
    // Kept, unmoved triangles: where the prepared grid has them.
    for (std::size_t c = 0; c < group.Kept.size() && !cuts; ++c)
    {
      const std::size_t entry = static_cast<std::size_t>(group.Kept[c]);
      const Id other = group.Near[entry];
      cuts = other != item.Source && cutBy(group.NearShapes[entry], other);
    }
    // Changed triangles (new ones, and kept ones with a moved corner): all
    // of those it cuts, since each of them folds too (a whole check would
    // find that from there; a partial one may not look there).
    for (const Id candidate : group.Changed)
    {
      const std::size_t j = static_cast<std::size_t>(candidate);
      if (j != k && !hasRepeatedCorner(this->idsOf(this->Items[j])) &&
        cutBy(this->Shapes[j], this->Items[j].Source))
      {
        cuts = true;
        this->CutItems[k].push_back(j);
      }
    }
    this->Verdict[k] = turned ? 1 : (cuts ? 2 : 0);
  }

  FoldFindings findings() const
  {
    FoldFindings findings;
    findings.FoldingRemeshed.assign(this->Frame.Remeshed.size(), 0);
    auto mark = [&](std::size_t k, bool untested) {
      if (this->Items[k].Remeshed >= 0)
      {
        unsigned char& folding =
          findings.FoldingRemeshed[static_cast<std::size_t>(this->Items[k].Remeshed)];
        folding = untested && folding != 1 ? 2 : 1;
      }
      for (const Id p : this->idsOf(this->Items[k]))
      {
        if (this->Geometry.isMoved(p))
        {
          findings.FoldingMovedPoints.push_back(p);
        }
      }
    };
    for (std::size_t k = 0; k < this->Items.size(); ++k)
    {
      if (this->Verdict[k] == 0)
      {
        continue;
      }
      ++(this->Verdict[k] == 1 ? findings.Turned
                               : (this->Verdict[k] == 2 ? findings.Cutting : findings.Crowded));
      mark(k, this->Verdict[k] == 3);
      for (const std::size_t j : this->CutItems[k])
      {
        mark(j, false);
      }
    }
    std::vector<Id>& moved = findings.FoldingMovedPoints;
    std::sort(moved.begin(), moved.end());
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    return findings;
  }

  const FoldGuardMesh& Mesh;
  const FoldGuardFrame& Frame;
  const FrameGeometry Geometry;
  std::vector<Item> Items;
  std::vector<TriangleShape> Shapes; // of the items where they are now
  /// Per item: 1 when it lies in its input triangle (liesIn), as every
  /// new triangle of a straight re-meshing does.
  std::vector<unsigned char> Flat;
  std::vector<glm::dvec3> Lows;
  std::vector<glm::dvec3> Highs;
  std::vector<unsigned char> ToCheck;
  /// Per item: 1 once Shapes and Flat hold it (shapeItems).
  std::vector<unsigned char> Shaped;
  bool Scan = true;
  TriangleGrid Changed;
  TriangleGrid CurvedChanged; // of the items that are not Flat, when some are
  bool AnyFlat = false;
  std::vector<unsigned char> Verdict;
  std::vector<std::vector<std::size_t>> CutItems;
  /// Items [GroupStarts[g], GroupStarts[g + 1]) share one search for kept
  /// candidates, with their joint box.
  std::vector<std::size_t> GroupStarts;
  std::vector<glm::dvec3> GroupLows;
  std::vector<glm::dvec3> GroupHighs;
  std::vector<std::vector<Id>> GroupNear;
  std::vector<std::vector<Id>> GroupNearChanged; // changed candidates of each group
  std::vector<std::size_t> GroupOf;              // each item's group
  std::vector<unsigned char> GroupFlat;          // every item to check is Flat
  std::vector<unsigned char> GroupCrowded;       // more candidates than CandidateCap
};

} // namespace

FoldFindings findFolds(
  const FoldGuardMesh& mesh, const FoldGuardFrame& frame, const FoldGuardParallelFor& parallelFor)
{
  return FoldCheck(mesh, frame).run(parallelFor);
}

} // namespace silsmooth
