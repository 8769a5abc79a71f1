// Feature edges, feature segments and the splitting of feature points
// (FeatureCurves.h), with answers known in closed form.
#include "CoreTestMeshes.h"
#include "FeatureCurves.h"
#include "SilhouetteSmoother.h"
#include "SmoothingResultCheck.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <thread>

using namespace silsmooth;

namespace
{

constexpr double Pi = 3.14159265358979323846;

std::vector<glm::dvec3> circlePoints(int n, double radius, double firstAngle = 0.0)
{
  std::vector<glm::dvec3> points;
  for (int i = 0; i < n; ++i)
  {
    const double a = firstAngle + 2.0 * Pi * i / n;
    points.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.0);
  }
  return points;
}

double worstRadiusError(const FeatureCurves& curves, double radius)
{
  double worst = 0.0;
  for (std::size_t i = 0; i < curves.edges().size(); ++i)
  {
    for (int k = 0; k <= 64; ++k)
    {
      const glm::dvec3 p = curves.curve(static_cast<Id>(i)).evaluate(k / 64.0);
      worst = std::max(worst, std::abs(glm::length(p) - radius));
    }
  }
  return worst;
}

// A closed n-gon's edges.
std::vector<FeatureEdge> loop(int n, Id offset = 0)
{
  std::vector<FeatureEdge> edges;
  for (int i = 0; i < n; ++i)
  {
    edges.emplace_back(offset + i, offset + (i + 1) % n);
  }
  return edges;
}

} // namespace

TEST(FeatureCurves, ClosedPolygonOnACircleGivesTheCircle)
{
  // 12 segments of 30 degrees: the cubic arc error is about 2e-6 of the radius
  // (the straight edges are 3.4e-2 off).
  const double radius = 3.0;
  const FeatureCurves curves(circlePoints(12, radius), loop(12));
  ASSERT_EQ(curves.curvedCount(), 12u);
  EXPECT_LT(worstRadiusError(curves, radius), 1e-5 * radius);
  // G1: at every vertex the two segments' tangents are parallel.
  for (int i = 0; i < 12; ++i)
  {
    const Id into = curves.find(static_cast<Id>((i + 11) % 12), static_cast<Id>(i));
    const Id out = curves.find(static_cast<Id>(i), static_cast<Id>((i + 1) % 12));
    ASSERT_GE(into, 0);
    ASSERT_GE(out, 0);
    // Tangent at vertex i as each segment leaves or arrives there.
    const auto tangentAt = [&](Id e) {
      const HermiteCurve& c = curves.curve(e);
      return curves.edges()[static_cast<std::size_t>(e)].first == i ? c.T0 : c.T1;
    };
    const glm::dvec3 a = glm::normalize(tangentAt(into));
    const glm::dvec3 b = glm::normalize(tangentAt(out));
    EXPECT_GT(std::abs(glm::dot(a, b)), 1.0 - 1e-12);
  }
}

TEST(FeatureCurves, OpenArcEndsFollowTheCircleToo)
{
  // A quarter circle in 4 edges: the end segments use the circle through the
  // end and its next two points.
  std::vector<glm::dvec3> points;
  for (int i = 0; i <= 4; ++i)
  {
    const double a = 0.5 * Pi * i / 4;
    points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  const FeatureCurves curves(points, { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 4 } });
  ASSERT_EQ(curves.curvedCount(), 4u);
  EXPECT_LT(worstRadiusError(curves, 1.0), 1e-5);
}

