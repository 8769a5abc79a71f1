// A uniform grid over the bounding boxes of a mesh's triangles, for finding
// the triangles near a region (the fold guard's candidates, FoldGuard.h).
// Built once per prepared mesh; queries are read-only and thread-safe.
//
// The cell size is the mean of the triangles' largest box extents, so a
// triangle spans a few cells and a cell holds a few triangles on meshes of
// even size; the cell count is capped at about 4 per triangle (or a budget
// given), so a mesh with one huge triangle among small ones cannot make the
// grid huge.
// Triangles with a repeated corner or a non-finite corner are left out.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace silsmooth
{

/// Whether the boxes [aLow, aHigh] and [bLow, bHigh] meet (closed boxes:
/// touching counts).
inline bool boxesMeet(
  const glm::dvec3& aLow, const glm::dvec3& aHigh, const glm::dvec3& bLow, const glm::dvec3& bHigh)
{
  return aLow.x <= bHigh.x && bLow.x <= aHigh.x && aLow.y <= bHigh.y && bLow.y <= aHigh.y &&
    aLow.z <= bHigh.z && bLow.z <= aHigh.z;
}

class TriangleGrid
{
public:
  TriangleGrid() = default;
  TriangleGrid(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles);
  /// A grid of boxes given by their corners (entry i is box i; a box whose
  /// low corner is not finite or lies above its high one is left out).
  /// `cellBudget`, when more than 4 per box, lets the cells be that many
  /// (smaller cells: for few boxes asked about by many queries).
  TriangleGrid(
    std::vector<glm::dvec3> low, std::vector<glm::dvec3> high, std::size_t cellBudget = 0);

  /// The box a grid keeps for triangle `t` over `points`; false, and
  /// `low` and `high` untouched, for a triangle with a repeated or
  /// non-finite corner, which grids leave out.
  static bool boxOf(
    const std::vector<glm::dvec3>& points, const Triangle& t, glm::dvec3& low, glm::dvec3& high);

  /// Appends to `out` (cleared first) every triangle (or box) whose box meets the box
  /// [low, high], each once, in no particular order; stops and returns false
  /// (`out` then holds maxCount of them) when there are more than maxCount.
  bool query(const glm::dvec3& low, const glm::dvec3& high, std::vector<Id>& out,
    std::size_t maxCount = SIZE_MAX) const;

  /// What queryTriangle remembers between calls on one thread: which boxes
  /// the current query has found (a box is found in several cells).
  struct TriangleQueryMarks
  {
    std::vector<std::uint32_t> Query; // per box: the query that found it last
    std::uint32_t Current = 0;
  };

  /// Appends to `out` (cleared first), each once and in no particular
  /// order, every box that meets the box of the triangle (a, b, c) and
  /// shares a cell with the triangle itself: all the boxes the triangle
  /// meets (triangleMeetsBox), and for a long thin triangle across the grid
  /// far fewer than query() with its box gives (its box may cover every
  /// cell).
  void queryTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
    std::vector<Id>& out, TriangleQueryMarks& marks) const;

  /// Whether entry t's box meets the box [low, high]: the test query()
  /// applies, for narrowing a query's result to a smaller box.
  bool meets(Id t, const glm::dvec3& low, const glm::dvec3& high) const
  {
    const std::size_t i = static_cast<std::size_t>(t);
    return boxesMeet(this->Low[i], this->High[i], low, high);
  }

  bool empty() const { return this->Offsets.empty(); }

  /// The edge length of the grid's cubic cells.
  double cellSize() const { return this->CellSize; }

private:
  void build(std::size_t cellBudget = 0);
  /// The cell along `axis` that coordinate x falls in, clamped to the grid.
  /// Monotonic in x (a product with a positive constant, then truncation of
  /// a value that is not negative), which
  /// is all that queries need: a box that meets another has a cell range
  /// that meets the other's.
  /// The first cell of the row of cells along x at (j, k).
  std::size_t rowStart(int j, int k) const
  {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(this->Cells[1]) +
             static_cast<std::size_t>(j)) *
      static_cast<std::size_t>(this->Cells[0]);
  }

  int cellIndex(double x, int axis) const
  {
    const double c = (x - this->Origin[axis]) * this->InverseCellSize;
    if (!(c >= 0.0))
    {
      return 0; // below the grid, or NaN
    }
    // Truncation is floor here (c is not negative), and much cheaper than
    // std::floor on baseline x86-64, which has no rounding instruction.
    return c < static_cast<double>(this->Cells[axis] - 1) ? static_cast<int>(c)
                                                          : this->Cells[axis] - 1;
  }

  glm::dvec3 Origin{ 0.0 };
  double CellSize = 1.0;
  double InverseCellSize = 1.0;
  int Cells[3] = { 0, 0, 0 };
  /// Triangles of cell c: Entries[Offsets[c] .. Offsets[c + 1]).
  std::vector<std::size_t> Offsets;
  /// Per (cell, triangle): the triangle's id << 3 with the bits below
  /// (queries report a triangle once, from the first cell it shares with
  /// the query, without reading anything but the entry).
  std::vector<Id> Entries;
  static constexpr Id FirstAlongX = 1; // the cell is the triangle's first along x
  static constexpr Id FirstAlongY = 2;
  static constexpr Id FirstAlongZ = 4;
  /// Each triangle's box, to drop candidates that share a cell only.
  std::vector<glm::dvec3> Low;
  std::vector<glm::dvec3> High;
};

} // namespace silsmooth
