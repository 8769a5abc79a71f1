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
        const std::size_t row =
          (static_cast<std::size_t>(k) * this->Cells[1] + static_cast<std::size_t>(j)) *
          this->Cells[0];
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

void TriangleGrid::query(const glm::dvec3& low, const glm::dvec3& high, std::vector<Id>& out) const
{
  out.clear();
  if (this->Offsets.empty() || !isFinite(low) || !isFinite(high))
  {
    return;
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
        const std::size_t c =
          (static_cast<std::size_t>(k) * this->Cells[1] + j) * this->Cells[0] + i;
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
            out.push_back(t);
          }
        }
      }
    }
  }
}

} // namespace silsmooth
