// The two-pass 3-4 chamfer distance transform, and silhouette proximity
// labels (Mata et al.) on meshes whose answers are known.
#include "DistanceTransform.h"
#include "SilhouetteProximity.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace silsmooth;

TEST(DistanceTransform, SquareHasExactDistances)
{
  // A 6 x 6 object square at columns and rows 2..7 of a 10 x 10 image: the
  // nearest background is straight across one side, so every label is exact.
  const int w = 10;
  const int h = 10;
  std::vector<unsigned char> image(w * h, 0);
  for (int y = 2; y <= 7; ++y)
    for (int x = 2; x <= 7; ++x)
      image[y * w + x] = 1;
  const std::vector<std::int32_t> d = chamferDistance34(image, w, h);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const bool inside = x >= 2 && x <= 7 && y >= 2 && y <= 7;
      const int expected = inside ? std::min({ x - 1, 8 - x, y - 1, 8 - y }) : 0;
      EXPECT_EQ(d[y * w + x], 3 * expected) << x << "," << y;
    }
  }
}

TEST(DistanceTransform, ImageBorderIsBackground)
{
  const std::vector<unsigned char> full(5 * 3, 1);
  const std::vector<std::int32_t> d = chamferDistance34(full, 5, 3);
  EXPECT_EQ(d[0], 3);
  EXPECT_EQ(d[1 * 5 + 2], 6); // the centre: two steps from outside
  EXPECT_EQ(d[1 * 5 + 4], 3);
}

TEST(DistanceTransform, WithinEightPercentOfEuclideanOnADisk)
{
  // Inside a disk of radius 40 the true distance to the background is about
  // 40 - r; the 3-4 chamfer stays within 8% (plus a pixel of rasterisation).
  const int n = 101;
  const double c = 50.0;
  std::vector<unsigned char> image(n * n, 0);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      image[y * n + x] = std::hypot(x - c, y - c) <= 40.0 ? 1 : 0;
  const std::vector<std::int32_t> d = chamferDistance34(image, n, n);
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      const double r = std::hypot(x - c, y - c);
      if (r > 40.0)
        continue;
      const double exact = 40.0 - r;
      EXPECT_NEAR(d[y * n + x] / 3.0, exact + 0.5, 0.08 * exact + 1.0) << x << "," << y;
    }
  }
}

namespace
{

// Parallel projection straight down -z, model x and y in [-1, 1] filling a
// 256 x 256 viewport (dyadic numbers: the pixel positions are exact).
ViewGeometry topView()
{
  ViewGeometry view;
  view.Parallel = true;
  view.TowardViewer = glm::dvec3(0, 0, 1);
  view.ModelToClip = glm::dmat4(1.0);
  view.ViewportWidth = 256;
  view.ViewportHeight = 256;
  return view;
}

} // namespace

TEST(SilhouetteProximity, SquarePlateLabels)
{
  // A square plate split into 8 x 8 quads; with a grid of 16 cells the
  // point (i, j) of the plate sits in cell (2i, 2j) (the last row and column
  // clamp into cell 15), whose label is its distance to the nearest side.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  const int n = 8;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      points.emplace_back(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const Id a = j * (n + 1) + i;
      triangles.push_back({ a, a + 1, a + n + 2 });
      triangles.push_back({ a, a + n + 2, a + n + 1 });
    }
  }
  const ProximityGrid grid = silhouetteProximity(points, triangles, topView(), 16);
  ASSERT_EQ(grid.Width, 16);
  ASSERT_EQ(grid.Height, 16);
  for (const unsigned char o : grid.Occupancy)
    EXPECT_EQ(o, 1);
  const ViewGeometry view = topView();
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      // The cell the point projects into (about (2i, 2j); rounding decides
      // at the cell borders), and the exact distance of that cell.
      glm::dvec2 pixel;
      ASSERT_TRUE(view.toPixels(points[j * (n + 1) + i], pixel));
      const int x =
        std::clamp(static_cast<int>(std::floor((pixel.x - grid.OriginX) / grid.CellSize)), 0, 15);
      const int y =
        std::clamp(static_cast<int>(std::floor((pixel.y - grid.OriginY) / grid.CellSize)), 0, 15);
      EXPECT_LE(std::abs(x - 2 * i), 1);
      const int expected = std::min({ x + 1, 16 - x, y + 1, 16 - y });
      EXPECT_DOUBLE_EQ(grid.PointDistance[j * (n + 1) + i], expected) << i << "," << j;
    }
  }
  // A face's label is the least over the cells it overlaps (in area): a
  // corner face covers cells 0 and 1, the quad at (4, 4) cells 8 and 9,
  // whose labels are 8 and 7.
  EXPECT_DOUBLE_EQ(grid.TriangleDistance[0], 1.0);
  EXPECT_DOUBLE_EQ(grid.TriangleDistance[2 * (4 * n + 4)], 7.0);
}

TEST(SilhouetteProximity, EnclosedHoleIsNotTheExternalContour)
{
  // A square frame: outer side 2, hole side 1. The hole's rim is not on the
  // external contour, so the points around the hole are about a quarter of
  // the grid from it, not 1.
  std::vector<glm::dvec3> points{ { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 },
    { -0.5, -0.5, 0 }, { 0.5, -0.5, 0 }, { 0.5, 0.5, 0 }, { -0.5, 0.5, 0 } };
  std::vector<Triangle> triangles;
  for (Id k = 0; k < 4; ++k)
  {
    const Id o0 = k;
    const Id o1 = (k + 1) % 4;
    triangles.push_back({ o0, o1, 4 + o1 });
    triangles.push_back({ o0, 4 + o1, 4 + o0 });
  }
  const ProximityGrid grid = silhouetteProximity(points, triangles, topView(), 40);
  ASSERT_EQ(grid.Width, 40);
  int filled = 0;
  for (const unsigned char o : grid.Occupancy)
    filled += o == 2 ? 1 : 0;
  EXPECT_GT(filled, 18 * 18); // the hole's inside, filled
  EXPECT_LE(filled, 20 * 20);
  for (Id p = 0; p < 4; ++p)
    EXPECT_DOUBLE_EQ(grid.PointDistance[static_cast<std::size_t>(p)], 1.0);
  for (Id p = 4; p < 8; ++p)
    EXPECT_NEAR(grid.PointDistance[static_cast<std::size_t>(p)], 11.0, 1.0);
}

TEST(SilhouetteProximity, OverlapTest)
{
  const glm::dvec2 a(0, 0), b(4, 0), c(0, 4);
  EXPECT_TRUE(triangleOverlapsSquare(a, b, c, 1, 1, 1));
  EXPECT_TRUE(triangleOverlapsSquare(a, b, c, 1.9, 1.9, 1));  // corner (1.9,1.9) is inside
  EXPECT_FALSE(triangleOverlapsSquare(a, b, c, 4, 0, 1));     // touches corner b only
  EXPECT_FALSE(triangleOverlapsSquare(a, b, c, 2.1, 2.1, 1)); // beyond the hypotenuse
  EXPECT_FALSE(triangleOverlapsSquare(a, b, c, -2, 0, 1));
}
