#include "TriangleGrid.h"

#include "FiniteVector.h"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace silsmooth
{
bool TriangleGrid::boxOf(
  const std::vector<glm::dvec3>& points, const Triangle& t, glm::dvec3& low, glm::dvec3& high)
{
  if (hasRepeatedCorner(t))
  {
    return false;
  }
  const glm::dvec3& a = points[static_cast<std::size_t>(t[0])];
  const glm::dvec3& b = points[static_cast<std::size_t>(t[1])];
  const glm::dvec3& c = points[static_cast<std::size_t>(t[2])];
  if (!isFinite(a) || !isFinite(b) || !isFinite(c))
  {
    return false;
  }
  low = glm::min(a, glm::min(b, c));
  high = glm::max(a, glm::max(b, c));
  return true;
}

TriangleGrid::TriangleGrid(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles)
  : Low(triangles.size(), glm::dvec3(HUGE_VAL))
  , High(triangles.size(), glm::dvec3(-HUGE_VAL))
{
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    boxOf(points, triangles[t], this->Low[t], this->High[t]); // left empty when false
  }
  this->build();
}

TriangleGrid::TriangleGrid(
  std::vector<glm::dvec3> low, std::vector<glm::dvec3> high, std::size_t cellBudget)
  : Low(std::move(low))
  , High(std::move(high))
{
  for (std::size_t t = 0; t < this->Low.size(); ++t)
  {
    if (!isFinite(this->Low[t]) || !isFinite(this->High[t]) ||
      !(this->Low[t].x <= this->High[t].x) || !(this->Low[t].y <= this->High[t].y) ||
      !(this->Low[t].z <= this->High[t].z))
    {
      this->Low[t] = glm::dvec3(HUGE_VAL);
      this->High[t] = glm::dvec3(-HUGE_VAL);
    }
  }
  this->build(cellBudget);
}

void TriangleGrid::build(std::size_t cellBudget)
{
  const std::size_t count = this->Low.size();
  glm::dvec3 low(HUGE_VAL);
  glm::dvec3 high(-HUGE_VAL);
  double extentSum = 0.0;
  std::size_t used = 0;
  for (std::size_t t = 0; t < count; ++t)
  {
    if (!(this->Low[t].x <= this->High[t].x))
    {
      continue;
    }
    low = glm::min(low, this->Low[t]);
    high = glm::max(high, this->High[t]);
    const glm::dvec3 d = this->High[t] - this->Low[t];
    extentSum += std::max({ d.x, d.y, d.z });
    ++used;
  }
  if (used == 0)
  {
    return;
  }
  const glm::dvec3 size = high - low;
  double cell = extentSum / static_cast<double>(used);
  const double largest = std::max({ size.x, size.y, size.z });
  // At most about 4 cells per triangle.
  const double budget =
    std::max(4.0 * static_cast<double>(used) + 1.0, static_cast<double>(cellBudget));
  if (!(cell > 0.0) || !std::isfinite(cell))
  {
    // Boxes without extent (points): cells as small as the budget allows,
    // not one cell for the whole extent (every query would test every box).
    cell = largest > 0.0 ? largest / std::cbrt(budget) : 1.0;
  }
  auto cellsFor = [&](double c) {
    return (std::floor(size.x / c) + 1) * (std::floor(size.y / c) + 1) *
      (std::floor(size.z / c) + 1);
  };
  while (cellsFor(cell) > budget)
  {
    cell *= 1.5;
  }
  this->Origin = low;
  this->CellSize = cell;
  this->InverseCellSize = 1.0 / cell;
  for (int axis = 0; axis < 3; ++axis)
  {
    this->Cells[axis] = static_cast<int>(std::floor(size[axis] / cell)) + 1;
  }
  const std::size_t cellCount = static_cast<std::size_t>(this->Cells[0]) *
    static_cast<std::size_t>(this->Cells[1]) * static_cast<std::size_t>(this->Cells[2]);
  // Two passes over the triangles: count per cell, then fill (compressed
  // rows, each cell's triangles in ascending order). An entry is the
  // triangle's id shifted left by 3 over three bits: whether the cell is the
  // first of the triangle's cells along x, y and z.
  this->Offsets.assign(cellCount + 1, 0);
  auto forEachCell = [this](std::size_t t, auto&& visit) {
    const int i0 = this->cellIndex(this->Low[t].x, 0);
    const int i1 = this->cellIndex(this->High[t].x, 0);
    const int j0 = this->cellIndex(this->Low[t].y, 1);
    const int j1 = this->cellIndex(this->High[t].y, 1);
    const int k0 = this->cellIndex(this->Low[t].z, 2);
    const int k1 = this->cellIndex(this->High[t].z, 2);
    for (int k = k0; k <= k1; ++k)
    {
      for (int j = j0; j <= j1; ++j)
      {
        const std::size_t row = this->rowStart(j, k);
        for (int i = i0; i <= i1; ++i)
        {
          visit(row + static_cast<std::size_t>(i),
            (i == i0 ? FirstAlongX : 0) | (j == j0 ? FirstAlongY : 0) |
              (k == k0 ? FirstAlongZ : 0));
        }
      }
    }
  };
  for (std::size_t t = 0; t < count; ++t)
  {
    if (this->Low[t].x <= this->High[t].x)
    {
      forEachCell(t, [this](std::size_t c, Id) { ++this->Offsets[c + 1]; });
    }
  }
  for (std::size_t c = 1; c <= cellCount; ++c)
  {
    this->Offsets[c] += this->Offsets[c - 1];
  }
  this->Entries.resize(this->Offsets[cellCount]);
  std::vector<std::size_t> next(this->Offsets.begin(), this->Offsets.end() - 1);
  for (std::size_t t = 0; t < count; ++t)
  {
    if (this->Low[t].x <= this->High[t].x)
    {
      forEachCell(t, [&](std::size_t c, Id first) {
        this->Entries[next[c]++] = static_cast<Id>(t) << 3 | first;
      });
    }
  }
}

