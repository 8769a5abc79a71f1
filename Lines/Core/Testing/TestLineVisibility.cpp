// Hidden-line removal (Lines/Core/LineVisibility.h) on scenes whose answers
// are exact: a square in front of a line (parallel view), a line just under
// a surface (the tolerance), and a sphere in front of a square's border
// (perspective), each point checked against the exact sphere.
#include "EdgeClassification.h"
#include "LineVisibility.h"
#include "SilhouetteSmoother.h"

#include "CoreTestMeshes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace silsmooth;

namespace
{

// Two triangles: the square [-1, 1]^2 at height z, facing +z.
void square(double z, std::vector<glm::dvec3>& points, std::vector<Triangle>& triangles)
{
  points = { { -1, -1, z }, { 1, -1, z }, { 1, 1, z }, { -1, 1, z } };
  triangles = { { { 0, 1, 2 } }, { { 0, 2, 3 } } };
}

ViewGeometry fromAbove()
{
  ViewGeometry view;
  view.Parallel = true;
  view.TowardViewer = glm::dvec3(0, 0, 1);
  return view;
}

// fromAbove() on a 1000 x 1000 viewport, 100 pixels per unit: a pixel is
// 0.01 (for the OutlinePixels rules).
ViewGeometry fromAboveInPixels()
{
  ViewGeometry view = fromAbove();
  view.ViewportWidth = view.ViewportHeight = 1000;
  view.ModelToClip = glm::dmat4(0.2);
  view.ModelToClip[3][3] = 1.0;
  return view;
}

// The rule the OutlinePixels tests use: a tolerance of 0.2 pixel, a pixel
// beside the line.
LineVisibilityParameters outlineRule()
{
  LineVisibilityParameters parameters;
  parameters.Tolerance = 2e-3;
  parameters.Precision = 1e-10;
  parameters.Contact = 1e-6;
  parameters.OutlinePixels = 1.0;
  return parameters;
}

// A line along y at x = x0, z = 0, in three vertices.
std::vector<glm::dvec3> lineAlongY(double x0)
{
  return { { x0, -0.5, 0.0 }, { x0, 0.0, 0.0 }, { x0, 0.5, 0.0 } };
}

// The pieces join end to start bit for bit, alternate, and hold every input
// vertex in order.
void expectWellFormed(const std::vector<LinePiece>& pieces, const std::vector<glm::dvec3>& line)
{
  ASSERT_FALSE(pieces.empty());
  std::vector<glm::dvec3> vertices;
  double along = 0.0;
  for (std::size_t k = 0; k < pieces.size(); ++k)
  {
    ASSERT_GE(pieces[k].Points.size(), 2u);
    ASSERT_EQ(pieces[k].Along.size(), pieces[k].Points.size());
    for (std::size_t i = 0; i < pieces[k].Points.size(); ++i)
    {
      // Ascending, and a point's place along the line is where it is.
      const double a = pieces[k].Along[i];
      EXPECT_GE(a, along);
      along = a;
      const std::size_t i0 = std::min(static_cast<std::size_t>(a), line.size() - 1);
      const glm::dvec3 expected = i0 + 1 < line.size()
        ? line[i0] + (a - static_cast<double>(i0)) * (line[i0 + 1] - line[i0])
        : line[i0];
      EXPECT_LT(glm::length(pieces[k].Points[i] - expected), 1e-12);
    }
    if (k > 0)
    {
      EXPECT_EQ(pieces[k].Points.front(), pieces[k - 1].Points.back());
      EXPECT_NE(pieces[k].Visible, pieces[k - 1].Visible);
    }
    const std::size_t begin = k == 0 ? 0 : 1;
    const std::size_t end =
      k + 1 == pieces.size() ? pieces[k].Points.size() : pieces[k].Points.size() - 1;
    vertices.insert(vertices.end(), pieces[k].Points.begin() + static_cast<std::ptrdiff_t>(begin),
      pieces[k].Points.begin() + static_cast<std::ptrdiff_t>(end));
  }
  EXPECT_EQ(vertices, line);
}

} // namespace

TEST(LineVisibility, SquareHidesTheLineBehindIt)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  square(1.0, points, triangles);
  const OcclusionMesh surface(points, triangles);
  LineVisibilityParameters parameters;
  parameters.Tolerance = 1e-6;
  parameters.Precision = 1e-10;
  std::vector<glm::dvec3> line;
  for (const double x : { -3.0, -1.5, -0.5, 0.5, 1.5, 3.0 })
  {
    line.emplace_back(x, 0.3, 0.0);
  }
  const std::vector<LinePiece> pieces = splitByVisibility(surface, fromAbove(), line, parameters);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_TRUE(pieces[0].Visible);
  EXPECT_FALSE(pieces[1].Visible);
  EXPECT_TRUE(pieces[2].Visible);
  // The changes where the line passes under the square's edges, x = -1 and 1.
  EXPECT_NEAR(pieces[0].Points.back().x, -1.0, 1e-9);
  EXPECT_NEAR(pieces[2].Points.front().x, 1.0, 1e-9);
  expectWellFormed(pieces, line);
}

