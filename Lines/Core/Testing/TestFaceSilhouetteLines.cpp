// Face-based silhouette lines: straight segments between the linear zero
// crossings of g on the mixed edges, chained into crack-free polylines.
#include "FaceSilhouetteLines.h"

#include "CoreTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

using namespace silsmooth;

namespace
{

PreparedMesh sphere(int rings, int sectors)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(rings, sectors, points, triangles);
  const std::vector<glm::dvec3> normals = points; // exact
  return PreparedMesh(points, triangles, normals);
}

// Checks the invariants that hold for any view of a closed mesh; returns the
// largest distance of a crossing from the exact contour of the unit sphere
// seen from `eye` (perspective), or -1 for parallel views.
double checkView(const PreparedMesh& mesh, const ViewGeometry& view)
{
  const FaceSilhouette s = faceSilhouette(mesh, view);
  const std::vector<glm::dvec3>& points = mesh.points();
  // Every crossing is on its edge, where the linear g is zero.
  for (const EdgeCrossing& c : s.Crossings)
  {
    EXPECT_LT(c.Low, c.High);
    EXPECT_GE(c.T, 0.0);
    EXPECT_LE(c.T, 1.0);
    const glm::dvec3 a = points[static_cast<std::size_t>(c.Low)];
    const glm::dvec3 b = points[static_cast<std::size_t>(c.High)];
    EXPECT_LT(glm::length(c.Position - (a + c.T * (b - a))), 1e-12);
    const double ga = view.visibility(a, mesh.normals()[static_cast<std::size_t>(c.Low)]);
    const double gb = view.visibility(b, mesh.normals()[static_cast<std::size_t>(c.High)]);
    EXPECT_NEAR((1.0 - c.T) * ga + c.T * gb, 0.0, 1e-12 * (std::abs(ga) + std::abs(gb)));
  }
  // One segment per silhouette triangle, its ends on two different sides
  // of that triangle.
  EXPECT_EQ(s.Segments.size(), s.Triangles.size());
  for (std::size_t i = 0; i < s.Triangles.size(); ++i)
  {
    const Id t = s.Triangles[i];
    const std::array<Id, 2> ends = s.Segments[i];
    EXPECT_NE(ends[0], ends[1]);
    std::set<Id> sides;
    for (int k = 0; k < 3; ++k)
    {
      sides.insert(mesh.edges().sideEdge(t, k));
    }
    for (const Id c : ends)
    {
      EXPECT_GE(c, 0);
      if (c >= 0)
        EXPECT_TRUE(sides.count(s.Crossings[static_cast<std::size_t>(c)].EdgeId));
    }
  }
  // Closed mesh: every crossing is shared by two segments, and every chain
  // is a closed loop; together the loops use every segment once.
  EXPECT_EQ(s.Crossings.size(), s.Segments.size());
  std::size_t used = 0;
  for (const std::vector<Id>& chain : s.Polylines)
  {
    EXPECT_GE(chain.size(), 4u);
    EXPECT_EQ(chain.front(), chain.back());
    used += chain.size() - 1;
  }
  EXPECT_EQ(used, s.Segments.size());
  if (view.Parallel)
  {
    return -1.0;
  }
  // The exact contour of the unit sphere seen from E: the circle of the
  // points p with |p| = 1 and p . E = 1.
  const double d = glm::length(view.Eye);
  const glm::dvec3 axis = view.Eye / d;
  const double radius = std::sqrt(1.0 - 1.0 / (d * d));
  double worst = 0.0;
  for (const EdgeCrossing& c : s.Crossings)
  {
    const double along = glm::dot(c.Position, axis);
    const double across = glm::length(c.Position - along * axis);
    worst = std::max(worst, std::hypot(along - 1.0 / d, across - radius));
  }
  return worst;
}

} // namespace

TEST(FaceSilhouetteLines, SphereFromManyViews)
{
  const PreparedMesh mesh = sphere(24, 48);
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  double worst = 0.0;
  for (int i = 0; i < 50; ++i)
  {
    const glm::dvec3 direction =
      glm::normalize(glm::dvec3(normal(random), normal(random), normal(random)));
    ViewGeometry view;
    view.Eye = direction * (2.0 + 0.2 * i);
    worst = std::max(worst, checkView(mesh, view));
    ViewGeometry parallel;
    parallel.Parallel = true;
    parallel.TowardViewer = direction;
    checkView(mesh, parallel);
  }
  // The crossings are on chords of the sphere, and the linear g misplaces
  // them along the edge by a fraction of its length: edges here are about
  // 0.13 long, so a few thousandths.
  EXPECT_LT(worst, 0.01);
  std::cout << "largest distance from the exact contour: " << worst << "\n";
}

TEST(FaceSilhouetteLines, FinerMeshesAreCloser)
{
  ViewGeometry view;
  view.Eye = glm::dvec3(0.3, -0.4, 3.0);
  const double coarse = checkView(sphere(8, 16), view);
  const double fine = checkView(sphere(32, 64), view);
  EXPECT_GT(coarse, 0.0);
  EXPECT_LT(fine, coarse / 8.0); // second order: edges 4x shorter, error about 16x smaller
}

TEST(FaceSilhouetteLines, NoSilhouetteWhenEverythingFacesTheEye)
{
  // One triangle facing the eye: no mixed edge, no line.
  const PreparedMesh mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 } },
    { { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 } });
  ViewGeometry view;
  view.Eye = glm::dvec3(0.2, 0.2, 5.0);
  const FaceSilhouette s = faceSilhouette(mesh, view);
  EXPECT_TRUE(s.Triangles.empty());
  EXPECT_TRUE(s.Polylines.empty());
}

TEST(FaceSilhouetteLines, OpenMeshGivesOpenChainsWithKnownCrossing)
{
  // Two triangles sharing edge (1, 2); normals tilt from +z to -z along x,
  // so from an eye on +z far away g changes sign halfway in x.
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } };
  const std::vector<glm::dvec3> normals{ { 0, 0, 1 }, { 0, 0, -1 }, { 0, 0, 1 }, { 0, 0, -1 } };
  const PreparedMesh mesh(points, { { 0, 1, 2 }, { 1, 3, 2 } }, normals);
  ViewGeometry view;
  view.Parallel = true;
  view.TowardViewer = glm::dvec3(0, 0, 1);
  const FaceSilhouette s = faceSilhouette(mesh, view);
  ASSERT_EQ(s.Triangles.size(), 2u);
  ASSERT_EQ(s.Polylines.size(), 1u);
  EXPECT_EQ(s.Polylines[0].size(), 3u); // open: two segments, three points
  EXPECT_NE(s.Polylines[0].front(), s.Polylines[0].back());
  for (const EdgeCrossing& c : s.Crossings)
  {
    EXPECT_NEAR(c.T, 0.5, 1e-15); // g = +1 and -1 at the ends
  }
}