bool TriangleGrid::query(
  const glm::dvec3& low, const glm::dvec3& high, std::vector<Id>& out, std::size_t maxCount) const
{
  out.clear();
  if (this->Offsets.empty() || !isFinite(low) || !isFinite(high))
  {
    return true;
  }
  const int i0 = this->cellIndex(low.x, 0);
  const int i1 = this->cellIndex(high.x, 0);
  const int j0 = this->cellIndex(low.y, 1);
  const int j1 = this->cellIndex(high.y, 1);
  const int k0 = this->cellIndex(low.z, 2);
  const int k1 = this->cellIndex(high.z, 2);
  for (int k = k0; k <= k1; ++k)
  {
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const std::size_t c = this->rowStart(j, k) + static_cast<std::size_t>(i);
        for (std::size_t e = this->Offsets[c]; e < this->Offsets[c + 1]; ++e)
        {
          // Each triangle once: from the first cell that both it and the
          // query cover. Along x that is the triangle's first cell, or the
          // query's first when the triangle starts before it (and so for y
          // and z); the entry says which cells are the triangle's first.
          const Id entry = this->Entries[e];
          const Id t = entry >> 3;
          if (((entry & FirstAlongX) != 0 || i == i0) && ((entry & FirstAlongY) != 0 || j == j0) &&
            ((entry & FirstAlongZ) != 0 || k == k0) && this->meets(t, low, high))
          {
            if (out.size() == maxCount)
            {
              return false;
            }
            out.push_back(t);
          }
        }
      }
    }
  }
  return true;
}

namespace
{
// A convex polygon of at most 7 corners: a triangle clipped by four planes.
struct ClippedPolygon
{
  glm::dvec3 P[8];
  int Count = 0;
};

// Keeps the part of `polygon` where coordinate `axis` is at least `bound`
// (keepAbove) or at most it (Sutherland and Hodgman's step).
void clipPolygon(ClippedPolygon& polygon, int axis, double bound, bool keepAbove)
{
  ClippedPolygon kept;
  auto inside = [&](const glm::dvec3& p) {
    return keepAbove ? p[axis] >= bound : p[axis] <= bound;
  };
  for (int i = 0; i < polygon.Count; ++i)
  {
    const glm::dvec3& from = polygon.P[i];
    const glm::dvec3& to = polygon.P[(i + 1) % polygon.Count];
    if (inside(from))
    {
      kept.P[kept.Count++] = from;
    }
    if (inside(from) != inside(to))
    {
      const double along = (bound - from[axis]) / (to[axis] - from[axis]);
      glm::dvec3 crossing = from + along * (to - from);
      crossing[axis] = bound;
      kept.P[kept.Count++] = crossing;
    }
  }
  polygon = kept;
}
} // namespace

