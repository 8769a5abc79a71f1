// Quadric edge collapse with the silhouette-aware error rule: the budget is
// met, the error bounds e and f * e hold, closed manifolds stay closed.
#include "QuadricSimplifier.h"

#include "CoreTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace silsmooth;

namespace
{

struct Sphere
{
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  Sphere(int rings, int sectors)
  {
    coretest::unitSphere(rings, sectors, this->Points, this->Triangles);
  }
};

int eulerCharacteristic(const SimplificationResult& r)
{
  std::set<std::pair<Id, Id>> edges;
  for (const Triangle& t : r.Triangles)
    for (int k = 0; k < 3; ++k)
      edges.insert({ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) });
  return static_cast<int>(r.Points.size()) - static_cast<int>(edges.size()) +
    static_cast<int>(r.Triangles.size());
}

// Near the contour for a view down -z: the band |z| < 0.25 (an equator).
std::vector<unsigned char> equatorBand(const std::vector<glm::dvec3>& points)
{
  std::vector<unsigned char> near(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    near[i] = std::abs(points[i].z) < 0.25 ? 1 : 0;
  return near;
}

} // namespace

TEST(QuadricSimplifier, ReachesTheCountAndStaysClosed)
{
  const Sphere s(20, 40); // 1,520 triangles
  for (const std::size_t target : { 1000u, 300u, 100u, 51u })
  {
    SimplificationParameters p;
    p.TargetTriangles = target;
    const SimplificationResult r = simplifyQuadric(s.Points, s.Triangles, p);
    EXPECT_TRUE(r.ReachedTarget);
    EXPECT_LE(r.Triangles.size(), target);
    EXPECT_GE(r.Triangles.size(), target - 1); // a collapse removes two
    EXPECT_TRUE(coretest::checkManifold(r.Triangles).closedManifold()) << target;
    EXPECT_EQ(eulerCharacteristic(r), 2);
  }
}

TEST(QuadricSimplifier, TorusKeepsItsGenus)
{
  // Genus 1: the Euler characteristic stays 0, whatever the budget.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(40, 20, 0.4, points, triangles); // 1,600 triangles
  for (const std::size_t target : { 800u, 200u, 60u })
  {
    SimplificationParameters p;
    p.TargetTriangles = target;
    p.Near = equatorBand(points);
    p.NearFactor = 0.2;
    const SimplificationResult r = simplifyQuadric(points, triangles, p);
    EXPECT_TRUE(coretest::checkManifold(r.Triangles).closedManifold()) << target;
    EXPECT_EQ(eulerCharacteristic(r), 0) << target;
    EXPECT_TRUE(r.ReachedTarget) << target;
    EXPECT_LE(r.Triangles.size(), target);
  }
}

TEST(QuadricSimplifier, NearPointsKeepTheSmallerError)
{
  const Sphere s(20, 40);
  SimplificationParameters p;
  p.TargetTriangles = 300;
  p.Near = equatorBand(s.Points);
  p.NearFactor = 0.1;
  const SimplificationResult aware = simplifyQuadric(s.Points, s.Triangles, p);
  ASSERT_TRUE(aware.ReachedTarget);
  EXPECT_TRUE(coretest::checkManifold(aware.Triangles).closedManifold());
  double nearWorst = 0.0;
  double farWorst = 0.0;
  for (std::size_t i = 0; i < aware.Points.size(); ++i)
  {
    (aware.PointNear[i] ? nearWorst : farWorst) =
      std::max(aware.PointNear[i] ? nearWorst : farWorst, aware.PointError[i]);
  }
  const double e = aware.Threshold;
  EXPECT_GT(e, 0.0);
  EXPECT_LE(farWorst, e * (1 + 1e-12));
  EXPECT_LE(nearWorst, p.NearFactor * e * (1 + 1e-12));
  EXPECT_GT(nearWorst, 0.0); // the band was simplified too, within f * e

  // The plain simplification to the same count spends its error evenly:
  // near the contour it is worse than the aware one.
  SimplificationParameters plain;
  plain.TargetTriangles = 300;
  const SimplificationResult flat = simplifyQuadric(s.Points, s.Triangles, plain);
  double plainNearWorst = 0.0;
  const std::vector<unsigned char> band = equatorBand(s.Points);
  for (std::size_t i = 0; i < flat.Points.size(); ++i)
    if (band[static_cast<std::size_t>(flat.SourcePoint[i])])
      plainNearWorst = std::max(plainNearWorst, flat.PointError[i]);
  EXPECT_LT(nearWorst, plainNearWorst);
  std::cout << "e = " << e << ", near worst " << nearWorst << " (plain " << plainNearWorst
            << "), far worst " << farWorst << "\n";
}

