#include "SilhouetteProximity.h"

#include "DistanceTransform.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace silsmooth
{

bool triangleOverlapsSquare(
  const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double x0, double y0, double size)
{
  // Overlap means a common area: touching along a border does not count, so
  // a face that ends on a cell border does not occupy the next cell.
  // Axes of the square.
  if (std::max({ a.x, b.x, c.x }) <= x0 || std::min({ a.x, b.x, c.x }) >= x0 + size ||
    std::max({ a.y, b.y, c.y }) <= y0 || std::min({ a.y, b.y, c.y }) >= y0 + size)
  {
    return false;
  }
  // A triangle seen edge-on has no area to share: the box test decides, so
  // that it is not lost.
  const glm::dvec2 ab = b - a;
  const glm::dvec2 ac = c - a;
  if (ab.x * ac.y - ab.y * ac.x == 0.0)
  {
    return true;
  }
  // Normals of the triangle's sides.
  const std::array<glm::dvec2, 3> corners{ { a, b, c } };
  const std::array<glm::dvec2, 4> square{ { { x0, y0 }, { x0 + size, y0 }, { x0, y0 + size },
    { x0 + size, y0 + size } } };
  for (int k = 0; k < 3; ++k)
  {
    const glm::dvec2 p = corners[static_cast<std::size_t>(k)];
    const glm::dvec2 q = corners[static_cast<std::size_t>((k + 1) % 3)];
    const glm::dvec2 n(q.y - p.y, p.x - q.x);
    if (n.x == 0.0 && n.y == 0.0)
    {
      continue;
    }
    double triMin = std::numeric_limits<double>::infinity();
    double triMax = -triMin;
    for (const glm::dvec2& v : corners)
    {
      const double s = n.x * v.x + n.y * v.y;
      triMin = std::min(triMin, s);
      triMax = std::max(triMax, s);
    }
    double sqMin = std::numeric_limits<double>::infinity();
    double sqMax = -sqMin;
    for (const glm::dvec2& v : square)
    {
      const double s = n.x * v.x + n.y * v.y;
      sqMin = std::min(sqMin, s);
      sqMax = std::max(sqMax, s);
    }
    if (triMax <= sqMin || sqMax <= triMin)
    {
      return false;
    }
  }
  return true;
}

ProximityGrid silhouetteProximity(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const ViewGeometry& view, int resolution)
{
  ProximityGrid grid;
  resolution = std::max(resolution, 1);
  std::vector<glm::dvec2> pixel(points.size());
  std::vector<unsigned char> projected(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    projected[i] = view.toPixels(points[i], pixel[i]) ? 1 : 0;
  }
  grid.PointDistance.assign(points.size(), -1.0);
  grid.TriangleDistance.assign(triangles.size(), -1.0);

  auto usable = [&](const Triangle& t) {
    return projected[static_cast<std::size_t>(t[0])] && projected[static_cast<std::size_t>(t[1])] &&
      projected[static_cast<std::size_t>(t[2])];
  };
  glm::dvec2 low(std::numeric_limits<double>::infinity());
  glm::dvec2 high(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : triangles)
  {
    if (!usable(t))
    {
      continue;
    }
    for (const Id p : t)
    {
      low = glm::min(low, pixel[static_cast<std::size_t>(p)]);
      high = glm::max(high, pixel[static_cast<std::size_t>(p)]);
    }
  }
  if (!(low.x <= high.x))
  {
    return grid; // nothing projects
  }
  const double extent = std::max({ high.x - low.x, high.y - low.y, 1e-300 });
  grid.CellSize = extent / resolution;
  grid.OriginX = low.x;
  grid.OriginY = low.y;
  grid.Width =
    std::clamp(static_cast<int>(std::ceil((high.x - low.x) / grid.CellSize)), 1, resolution);
  grid.Height =
    std::clamp(static_cast<int>(std::ceil((high.y - low.y) / grid.CellSize)), 1, resolution);
  const std::size_t cells =
    static_cast<std::size_t>(grid.Width) * static_cast<std::size_t>(grid.Height);
  grid.Occupancy.assign(cells, 0);
  auto cellIndex = [&](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.Width) +
      static_cast<std::size_t>(x);
  };
  // Grid coordinates (cells are unit squares there).
  auto toGrid = [&](const glm::dvec2& p) {
    return glm::dvec2((p.x - grid.OriginX) / grid.CellSize, (p.y - grid.OriginY) / grid.CellSize);
  };
  auto cellRange = [](double lo, double hi, int n, int& first, int& last) {
    first = std::clamp(static_cast<int>(std::floor(lo)), 0, n - 1);
    last = std::clamp(static_cast<int>(std::floor(hi)), 0, n - 1);
  };

  // 1. Mesh mapping: the cells each triangle overlaps (kept for step 4).
  std::vector<std::vector<std::size_t>> cellsOf(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (!usable(triangles[t]))
    {
      continue;
    }
    const glm::dvec2 a = toGrid(pixel[static_cast<std::size_t>(triangles[t][0])]);
    const glm::dvec2 b = toGrid(pixel[static_cast<std::size_t>(triangles[t][1])]);
    const glm::dvec2 c = toGrid(pixel[static_cast<std::size_t>(triangles[t][2])]);
    int x0, x1, y0, y1;
    cellRange(std::min({ a.x, b.x, c.x }), std::max({ a.x, b.x, c.x }), grid.Width, x0, x1);
    cellRange(std::min({ a.y, b.y, c.y }), std::max({ a.y, b.y, c.y }), grid.Height, y0, y1);
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        if (triangleOverlapsSquare(a, b, c, x, y, 1.0))
        {
          grid.Occupancy[cellIndex(x, y)] = 1;
          cellsOf[t].push_back(cellIndex(x, y));
        }
      }
    }
  }

  // 2. External contour: flood the background from the grid's border.
  std::vector<unsigned char> outside(cells, 0);
  std::vector<std::size_t> stack;
  auto seed = [&](int x, int y) {
    const std::size_t i = cellIndex(x, y);
    if (!grid.Occupancy[i] && !outside[i])
    {
      outside[i] = 1;
      stack.push_back(i);
    }
  };
  for (int x = 0; x < grid.Width; ++x)
  {
    seed(x, 0);
    seed(x, grid.Height - 1);
  }
  for (int y = 0; y < grid.Height; ++y)
  {
    seed(0, y);
    seed(grid.Width - 1, y);
  }
  while (!stack.empty())
  {
    const std::size_t i = stack.back();
    stack.pop_back();
    const int x = static_cast<int>(i % static_cast<std::size_t>(grid.Width));
    const int y = static_cast<int>(i / static_cast<std::size_t>(grid.Width));
    if (x > 0)
      seed(x - 1, y);
    if (x + 1 < grid.Width)
      seed(x + 1, y);
    if (y > 0)
      seed(x, y - 1);
    if (y + 1 < grid.Height)
      seed(x, y + 1);
  }
  std::vector<unsigned char> object(cells, 0);
  for (std::size_t i = 0; i < cells; ++i)
  {
    if (!grid.Occupancy[i] && !outside[i])
    {
      grid.Occupancy[i] = 2;
    }
    object[i] = grid.Occupancy[i] ? 1 : 0;
  }

  // 3. Distance transform, in cells.
  const std::vector<std::int32_t> chamfer = chamferDistance34(object, grid.Width, grid.Height);
  grid.Distance.resize(cells);
  for (std::size_t i = 0; i < cells; ++i)
  {
    grid.Distance[i] = chamfer[i] / 3.0;
  }

  // 4. Labels.
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    double best = -1.0;
    for (const std::size_t i : cellsOf[t])
    {
      best = best < 0.0 ? grid.Distance[i] : std::min(best, grid.Distance[i]);
    }
    grid.TriangleDistance[t] = best;
  }
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    if (!projected[p])
    {
      continue;
    }
    const glm::dvec2 g = toGrid(pixel[p]);
    int x, y, unused;
    cellRange(g.x, g.x, grid.Width, x, unused);
    cellRange(g.y, g.y, grid.Height, y, unused);
    grid.PointDistance[p] = grid.Distance[cellIndex(x, y)];
  }
  return grid;
}

} // namespace silsmooth
