#include "SurfaceEdgeLines.h"

#include "CoreTestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

using namespace silsmooth;

namespace
{

const std::vector<glm::dvec3> CubeCorners{ { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 },
  { -1, 1, -1 }, { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
// Outward quads, corner ids into CubeCorners.
const int CubeFaces[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 },
  { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };

/// A cube as an asset file writes it: four points per face, each with the
/// face's normal (hard edges), 24 points and 12 triangles.
void splitCube(std::vector<glm::dvec3>& points, std::vector<glm::dvec3>& normals,
  std::vector<Triangle>& triangles)
{
  for (const auto& face : CubeFaces)
  {
    const Id base = static_cast<Id>(points.size());
    for (int k = 0; k < 4; ++k)
    {
      points.push_back(CubeCorners[static_cast<std::size_t>(face[k])]);
    }
    const glm::dvec3 normal =
      glm::normalize(glm::cross(points[base + 1] - points[base], points[base + 2] - points[base]));
    normals.insert(normals.end(), 4, normal);
    triangles.push_back({ base, base + 1, base + 2 });
    triangles.push_back({ base, base + 2, base + 3 });
  }
}

/// The drawn edges as sorted pairs of positions' first ids.
std::set<std::pair<Id, Id>> edgesOf(const std::vector<SurfaceEdgeLine>& lines, LineKind kind)
{
  std::set<std::pair<Id, Id>> edges;
  for (const SurfaceEdgeLine& line : lines)
  {
    if (line.Kind != kind)
    {
      continue;
    }
    for (std::size_t i = 1; i < line.Points.size(); ++i)
    {
      const bool inserted = edges
                              .emplace(std::min(line.Points[i - 1], line.Points[i]),
                                std::max(line.Points[i - 1], line.Points[i]))
                              .second;
      EXPECT_TRUE(inserted) << "an edge drawn twice";
    }
  }
  return edges;
}

} // namespace

TEST(SurfaceEdgeLines, HardEdgedCubeGivesItsTwelveEdges)
{
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec3> normals;
  std::vector<Triangle> triangles;
  splitCube(points, normals, triangles);
  const std::vector<SurfaceEdgeLine> lines = surfaceEdgeLines(points, triangles, normals, {});
  // The corners join three creases, so every edge is a polyline of its own.
  EXPECT_EQ(lines.size(), 12u);
  const std::set<std::pair<Id, Id>> creases = edgesOf(lines, LineKind::Crease);
  EXPECT_EQ(creases.size(), 12u);
  EXPECT_TRUE(edgesOf(lines, LineKind::Border).empty());
  for (const auto& [a, b] : creases)
  {
    // A cube edge: its ends differ in exactly one coordinate (no diagonal).
    const glm::dvec3 d = points[static_cast<std::size_t>(a)] - points[static_cast<std::size_t>(b)];
    EXPECT_EQ((d.x != 0) + (d.y != 0) + (d.z != 0), 1);
  }
}

TEST(SurfaceEdgeLines, SharedNormalsAcrossACopyAreATextureSeamNotACrease)
{
  // The same split cube, but every copy of a corner carries the one corner
  // normal (a smooth-shaded box with texture seams): nothing jumps, so no
  // crease, and the welded surface is closed, so no border.
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec3> normals;
  std::vector<Triangle> triangles;
  splitCube(points, normals, triangles);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    normals[i] = glm::normalize(points[i]);
  }
  EXPECT_TRUE(surfaceEdgeLines(points, triangles, normals, {}).empty());

  // The wrong variant, welding by point id instead of position: the 24
  // copies would make every cube edge a border.
  std::vector<Triangle> shifted = triangles;
  std::vector<glm::dvec3> apart = points;
  for (std::size_t i = 0; i < apart.size(); ++i)
  {
    apart[i] += 1e-9 * static_cast<double>(i); // no longer equal coordinates
  }
  EXPECT_EQ(edgesOf(surfaceEdgeLines(apart, shifted, normals, {}), LineKind::Border).size(), 24u);
}

TEST(SurfaceEdgeLines, WithoutNormalsTheFaceAngleDecides)
{
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec3> normals;
  std::vector<Triangle> triangles;
  splitCube(points, normals, triangles);
  SurfaceEdgeLineParameters parameters;
  parameters.CreaseAngleDegrees = 89.0;
  EXPECT_EQ(
    edgesOf(surfaceEdgeLines(points, triangles, {}, parameters), LineKind::Crease).size(), 12u);
  parameters.CreaseAngleDegrees = 91.0; // the cube's faces meet at 90 degrees
  EXPECT_TRUE(surfaceEdgeLines(points, triangles, {}, parameters).empty());

  // A smooth UV sphere has no edge sharper than 30 degrees at 24 x 48.
  std::vector<glm::dvec3> sphere;
  std::vector<Triangle> sphereTriangles;
  coretest::unitSphere(24, 48, sphere, sphereTriangles);
  EXPECT_TRUE(surfaceEdgeLines(sphere, sphereTriangles, {}, {}).empty());
}

TEST(SurfaceEdgeLines, OpenSquareGivesOneClosedBorderLoop)
{
  // A 3 x 3 grid of quads in z = 0, split in two: its border is one loop of
  // 12 edges; the inner edges are flat, so no crease.
  std::vector<glm::dvec3> points;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      points.emplace_back(i, j, 0.0);
    }
  }
  std::vector<Triangle> triangles;
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const Id a = j * 4 + i;
      triangles.push_back({ a, a + 1, a + 5 });
      triangles.push_back({ a, a + 5, a + 4 });
    }
  }
  const std::vector<glm::dvec3> normals(points.size(), glm::dvec3(0, 0, 1));
  const std::vector<SurfaceEdgeLine> lines = surfaceEdgeLines(points, triangles, normals, {});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Kind, LineKind::Border);
  ASSERT_EQ(lines[0].Points.size(), 13u);
  EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());
  for (const Id p : lines[0].Points)
  {
    const glm::dvec3& q = points[static_cast<std::size_t>(p)];
    EXPECT_TRUE(q.x == 0 || q.x == 3 || q.y == 0 || q.y == 3);
  }

  SurfaceEdgeLineParameters noBorders;
  noBorders.Borders = false;
  EXPECT_TRUE(surfaceEdgeLines(points, triangles, normals, noBorders).empty());
}

