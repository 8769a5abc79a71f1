// Cone apexes (ConeApexes.h): found at a cone's tip, and nowhere on coarse
// or fine smooth surfaces.
#include "ConeApexes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace silsmooth;

namespace
{

const double Pi = 3.14159265358979323846;

struct Mesh
{
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
};

std::vector<Id> apexesOf(const Mesh& mesh)
{
  return coneApexes(mesh.Points, mesh.Triangles);
}

// A cone of n sides, its apex (point 0) at height `height` over a unit
// circle, closed by a fan from the base's centre (the last point).
Mesh cone(int n, double height)
{
  Mesh mesh;
  mesh.Points.emplace_back(0.0, 0.0, height);
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * Pi * i / n;
    mesh.Points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  mesh.Points.emplace_back(0.0, 0.0, 0.0);
  const Id centre = n + 1;
  for (int i = 0; i < n; ++i)
  {
    mesh.Triangles.push_back({ 0, 1 + i, 1 + (i + 1) % n });
    mesh.Triangles.push_back({ centre, 1 + (i + 1) % n, 1 + i });
  }
  return mesh;
}

// A UV sphere of `around` segments and `rings` rings, one point per pole.
Mesh uvSphere(int around, int rings)
{
  Mesh mesh;
  mesh.Points.emplace_back(0.0, 0.0, 1.0);
  for (int r = 1; r < rings; ++r)
  {
    const double polar = Pi * r / rings;
    for (int i = 0; i < around; ++i)
    {
      const double a = 2 * Pi * i / around;
      mesh.Points.emplace_back(
        std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    }
  }
  mesh.Points.emplace_back(0.0, 0.0, -1.0);
  const Id south = static_cast<Id>(mesh.Points.size()) - 1;
  auto at = [around](int r, int i) {
    return 1 + (r - 1) * around + (i % around);
  };
  for (int i = 0; i < around; ++i)
  {
    mesh.Triangles.push_back({ 0, at(1, i), at(1, i + 1) });
    for (int r = 1; r + 1 < rings; ++r)
    {
      mesh.Triangles.push_back({ at(r, i), at(r + 1, i), at(r + 1, i + 1) });
      mesh.Triangles.push_back({ at(r, i), at(r + 1, i + 1), at(r, i + 1) });
    }
    mesh.Triangles.push_back({ south, at(rings - 1, i + 1), at(rings - 1, i) });
  }
  return mesh;
}

Mesh icosahedron()
{
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh mesh;
  mesh.Points = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g }, { 0, 1, g },
    { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 }, { -g, 0, 1 } };
  mesh.Triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };
  return mesh;
}

} // namespace

TEST(ConeApexes, AConesTipIsAnApex)
{
  // Half-angles of 45 and 14 degrees: spreads of 45 and 76 degrees.
  for (const double height : { 1.0, 4.0 })
  {
    for (const int n : { 12, 16, 64, 1000 })
    {
      EXPECT_EQ(apexesOf(cone(n, height)), std::vector<Id>{ 0 }) << n << " sides, " << height;
    }
  }
  // A blunt cone (half-angle 56 degrees: a spread of 34) is a smooth vertex.
  EXPECT_TRUE(apexesOf(cone(64, 0.67)).empty());
}

TEST(ConeApexes, CoarseAndFineSmoothSurfacesHaveNone)
{
  // Spread 37 degrees, turn 42: coarse, not pointed.
  EXPECT_TRUE(apexesOf(icosahedron()).empty());
  // The poles of UV spheres: fans of small spread.
  EXPECT_TRUE(apexesOf(uvSphere(24, 12)).empty());
  EXPECT_TRUE(apexesOf(uvSphere(400, 200)).empty());
  // A cone of few sides turns as much between its sides as a coarse smooth
  // vertex does: 8 sides at 45 degrees turn by 32 against a spread of 45.
  EXPECT_TRUE(apexesOf(cone(8, 1.0)).empty());
  // The poles of a coarse ellipsoid stretched 4:1 along them: fans of 16
  // spread 38 degrees (a user's trial found them drawn pointed at 30).
  Mesh ellipsoid = uvSphere(16, 8);
  for (glm::dvec3& p : ellipsoid.Points)
  {
    p.z *= 4.0;
  }
  EXPECT_TRUE(apexesOf(ellipsoid).empty());
}