TEST(FeatureCurves, SingleEdgesAndCornersStayStraight)
{
  // A square's outline turns by 90 degrees at every vertex: corners.
  const std::vector<glm::dvec3> square{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  const FeatureCurves corners(square, loop(4));
  EXPECT_EQ(corners.curvedCount(), 0u);
  // A lone edge is not smoothed; its segment is the edge.
  const FeatureCurves lone(square, { { 2, 0 } });
  ASSERT_EQ(lone.edges().size(), 1u);
  EXPECT_FALSE(lone.isCurved(0));
  const glm::dvec3 middle = lone.curve(0).evaluate(0.5);
  EXPECT_NEAR(glm::length(middle - glm::dvec3(0.5, 0.5, 0.0)), 0.0, 1e-15);
  // Repeats, reversed pairs, self-edges and unknown points are dropped.
  const FeatureCurves messy(square, { { 1, 0 }, { 0, 1 }, { 2, 2 }, { 3, 9 } });
  EXPECT_EQ(messy.edges().size(), 1u);
  EXPECT_EQ(messy.find(1, 0), 0);
  EXPECT_EQ(messy.find(2, 3), -1);
}

// A rounded rectangle as OpenSCAD tessellates hull() of four cylinders:
// 60 x 30 straight sides between quarter circles of radius 6 in 5 segments
// each (18 degrees; a side is 32 times as long). The sides stay straight
// (their end tangents are their own direction), while eq. 1's tangent there,
// the bisector of the two edges' directions, turns 4.5 degrees off the side
// (the wrong variant: it bowed a plate's sides by 11 px) and would put the
// side's middle 0.6 (short sides) to 1.2 (long sides) off the line. The arcs
// still follow their circle.
TEST(FeatureCurves, ACadLineBesideAnArcStaysStraight)
{
  const double radius = 6.0;
  const glm::dvec2 centres[4] = { { 60, 30 }, { 0, 30 }, { 0, 0 }, { 60, 0 } };
  std::vector<glm::dvec3> points;
  for (int corner = 0; corner < 4; ++corner)
  {
    for (int k = 0; k <= 5; ++k) // from the corner's first side to its next
    {
      const double a = Pi / 2.0 * corner + Pi / 2.0 * k / 5.0;
      points.emplace_back(
        centres[corner].x + radius * std::cos(a), centres[corner].y + radius * std::sin(a), 0.0);
    }
  }
  const int n = static_cast<int>(points.size()); // 24: sides join k = 5 to the next k = 0
  const FeatureCurves curves(points, loop(n));
  ASSERT_EQ(curves.curvedCount(), static_cast<std::size_t>(n));
  for (int corner = 0; corner < 4; ++corner)
  {
    const Id a = 6 * corner + 5;
    const Id b = (6 * corner + 6) % n;
    const Id side = curves.find(a, b);
    ASSERT_GE(side, 0);
    const glm::dvec3 from = points[static_cast<std::size_t>(a)];
    const glm::dvec3 chord = points[static_cast<std::size_t>(b)] - from;
    double farthest = 0.0;
    for (int k = 0; k <= 64; ++k)
    {
      const glm::dvec3 p = curves.curve(side).evaluate(k / 64.0) - from;
      farthest = std::max(farthest, glm::length(glm::cross(p, chord)) / glm::length(chord));
    }
    EXPECT_LT(farthest, 1e-9 * glm::length(chord)) << "side " << corner;
    // Eq. 1's tangent at the side's start, and the bow it would give.
    const glm::dvec3 w0 = from - points[static_cast<std::size_t>(a - 1)];
    const glm::dvec3 eq1 = glm::normalize(glm::length(chord) * w0 + glm::length(w0) * chord);
    const double turn = std::acos(glm::dot(eq1, glm::normalize(chord))) * 180.0 / Pi;
    EXPECT_NEAR(turn, 4.5, 1e-6) << "side " << corner;
    EXPECT_GT(glm::length(chord) * std::tan(turn * Pi / 180.0) / 4.0, 0.5);
  }
  for (int corner = 0; corner < 4; ++corner)
  {
    for (int k = 0; k < 5; ++k)
    {
      const Id e = curves.find(6 * corner + k, 6 * corner + k + 1);
      ASSERT_GE(e, 0);
      for (int j = 0; j <= 16; ++j)
      {
        const glm::dvec3 p = curves.curve(e).evaluate(j / 16.0);
        const glm::dvec3 c(centres[corner].x, centres[corner].y, 0.0);
        EXPECT_NEAR(glm::length(p - c), radius, 0.02 * radius) << corner << " " << k;
      }
    }
  }
}

// The counter-case: a circle sampled unevenly, edges of 5 and 25 degrees in
// turn (five times as long) or runs of short edges then one long one. It is
// no line meeting an arc (every vertex turns as much as, or more than, its
// short edge's far end), so every tangent stays eq. 1's (the bisector);
// taking the long edge's direction there would lean the wrong way.
TEST(FeatureCurves, AnUnevenlySampledCurveKeepsEqOneTangents)
{
  for (const std::vector<double>& steps :
    { std::vector<double>{ 5, 25 }, std::vector<double>{ 4, 4, 4, 24 } })
  {
    std::vector<glm::dvec3> points;
    double angle = 0.0;
    for (std::size_t k = 0; angle < 359.0; ++k)
    {
      points.emplace_back(std::cos(angle * Pi / 180.0), std::sin(angle * Pi / 180.0), 0.0);
      angle += steps[k % steps.size()];
    }
    const int n = static_cast<int>(points.size());
    const FeatureCurves curves(points, loop(n));
    ASSERT_EQ(curves.curvedCount(), static_cast<std::size_t>(n));
    for (int v = 0; v < n; ++v)
    {
      const glm::dvec3& p = points[static_cast<std::size_t>(v)];
      const glm::dvec3 w0 = p - points[static_cast<std::size_t>((v + n - 1) % n)];
      const glm::dvec3 w1 = points[static_cast<std::size_t>((v + 1) % n)] - p;
      const glm::dvec3 bisector = glm::normalize(glm::normalize(w0) + glm::normalize(w1));
      const Id e = curves.find(v, (v + 1) % n);
      ASSERT_GE(e, 0);
      const HermiteCurve& c = curves.curve(e);
      const glm::dvec3 t = c.P0 == p ? c.T0 : c.T1;
      EXPECT_LT(glm::length(glm::cross(glm::normalize(t), bisector)), 1e-12) << v;
    }
  }
}

TEST(FeatureCurves, CircleTangentLengthIsTheArcApproximation)
{
  // A 90-degree arc of radius 1: chord sqrt(2), theta 45 degrees; the
  // standard cubic has tangent length 4 tan(22.5 degrees).
  const glm::dvec3 chord(-1.0, 1.0, 0.0);
  const glm::dvec3 t = circleTangentAlong(glm::dvec3(0.0, 1.0, 0.0), chord);
  EXPECT_NEAR(glm::length(t), 4.0 * std::tan(Pi / 8), 1e-12);
  // A direction against the chord is turned round; none gives the chord.
  EXPECT_GT(glm::dot(circleTangentAlong(glm::dvec3(0.0, -1.0, 0.0), chord), chord), 0.0);
  EXPECT_EQ(circleTangentAlong(glm::dvec3(0.0), chord), chord);
}

namespace
{

// An axis-aligned cube, two outward triangles per face.
void cube(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles)
{
  points.clear();
  for (int i = 0; i < 8; ++i)
  {
    points.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  }
  const int faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  triangles.clear();
  for (const auto& f : faces)
  {
    triangles.push_back({ f[0], f[1], f[2] });
    triangles.push_back({ f[0], f[2], f[3] });
  }
}

} // namespace

TEST(FeatureCurves, CubeEdgesAreDetectedAndItsCornersSplitInThree)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  cube(points, triangles);
  const std::vector<FeatureEdge> sharp = featureEdgesByAngle(points, triangles, 30.0);
  EXPECT_EQ(sharp.size(), 12u); // the face diagonals are flat
  // One triangle turned over must not make its flat diagonal a feature.
  std::vector<Triangle> turned = triangles;
  std::swap(turned[0][1], turned[0][2]);
  EXPECT_EQ(featureEdgesByAngle(points, turned, 30.0).size(), 12u);

  const FeatureCurves features(points, sharp);
  EXPECT_EQ(features.curvedCount(), 0u); // every vertex is a corner of three
  const FeatureSplit split = splitAtFeatureEdges(points.size(), triangles, features);
  EXPECT_EQ(split.CopySources.size(), 16u); // 3 groups per corner: 2 copies each
  // Each face's two triangles share their points; no two faces share one.
  std::map<Id, std::set<int>> facesOfPoint;
  for (std::size_t t = 0; t < split.Triangles.size(); ++t)
  {
    for (const Id v : split.Triangles[t])
    {
      facesOfPoint[v].insert(static_cast<int>(t / 2));
    }
  }
  EXPECT_EQ(facesOfPoint.size(), 24u);
  for (const auto& entry : facesOfPoint)
  {
    EXPECT_EQ(entry.second.size(), 1u);
  }
}