TEST(SurfaceEdgeLines, ThreeSheetsOnOneEdgeMakeACrease)
{
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 0, 0, 1 }, { 1, 0, 0 }, { -1, 1, 0 },
    { -1, -1, 0 } };
  const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 1, 0, 3 } }, { { 0, 1, 4 } } };
  const std::vector<SurfaceEdgeLine> lines = surfaceEdgeLines(points, triangles, {}, {});
  const std::set<std::pair<Id, Id>> creases = edgesOf(lines, LineKind::Crease);
  EXPECT_EQ(creases, (std::set<std::pair<Id, Id>>{ { 0, 1 } }));
  EXPECT_EQ(edgesOf(lines, LineKind::Border).size(), 6u);
}

TEST(SurfaceEdgeLines, DegenerateTrianglesTakeNoPart)
{
  // A triangle whose corners weld to two positions adds no edge.
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 0 } };
  EXPECT_TRUE(surfaceEdgeLines(points, { { 0, 1, 2 } }, {}, {}).empty());
}

// An OpenSCAD STL where two solids meet (issue 16's boss on its fillet ring):
// the exporter rounds two copies of a point to positions 1e-4 apart and
// joins them by a sliver triangle standing across the surface. Welded with
// the smoothing filter's WeldTolerance, the sliver has two corners on one
// vertex and the strip is one flat sheet: its border and nothing else.
TEST(SurfaceEdgeLines, NearCopiesWeldWithTheToleranceAndTheirSliverDrawsNoCrease)
{
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 1, 0, 0 },
    { 1, 0, 1e-4 }, { 2, 0, 0 }, { 2, 1, 0 } };
  const std::vector<Triangle> triangles{ { { 0, 3, 2 } }, { { 0, 2, 1 } }, { { 3, 4, 2 } },
    { { 4, 5, 6 } }, { { 4, 6, 2 } } };
  const std::set<std::pair<Id, Id>> outline{ { 0, 1 }, { 0, 3 }, { 3, 5 }, { 5, 6 }, { 2, 6 },
    { 1, 2 } };

  SurfaceEdgeLineParameters welded;
  welded.WeldTolerance = 1e-3;
  const std::vector<SurfaceEdgeLine> lines = surfaceEdgeLines(points, triangles, {}, welded);
  EXPECT_TRUE(edgesOf(lines, LineKind::Crease).empty());
  EXPECT_EQ(edgesOf(lines, LineKind::Border), outline);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].Points.front(), lines[0].Points.back());

  // With normals (one per point, the same on both copies) too.
  const std::vector<glm::dvec3> up(points.size(), glm::dvec3(0, 0, 1));
  const std::vector<SurfaceEdgeLine> shaded = surfaceEdgeLines(points, triangles, up, welded);
  EXPECT_TRUE(edgesOf(shaded, LineKind::Crease).empty());
  EXPECT_EQ(edgesOf(shaded, LineKind::Border), outline);

  // The wrong variant, equal coordinates only: the sliver's facet, at 90
  // degrees to the strip, makes creases of both its long edges.
  const std::vector<SurfaceEdgeLine> exact = surfaceEdgeLines(points, triangles, {}, {});
  EXPECT_EQ(edgesOf(exact, LineKind::Crease), (std::set<std::pair<Id, Id>>{ { 2, 3 }, { 2, 4 } }));
}