// OutlinePixels, on a sheet that folds back over the edge a line lies along
// (as a smoothed surface's flat triangles stand a little beyond its
// silhouette curve): the square [0, 1] x [-1, 1] at z = 0 with a flap
// hinged on its edge x = 1 leaning back over it to x = `back` at height
// 0.01, seen from above at 100 pixels per unit. A line on the square at x0
// is hidden by the flap 2.5 to 3 tolerances above it.
//   - Half a pixel inside the outline (x = 1): drawn; with the rule off (the
//     wrong variant), hidden.
//   - Three pixels inside: hidden (a pixel across is still under the flap).
//   - The flap a separate sheet (its hinge a hair off the square's edge):
//     hidden; an occluder that is not the line's own sheet is never
//     discounted, so a line passing behind another part keeps its exact
//     change points.
TEST(LineVisibility, ALineWithinAPixelOfItsSheetsOutlineIsDrawn)
{
  auto fold = [](double back, double hinge) {
    const std::vector<glm::dvec3> points{ { 0, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
      { hinge, -1, 0 }, { hinge, 1, 0 }, { back, 1, 0.01 }, { back, -1, 0.01 } };
    const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 0, 2, 3 } }, { { 4, 5, 6 } },
      { { 4, 6, 7 } } };
    return OcclusionMesh(points, triangles);
  };
  const ViewGeometry view = fromAboveInPixels();
  const LineVisibilityParameters parameters = outlineRule();
  LineVisibilityParameters off = parameters;
  off.OutlinePixels = 0.0;
  auto visibleAt = [&](const OcclusionMesh& surface, double x0,
                     const LineVisibilityParameters& rule) {
    const std::vector<glm::dvec3> line = lineAlongY(x0);
    const std::vector<LinePiece> pieces = splitByVisibility(surface, view, line, rule);
    EXPECT_EQ(pieces.size(), 1u) << x0;
    return !pieces.empty() && pieces[0].Visible;
  };
  EXPECT_TRUE(visibleAt(fold(0.99, 1.0), 0.995, parameters));
  EXPECT_FALSE(visibleAt(fold(0.99, 1.0), 0.995, off));
  EXPECT_FALSE(visibleAt(fold(0.95, 1.0), 0.97, parameters));
  EXPECT_FALSE(visibleAt(fold(0.99, 1.0 + 1e-7), 0.995, parameters));
}

// The other way round: a line under a flap of its own sheet nearer than the
// tolerance (a part thinner than the tolerance, folded over it) is visible by
// the sheet rule; with OutlinePixels it is hidden when the points 1.5 pixels
// to both sides of it are hidden too, and drawn when it is within that of
// either edge of the flap's image.
TEST(LineVisibility, ALineWellInsideItsSheetsImageIsHidden)
{
  // The square z = 0, x in [0, 1], folded at x = 1 back over itself to
  // x = 0.9, 0.001 above it (the tolerance is 0.002).
  const std::vector<glm::dvec3> points{ { 0, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0.9, 1, 0.001 }, { 0.9, -1, 0.001 } };
  const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 0, 2, 3 } }, { { 1, 2, 4 } },
    { { 1, 4, 5 } } };
  const OcclusionMesh fold(points, triangles);
  const ViewGeometry view = fromAboveInPixels();
  const LineVisibilityParameters parameters = outlineRule();
  LineVisibilityParameters off = parameters;
  off.OutlinePixels = 0.0;
  auto visibleAt = [&](double x0, const LineVisibilityParameters& rule) {
    const std::vector<glm::dvec3> line = lineAlongY(x0);
    EXPECT_EQ(fold.occlusion(view, line[1], rule), OcclusionMesh::Occlusion::BehindItsOwnSheet)
      << x0;
    const std::vector<LinePiece> pieces = splitByVisibility(fold, view, line, rule);
    EXPECT_EQ(pieces.size(), 1u) << x0;
    return !pieces.empty() && pieces[0].Visible;
  };
  EXPECT_FALSE(visibleAt(0.95, parameters)); // 5 pixels inside either edge
  EXPECT_TRUE(visibleAt(0.95, off));
  EXPECT_FALSE(visibleAt(0.98, parameters)); // 2 pixels inside the fold's edge
  EXPECT_TRUE(visibleAt(0.99, parameters));  // 1 pixel
  EXPECT_TRUE(visibleAt(0.91, parameters));  // 1 pixel inside the flap's free edge
  // Beyond the flap the sheet is clear.
  EXPECT_EQ(
    fold.occlusion(view, glm::dvec3(0.5, 0, 0), parameters), OcclusionMesh::Occlusion::Clear);
}