TEST(QuadricSimplifier, FactorZeroFreezesTheBand)
{
  const Sphere s(20, 40);
  SimplificationParameters p;
  p.TargetTriangles = 600;
  p.Near = equatorBand(s.Points);
  p.NearFactor = 0.0;
  const SimplificationResult r = simplifyQuadric(s.Points, s.Triangles, p);
  EXPECT_TRUE(coretest::checkManifold(r.Triangles).closedManifold());
  // Every band point is still there, unmoved.
  std::set<Id> kept(r.SourcePoint.begin(), r.SourcePoint.end());
  for (std::size_t i = 0; i < s.Points.size(); ++i)
  {
    if (!p.Near[i])
      continue;
    ASSERT_TRUE(kept.count(static_cast<Id>(i))) << i;
  }
  for (std::size_t i = 0; i < r.Points.size(); ++i)
  {
    if (p.Near[static_cast<std::size_t>(r.SourcePoint[i])])
      EXPECT_EQ(r.Points[i], s.Points[static_cast<std::size_t>(r.SourcePoint[i])]);
  }
}

TEST(QuadricSimplifier, OpenMeshKeepsItsBoundary)
{
  // A plate: its boundary points are locked, the inside collapses freely.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  const int n = 10;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      points.emplace_back(i, j, 0.01 * ((i * 7 + j * 3) % 5));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const Id a = j * (n + 1) + i;
      triangles.push_back({ a, a + 1, a + n + 2 });
      triangles.push_back({ a, a + n + 2, a + n + 1 });
    }
  SimplificationParameters p;
  p.TargetTriangles = 60;
  const SimplificationResult r = simplifyQuadric(points, triangles, p);
  EXPECT_LE(r.Triangles.size(), 60u);
  std::set<Id> kept(r.SourcePoint.begin(), r.SourcePoint.end());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (i == 0 || j == 0 || i == n || j == n)
        EXPECT_TRUE(kept.count(j * (n + 1) + i));
}

// The edge link condition: a small closed component (a tetrahedron beside a
// sphere) is not folded into two triangles back to back when the budget asks
// for fewer triangles than the sphere can give; every edge keeps two
// triangles, and the component its four.
TEST(QuadricSimplifier, ATetrahedronIsNotFolded)
{
  Sphere sphere(12, 24);
  const Id base = static_cast<Id>(sphere.Points.size());
  for (const glm::dvec3& p :
    { glm::dvec3(3, 0, 0), glm::dvec3(3.1, 0, 0), glm::dvec3(3, 0.1, 0), glm::dvec3(3, 0, 0.1) })
    sphere.Points.push_back(p);
  for (const Triangle& t :
    std::vector<Triangle>{ { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } })
    sphere.Triangles.push_back({ base + t[0], base + t[1], base + t[2] });
  SimplificationParameters parameters;
  parameters.TargetTriangles = 4;
  const SimplificationResult result = simplifyQuadric(sphere.Points, sphere.Triangles, parameters);
  EXPECT_TRUE(coretest::checkManifold(result.Triangles).closedManifold());
  std::size_t onTetrahedron = 0;
  for (const Triangle& t : result.Triangles)
    onTetrahedron += result.SourcePoint[static_cast<std::size_t>(t[0])] >= base ? 1 : 0;
  EXPECT_EQ(onTetrahedron, 4u);
}

// Two spheres touching at one point (their poles welded): the shared point's
// triangles make two fans, and no collapse may involve it, so every
// collapse's end has a disk around it (what a vertex hierarchy needs).
TEST(QuadricSimplifier, APinchedPointStays)
{
  Sphere first(10, 20);
  Sphere second(10, 20);
  const Id offset = static_cast<Id>(first.Points.size());
  for (glm::dvec3 p : second.Points)
    first.Points.push_back(p * glm::dvec3(1, 1, -1) + glm::dvec3(0, 0, 2)); // pole 0 at (0, 0, 1)
  for (const Triangle& t : second.Triangles)
  {
    Triangle u = { t[0] + offset, t[2] + offset, t[1] + offset }; // mirrored: turn back outward
    for (Id& v : u)
      v = v == offset ? 0 : v; // the second north pole is the first's
    first.Triangles.push_back(u);
  }
  SimplificationParameters parameters;
  parameters.TargetTriangles = 8;
  parameters.RecordSequence = true;
  const SimplificationResult result = simplifyQuadric(first.Points, first.Triangles, parameters);
  EXPECT_GT(result.Sequence.size(), 100u);
  for (const CollapseRecord& c : result.Sequence)
  {
    EXPECT_NE(c.Kept, 0);
    EXPECT_NE(c.Removed, 0);
  }
}