namespace
{

// A capped cylinder (12 sides, axis z, unit radius, z in [-1, 1]).
void cylinder(std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles)
{
  coretest::cappedCylinder(12, points, triangles);
}

} // namespace

TEST(FeatureCurves, CylinderRimsAreSmoothAndTheMeshStaysClosed)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  cylinder(points, triangles);
  const PreparedMesh mesh(points, triangles, {}, featureEdgesByAngle(points, triangles, 60.0));
  ASSERT_EQ(mesh.features().edges().size(), 24u);
  ASSERT_EQ(mesh.features().curvedCount(), 24u);
  EXPECT_EQ(mesh.points().size(), points.size() + 24); // a copy per rim point
  EXPECT_EQ(mesh.featureTriangles().size(), triangles.size());
  // The rim points' copies: one with the side's normal, one with the cap's.
  for (std::size_t p = 0; p < mesh.points().size(); ++p)
  {
    const glm::dvec3 n = mesh.normals()[p];
    if (mesh.onFeature(static_cast<Id>(p)))
    {
      EXPECT_TRUE(std::abs(n.z) > 1.0 - 1e-12 || std::abs(n.z) < 1e-12);
    }
  }

  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * Pi);
  std::uniform_real_distribution<double> height(-4.0, 4.0);
  for (int v = 0; v < 200; ++v)
  {
    const double a = angle(random);
    ViewGeometry view;
    view.Eye = glm::dvec3(5.0 * std::cos(a), 5.0 * std::sin(a), height(random));
    view.ModelToClip = glm::dmat4(0.5);
    view.ModelToClip[3][3] = 1.0;
    const SmoothingResult result = smoothSilhouettes(mesh, view, SmoothingParameters{});
    ASSERT_TRUE(coretest::closedOnceWelded(mesh, result)) << "view " << v;
    std::size_t featureKinds = 0;
    for (const RemeshKind kind : result.RemeshKinds)
    {
      featureKinds += kind == RemeshKind::Feature ? 1 : 0;
    }
    EXPECT_EQ(featureKinds, triangles.size());
    // Every added point between two points of one rim (feature samples and
    // silhouette points on the rim's feature segments) lies on the rim's
    // circle, to the cubic's arc error.
    for (const NewPoint& p : result.NewPoints)
    {
      const glm::dvec3& a = mesh.points()[static_cast<std::size_t>(p.Sources[0])];
      const glm::dvec3& b = mesh.points()[static_cast<std::size_t>(p.Sources[1])];
      if (p.Weights[2] == 0.0 && std::abs(a.z) == 1.0 && a.z == b.z &&
        std::abs(glm::length(glm::dvec2(a)) - 1.0) < 1e-12 &&
        std::abs(glm::length(glm::dvec2(b)) - 1.0) < 1e-12)
      {
        EXPECT_NEAR(glm::length(glm::dvec2(p.Position)), 1.0, 1e-5);
        EXPECT_EQ(p.Position.z, a.z);
      }
    }
  }
}

