// Silhouette, crease and border edges (Kim and Choe 3.3).
#include "EdgeClassification.h"

#include <gtest/gtest.h>

using namespace silsmooth;

namespace
{

// A unit cube, 12 outward triangles.
void cube(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles)
{
  points.clear();
  for (int i = 0; i < 8; ++i)
  {
    points.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  }
  triangles = { { 0, 2, 1 }, { 1, 2, 3 }, { 4, 5, 6 }, { 5, 7, 6 }, { 0, 1, 4 }, { 1, 5, 4 },
    { 2, 6, 3 }, { 3, 6, 7 }, { 0, 4, 2 }, { 2, 4, 6 }, { 1, 3, 5 }, { 3, 7, 5 } };
}

} // namespace

TEST(EdgeClassification, CubeSeenAlongAFace)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  cube(points, triangles);
  EdgeView view;
  view.parallel = true;
  view.direction = glm::dvec3(0, 0, -1);
  const std::vector<FlaggedEdge> edges = classifyEdges(points, triangles, view, 30.0);
  ASSERT_EQ(edges.size(), 18u); // 12 cube edges + 6 face diagonals
  int creases = 0, silhouettes = 0, borders = 0;
  for (const FlaggedEdge& e : edges)
  {
    creases += (e.flags & CreaseEdge) != 0;
    silhouettes += (e.flags & SilhouetteEdge) != 0;
    borders += (e.flags & BorderEdge) != 0;
    EXPECT_LT(e.a, e.b);
  }
  EXPECT_EQ(creases, 12);
  EXPECT_EQ(borders, 0);
  // Side faces are edge-on: N . V = 0, so by eq. 2 (<= 0) the edges of the
  // front and back faces and the side faces' own edges and diagonals are silhouettes:
  // 4 + 4 front/back edges, 4 side edges, 4 side diagonals.
  EXPECT_EQ(silhouettes, 16);
  // The loops: chaining the silhouette edges that are creases.
  EXPECT_FALSE(chainFlaggedEdges(edges, SilhouetteEdge).empty());
}

TEST(EdgeClassification, CubeSeenAlongADiagonal)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  cube(points, triangles);
  EdgeView view;
  view.eye = glm::dvec3(10.0, 11.0, 12.0); // three faces visible
  const std::vector<FlaggedEdge> edges = classifyEdges(points, triangles, view, 30.0);
  int silhouettes = 0;
  for (const FlaggedEdge& e : edges)
  {
    silhouettes += (e.flags & SilhouetteEdge) != 0;
  }
  EXPECT_EQ(silhouettes, 6); // the hexagonal outline
  const auto loops = chainFlaggedEdges(edges, SilhouetteEdge);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 7u);
  EXPECT_EQ(loops[0].front(), loops[0].back());
}

TEST(EdgeClassification, BorderEdgesOfAnOpenSquare)
{
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  const std::vector<Triangle> triangles{ { 0, 1, 2 }, { 0, 2, 3 } };
  const std::vector<FlaggedEdge> edges = classifyEdges(points, triangles, EdgeView(), 30.0);
  ASSERT_EQ(edges.size(), 5u);
  int borders = 0;
  for (const FlaggedEdge& e : edges)
  {
    borders += (e.flags & BorderEdge) != 0;
    EXPECT_EQ(e.flags & (SilhouetteEdge | CreaseEdge), 0u);
  }
  EXPECT_EQ(borders, 4);
}
