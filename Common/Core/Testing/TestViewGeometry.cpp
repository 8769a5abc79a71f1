// ViewGeometry::pixelShiftBound: how far an image point moves, at most, for a
// point near a triangle moved by a given distance.
#include "ViewGeometry.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using silsmooth::ViewGeometry;

namespace
{

glm::dvec3 randomDirection(std::mt19937& random)
{
  std::normal_distribution<double> gauss;
  return glm::normalize(glm::dvec3(gauss(random), gauss(random), gauss(random)));
}

ViewGeometry viewFrom(const glm::dvec3& eye, bool parallel, double fovDegrees = 40.0)
{
  ViewGeometry view;
  view.Parallel = parallel;
  view.Eye = eye;
  view.TowardViewer = glm::normalize(eye);
  view.ViewportWidth = 800;
  view.ViewportHeight = 600;
  const glm::dmat4 camera = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  view.ModelToClip = parallel
    ? glm::ortho(-2.0, 2.0, -1.5, 1.5, 0.1, 20.0) * camera
    : glm::perspective(glm::radians(fovDegrees), 800.0 / 600.0, 0.1, 20.0) * camera;
  return view;
}

struct Measured
{
  double Worst = 0.0; // largest measured move / bound
};

// Random points of random triangles near the origin, moved by `distance` in
// random directions (staying within `distance` of the triangle).
Measured measure(const ViewGeometry& view, double size, double distance, std::mt19937& random)
{
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Measured m;
  for (int i = 0; i < 2000; ++i)
  {
    const glm::dvec3 centre = 1.2 * randomDirection(random);
    const glm::dvec3 a = centre + size * randomDirection(random);
    const glm::dvec3 b = centre + size * randomDirection(random);
    const glm::dvec3 c = centre + size * randomDirection(random);
    const double bound = view.pixelShiftBound(a, b, c, distance);
    for (int k = 0; k < 20; ++k)
    {
      double u = uniform(random);
      double v = uniform(random);
      if (u + v > 1.0)
      {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      const glm::dvec3 from = a + u * (b - a) + v * (c - a);
      const glm::dvec3 to = from + distance * randomDirection(random);
      glm::dvec2 p;
      glm::dvec2 q;
      const bool projected = view.toPixels(from, p) && view.toPixels(to, q);
      EXPECT_TRUE(projected);
      if (!projected)
      {
        continue;
      }
      const double moved = glm::length(q - p);
      m.Worst = std::max(m.Worst, moved / bound);
    }
  }
  return m;
}

} // namespace

TEST(ViewGeometry, PixelShiftBoundHoldsInPerspectiveAndParallel)
{
  std::mt19937 random(7);
  for (const bool parallel : { false, true })
  {
    const ViewGeometry view = viewFrom(glm::dvec3(0.5, 0.8, 4.0), parallel);
    for (const double distance : { 1e-4, 1e-2, 0.3 })
    {
      const Measured m = measure(view, 0.2, distance, random);
      EXPECT_LE(m.Worst, 1.0) << (parallel ? "parallel" : "perspective") << ", move " << distance;
      // Not far above what is measured (random directions rarely take the worst one).
      EXPECT_GT(m.Worst, 0.25) << (parallel ? "parallel" : "perspective") << ", move " << distance;
    }
  }
  // A wide view, and a point near the image's right edge moved along the
  // view's axis, toward the eye plane: its image moves outward as the
  // perspective's scale grows, by more than a bound that took the scale
  // (w) as fixed at the corners' would allow.
  const ViewGeometry wide = viewFrom(glm::dvec3(0.0, 0.0, 3.0), false, 120.0);
  const glm::dvec3 a(2.0, 0.0, 1.5);
  const glm::dvec3 b(2.1, 0.0, 1.5);
  const glm::dvec3 c(2.0, 0.1, 1.5);
  const double distance = 0.3;
  glm::dvec2 p;
  glm::dvec2 q;
  ASSERT_TRUE(wide.toPixels(a, p) && wide.toPixels(a + glm::dvec3(0.0, 0.0, distance), q));
  ASSERT_GT(p.x, 0.7 * wide.ViewportWidth);
  const double moved = glm::length(q - p);
  EXPECT_LE(moved, wide.pixelShiftBound(a, b, c, distance));
  const glm::dmat4& mm = wide.ModelToClip;
  const double wLeast = std::min({ mm[2][3] * a.z, mm[2][3] * b.z, mm[2][3] * c.z }) + mm[3][3];
  const double fixedScale = distance / wLeast *
    std::hypot(glm::length(glm::dvec3(mm[0][0], mm[1][0], mm[2][0])) * 0.5 * wide.ViewportWidth,
      glm::length(glm::dvec3(mm[0][1], mm[1][1], mm[2][1])) * 0.5 * wide.ViewportHeight);
  EXPECT_GT(moved, fixedScale);
}

TEST(ViewGeometry, PixelShiftBoundIsInfiniteWhereTheRegionReachesTheEyePlane)
{
  const ViewGeometry view = viewFrom(glm::dvec3(0.0, 0.0, 4.0), false);
  const glm::dvec3 a(0.0, 0.0, 3.5);
  const glm::dvec3 b(0.1, 0.0, 3.5);
  const glm::dvec3 c(0.0, 0.1, 3.5);
  EXPECT_TRUE(std::isfinite(view.pixelShiftBound(a, b, c, 0.1)));
  EXPECT_TRUE(std::isinf(view.pixelShiftBound(a, b, c, 0.6))) << "may move past the eye";
  EXPECT_EQ(view.pixelShiftBound(a, b, c, 0.0), 0.0);
}