TEST(FeatureCurves, WithoutFeaturesNothingIsSplit)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  cylinder(points, triangles);
  const PreparedMesh mesh(points, triangles);
  EXPECT_EQ(mesh.points().size(), points.size());
  EXPECT_TRUE(mesh.featureTriangles().empty());
  EXPECT_EQ(mesh.triangles(), triangles);
}

TEST(FeatureCurves, DihedralAnglesAreTheSameOnAnySplit)
{
  // A bumpy, partly flipped sphere with repeated and degenerate triangles
  // and a flat patch: the cosines (bit for bit, NaN where an edge is not
  // between two usable triangles) and the flat-sided creases do not depend
  // on how the loops are split over threads.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> bump(-0.02, 0.02);
  const int rings = 24;
  const int sectors = 48;
  for (int r = 0; r <= rings; ++r)
  {
    for (int k = 0; k < sectors; ++k)
    {
      const double theta = 3.14159265358979 * r / rings;
      const double phi = 2.0 * 3.14159265358979 * k / sectors;
      const double radius = r < 6 ? 1.0 : 1.0 + bump(rng); // a smooth cap, a bumpy rest
      points.emplace_back(radius * std::sin(theta) * std::cos(phi),
        radius * std::sin(theta) * std::sin(phi), r < 3 ? 0.9 : radius * std::cos(theta));
    }
  }
  auto at = [&](int r, int k) {
    return static_cast<Id>(r * sectors + (k % sectors));
  };
  for (int r = 0; r < rings; ++r)
  {
    for (int k = 0; k < sectors; ++k)
    {
      triangles.push_back({ { at(r, k), at(r + 1, k), at(r + 1, k + 1) } });
      triangles.push_back({ { at(r, k), at(r + 1, k + 1), at(r, k + 1) } });
    }
  }
  for (std::size_t t = 0; t < triangles.size(); t += 11)
  {
    std::swap(triangles[t][1], triangles[t][2]);
  }
  triangles.push_back(triangles[40]);
  triangles[77][2] = triangles[77][0];
  const EdgeTable table(triangles);
  const EdgeSides sides = edgeSidesOf(triangles, table);
  auto threaded = [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
    std::vector<std::thread> pool;
    const std::size_t chunk = count / 3 + 1;
    for (std::size_t begin = 0; begin < count; begin += chunk)
    {
      pool.emplace_back(body, begin, std::min(count, begin + chunk));
    }
    for (std::thread& t : pool)
    {
      t.join();
    }
  };
  const std::vector<double> serial = dihedralCosines(points, triangles, table);
  const std::vector<double> split = dihedralCosines(points, triangles, sides, threaded);
  ASSERT_EQ(serial.size(), split.size());
  EXPECT_EQ(std::memcmp(serial.data(), split.data(), serial.size() * sizeof(double)), 0);
  EXPECT_GT(std::count_if(serial.begin(), serial.end(), [](double c) { return std::isnan(c); }), 0);
  const std::vector<FeatureEdge> creases = flatSidedCreases(points, triangles, 20.0, &table);
  EXPECT_EQ(flatSidedCreases(split, sides, table, 20.0, threaded), creases);
  EXPECT_FALSE(creases.empty()); // the flat cap's rim
}

// An angle equal to the limit, up to rounding, falls on one side for every
// edge: a regular 12-sided cylinder's side edges turn by exactly 30 degrees,
// and at a feature angle of 30 none of them is a crease (rounding made some
// of them creases and not others: a user's OpenSCAD cylinder drew a stray
// hard line down one side). Its rims (90 degrees) are, all 24; at 29.9
// degrees the side edges are too, all 12.
TEST(FeatureCurves, AnAngleEqualToTheLimitIsTheSameForEveryEdge)
{
  for (const double radius : { 1.0, 20.0, 0.37 })
  {
    std::vector<glm::dvec3> points;
    std::vector<Triangle> triangles;
    coretest::cappedCylinder(12, points, triangles);
    for (glm::dvec3& p : points)
    {
      p = glm::dvec3(radius * p.x, radius * p.y, 15.0 * p.z);
    }
    EXPECT_EQ(featureEdgesByAngle(points, triangles, 30.0).size(), 24u) << "radius " << radius;
    EXPECT_EQ(featureEdgesByAngle(points, triangles, 29.9).size(), 36u) << "radius " << radius;
  }
}