// The square z = 0, x in [0, 1], with a flap over each span [y0, y1] folded
// at x = 1 back to x = 0.9, 0.001 above it (within the tolerance of
// outlineRule()), and, when `bar` is given, a separate bar 0.5 above the
// square over x in [0.8, 1.1], y in the bar's span (an occluder beyond the
// tolerance).
OcclusionMesh flaps(const std::vector<std::pair<double, double>>& spans,
  const std::pair<double, double>* bar = nullptr)
{
  std::vector<double> ys{ -1.0, 1.0 };
  for (const auto& span : spans)
  {
    ys.push_back(span.first);
    ys.push_back(span.second);
  }
  std::sort(ys.begin(), ys.end());
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  auto quad = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
    const Id first = static_cast<Id>(points.size());
    points.insert(points.end(), { a, b, c, d });
    triangles.push_back({ { first, first + 1, first + 2 } });
    triangles.push_back({ { first, first + 2, first + 3 } });
  };
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) // the square, in strips
  {
    quad({ 0, ys[k], 0 }, { 1, ys[k], 0 }, { 1, ys[k + 1], 0 }, { 0, ys[k + 1], 0 });
  }
  for (const auto& [y0, y1] : spans) // joined to the square at x = 1
  {
    quad({ 1, y0, 0 }, { 1, y1, 0 }, { 0.9, y1, 0.001 }, { 0.9, y0, 0.001 });
  }
  if (bar)
  {
    quad({ 0.8, bar->first, 0.5 }, { 1.1, bar->first, 0.5 }, { 1.1, bar->second, 0.5 },
      { 0.8, bar->second, 0.5 });
  }
  return OcclusionMesh(points, triangles);
}

// A piece hidden only by that rule, shorter than InsideGapOutlines times
// OutlinePixels in the image and between two visible pieces, is drawn: the
// line comes back whole, as if never split. A longer one stays hidden, and
// so does a short one that a probe finds hidden by the ray rule, or that
// starts or ends the line.
TEST(LineVisibility, AShortDipInsideItsSheetsImageLeavesNoGap)
{
  const ViewGeometry view = fromAboveInPixels();
  LineVisibilityParameters parameters = outlineRule();
  parameters.SampleSpacing = 1e-3;
  ASSERT_EQ(OcclusionMesh::InsideGapOutlines, 8.0);
  const std::vector<glm::dvec3> line = lineAlongY(0.95);
  const std::vector<LinePiece> dip =
    splitByVisibility(flaps({ { -0.02, 0.02 } }), view, line, parameters);
  ASSERT_EQ(dip.size(), 1u) << "4 pixels under the flap";
  EXPECT_TRUE(dip[0].Visible);
  EXPECT_EQ(dip[0].Points, line);
  EXPECT_EQ(dip[0].Along, (std::vector<double>{ 0.0, 1.0, 2.0 }));
  LineVisibilityParameters noDips = parameters;
  noDips.DrawShortDips = false;
  const std::vector<LinePiece> leftOut =
    splitByVisibility(flaps({ { -0.02, 0.02 } }), view, line, noDips);
  expectWellFormed(leftOut, line);
  ASSERT_EQ(leftOut.size(), 3u) << "the dip left to the outline's gaps";
  EXPECT_FALSE(leftOut[1].Visible);

  const std::vector<LinePiece> run =
    splitByVisibility(flaps({ { -0.2, 0.2 } }), view, line, parameters);
  ASSERT_EQ(run.size(), 3u) << "40 pixels under the flap";
  EXPECT_FALSE(run[1].Visible);
  EXPECT_NEAR(run[1].Points.front().y, -0.2, 1e-6);
  EXPECT_NEAR(run[1].Points.back().y, 0.2, 1e-6);

  // A bar beyond the tolerance over part of the dip: hidden for good.
  for (const std::pair<double, double> bar : { std::pair(0.003, 0.013), std::pair(-0.03, -0.01) })
  {
    const std::vector<LinePiece> barred =
      splitByVisibility(flaps({ { -0.02, 0.02 } }, &bar), view, line, parameters);
    expectWellFormed(barred, line);
    ASSERT_EQ(barred.size(), 3u) << bar.first;
    EXPECT_FALSE(barred[1].Visible);
    EXPECT_LE(barred[1].Points.front().y, std::max(bar.first, -0.02) + 1e-6);
    EXPECT_GE(barred[1].Points.back().y, bar.second - 1e-6);
  }

  // Under the flap at the line's start, or at its end: hidden (a bar
  // elsewhere makes four pieces).
  const std::pair<double, double> farBar(-0.3, -0.2);
  const OcclusionMesh barAndFlap = flaps({ { -0.02, 0.02 } }, &farBar);
  const std::vector<glm::dvec3> starting{ { 0.95, -0.01, 0 }, { 0.95, -0.4, 0 },
    { 0.95, -0.5, 0 } };
  const std::vector<LinePiece> start = splitByVisibility(barAndFlap, view, starting, parameters);
  expectWellFormed(start, starting);
  ASSERT_EQ(start.size(), 4u);
  EXPECT_FALSE(start[0].Visible);
  const std::vector<glm::dvec3> ending{ { 0.95, -0.5, 0 }, { 0.95, -0.1, 0 }, { 0.95, 0.01, 0 } };
  const std::vector<LinePiece> end = splitByVisibility(barAndFlap, view, ending, parameters);
  expectWellFormed(end, ending);
  ASSERT_EQ(end.size(), 4u);
  EXPECT_FALSE(end[3].Visible);

  // Three dips: one piece, the line itself, with or without the joining of
  // short pieces after.
  const OcclusionMesh three = flaps({ { -0.3, -0.27 }, { -0.02, 0.02 }, { 0.2, 0.23 } });
  for (const double minimum : { 0.0, 0.05 })
  {
    parameters.MinimumPieceLength = minimum;
    const std::vector<LinePiece> dips = splitByVisibility(three, view, line, parameters);
    expectWellFormed(dips, line);
    ASSERT_EQ(dips.size(), 1u) << minimum;
    EXPECT_TRUE(dips[0].Visible);
    EXPECT_EQ(dips[0].Points, line);
  }
}

