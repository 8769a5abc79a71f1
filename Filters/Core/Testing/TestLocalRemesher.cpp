// Local re-meshing of one silhouette triangle: orientation kept, ids never
// repeated, sides split only at the silhouette points.
#include "LocalRemesher.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

using namespace silsmooth;

namespace
{

// A planar triangle A(0) B(1) C(2) in z = 0, counter-clockwise, P (3) on AB,
// Q (4) on AC, interior samples 5.. on the chord between them.
struct Fixture
{
  std::vector<glm::dvec3> Positions{ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  SilhouetteTriangleLayout Layout;

  Fixture(double p, double q, int interior)
  {
    Layout.Lone = 0;
    Layout.BaseFirst = 1;
    Layout.BaseSecond = 2;
    Layout.BaseFirstPosition = Positions[1];
    Layout.BaseSecondPosition = Positions[2];
    const glm::dvec3 pp(p, 0, 0);
    const glm::dvec3 qq(0, q, 0);
    Positions.push_back(pp);
    Positions.push_back(qq);
    Layout.Chain.push_back(3);
    Layout.ChainPositions.push_back(pp);
    for (int i = 1; i <= interior; ++i)
    {
      const double t = static_cast<double>(i) / (interior + 1);
      Positions.push_back((1 - t) * pp + t * qq);
      Layout.Chain.push_back(static_cast<Id>(Positions.size() - 1));
      Layout.ChainPositions.push_back(Positions.back());
    }
    Layout.Chain.push_back(4);
    Layout.ChainPositions.push_back(qq);
  }

  double signedArea(const Triangle& t) const
  {
    const glm::dvec3 n = glm::cross(
      Positions[static_cast<std::size_t>(t[1])] - Positions[static_cast<std::size_t>(t[0])],
      Positions[static_cast<std::size_t>(t[2])] - Positions[static_cast<std::size_t>(t[0])]);
    return 0.5 * n.z;
  }
};

} // namespace

TEST(LocalRemesher, TilesTheTriangleWithItsOrientation)
{
  for (int interior : { 0, 1, 5 })
  {
    Fixture f(0.4, 0.7, interior);
    std::vector<Triangle> out;
    const std::size_t count = remeshSilhouetteTriangle(f.Layout, out);
    ASSERT_EQ(count, out.size());
    // Lone fan: interior + 1 triangles; base side: interior + 2.
    EXPECT_EQ(count, static_cast<std::size_t>(2 * interior + 3));
    double area = 0.0;
    for (const Triangle& t : out)
    {
      EXPECT_GT(f.signedArea(t), 0.0);
      area += f.signedArea(t);
    }
    EXPECT_NEAR(area, 0.5, 1e-15);
    // Directed edges: every interior edge once each way, and the outline is
    // A-P, P-B, B-C, C-Q, Q-A (no other boundary edge, so no T-junction).
    std::map<std::pair<Id, Id>, int> directed;
    for (const Triangle& t : out)
    {
      for (int k = 0; k < 3; ++k)
      {
        ++directed[{ t[k], t[(k + 1) % 3] }];
      }
    }
    std::set<std::pair<Id, Id>> outline;
    for (const auto& [edge, uses] : directed)
    {
      EXPECT_EQ(uses, 1);
      if (!directed.count({ edge.second, edge.first }))
      {
        outline.insert(edge);
      }
    }
    const std::set<std::pair<Id, Id>> expected{ { 0, 3 }, { 3, 1 }, { 1, 2 }, { 2, 4 }, { 4, 0 } };
    EXPECT_EQ(outline, expected);
  }
}

TEST(LocalRemesher, SnappedSilhouettePointsCollapseSlivers)
{
  // P on A itself (its id is A's): the triangle on the edge A-P vanishes,
  // and the lone side degenerates to slivers along A-Q in the flat domain
  // (in 3D they hold the curve's bulge).
  Fixture f(0.0, 0.5, 2);
  f.Layout.Chain.front() = 0;
  std::vector<Triangle> out;
  EXPECT_EQ(remeshSilhouetteTriangle(f.Layout, out), 6u);
  double area = 0.0;
  for (const Triangle& t : out)
  {
    EXPECT_FALSE(hasRepeatedCorner(t));
    EXPECT_GE(f.signedArea(t), 0.0);
    area += f.signedArea(t);
  }
  EXPECT_NEAR(area, 0.5, 1e-15);
}

TEST(LocalRemesher, BothPointsOnOneVertexKeepsTheTriangle)
{
  Fixture f(0.0, 0.0, 0);
  f.Layout.Chain = { 0, 0 };
  std::vector<Triangle> out;
  EXPECT_EQ(remeshSilhouetteTriangle(f.Layout, out), 1u);
  EXPECT_EQ(out.front(), (Triangle{ 0, 1, 2 }));
}
