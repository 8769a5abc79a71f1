// Wang et al. 2003 (the baseline): the 2D boundary curve reproduces circular
// arcs, stays straight when the normals say so, and the re-meshed octahedron
// stays a closed, consistently oriented manifold.
#include "BoundaryCurveSmoother.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

using silsmooth::BoundaryCurveMesh;
using silsmooth::BoundaryCurveParameters;
using silsmooth::BoundaryCurveResult;
using silsmooth::HermiteCurve2D;
using silsmooth::Id;
using silsmooth::Triangle;

namespace
{

// Largest |radius - 1| along the boundary curve for an arc of the unit circle
// subtending `angle` radians, with radial end normals.
double arcError(double angle)
{
  const glm::dvec2 x0(1.0, 0.0);
  const glm::dvec2 x1(std::cos(angle), std::sin(angle));
  const HermiteCurve2D curve = silsmooth::boundaryCurve(x0, x1, x0, x1);
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i)
  {
    worst = std::max(worst, std::abs(glm::length(curve.at(i / 1000.0)) - 1.0));
  }
  return worst;
}

} // namespace

TEST(BoundaryCurve, RhoIsTheArcValue)
{
  // theta = 0 (a straight edge) must give tangents of the chord's length:
  // 4 rho |Q - X0| = 4 rho (c / 2) = c needs rho = 1/2.
  EXPECT_DOUBLE_EQ(silsmooth::rhoForHalfAngle(1.0), 0.5);
  EXPECT_DOUBLE_EQ(silsmooth::rhoForHalfAngle(0.5), 0.5 / 1.5);
}

TEST(BoundaryCurve, ReproducesCircularArcs)
{
  // The classical cubic arc error: about 2.7e-4 of the radius for a quarter
  // circle, growing with the sixth power of the angle.
  EXPECT_LT(arcError(M_PI / 6.0), 1e-5);
  EXPECT_LT(arcError(M_PI / 3.0), 3e-5);
  EXPECT_LT(arcError(M_PI / 2.0), 3e-4);
  EXPECT_LT(arcError(2.0 * M_PI / 3.0), 2e-3);
}

TEST(BoundaryCurve, InterpolatesTheEnds)
{
  const HermiteCurve2D curve = silsmooth::boundaryCurve(
    glm::dvec2(3, 4), glm::dvec2(10, -2), glm::dvec2(0.2, 1), glm::dvec2(1, 0.3));
  EXPECT_EQ(curve.at(0.0), glm::dvec2(3, 4));
  EXPECT_LT(glm::distance(curve.at(1.0), glm::dvec2(10, -2)), 1e-12);
}

TEST(BoundaryCurve, StraightWhenTheNormalsAgree)
{
  // Normals perpendicular to the chord: the tangents are the chord.
  const HermiteCurve2D curve = silsmooth::boundaryCurve(
    glm::dvec2(0, 0), glm::dvec2(10, 0), glm::dvec2(0, 1), glm::dvec2(0, 1));
  for (int i = 0; i <= 10; ++i)
  {
    const glm::dvec2 p = curve.at(i / 10.0);
    EXPECT_NEAR(p.y, 0.0, 1e-12);
    EXPECT_NEAR(p.x, static_cast<double>(i), 1e-12);
  }
  BoundaryCurveParameters adaptive;
  EXPECT_EQ(silsmooth::boundaryCurveSampleCount(curve, adaptive), 2);
  // No normal direction in the image: the chord.
  const HermiteCurve2D fallback = silsmooth::boundaryCurve(
    glm::dvec2(0, 0), glm::dvec2(10, 0), glm::dvec2(0, 0), glm::dvec2(0, 0));
  EXPECT_NEAR(fallback.at(0.5).y, 0.0, 1e-12);
}

TEST(BoundaryCurve, AdaptiveSamplingKeepsTheTolerance)
{
  // A quarter of a circle of radius 400 px.
  const double r = 400.0;
  const HermiteCurve2D curve = silsmooth::boundaryCurve(
    glm::dvec2(r, 0), glm::dvec2(0, r), glm::dvec2(1, 0), glm::dvec2(0, 1));
  BoundaryCurveParameters p;
  p.TolerancePixels = 0.5;
  const int samples = silsmooth::boundaryCurveSampleCount(curve, p);
  double worst = 0.0;
  for (int s = 0; s + 1 < samples; ++s)
  {
    const glm::dvec2 a = curve.at(static_cast<double>(s) / (samples - 1));
    const glm::dvec2 b = curve.at(static_cast<double>(s + 1) / (samples - 1));
    for (int i = 0; i <= 20; ++i)
    {
      const double u = (s + i / 20.0) / (samples - 1);
      const glm::dvec2 q = curve.at(u);
      const glm::dvec2 d = b - a;
      const double along = std::clamp(glm::dot(q - a, d) / glm::dot(d, d), 0.0, 1.0);
      worst = std::max(worst, glm::distance(q, a + along * d));
    }
  }
  EXPECT_LE(worst, 0.5);
  EXPECT_GT(samples, 10);
  p.SamplesPerCurve = 5;
  EXPECT_EQ(silsmooth::boundaryCurveSampleCount(curve, p), 5);
}

TEST(BoundaryCurveSmoother, OctahedronStaysClosedAndOriented)
{
  const std::vector<glm::dvec3> points{ { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };
  const std::vector<Triangle> triangles{ { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 },
    { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  const BoundaryCurveMesh mesh(points, triangles, points); // exact sphere normals
  for (const double tilt : { 0.3, 1.0, 2.2 })
  {
    silsmooth::ViewGeometry view;
    view.Eye = 6.0 * glm::normalize(glm::dvec3(std::cos(tilt), 0.7, std::sin(tilt)));
    const glm::dmat4 lookAt =
      glm::lookAt(view.Eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0) + 0.1 * tilt);
    const glm::dmat4 projection = glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.1, 100.0);
    view.ModelToClip = projection * lookAt;
    const glm::dmat3 normalToEye = glm::transpose(glm::inverse(glm::dmat3(lookAt)));
    const BoundaryCurveResult result = mesh.smooth(view, normalToEye, BoundaryCurveParameters());
    EXPECT_GT(result.SilhouetteEdgeCount, 2u);
    EXPECT_GT(result.NewPoints.size(), 0u);
    // Every directed edge once, and its reverse once.
    std::map<std::pair<Id, Id>, int> directed;
    for (const Triangle& t : result.Triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        ++directed[{ t[k], t[(k + 1) % 3] }];
      }
    }
    for (const auto& [edge, count] : directed)
    {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(directed.count({ edge.second, edge.first }), 1u);
    }
    // Sampled curve points lie between the straight edge and the unit sphere's
    // reach: no further out than the sphere's radius by much.
    for (const glm::dvec3& p : result.NewPoints)
    {
      EXPECT_LT(glm::length(p), 1.3);
    }
  }
}