TEST(LineVisibility, NothingInTheWayGivesTheLineBack)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  square(-1.0, points, triangles); // below the line: it hides nothing
  const OcclusionMesh surface(points, triangles);
  const std::vector<glm::dvec3> line{ { -2, 0, 0 }, { 0, 0.5, 0 }, { 2, 0, 0 } };
  const std::vector<LinePiece> pieces =
    splitByVisibility(surface, fromAbove(), line, LineVisibilityParameters{ 1e-6, 1e-9 });
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_TRUE(pieces[0].Visible);
  EXPECT_EQ(pieces[0].Points, line);
  EXPECT_TRUE(splitByVisibility(surface, fromAbove(), {}, LineVisibilityParameters{}).empty());
}

TEST(LineVisibility, TheToleranceKeepsALineOnTheSurfaceVisible)
{
  // A line 1e-4 under the square, as a line on a surface lies within
  // rounding of it: a tolerance of 1e-3 keeps it visible; 1e-5 (the wrong
  // variant: below the gap) hides it.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  square(1.0, points, triangles);
  const OcclusionMesh surface(points, triangles);
  const std::vector<glm::dvec3> line{ { -0.5, -0.5, 1.0 - 1e-4 }, { 0.5, 0.5, 1.0 - 1e-4 } };
  const auto kept =
    splitByVisibility(surface, fromAbove(), line, LineVisibilityParameters{ 1e-3, 1e-9 });
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept[0].Visible);
  const auto lost =
    splitByVisibility(surface, fromAbove(), line, LineVisibilityParameters{ 1e-5, 1e-9 });
  ASSERT_EQ(lost.size(), 1u);
  EXPECT_FALSE(lost[0].Visible);
}