void TriangleGrid::queryTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
  std::vector<Id>& out, TriangleQueryMarks& marks) const
{
  out.clear();
  if (this->Offsets.empty() || !isFinite(a) || !isFinite(b) || !isFinite(c))
  {
    return;
  }
  if (marks.Query.size() != this->Low.size() || ++marks.Current == 0)
  {
    marks.Query.assign(this->Low.size(), 0); // new, or the counter wrapped
    marks.Current = 1;
  }
  const glm::dvec3 low = glm::min(a, glm::min(b, c));
  const glm::dvec3 high = glm::max(a, glm::max(b, c));
  // Rows of cells along x: the triangle's part within a row's slab of y
  // and z gives the cells of the row it passes through. Slabs are widened
  // a little (rounding may not lose a cell); the grid's outer cells hold
  // everything beyond it, so their slabs are open on that side.
  const double margin = 1e-6 * this->CellSize;
  auto slab = [this, margin](int cell, int axis, double& from, double& to) {
    from = cell == 0 ? -HUGE_VAL : this->Origin[axis] + cell * this->CellSize - margin;
    to = cell == this->Cells[axis] - 1 ? HUGE_VAL
                                       : this->Origin[axis] + (cell + 1) * this->CellSize + margin;
  };
  const int j0 = this->cellIndex(low.y, 1);
  const int j1 = this->cellIndex(high.y, 1);
  const int k0 = this->cellIndex(low.z, 2);
  const int k1 = this->cellIndex(high.z, 2);
  const int boxI0 = this->cellIndex(low.x, 0);
  const int boxI1 = this->cellIndex(high.x, 0);
  for (int k = k0; k <= k1; ++k)
  {
    double zFrom = 0.0;
    double zTo = 0.0;
    slab(k, 2, zFrom, zTo);
    for (int j = j0; j <= j1; ++j)
    {
      const std::size_t row = this->rowStart(j, k);
      if (this->Offsets[row + static_cast<std::size_t>(boxI0)] ==
        this->Offsets[row + static_cast<std::size_t>(boxI1) + 1])
      {
        continue; // nothing in the row under the triangle's box: no clipping
      }
      double yFrom = 0.0;
      double yTo = 0.0;
      slab(j, 1, yFrom, yTo);
      ClippedPolygon part;
      part.P[0] = a;
      part.P[1] = b;
      part.P[2] = c;
      part.Count = 3;
      const double bounds[4] = { yFrom, yTo, zFrom, zTo };
      for (int side = 0; side < 4 && part.Count > 0; ++side)
      {
        if (std::isfinite(bounds[side]))
        {
          clipPolygon(part, side < 2 ? 1 : 2, bounds[side], side % 2 == 0);
        }
      }
      if (part.Count == 0)
      {
        continue;
      }
      double xLow = part.P[0].x;
      double xHigh = part.P[0].x;
      for (int p = 1; p < part.Count; ++p)
      {
        xLow = std::min(xLow, part.P[p].x);
        xHigh = std::max(xHigh, part.P[p].x);
      }
      const int i0 = std::max(boxI0, this->cellIndex(xLow - margin, 0));
      const int i1 = std::min(boxI1, this->cellIndex(xHigh + margin, 0));
      for (std::size_t cell = row + static_cast<std::size_t>(i0);
           cell <= row + static_cast<std::size_t>(i1); ++cell)
      {
        for (std::size_t e = this->Offsets[cell]; e < this->Offsets[cell + 1]; ++e)
        {
          const Id box = this->Entries[e] >> 3;
          std::uint32_t& found = marks.Query[static_cast<std::size_t>(box)];
          if (found != marks.Current && this->meets(box, low, high))
          {
            found = marks.Current;
            out.push_back(box);
          }
        }
      }
    }
  }
}

} // namespace silsmooth
