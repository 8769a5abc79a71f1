// Vertex-normal estimates (ShadingNormals.h): known answers, and the
// deliberately wrong estimate that misses each.
#include "CoreTestMeshes.h"
#include "ShadingNormals.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace silsmooth;

namespace
{

// Worst angle (radians) between the estimate and the unit sphere's normal.
double worstSphereError(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& n)
{
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    // atan2 of sine and cosine: acos loses half the digits near 0.
    const glm::dvec3 exact = glm::normalize(points[i]);
    worst =
      std::max(worst, std::atan2(glm::length(glm::cross(exact, n[i])), glm::dot(exact, n[i])));
  }
  return worst;
}

// A UV sphere whose rings are turned by random amounts: points on the unit
// sphere, irregular fans.
void irregularSphere(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles)
{
  coretest::unitSphere(9, 13, points, triangles);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> turn(-0.2, 0.2);
  for (int ring = 1; ring < 9; ++ring)
  {
    const double a = turn(random);
    for (int s = 0; s < 13; ++s)
    {
      glm::dvec3& p = points[static_cast<std::size_t>(1 + (ring - 1) * 13 + s)];
      p = glm::dvec3(
        std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y, p.z);
    }
  }
}

} // namespace

TEST(ShadingNormals, MaxWeightsAreExactOnASphere)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  irregularSphere(points, triangles);
  const double max =
    worstSphereError(points, vertexNormals(points, triangles, NormalWeighting::Max));
  const double angle =
    worstSphereError(points, vertexNormals(points, triangles, NormalWeighting::Angle));
  const double area =
    worstSphereError(points, vertexNormals(points, triangles, NormalWeighting::Area));
  std::printf("irregular sphere, worst normal error: Max %.2e, angle %.2e, area %.2e rad\n", max,
    angle, area);
  EXPECT_LT(max, 1e-12);
  // The weights that are not exact here miss by far more.
  EXPECT_GT(angle, 1e-4);
  EXPECT_GT(area, 1e-4);
}

TEST(ShadingNormals, AngleWeightingIsTheDefault)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  irregularSphere(points, triangles);
  EXPECT_EQ(vertexNormals(points, triangles, NormalWeighting::Angle),
    angleWeightedNormals(points, triangles));
}

TEST(ShadingNormals, AreaWeightsFollowTheLargerFace)
{
  // Two faces at the origin: a large one in the z = 0 plane, a small one in
  // the x = 0 plane, with equal corner angles (90 degrees) at the origin.
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, { 0, 0, 1 },
    { 0, 1, 0 } };
  const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 0, 4, 3 } } };
  const glm::dvec3 area = vertexNormals(points, triangles, NormalWeighting::Area)[0];
  const glm::dvec3 angle = vertexNormals(points, triangles, NormalWeighting::Angle)[0];
  // Area: (0, 0, 16) + (1, 0, 0) normalised; angle: equal halves.
  EXPECT_NEAR(area.z / area.x, 16.0, 1e-12);
  EXPECT_NEAR(angle.z / angle.x, 1.0, 1e-12);
}

TEST(ShadingNormals, QuadricFitIsNearTheNormalOfAParaboloid)
{
  // A vertex on z = 0.3 x^2 + 0.2 x y - 0.5 y^2 + 0.4 x - 0.1 y with six
  // neighbours on the same surface: the fitted normal is the surface's.
  auto z = [](double x, double y) {
    return 0.3 * x * x + 0.2 * x * y - 0.5 * y * y + 0.4 * x - 0.1 * y;
  };
  std::vector<glm::dvec3> points{ { 0, 0, 0 } };
  std::vector<Triangle> triangles;
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < 7; ++k)
  {
    const double a = 2 * pi * k / 7 + 0.3 * (k % 2);
    const double r = 0.5 + 0.1 * k;
    points.emplace_back(r * std::cos(a), r * std::sin(a), z(r * std::cos(a), r * std::sin(a)));
  }
  for (Id k = 0; k < 7; ++k)
  {
    triangles.push_back({ { 0, 1 + k, 1 + (k + 1) % 7 } });
  }
  const glm::dvec3 exact = glm::normalize(glm::dvec3(-0.4, 0.1, 1.0));
  auto error = [&](const glm::dvec3& n) {
    return std::atan2(glm::length(glm::cross(exact, n)), glm::dot(exact, n));
  };
  const double fit = error(vertexNormals(points, triangles, NormalWeighting::QuadricFit)[0]);
  const double angle = error(vertexNormals(points, triangles, NormalWeighting::Angle)[0]);
  std::printf(
    "paraboloid vertex, normal error: quadric fit %.2e, angle-weighted %.2e rad\n", fit, angle);
  // The fit is made in the tilted frame of the angle-weighted normal, where
  // the surface is a quadric only to second order: near, not exact.
  EXPECT_LT(fit, 0.5 * angle);
  EXPECT_GT(angle, 1e-2); // the fan alone is biased here
}

TEST(ShadingNormals, QuadricFitFallsBackWithFewNeighbours)
{
  // A tetrahedron: three neighbours per vertex, too few for the fit.
  const std::vector<glm::dvec3> points{ { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
  const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 0, 3, 1 } }, { { 0, 2, 3 } },
    { { 1, 3, 2 } } };
  EXPECT_EQ(vertexNormals(points, triangles, NormalWeighting::QuadricFit),
    angleWeightedNormals(points, triangles));
}
