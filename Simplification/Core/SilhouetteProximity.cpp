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

namespace
{

// The steps of silhouetteProximity (SilhouetteProximity.h), numbered as the
// paper's.
class ProximityBuilder
{
public:
  ProximityBuilder(
    const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles, int resolution)
    : Points(points)
    , Triangles(triangles)
    , Resolution(std::max(resolution, 1))
  {
  }

  ProximityGrid build(const ViewGeometry& view)
  {
    this->project(view);
    if (!this->frameGrid())
    {
      return std::move(this->Grid); // nothing projects
    }
    this->mapMesh();
    this->markOutside();
    this->measureDistances();
    this->label();
    return std::move(this->Grid);
  }

private:
  bool usable(const Triangle& t) const
  {
    return this->Projected[static_cast<std::size_t>(t[0])] &&
      this->Projected[static_cast<std::size_t>(t[1])] &&
      this->Projected[static_cast<std::size_t>(t[2])];
  }
  std::size_t cellIndex(int x, int y) const
  {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(this->Grid.Width) +
      static_cast<std::size_t>(x);
  }
  // Grid coordinates (cells are unit squares there).
  glm::dvec2 toGrid(const glm::dvec2& p) const
  {
    return glm::dvec2((p.x - this->Grid.OriginX) / this->Grid.CellSize,
      (p.y - this->Grid.OriginY) / this->Grid.CellSize);
  }
  static void cellRange(double lo, double hi, int n, int& first, int& last)
  {
    first = std::clamp(static_cast<int>(std::floor(lo)), 0, n - 1);
    last = std::clamp(static_cast<int>(std::floor(hi)), 0, n - 1);
  }

  void project(const ViewGeometry& view)
  {
    this->Pixel.resize(this->Points.size());
    this->Projected.assign(this->Points.size(), 0);
    for (std::size_t i = 0; i < this->Points.size(); ++i)
    {
      this->Projected[i] = view.toPixels(this->Points[i], this->Pixel[i]) ? 1 : 0;
    }
    this->Grid.PointDistance.assign(this->Points.size(), -1.0);
    this->Grid.TriangleDistance.assign(this->Triangles.size(), -1.0);
  }

  // The grid over the projected triangles' bounding box; false when none projects.
  bool frameGrid()
  {
    glm::dvec2 low(std::numeric_limits<double>::infinity());
    glm::dvec2 high(-std::numeric_limits<double>::infinity());
    for (const Triangle& t : this->Triangles)
    {
      if (!this->usable(t))
      {
        continue;
      }
      for (const Id p : t)
      {
        low = glm::min(low, this->Pixel[static_cast<std::size_t>(p)]);
        high = glm::max(high, this->Pixel[static_cast<std::size_t>(p)]);
      }
    }
    if (!(low.x <= high.x))
    {
      return false;
    }
    ProximityGrid& grid = this->Grid;
    const double extent = std::max({ high.x - low.x, high.y - low.y, 1e-300 });
    grid.CellSize = extent / this->Resolution;
    grid.OriginX = low.x;
    grid.OriginY = low.y;
    grid.Width = std::clamp(
      static_cast<int>(std::ceil((high.x - low.x) / grid.CellSize)), 1, this->Resolution);
    grid.Height = std::clamp(
      static_cast<int>(std::ceil((high.y - low.y) / grid.CellSize)), 1, this->Resolution);
    this->Cells = static_cast<std::size_t>(grid.Width) * static_cast<std::size_t>(grid.Height);
    grid.Occupancy.assign(this->Cells, 0);
    return true;
  }