TEST(LineVisibility, SphereHidesTheBorderBehindIt)
{
  // A unit sphere (48 x 96 UV mesh, inscribed in the exact sphere by at most
  // 0.0022) seen from (0, 0, 5), and the border of the square of half-side
  // 1.2 at z = -2 behind it: from the eye, the sphere covers a disc of
  // radius about 1.43 there, so the middles of the sides are hidden and the
  // corners are not. Each border point's answer is the exact sphere's (does
  // the segment to the eye pass within 1 of the centre?), except within
  // 0.01 of grazing, where the mesh and the sphere may differ.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(48, 96, points, triangles);
  const LineVisibilityParameters parameters = LineVisibilityParameters::forMesh(points, triangles);
  EXPECT_GT(parameters.Tolerance, 0.01);
  EXPECT_LT(parameters.Tolerance, 0.1);
  const OcclusionMesh surface(points, triangles);
  const glm::dvec3 eye(0, 0, 5);
  const ViewGeometry view = coretest::perspectiveFrom(eye);
  std::vector<glm::dvec3> border;
  const glm::dvec3 corners[4] = { { -1.2, -1.2, -2 }, { 1.2, -1.2, -2 }, { 1.2, 1.2, -2 },
    { -1.2, 1.2, -2 } };
  for (int side = 0; side < 4; ++side)
  {
    for (int k = 0; k < 40; ++k)
    {
      border.push_back(corners[side] + (k / 40.0) * (corners[(side + 1) % 4] - corners[side]));
    }
  }
  border.push_back(corners[0]);
  // The distance from the centre to the segment from p to the eye.
  auto clearance = [&eye](const glm::dvec3& p) {
    const glm::dvec3 d = eye - p;
    const double t = std::clamp(-glm::dot(p, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p + t * d);
  };
  int hidden = 0;
  int visible = 0;
  for (const glm::dvec3& p : border)
  {
    const double c = clearance(p);
    if (std::abs(c - 1.0) < 0.01)
    {
      continue;
    }
    const bool exactHidden = c < 1.0;
    EXPECT_EQ(surface.hides(view, p, parameters.Tolerance), exactHidden)
      << p.x << " " << p.y << ": " << c;
    (exactHidden ? hidden : visible) += 1;
  }
  EXPECT_GT(hidden, 40);
  EXPECT_GT(visible, 40);
  // The change points lie where the segment to the eye grazes the sphere.
  const std::vector<LinePiece> pieces = splitByVisibility(surface, view, border, parameters);
  EXPECT_EQ(pieces.size(), 9u); // visible corner, hidden middle, ..., back to the first corner
  for (std::size_t k = 1; k < pieces.size(); ++k)
  {
    EXPECT_NEAR(clearance(pieces[k].Points.front()), 1.0, 0.005);
  }
  expectWellFormed(pieces, border);
}

TEST(LineVisibility, TorusContoursAgainstTheExactTorus)
{
  // The smoothed silhouette of a 64 x 32 torus (ring 1, tube 0.4, exact
  // normals) seen obliquely from (0, -4, 2.5), tested against the smoothed
  // mesh it lies on: the rays from its points graze that mesh, which is what
  // the tolerance is for. Each point's answer is the exact torus's, found by
  // marching the ray to the eye through the torus's implicit function f;
  // points whose ray comes within |f| < 0.03 (about 0.04 of the surface)
  // beyond its first tenth are left out: there the smoothed mesh, whose
  // vertices around the concave inner contour the perturbation lowers, and
  // the exact torus may differ (at |f| < 0.025, two points of 291 did).
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  const double tube = 0.4;
  coretest::torus(64, 32, tube, points, triangles);
  std::vector<glm::dvec3> normals;
  for (const glm::dvec3& p : points)
  {
    const glm::dvec3 ring = glm::normalize(glm::dvec3(p.x, p.y, 0.0));
    normals.push_back(glm::normalize(p - ring));
  }
  const PreparedMesh mesh(points, triangles, normals);
  const glm::dvec3 eye(0.0, -4.0, 2.5);
  const ViewGeometry view = coretest::perspectiveFrom(eye);
  const SmoothingResult result = smoothSilhouettes(mesh, view, SmoothingParameters());
  ASSERT_FALSE(result.Polylines.empty());

  std::vector<glm::dvec3> output = mesh.points();
  for (const auto& [id, position] : result.MovedPoints)
  {
    output[static_cast<std::size_t>(id)] = position;
  }
  for (const NewPoint& p : result.NewPoints)
  {
    output.push_back(p.Position);
  }
  std::vector<Triangle> outputTriangles;
  std::vector<Id> source;
  std::vector<unsigned char> isNew;
  assembleTriangles(mesh, result, outputTriangles, source, isNew);
  const LineVisibilityParameters parameters =
    LineVisibilityParameters::forMesh(output, outputTriangles);
  const OcclusionMesh surface(output, outputTriangles);

  // The torus's implicit function: negative inside the tube.
  auto inside = [tube](const glm::dvec3& q) {
    const double ring = std::sqrt(q.x * q.x + q.y * q.y) - 1.0;
    return ring * ring + q.z * q.z - tube * tube;
  };
  int hidden = 0;
  int visible = 0;
  int skipped = 0;
  int selfHidden = 0;
  for (const std::vector<Id>& polyline : result.Polylines)
  {
    for (const Id id : polyline)
    {
      const glm::dvec3 p = output[static_cast<std::size_t>(id)];
      const glm::dvec3 toEye = eye - p;
      double lowest = 1e9;
      for (double t = 0.1; t < 1.0; t += 0.0005)
      {
        lowest = std::min(lowest, inside(p + t * toEye));
      }
      if (std::abs(lowest) < 0.03)
      {
        ++skipped;
        continue;
      }
      const bool exactHidden = lowest < 0.0;
      EXPECT_EQ(surface.hides(view, p, parameters.Tolerance), exactHidden)
        << p.x << " " << p.y << " " << p.z << ": lowest " << lowest;
      (exactHidden ? hidden : visible) += 1;
      // The wrong variant: no tolerance, and the surface the line lies on
      // hides it.
      selfHidden += !exactHidden && surface.hides(view, p, 1e-9) ? 1 : 0;
    }
  }
  std::printf("torus contours: %d points visible, %d hidden, %d near grazing left out; "
              "without a tolerance %d visible ones hidden\n",
    visible, hidden, skipped, selfHidden);
  EXPECT_GT(hidden, 10);
  EXPECT_GT(visible, 100);
  EXPECT_GT(selfHidden, 0); // measured: 5 of 242
}

TEST(LineVisibility, CubeShowsItsNineVisibleEdges)
{
  // Kim and Choe's crease edges of a cube (EdgeClassification), each edge a
  // line, seen in perspective from a generic direction: three faces face the
  // eye, so 9 edges are visible and the 3 that meet at the far corner are
  // hidden. A hidden edge is hidden right up to its ends, where the
  // occluding face comes within the tolerance (1e-6 here): a visible stub no
  // longer than 1e-4 may remain there, and is not counted.
  const std::vector<glm::dvec3> points{ { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
  const std::vector<Triangle> triangles{ { { 0, 2, 1 } }, { { 0, 3, 2 } }, { { 4, 5, 6 } },
    { { 4, 6, 7 } }, { { 0, 1, 5 } }, { { 0, 5, 4 } }, { { 1, 2, 6 } }, { { 1, 6, 5 } },
    { { 2, 3, 7 } }, { { 2, 7, 6 } }, { { 3, 0, 4 } }, { { 3, 4, 7 } } };
  const glm::dvec3 eye(5.0, 3.7, 4.3);
  EdgeView edgeView;
  edgeView.eye = eye;
  const std::vector<FlaggedEdge> edges = classifyEdges(points, triangles, edgeView, 60.0);
  const OcclusionMesh surface(points, triangles);
  const ViewGeometry view = coretest::perspectiveFrom(eye);
  const LineVisibilityParameters parameters{ 1e-6, 1e-9 };
  int creases = 0;
  int visibleEdges = 0;
  int hiddenEdges = 0;
  for (const FlaggedEdge& edge : edges)
  {
    if (!(edge.flags & CreaseEdge))
    {
      continue;
    }
    ++creases;
    const std::vector<glm::dvec3> line{ points[static_cast<std::size_t>(edge.a)],
      points[static_cast<std::size_t>(edge.b)] };
    double visibleLength = 0.0;
    double hiddenLength = 0.0;
    for (const LinePiece& piece : splitByVisibility(surface, view, line, parameters))
    {
      const double length = glm::length(piece.Points.back() - piece.Points.front());
      (piece.Visible ? visibleLength : hiddenLength) += length;
    }
    // Every edge is 2 long: wholly visible, or hidden but for stubs.
    if (hiddenLength == 0.0)
    {
      EXPECT_NEAR(visibleLength, 2.0, 1e-12);
      ++visibleEdges;
    }
    else
    {
      EXPECT_LT(visibleLength, 1e-4) << edge.a << "-" << edge.b;
      ++hiddenEdges;
      // The far corner (-1, -1, -1) is an end of each hidden edge.
      EXPECT_TRUE(edge.a == 0 || edge.b == 0) << edge.a << "-" << edge.b;
    }
  }
  EXPECT_EQ(creases, 12);
  EXPECT_EQ(visibleEdges, 9);
  EXPECT_EQ(hiddenEdges, 3);
}

TEST(LineVisibility, ShortPiecesJoinTheirNeighbours)
{
  // Pieces of lengths 1, 0.01 (hidden), 1, then 0.02 (hidden) at the end.
  auto piece = [](double from, double to, bool visible) {
    LinePiece p;
    p.Points = { glm::dvec3(from, 0, 0), glm::dvec3(to, 0, 0) };
    p.Along = { from, to };
    p.Visible = visible;
    return p;
  };
  const std::vector<LinePiece> pieces{ piece(0, 1, true), piece(1, 1.01, false),
    piece(1.01, 2.01, true), piece(2.01, 2.03, false) };
  EXPECT_EQ(mergeShortPieces(pieces, 0.0).size(), 4u); // 0 keeps every piece
  EXPECT_EQ(mergeShortPieces(pieces, 0.015).size(), 2u);
  const std::vector<LinePiece> merged = mergeShortPieces(pieces, 0.05);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_TRUE(merged[0].Visible);
  // Every point in order, each joint once.
  const std::vector<double> along{ 0, 1, 1.01, 2.01, 2.03 };
  ASSERT_EQ(merged[0].Along.size(), along.size());
  for (std::size_t i = 0; i < along.size(); ++i)
  {
    EXPECT_EQ(merged[0].Along[i], along[i]);
    EXPECT_EQ(merged[0].Points[i].x, along[i]);
  }
  // A short piece between two long ones of the other state: one piece of
  // their state, not three.
  const std::vector<LinePiece> middle =
    mergeShortPieces({ piece(0, 1, false), piece(1, 1.001, true), piece(1.001, 2, false) }, 0.01);
  ASSERT_EQ(middle.size(), 1u);
  EXPECT_FALSE(middle[0].Visible);
}

TEST(LineVisibility, SplitWhereFindsEachChangeAndEndsEachPieceAfterItsLastProbe)
{
  // x from 0 to 10 in two segments (a repeated point between them); true
  // below 3.3 and above 7.1. Probes 1 apart find both changes; bisection
  // puts them within 1e-9. Each piece ends after the probes that decided
  // it: counted per state since the last end, the false piece's probes
  // include the bisections' far sides.
  const std::vector<glm::dvec3> line{ { 0, 0, 0 }, { 5, 0, 0 }, { 5, 0, 0 }, { 10, 0, 0 } };
  int probes[2] = { 0, 0 };
  std::vector<glm::dvec3> directions;
  auto holds = [&](const glm::dvec3& p, const glm::dvec3& direction) {
    directions.push_back(direction);
    const bool state = p.x < 3.3 || p.x > 7.1;
    ++probes[state];
    return state;
  };
  std::vector<std::pair<bool, int>> ended;
  auto pieceEnds = [&](bool state) {
    ended.emplace_back(state, probes[state]);
    probes[state] = 0;
  };
  const std::vector<LinePiece> pieces = splitWhere(line, 1.0, 1e-9, holds, pieceEnds);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_TRUE(pieces[0].Visible);
  EXPECT_FALSE(pieces[1].Visible);
  EXPECT_TRUE(pieces[2].Visible);
  EXPECT_NEAR(pieces[1].Points.front().x, 3.3, 1e-9);
  EXPECT_NEAR(pieces[1].Points.back().x, 7.1, 1e-9);
  EXPECT_EQ(pieces[0].Points.back(), pieces[1].Points.front());
  EXPECT_EQ(pieces[1].Points.back(), pieces[2].Points.front());
  EXPECT_NEAR(pieces[1].Along.front(), 3.3 / 5.0, 1e-9);
  EXPECT_NEAR(pieces[1].Along.back(), 2.0 + 2.1 / 5.0, 1e-9);
  // The repeated point is probed with the last real segment's direction.
  for (const glm::dvec3& direction : directions)
  {
    EXPECT_EQ(direction, glm::dvec3(5, 0, 0));
  }
  ASSERT_EQ(ended.size(), 3u);
  EXPECT_TRUE(ended[0].first);
  EXPECT_FALSE(ended[1].first);
  EXPECT_TRUE(ended[2].first);
  EXPECT_GT(ended[1].second, 4); // probes at 4, 5, 5, 6, 7 and the bisections' far sides
  EXPECT_EQ(probes[0] + probes[1], 0);
  // With no spacing only the vertices are probed, and both are true:
  // one piece (the wrong variant of probing the vertices alone).
  EXPECT_EQ(splitWhere({ { 0, 0, 0 }, { 10, 0, 0 } }, 0.0, 1e-9, holds).size(), 1u);
}

TEST(LineVisibility, ProbesFindAnOccluderBetweenTwoVisibleEnds)
{
  // One long segment from x = -3 to 3 under a square of side 2: both ends
  // are visible, the middle hidden. Vertices alone find nothing (the wrong
  // variant); probes every 0.1 find both changes.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  square(1.0, points, triangles);
  const OcclusionMesh surface(points, triangles);
  const std::vector<glm::dvec3> line{ { -3, 0.3, 0 }, { 3, 0.3, 0 } };
  LineVisibilityParameters parameters{ 1e-6, 1e-10 };
  EXPECT_EQ(splitByVisibility(surface, fromAbove(), line, parameters).size(), 1u);
  parameters.SampleSpacing = 0.1;
  const std::vector<LinePiece> pieces = splitByVisibility(surface, fromAbove(), line, parameters);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_FALSE(pieces[1].Visible);
  EXPECT_NEAR(pieces[1].Points.front().x, -1.0, 1e-9);
  EXPECT_NEAR(pieces[1].Points.back().x, 1.0, 1e-9);
  expectWellFormed(pieces, line);
}

TEST(LineVisibility, AFaceOnTheBoundingBoxIsNotMissed)
{
  // Every point of a cube's hidden edge is hidden by its front faces, which
  // lie on the sides of the surface's bounding box. Unpadded grid queries
  // missed them where rounding ended the ray's last piece a hair short (204
  // of 1,999 points tested visible).
  const std::vector<glm::dvec3> points{ { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
  const std::vector<Triangle> triangles{ { { 0, 2, 1 } }, { { 0, 3, 2 } }, { { 4, 5, 6 } },
    { { 4, 6, 7 } }, { { 0, 1, 5 } }, { { 0, 5, 4 } }, { { 1, 2, 6 } }, { { 1, 6, 5 } },
    { { 2, 3, 7 } }, { { 2, 7, 6 } }, { { 3, 0, 4 } }, { { 3, 4, 7 } } };
  const OcclusionMesh surface(points, triangles);
  const ViewGeometry view = coretest::perspectiveFrom(glm::dvec3(5.0, 3.7, 4.3));
  int visible = 0;
  for (int i = 1; i < 2000; ++i)
  {
    visible += surface.hides(view, glm::dvec3(-1, -1, -1 + 2.0 * i / 2000), 1e-5) ? 0 : 1;
  }
  EXPECT_EQ(visible, 0);
}

TEST(LineVisibility, AThinFoldHidesItsFarSideBeyondTheLocalTolerance)
{
  // A U of fine triangles (sides 0.1): a back sheet at z = 0 and a front
  // sheet at z = 0.3 over x in [0, 2], y in [0, 1], joined by a wall along
  // y = 0, seen from above. A coarse mesh elsewhere makes the mesh-wide
  // tolerance 2, beyond the gap: the front sheet, connected to the back one
  // through the wall within the ball, would be the point's own sheet. With
  // the tolerance at a point capped at 1.5 times the longest side of the
  // triangles it lies on (0.21 here), the front sheet, 0.3 away, hides the
  // back one; with the cap off (the wrong variant), it does not.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  auto grid = [&](auto at, int nu, int nv) {
    const Id first = static_cast<Id>(points.size());
    for (int j = 0; j <= nv; ++j)
    {
      for (int i = 0; i <= nu; ++i)
      {
        points.push_back(at(i, j));
      }
    }
    auto id = [&](int i, int j) {
      return first + static_cast<Id>(j * (nu + 1) + i);
    };
    for (int j = 0; j < nv; ++j)
    {
      for (int i = 0; i < nu; ++i)
      {
        triangles.push_back({ { id(i, j), id(i + 1, j), id(i + 1, j + 1) } });
        triangles.push_back({ { id(i, j), id(i + 1, j + 1), id(i, j + 1) } });
      }
    }
  };
  grid([](int i, int j) { return glm::dvec3(0.1 * i, 0.1 * j, 0.0); }, 20, 10);     // back
  grid([](int i, int j) { return glm::dvec3(0.1 * i, 0.1 * j, 0.1 * 3); }, 20, 10); // front
  grid([](int i, int j) { return glm::dvec3(0.1 * i, 0.0, 0.1 * j); }, 20, 3);      // wall
  ViewGeometry view;
  view.Parallel = true;
  view.TowardViewer = glm::dvec3(0, 0, 1);
  LineVisibilityParameters rule;
  rule.Tolerance = 2.0;
  rule.Precision = 1e-9;
  rule.Contact = 1e-7;
  // The wall's points duplicate the sheets' along the folds (the front at
  // 0.1 * 3, the wall's top row, not 0.3); without normals, points at one
  // position are one vertex, so the U is one sheet.
  const OcclusionMesh fold(points, triangles);
  const glm::dvec3 behind(1.03, 0.55, 0.0); // on the back sheet, under the front
  EXPECT_TRUE(fold.hides(view, behind, rule));
  const glm::dvec3 onFront(1.03, 0.55, 0.3);
  EXPECT_FALSE(fold.hides(view, onFront, rule));
  LineVisibilityParameters meshWide = rule;
  meshWide.LocalToleranceFactor = 0.0;
  EXPECT_FALSE(fold.hides(view, behind, meshWide));
  // A point on no triangle keeps the mesh-wide tolerance.
  EXPECT_FALSE(fold.hides(view, glm::dvec3(1.03, 0.55, 0.05), rule));
}

TEST(LineVisibility, ACreaseBoundsTheLocalSheet)
{
  // An L: a floor (z = 0, x in [0, 2]) and a wall (x = 0, z in [0, 2]) meeting
  // at a crease along y, each side with its own copies of the crease's
  // points and its own normal, seen from below the floor, beyond the wall.
  // The floor hides a point on the wall just above the crease from 0.07
  // away along its ray, inside the tolerance of 0.5. The floor is another
  // sheet (its copies of the crease have another normal), so the point is
  // hidden; without normals floor and wall are one sheet and the point stays
  // visible (the wrong variant), as a bore's silhouette running into a
  // plate did.
  const std::vector<glm::dvec3> points{ { 0, -1, 0 }, { 2, -1, 0 }, { 2, 1, 0 }, { 0, 1, 0 },
    { 0, -1, 0 }, { 0, 1, 0 }, { 0, 1, 2 }, { 0, -1, 2 } };
  const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 0, 2, 3 } }, { { 4, 5, 6 } },
    { { 4, 6, 7 } } };
  std::vector<glm::dvec3> normals(4, glm::dvec3(0, 0, 1));
  normals.insert(normals.end(), 4, glm::dvec3(1, 0, 0));
  ViewGeometry view;
  view.Parallel = true;
  view.TowardViewer = glm::normalize(glm::dvec3(1, 0, -1)); // from below, beyond the wall
  LineVisibilityParameters rule;
  rule.Tolerance = 0.5;
  rule.Precision = 1e-9;
  rule.Contact = 1e-7;
  const glm::dvec3 onWall(0, 0.2, 0.05); // its ray meets the floor 0.07 away
  const glm::dvec3 high(0, 0.2, 1.5);    // its ray meets the floor 2.1 away
  const OcclusionMesh creased(points, triangles, normals);
  EXPECT_TRUE(creased.hides(view, onWall, rule));
  EXPECT_TRUE(creased.hides(view, high, rule));
  const OcclusionMesh oneSheet(points, triangles);
  EXPECT_FALSE(oneSheet.hides(view, onWall, rule));
  EXPECT_TRUE(oneSheet.hides(view, high, rule)); // beyond the tolerance: any triangle
  // A point on no triangle keeps the plain rule.
  EXPECT_FALSE(creased.hides(view, glm::dvec3(-0.01, 0.2, 0.05), rule));
}
