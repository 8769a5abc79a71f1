#include "PenOrder.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

namespace silsmooth
{
namespace
{

// An end of a line: which line, and which of its points (0 its first, 1
// its last; a loop's index among its points).
struct End
{
  std::size_t Line;
  std::size_t Point;
};

// Where each end is: a line's first and last points, or every point of a
// loop.
class LineEnds
{
public:
  LineEnds(const std::vector<std::array<glm::dvec2, 2>>& ends,
    const std::vector<std::vector<glm::dvec2>>& loops)
    : Ends(ends)
    , Loops(loops)
  {
  }
  bool isLoop(std::size_t line) const
  {
    return line < this->Loops.size() && !this->Loops[line].empty();
  }
  std::size_t count(std::size_t line) const
  {
    return this->isLoop(line) ? this->Loops[line].size() : 2;
  }
  const glm::dvec2& at(const End& end) const
  {
    return this->isLoop(end.Line) ? this->Loops[end.Line][end.Point]
                                  : this->Ends[end.Line][end.Point];
  }

private:
  const std::vector<std::array<glm::dvec2, 2>>& Ends;
  const std::vector<std::vector<glm::dvec2>>& Loops;
};

class EndGrid
{
public:
  EndGrid(const LineEnds& ends, std::size_t lines)
    : Ends(ends)
  {
    Low = glm::dvec2(std::numeric_limits<double>::infinity());
    glm::dvec2 high(-std::numeric_limits<double>::infinity());
    std::size_t total = 0;
    for (std::size_t i = 0; i < lines; ++i)
    {
      for (std::size_t k = 0; k < ends.count(i); ++k)
      {
        Low = glm::min(Low, ends.at({ i, k }));
        high = glm::max(high, ends.at({ i, k }));
        ++total;
      }
    }
    const glm::dvec2 size = high - Low;
    // About two ends a cell, and no more cells than ends on a side.
    const double count = std::max(1.0, double(total) / 2.0);
    Cell = std::sqrt(std::max(size.x * size.y, 1e-300) / count);
    Cell = std::max({ Cell, size.x / count, size.y / count, 1e-300 });
    Columns = std::max<std::int64_t>(1, std::int64_t(size.x / Cell) + 1);
    Rows = std::max<std::int64_t>(1, std::int64_t(size.y / Cell) + 1);
    Cells.resize(std::size_t(Columns * Rows));
    for (std::size_t i = 0; i < lines; ++i)
    {
      for (std::size_t k = 0; k < ends.count(i); ++k)
      {
        const auto [x, y] = cellOf(ends.at({ i, k }));
        Cells[std::size_t(y * Columns + x)].push_back({ i, k });
      }
    }
  }

  /// The nearest end of a line not yet used, removing the used ones met.
  End nearest(const glm::dvec2& pen, const std::vector<unsigned char>& used)
  {
    // Rings around the cell of the pen's nearest point in the grid's box:
    // an end in ring r + 1 or beyond lies at least r cells from that point,
    // and the pen is no nearer to it than that point is.
    const auto [cx, cy] = cellOf(pen);
    auto best =
      std::make_tuple(std::numeric_limits<double>::infinity(), std::size_t(0), std::size_t(0));
    const std::int64_t rings = std::max(Columns, Rows);
    for (std::int64_t r = 0; r <= rings; ++r)
    {
      for (std::int64_t y = cy - r; y <= cy + r; ++y)
      {
        if (y < 0 || y >= Rows)
        {
          continue;
        }
        const bool edgeRow = y == cy - r || y == cy + r;
        for (std::int64_t x = cx - r; x <= cx + r; x += edgeRow ? 1 : 2 * r)
        {
          if (x >= 0 && x < Columns)
          {
            visit(Cells[std::size_t(y * Columns + x)], pen, used, best);
          }
          if (r == 0)
          {
            break;
          }
        }
      }
      if (std::get<0>(best) <= double(r) * Cell)
      {
        break;
      }
    }
    return { std::get<1>(best), std::get<2>(best) };
  }

private:
  std::pair<std::int64_t, std::int64_t> cellOf(const glm::dvec2& p) const
  {
    const auto clamped = [](double v, std::int64_t n) {
      return std::clamp<std::int64_t>(std::int64_t(std::clamp(v, -1.0, double(n))), 0, n - 1);
    };
    return { clamped((p.x - Low.x) / Cell, Columns), clamped((p.y - Low.y) / Cell, Rows) };
  }

  void visit(std::vector<End>& cell, const glm::dvec2& pen, const std::vector<unsigned char>& used,
    std::tuple<double, std::size_t, std::size_t>& best) const
  {
    std::size_t kept = 0;
    for (const End& end : cell)
    {
      if (used[end.Line])
      {
        continue; // dropped from the cell
      }
      cell[kept++] = end;
      best = std::min(best, std::make_tuple(glm::distance(pen, Ends.at(end)), end.Line, end.Point));
    }
    cell.resize(kept);
  }

  const LineEnds& Ends;
  glm::dvec2 Low{ 0.0 };
  double Cell = 1.0;
  std::int64_t Columns = 1;
  std::int64_t Rows = 1;
  std::vector<std::vector<End>> Cells;
};

} // namespace

std::vector<PenStep> penOrder(const std::vector<std::array<glm::dvec2, 2>>& ends,
  const glm::dvec2& start, bool backToEntry, const std::vector<std::vector<glm::dvec2>>& loops)
{
  std::vector<PenStep> order;
  if (ends.empty())
  {
    return order;
  }
  order.reserve(ends.size());
  const LineEnds lineEnds(ends, loops);
  EndGrid grid(lineEnds, ends.size());
  std::vector<unsigned char> used(ends.size(), 0);
  glm::dvec2 pen = start;
  for (std::size_t k = 0; k < ends.size(); ++k)
  {
    const End next = grid.nearest(pen, used);
    used[next.Line] = 1;
    if (lineEnds.isLoop(next.Line))
    {
      order.push_back({ next.Line, false, next.Point });
      pen = lineEnds.at(next); // round the loop, back where it began
      continue;
    }
    const bool last = next.Point == 1;
    order.push_back({ next.Line, last, 0 });
    pen = ends[next.Line][last != backToEntry ? 0 : 1];
  }
  return order;
}

} // namespace silsmooth