  // 1. Mesh mapping: the cells each triangle overlaps (kept for step 4).
  void mapMesh()
  {
    ProximityGrid& grid = this->Grid;
    this->CellsOf.assign(this->Triangles.size(), {});
    for (std::size_t t = 0; t < this->Triangles.size(); ++t)
    {
      const Triangle& tri = this->Triangles[t];
      if (!this->usable(tri))
      {
        continue;
      }
      const glm::dvec2 a = this->toGrid(this->Pixel[static_cast<std::size_t>(tri[0])]);
      const glm::dvec2 b = this->toGrid(this->Pixel[static_cast<std::size_t>(tri[1])]);
      const glm::dvec2 c = this->toGrid(this->Pixel[static_cast<std::size_t>(tri[2])]);
      int x0, x1, y0, y1;
      cellRange(std::min({ a.x, b.x, c.x }), std::max({ a.x, b.x, c.x }), grid.Width, x0, x1);
      cellRange(std::min({ a.y, b.y, c.y }), std::max({ a.y, b.y, c.y }), grid.Height, y0, y1);
      for (int y = y0; y <= y1; ++y)
      {
        for (int x = x0; x <= x1; ++x)
        {
          if (triangleOverlapsSquare(a, b, c, x, y, 1.0))
          {
            grid.Occupancy[this->cellIndex(x, y)] = 1;
            this->CellsOf[t].push_back(this->cellIndex(x, y));
          }
        }
      }
    }
  }

  // 2. External contour: flood the background from the grid's border; empty
  // cells it does not reach are holes inside the object (occupancy 2).
  void markOutside()
  {
    ProximityGrid& grid = this->Grid;
    std::vector<unsigned char> outside(this->Cells, 0);
    std::vector<std::size_t> stack;
    auto seed = [&](int x, int y) {
      const std::size_t i = this->cellIndex(x, y);
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
    for (std::size_t i = 0; i < this->Cells; ++i)
    {
      if (!grid.Occupancy[i] && !outside[i])
      {
        grid.Occupancy[i] = 2;
      }
    }
  }

  // 3. Distance transform, in cells.
  void measureDistances()
  {
    ProximityGrid& grid = this->Grid;
    std::vector<unsigned char> object(this->Cells, 0);
    for (std::size_t i = 0; i < this->Cells; ++i)
    {
      object[i] = grid.Occupancy[i] ? 1 : 0;
    }
    const std::vector<std::int32_t> chamfer = chamferDistance34(object, grid.Width, grid.Height);
    grid.Distance.resize(this->Cells);
    for (std::size_t i = 0; i < this->Cells; ++i)
    {
      grid.Distance[i] = chamfer[i] / 3.0;
    }
  }

  // 4. Labels: a triangle's is its nearest cell's, a point's its cell's.
  void label()
  {
    ProximityGrid& grid = this->Grid;
    for (std::size_t t = 0; t < this->Triangles.size(); ++t)
    {
      double best = -1.0;
      for (const std::size_t i : this->CellsOf[t])
      {
        best = best < 0.0 ? grid.Distance[i] : std::min(best, grid.Distance[i]);
      }
      grid.TriangleDistance[t] = best;
    }
    for (std::size_t p = 0; p < this->Points.size(); ++p)
    {
      if (!this->Projected[p])
      {
        continue;
      }
      const glm::dvec2 g = this->toGrid(this->Pixel[p]);
      int x, y, unused;
      cellRange(g.x, g.x, grid.Width, x, unused);
      cellRange(g.y, g.y, grid.Height, y, unused);
      grid.PointDistance[p] = grid.Distance[this->cellIndex(x, y)];
    }
  }

  const std::vector<glm::dvec3>& Points;
  const std::vector<Triangle>& Triangles;
  const int Resolution;
  ProximityGrid Grid;
  std::vector<glm::dvec2> Pixel;
  std::vector<unsigned char> Projected;
  std::size_t Cells = 0;
  std::vector<std::vector<std::size_t>> CellsOf;
};

} // namespace

ProximityGrid silhouetteProximity(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const ViewGeometry& view, int resolution)
{
  return ProximityBuilder(points, triangles, resolution).build(view);
}

} // namespace silsmooth
