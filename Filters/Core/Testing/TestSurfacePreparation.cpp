// Asset-file meshes: welding coincident points, normal seams, consistent
// orientation, and WeldedSurface's output on the input's own points.
#include "CoreTestMeshes.h"
#include "PlainSurfaceOptions.h"
#include "SurfaceOrientation.h"
#include "SurfaceWelding.h"
#include "WeldedSurface.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>

using namespace silsmooth;

namespace
{

// The output triangles as triples of positions, each rotated to start at its
// smallest corner (winding kept), sorted: comparable across point numberings.
using PositionTriangle = std::array<std::tuple<double, double, double>, 3>;
std::vector<PositionTriangle> positionTriangles(const WeldedSurface& surface,
  const std::vector<glm::dvec3>& inputPoints, const SmoothingResult& result,
  const SurfaceFrame& frame)
{
  const Id base = static_cast<Id>(surface.outputPointCount());
  auto position = [&](Id o) {
    const glm::dvec3 p = o < base
      ? inputPoints[static_cast<std::size_t>(surface.outputSource(o))]
      : result.NewPoints[frame.Added[static_cast<std::size_t>(o - base)].NewPoint].Position;
    return std::make_tuple(p.x, p.y, p.z);
  };
  std::vector<PositionTriangle> out;
  for (const Triangle& t : frame.Triangles)
  {
    PositionTriangle pt{ { position(t[0]), position(t[1]), position(t[2]) } };
    const auto smallest = std::min_element(pt.begin(), pt.end());
    std::rotate(pt.begin(), smallest, pt.end());
    out.push_back(pt);
  }
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace

TEST(SurfaceWelding, ExactWeldJoinsEqualCoordinatesOnly)
{
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 0 }, { 1, 0, 1e-12 },
    { 1, 0, 0 }, { std::nan(""), 0, 0 }, { std::nan(""), 0, 0 } };
  const std::vector<Id> vertex = weldCoincidentPoints(points);
  EXPECT_EQ(vertex, (std::vector<Id>{ 0, 1, 0, 3, 1, 5, 6 }));
}

TEST(SurfaceWelding, ToleranceJoinsNearPointsTransitively)
{
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 0.6e-3, 0, 0 }, { 1.2e-3, 0, 0 },
    { 5, 5, 5 }, { 5, 5, 5.01 } };
  EXPECT_EQ(weldCoincidentPoints(points, 1e-3), (std::vector<Id>{ 0, 0, 0, 3, 4 }));
  // The deliberately wrong tolerance (too small) joins nothing.
  EXPECT_EQ(weldCoincidentPoints(points, 1e-4), (std::vector<Id>{ 0, 1, 2, 3, 4 }));
}

TEST(SurfaceWelding, WeldingStaysWithinSheets)
{
  // Two squares of two triangles each, the second's corner 4 at the first's
  // corner 2 (they touch at that point only), and a texture seam: the first
  // square's corner 0 written twice (0 and 8, each used by one triangle).
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 1, 1, 0 }, { 2, 1, 1 }, { 2, 2, 1 }, { 1, 2, 1 }, { 0, 0, 0 } };
  const std::vector<Triangle> triangles{ { 0, 1, 2 }, { 8, 2, 3 }, { 4, 5, 6 }, { 4, 6, 7 } };
  const std::vector<Id> welded = weldCoincidentPoints(points);
  EXPECT_EQ(welded, (std::vector<Id>{ 0, 1, 2, 3, 2, 5, 6, 7, 0 }));
  // The seam stays welded (its triangles share the side 0-2 once welded);
  // the touching corner does not (the squares share no side).
  EXPECT_EQ(weldWithinSheets(triangles, welded, EdgeTable(weldTriangles(triangles, welded))),
    (std::vector<Id>{ 0, 1, 2, 3, 4, 5, 6, 7, 0 }));
  // A point whose own triangles lie on two sheets (the second square pinned
  // to the first by its corner 2 itself) keeps its group whole.
  const std::vector<Triangle> pinched{ { 0, 1, 2 }, { 8, 2, 3 }, { 2, 5, 6 }, { 4, 6, 7 } };
  EXPECT_EQ(weldWithinSheets(pinched, welded, EdgeTable(weldTriangles(pinched, welded))), welded);

  // The surface keeps the squares' shading apart at the corner they touch
  // at: the flat square's normal there is its own, (0, 0, 1), not a blend
  // with the tilted square's (a user's trial found smeared patches where a
  // sphere's points sat on a face's grid points).
  SurfaceOptions options = coretest::plainOptions();
  options.DetectFeatures = false;
  const WeldedSurface surface(points, triangles, {}, {}, options);
  // (The prepared mesh's points are the input's, welded ones unused.)
  const std::vector<glm::dvec3>& normals = surface.prepared().normals();
  ASSERT_GE(normals.size(), 5u);
  EXPECT_NEAR(normals[2].z, 1.0, 1e-12);
  EXPECT_LT(glm::dot(normals[4], glm::dvec3(0.0, 0.0, 1.0)), 0.99);
}

TEST(SurfaceWelding, TheSidesOfADoubleSidedSheetStayApart)
{
  // A tent of four triangles over a 3 x 2 grid of points (a curved sheet),
  // written double-sided as exporters write cloth: the back side repeats
  // every triangle with the opposite winding, on copies of the points
  // (points 6 to 11).
  const std::vector<glm::dvec3> front{ { 0, 0, 0 }, { 1, 0, 0.5 }, { 2, 0, 0 }, { 0, 1, 0 },
    { 1, 1, 0.5 }, { 2, 1, 0 } };
  std::vector<glm::dvec3> points = front;
  points.insert(points.end(), front.begin(), front.end());
  const std::vector<Triangle> frontTriangles{ { 0, 1, 4 }, { 0, 4, 3 }, { 1, 2, 5 }, { 1, 5, 4 } };
  std::vector<Triangle> triangles = frontTriangles;
  for (const Triangle& t : frontTriangles)
  {
    triangles.push_back({ t[0] + 6, t[2] + 6, t[1] + 6 });
  }
  const std::vector<Id> welded = weldCoincidentPoints(points);
  const EdgeTable table(weldTriangles(triangles, welded));
  // Welded, each triangle has its twin on the same vertices.
  const std::vector<unsigned char> twins = backToBackTwins(weldTriangles(triangles, welded), table);
  EXPECT_EQ(std::count(twins.begin(), twins.end(), 1), 8);
  // The sides are two sheets, so the copies stay apart...
  const std::vector<Id> apart = weldWithinSheets(triangles, welded, table);
  for (Id p = 0; p < 6; ++p)
  {
    EXPECT_NE(apart[static_cast<std::size_t>(p)], apart[static_cast<std::size_t>(p + 6)]);
  }
  // ... and each side's normals are its own: up on the front, down on the
  // back (welded into one, they would cancel).
  SurfaceOptions options = coretest::plainOptions();
  options.DetectFeatures = false;
  const WeldedSurface surface(points, triangles, {}, {}, options);
  EXPECT_EQ(surface.statistics().BackToBackTriangleCount, 0u);
  const std::vector<glm::dvec3>& normals = surface.prepared().normals();
  ASSERT_GE(normals.size(), 12u);
  EXPECT_NEAR(glm::length(normals[4]), 1.0, 1e-9);
  EXPECT_NEAR(glm::length(normals[10]), 1.0, 1e-9);
  EXPECT_LT(glm::dot(normals[4], normals[10]), -0.99);
  // The wrong variant: sheets joined across the twins' edges, as without
  // backToBackApart, keep the copies welded.
  const std::vector<std::size_t> joined = sheetsOf(weldTriangles(triangles, welded), table);
  EXPECT_EQ(joined[0], joined[4]);
  const std::vector<std::size_t> sides = sheetsOf(weldTriangles(triangles, welded), table, true);
  EXPECT_NE(sides[0], sides[4]);
  EXPECT_EQ(sides[0], sides[3]);
  EXPECT_EQ(sides[4], sides[7]);
  // The same triangles repeated with the same winding are no twins; on the
  // same points (not copies), the sides cannot be kept apart, which the
  // statistics say.
  std::vector<Triangle> repeated = frontTriangles;
  repeated.insert(repeated.end(), frontTriangles.begin(), frontTriangles.end());
  const std::vector<unsigned char> none = backToBackTwins(repeated, EdgeTable(repeated));
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
  std::vector<Triangle> shared = frontTriangles;
  for (const Triangle& t : frontTriangles)
  {
    shared.push_back({ t[0], t[2], t[1] });
  }
  const WeldedSurface sharedSurface(front, shared, {}, {}, options);
  EXPECT_EQ(sharedSurface.statistics().BackToBackTriangleCount, 8u);
}

TEST(SurfaceWelding, NearCopiesAreEdgesBelowAHundredThousandthOfTheDiagonal)
{
  // A unit square (diagonal sqrt 2) split in two, corner 2 with a copy (4)
  // `gap` away joined to it by a sliver; a NaN point with an edge of its own.
  auto square = [](double gap) {
    return std::vector<glm::dvec3>{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
      { 1, 1, gap }, { std::nan(""), 0, 0 } };
  };
  const std::vector<Triangle> triangles{ { 0, 1, 2 }, { 0, 4, 3 }, { 0, 2, 4 }, { 3, 4, 5 } };
  const EdgeTable table(triangles);
  const double limit = 1e-5 * std::sqrt(2.0);
  // Edge 2-4 at 0.9 of the limit is a near copy (one edge, both slivers'
  // sides), and its length the longest.
  const NearCopies found = nearCopyEdges(square(0.9 * limit), table);
  EXPECT_EQ(found.EdgeCount, 1u);
  EXPECT_DOUBLE_EQ(found.LongestEdge, 0.9 * limit);
  // The wrong side of the threshold: 1.1 of the limit is an edge as any other.
  EXPECT_EQ(nearCopyEdges(square(1.1 * limit), table).EdgeCount, 0u);
  // Equal coordinates are one point (the exact weld's business), not a near copy.
  EXPECT_EQ(nearCopyEdges(square(0.0), table).EdgeCount, 0u);
  // The threshold follows the mesh's size: scaled by 1e6, the same mesh has
  // the same near copy.
  std::vector<glm::dvec3> large = square(0.9 * limit);
  for (glm::dvec3& p : large)
  {
    p *= 1e6;
  }
  EXPECT_EQ(nearCopyEdges(large, table).EdgeCount, 1u);
  // A mesh whose size overflows (corners at -1e308 and 1e308) has none: the
  // weld would take every edge for a rounding copy and join all points.
  std::vector<glm::dvec3> huge = square(0.5);
  huge[0] = glm::dvec3(-1e308, 0, 0);
  huge[1] = glm::dvec3(1e308, 0, 0);
  EXPECT_EQ(nearCopyEdges(huge, table, 1e-9).EdgeCount, 0u);
}

TEST(SurfaceWelding, NormalSeamsOfASplitCubeAreItsTwelveEdges)
{
  // A cube as exporters write one: 4 points per face with the face normal.
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec3> normals;
  std::vector<Triangle> triangles;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side : { -1, 1 })
    {
      glm::dvec3 n(0.0);
      n[axis] = side;
      const glm::dvec3 u = axis == 0 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
      const glm::dvec3 v = glm::cross(n, u);
      const Id base = static_cast<Id>(points.size());
      for (const auto& [a, b] : { std::pair{ -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } })
      {
        points.push_back(n + double(a) * u + double(b) * v);
        normals.push_back(n);
      }
      triangles.push_back({ { base, base + 1, base + 2 } });
      triangles.push_back({ { base, base + 2, base + 3 } });
    }
  }
  const std::vector<Id> vertex = weldCoincidentPoints(points);
  EXPECT_EQ(std::set<Id>(vertex.begin(), vertex.end()).size(), 8u);
  EXPECT_EQ(normalSeamEdges(triangles, vertex, normals).size(), 12u);
  // With one smooth normal per position there is no seam.
  std::vector<glm::dvec3> smooth(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    smooth[i] = glm::normalize(points[i]);
  }
  EXPECT_TRUE(normalSeamEdges(triangles, vertex, smooth).empty());
}

TEST(SurfaceOrientation, InvertedAndPartlyReversedSpheresComeBackOutward)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(8, 12, points, triangles);
  std::mt19937 random(7);
  std::vector<unsigned char> turned(triangles.size(), 0);
  std::vector<Triangle> mixed = triangles;
  for (std::size_t t = 0; t < mixed.size(); ++t)
  {
    if (random() % 10 < 3)
    {
      turned[t] = 1;
      mixed[t] = oriented(mixed[t], true);
    }
  }
  const Orientation partly = orientConsistently(points, mixed);
  EXPECT_EQ(partly.Reversed, turned);
  EXPECT_EQ(partly.ComponentCount, 1u);
  EXPECT_EQ(partly.InconsistentEdgeCount, 0u);

  std::vector<Triangle> inverted = triangles;
  for (Triangle& t : inverted)
  {
    t = oriented(t, true);
  }
  const Orientation all = orientConsistently(points, inverted);
  EXPECT_EQ(all.ReversedCount, triangles.size());
}

TEST(SurfaceOrientation, OpenPatchFollowsItsNormalsAndMoebiusStripIsReported)
{
  // A flat 2x1 strip of four triangles, two of them reversed, normals +z.
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 0, 1, 0 },
    { 1, 1, 0 }, { 2, 1, 0 } };
  const std::vector<Triangle> strip{ { { 0, 1, 4 } }, { { 0, 3, 4 } }, { { 1, 2, 5 } },
    { { 1, 4, 5 } } };
  std::vector<glm::dvec3> up(12, glm::dvec3(0, 0, 1));
  const Orientation o = orientConsistently(points, strip, up);
  EXPECT_EQ(o.Reversed, (std::vector<unsigned char>{ 0, 1, 0, 1 }));
  std::vector<glm::dvec3> down(12, glm::dvec3(0, 0, -1));
  EXPECT_EQ(
    orientConsistently(points, strip, down).Reversed, (std::vector<unsigned char>{ 1, 0, 1, 0 }));

  // A Moebius strip: a band of 6 quads whose ends join with a half twist.
  std::vector<glm::dvec3> band;
  const int n = 6;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * pi * i / n;
    for (int s : { -1, 1 })
    {
      const double w = 0.3 * s;
      band.emplace_back((1 + w * std::cos(a / 2)) * std::cos(a),
        (1 + w * std::cos(a / 2)) * std::sin(a), w * std::sin(a / 2));
    }
  }
  std::vector<Triangle> moebius;
  for (int i = 0; i < n; ++i)
  {
    const Id a0 = 2 * i, a1 = 2 * i + 1;
    // The last quad joins the first with its sides exchanged.
    const Id b0 = i + 1 < n ? 2 * (i + 1) : 1;
    const Id b1 = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    moebius.push_back({ { a0, b0, b1 } });
    moebius.push_back({ { a0, b1, a1 } });
  }
  const Orientation m = orientConsistently(band, moebius);
  EXPECT_EQ(m.ComponentCount, 1u);
  EXPECT_GE(m.InconsistentEdgeCount, 1u);
}

TEST(WeldedSurface, TriangleSoupSmoothsExactlyAsTheWeldedMesh)
{
  const auto [points, triangles, soupPoints, soupTriangles] = coretest::sphereAndSoup(6, 10);
  const std::vector<glm::dvec3> soupNormals = soupPoints; // exact sphere normals
  for (const bool withNormals : { true, false })
  {
    const WeldedSurface welded(points, triangles, withNormals ? points : std::vector<glm::dvec3>{},
      {}, coretest::plainOptions());
    const WeldedSurface soup(soupPoints, soupTriangles,
      withNormals ? soupNormals : std::vector<glm::dvec3>{}, {}, coretest::plainOptions());
    EXPECT_EQ(soup.statistics().WeldedPointCount, soupPoints.size() - points.size());

    for (const glm::dvec3& eye : { glm::dvec3(4, 1, 0.5), glm::dvec3(-1, 3, 2) })
    {
      const ViewGeometry view = coretest::perspectiveFrom(eye);
      const SmoothingParameters parameters;
      const SmoothingResult a = smoothSilhouettes(welded.prepared(), view, parameters);
      const SmoothingResult b = smoothSilhouettes(soup.prepared(), view, parameters);
      ASSERT_GT(a.SilhouetteTriangleCount, 0u);
      EXPECT_EQ(a.SilhouetteTriangleCount, b.SilhouetteTriangleCount);
      const SurfaceFrame fa = welded.assemble(a);
      const SurfaceFrame fb = soup.assemble(b);
      EXPECT_EQ(
        positionTriangles(welded, points, a, fa), positionTriangles(soup, soupPoints, b, fb));
      // Each soup triangle keeps its own corners: every output triangle's
      // input points are its input triangle's.
      for (std::size_t t = 0; t < fb.Triangles.size(); ++t)
      {
        const Triangle& own = soupTriangles[static_cast<std::size_t>(fb.SourceTriangle[t])];
        for (const Id o : fb.Triangles[t])
        {
          const std::array<Id, 3> sources = o < static_cast<Id>(soup.outputPointCount())
            ? std::array<Id, 3>{ { soup.outputSource(o), soup.outputSource(o),
                soup.outputSource(o) } }
            : fb.Added[static_cast<std::size_t>(o - static_cast<Id>(soup.outputPointCount()))]
                .Sources;
          for (const Id s : sources)
          {
            EXPECT_TRUE(std::find(own.begin(), own.end(), s) != own.end());
          }
        }
      }
    }
  }
  // The deliberately wrong variant: without welding and without normals,
  // every soup triangle is its own flat patch and none is a silhouette
  // triangle (what users saw). (With exact normals a soup already smoothed
  // right: silhouette points depend on positions and normals only.)
  SurfaceOptions noWeld = coretest::plainOptions();
  noWeld.Weld = false;
  const WeldedSurface bare(soupPoints, soupTriangles, {}, {}, noWeld);
  EXPECT_EQ(smoothSilhouettes(
              bare.prepared(), coretest::perspectiveFrom({ 4, 1, 0.5 }), SmoothingParameters())
              .SilhouetteTriangleCount,
    0u);
}

TEST(WeldedSurface, TextureSeamKeepsOnePointPerSide)
{
  // The sphere cut into two charts: the triangles of the last sector (a
  // strip from pole to pole) get their own copies of all their points, as
  // an exporter does for a separate texture chart.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  const int sectors = 10;
  coretest::unitSphere(6, sectors, points, triangles);
  const std::size_t original = points.size();
  const double pi = 3.14159265358979323846;
  std::map<Id, Id> copyOf;
  std::vector<unsigned char> chart(original, 0);
  for (Triangle& t : triangles)
  {
    const glm::dvec3 centre =
      (points[static_cast<std::size_t>(t[0])] + points[static_cast<std::size_t>(t[1])] +
        points[static_cast<std::size_t>(t[2])]) /
      3.0;
    const double phi = std::atan2(centre.y, centre.x);
    if (!(phi < 0.0 && phi > -2.0 * pi / sectors))
    {
      continue;
    }
    for (Id& p : t)
    {
      auto inserted = copyOf.emplace(p, static_cast<Id>(points.size()));
      if (inserted.second)
      {
        points.push_back(points[static_cast<std::size_t>(p)]);
        chart.push_back(1);
      }
      p = inserted.first->second;
    }
  }
  ASSERT_FALSE(copyOf.empty());
  const WeldedSurface surface(points, triangles, points, {}, coretest::plainOptions());
  EXPECT_EQ(surface.statistics().WeldedPointCount, copyOf.size());
  // A view from above: its silhouette runs round the sphere below the
  // equator's height and crosses the seam (the +x meridian).
  const SmoothingResult result = smoothSilhouettes(
    surface.prepared(), coretest::perspectiveFrom({ 0, 0.3, 4 }), SmoothingParameters());
  const SurfaceFrame frame = surface.assemble(result);
  std::map<std::size_t, std::set<unsigned char>> chartsOfNewPoint;
  std::size_t onSeam = 0;
  for (const SurfaceFrame::AddedPoint& added : frame.Added)
  {
    std::set<unsigned char> charts;
    for (const Id s : added.Sources)
    {
      charts.insert(chart[static_cast<std::size_t>(s)]);
    }
    // An added point comes from one side of the seam only.
    EXPECT_EQ(charts.size(), 1u);
    chartsOfNewPoint[added.NewPoint].insert(*charts.begin());
  }
  for (const auto& entry : chartsOfNewPoint)
  {
    onSeam += entry.second.size() == 2 ? 1 : 0;
  }
  // The silhouette crosses the seam: its points there exist once per side.
  EXPECT_GE(onSeam, 1u);
  EXPECT_EQ(frame.Added.size(), result.NewPoints.size() + onSeam);
}

// A mesh with some of its triangles turned over smooths as the oriented
// one, and is written with one winding per connected part, its majority's:
// a sphere with 30% of its triangles turned over is written as the sphere
// (before 2026-12-04 each triangle kept its own winding, and VTK lit the
// turned ones from behind, black), one with 70% turned over as the
// inside-out sphere.
TEST(WeldedSurface, MixedWindingIsWrittenAsItsPartsMajorityAndSmoothsAsTheOrientedMesh)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(6, 10, points, triangles);
  const WeldedSurface clean(points, triangles, {}, {}, coretest::plainOptions());
  const ViewGeometry view = coretest::perspectiveFrom({ 3, -2, 1 });
  const SmoothingResult a = smoothSilhouettes(clean.prepared(), view, SmoothingParameters());
  const SurfaceFrame fa = clean.assemble(a);
  for (const int percent : { 30, 70 })
  {
    std::vector<Triangle> mixed = triangles;
    std::mt19937 random(3);
    std::size_t inputTurned = 0;
    for (Triangle& t : mixed)
    {
      if (static_cast<int>(random() % 100) < percent)
      {
        t = oriented(t, true);
        ++inputTurned;
      }
    }
    const WeldedSurface reversed(points, mixed, {}, {}, coretest::plainOptions());
    EXPECT_GT(reversed.statistics().ReversedTriangleCount, 0u);
    const SmoothingResult b = smoothSilhouettes(reversed.prepared(), view, SmoothingParameters());
    EXPECT_EQ(a.SilhouetteTriangleCount, b.SilhouetteTriangleCount);
    const SurfaceFrame fb = reversed.assemble(b);
    ASSERT_EQ(fa.Triangles.size(), fb.Triangles.size());
    // Same triangles, all wound the majority's way.
    const bool majorityTurned = 2 * inputTurned > mixed.size();
    std::size_t turned = 0;
    for (std::size_t t = 0; t < fb.Triangles.size(); ++t)
    {
      const Triangle& x = fa.Triangles[t];
      const Triangle& y = fb.Triangles[t];
      EXPECT_TRUE(std::is_permutation(x.begin(), x.end(), y.begin()));
      const bool reversedWinding = y == oriented(x, true) ||
        y == Triangle{ { x[1], x[0], x[2] } } || y == Triangle{ { x[2], x[1], x[0] } };
      turned += reversedWinding ? 1 : 0;
    }
    EXPECT_EQ(turned, majorityTurned ? fb.Triangles.size() : 0u) << percent << "% turned over";
    // Every output point's normal is reversed exactly when its part is.
    for (std::size_t o = 0; o < reversed.outputPointCount(); ++o)
    {
      EXPECT_EQ(reversed.outputNormalReversed(static_cast<Id>(o)), majorityTurned) << o;
    }
  }
  // The deliberately wrong variant: without orientation the silhouette
  // triangles are not those of the sphere.
  std::vector<Triangle> mixed = triangles;
  std::mt19937 random(3);
  for (Triangle& t : mixed)
  {
    t = random() % 10 < 3 ? oriented(t, true) : t;
  }
  SurfaceOptions noOrient = coretest::plainOptions();
  noOrient.Orient = false;
  const WeldedSurface raw(points, mixed, {}, {}, noOrient);
  EXPECT_NE(smoothSilhouettes(raw.prepared(), view, SmoothingParameters()).SilhouetteTriangleCount,
    a.SilhouetteTriangleCount);
}

// Given normals pointing into the surface are reversed per component, corner
// by corner (they are read in place, not copied per corner): the shading
// normals are those of the same surface given the outward normals, bit for
// bit, built anew and moved, on a welded sphere, on a soup of its triangles,
// and on the sphere with a third of its triangles turned over (each corner's
// normal is then found through the turn).
TEST(WeldedSurface, InwardGivenNormalsShadeAsTheOutwardOnes)
{
  const auto [points, triangles, soupPoints, soupTriangles] = coretest::sphereAndSoup(8, 12);
  std::vector<Triangle> mixed = triangles;
  std::mt19937 random(7);
  for (Triangle& t : mixed)
  {
    if (random() % 3 == 0)
    {
      t = oriented(t, true);
    }
  }
  struct Case
  {
    const char* Name;
    const std::vector<glm::dvec3>& Points;
    const std::vector<Triangle>& Triangles; // given with the inward normals
    const std::vector<Triangle>& Clean;     // the same surface, all wound outward
  };
  const Case cases[] = { { "welded", points, triangles, triangles },
    { "soup", soupPoints, soupTriangles, soupTriangles }, { "turned", points, mixed, triangles } };
  for (const Case& c : cases)
  {
    std::vector<glm::dvec3> outward = c.Points;
    std::vector<glm::dvec3> inward;
    for (const glm::dvec3& n : outward)
    {
      inward.push_back(-n);
    }
    const WeldedSurface out(c.Points, c.Clean, outward, {}, coretest::plainOptions());
    WeldedSurface in(c.Points, c.Triangles, inward, {}, coretest::plainOptions());
    EXPECT_EQ(in.statistics().ReversedTriangleCount > 0, c.Triangles != c.Clean) << c.Name;
    EXPECT_EQ(in.prepared().normals(), out.prepared().normals()) << c.Name;
    // Moved: stretched along x, the normals with it.
    std::vector<glm::dvec3> moved = c.Points;
    std::vector<glm::dvec3> movedInward = inward;
    for (std::size_t i = 0; i < moved.size(); ++i)
    {
      moved[i].x *= 1.25;
      movedInward[i].x /= 1.25;
    }
    ASSERT_TRUE(in.movePoints(moved, movedInward, {}, coretest::plainOptions())) << c.Name;
    std::vector<glm::dvec3> movedOutward;
    for (const glm::dvec3& n : movedInward)
    {
      movedOutward.push_back(-n);
    }
    const WeldedSurface anew(moved, c.Clean, movedOutward, {}, coretest::plainOptions());
    EXPECT_EQ(in.prepared().normals(), anew.prepared().normals()) << c.Name;
    // The comparison can fail: left unoriented, the inward normals stay.
    SurfaceOptions keep = coretest::plainOptions();
    keep.Orient = false;
    const WeldedSurface raw(c.Points, c.Triangles, inward, {}, keep);
    EXPECT_NE(raw.prepared().normals(), out.prepared().normals()) << c.Name;
  }
}

TEST(WeldedSurface, CleanMeshIsThePreparedMeshItself)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(16, 8, 0.4, points, triangles);
  const WeldedSurface surface(
    points, triangles, {}, { { 0, 1 }, { 1, 2 } }, coretest::plainOptions());
  const SmoothingResult result = smoothSilhouettes(
    surface.prepared(), coretest::perspectiveFrom({ 0.5, 3, 1 }), SmoothingParameters());
  const SurfaceFrame frame = surface.assemble(result);
  std::vector<Triangle> expected;
  std::vector<Id> source;
  std::vector<unsigned char> kind;
  assembleTriangles(surface.prepared(), result, expected, source, kind);
  EXPECT_EQ(frame.Triangles, expected);
  EXPECT_EQ(frame.SourceTriangle, source);
  EXPECT_EQ(frame.Kind, kind);
  EXPECT_EQ(frame.Added.size(), result.NewPoints.size());
  EXPECT_EQ(surface.outputPointCount(), surface.prepared().points().size());
}

TEST(WeldedSurface, FlatShadedNormalsAreNotSeams)
{
  // The sphere as a soup whose normals are the faces' own (flat shading):
  // every edge would be a normal seam.
  const auto [points, triangles, soupPoints, soupTriangles] = coretest::sphereAndSoup(6, 10);
  std::vector<glm::dvec3> faceNormals;
  for (const Triangle& t : soupTriangles)
  {
    const glm::dvec3 n = glm::normalize(
      glm::cross(soupPoints[t[1]] - soupPoints[t[0]], soupPoints[t[2]] - soupPoints[t[0]]));
    faceNormals.insert(faceNormals.end(), 3, n);
  }
  const WeldedSurface surface(soupPoints, soupTriangles, faceNormals, {}, coretest::plainOptions());
  EXPECT_TRUE(surface.statistics().FlatShadedNormals);
  EXPECT_EQ(surface.statistics().NormalSeamEdgeCount, 0u);
  EXPECT_TRUE(surface.prepared().features().empty());
}

TEST(FlatSidedCreases, BoxEdgesYesCoarseSphereNo)
{
  // An 8-point box: 12 creases at 90 degrees between flat pairs.
  const std::vector<glm::dvec3> box{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  const std::vector<Triangle> faces{ { { 0, 2, 1 } }, { { 0, 3, 2 } }, { { 4, 5, 6 } },
    { { 4, 6, 7 } }, { { 0, 1, 5 } }, { { 0, 5, 4 } }, { { 1, 2, 6 } }, { { 1, 6, 5 } },
    { { 2, 3, 7 } }, { { 2, 7, 6 } }, { { 3, 0, 4 } }, { { 3, 4, 7 } } };
  EXPECT_EQ(flatSidedCreases(box, faces, 60.0).size(), 12u);
  EXPECT_EQ(flatSidedCreases(box, faces, 95.0).size(), 0u);
  // The octahedron (109-degree edges, no flat neighbours): none, where a
  // plain dihedral threshold marks all 12.
  const std::vector<glm::dvec3> octahedron{ { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };
  std::vector<Triangle> eight;
  for (const Id x : { 0, 1 })
  {
    for (const Id y : { 2, 3 })
    {
      for (const Id z : { 4, 5 })
      {
        const bool positive = (x == 0) == (y == 2) ? z == 4 : z == 5;
        eight.push_back(positive ? Triangle{ { x, y, z } } : Triangle{ { x, z, y } });
      }
    }
  }
  EXPECT_TRUE(flatSidedCreases(octahedron, eight, 60.0).empty());
  EXPECT_EQ(featureEdgesByAngle(octahedron, eight, 60.0).size(), 12u);
  // Parametric grids have planar quads: a 12 x 6 torus (60-degree rings) is
  // clear of the default 65 degrees; an 8 x 4 torus (90) is taken as creased,
  // a limitation the header states.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(12, 6, 0.4, points, triangles);
  EXPECT_TRUE(flatSidedCreases(points, triangles, 65.0).empty());
  coretest::torus(8, 4, 0.4, points, triangles);
  EXPECT_FALSE(flatSidedCreases(points, triangles, 65.0).empty());
}

TEST(FlatSidedCreases, ALoneSharpEdgeIsNoCrease)
{
  // vtkSphereSource's sphere of 8 x 6 samples (poles among the 6: rings at
  // 36, 72, 108 and 144 degrees) stretched to twice its length and turned by
  // 30 degrees (a user's trial): at each pointed end the edge across the
  // equator, between planar quads, turns by 79 degrees, its neighbours by
  // 50. Each meets no other sharp edge.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(5, 8, points, triangles);
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (glm::dvec3& p : points)
  {
    const double x = 2.0 * p.x; // stretched, then turned (vtkTransform's order)
    p = glm::dvec3(c * x - s * p.y, s * x + c * p.y, p.z);
  }
  EXPECT_EQ(featureEdgesByAngle(points, triangles, 65.0).size(), 2u);
  EXPECT_TRUE(flatSidedCreases(points, triangles, 65.0).empty());
  // (A box's edges, which meet at its corners, stay creases: above; a sheet
  // folded once keeps its fold, which runs to its borders:
  // core.WeldedSurface.MovedPointsThatMakeANewCreaseAskForARebuild.)
}

TEST(FlatSidedCreases, AFaceOfOneTriangleBesideFlatFacesIsFlat)
{
  // A wedge (OpenSCAD's linear_extrude of a right triangle): two rectangles
  // of two triangles each and a slanted one, and two end caps of one
  // triangle. All 9 edges of the solid are creases; the caps have no
  // coplanar neighbour, so the rule of flat pairs alone finds only the 3
  // long edges between the rectangles.
  const std::vector<glm::dvec3> wedge{ { 0, 0, 0 }, { 30, 0, 0 }, { 0, 15, 0 }, { 0, 0, 10 },
    { 30, 0, 10 }, { 0, 15, 10 } };
  const std::vector<Triangle> faces{ { { 0, 2, 1 } }, { { 3, 4, 5 } }, // the caps
    { { 0, 1, 4 } }, { { 0, 4, 3 } },                                  // the floor
    { { 0, 3, 5 } }, { { 0, 5, 2 } },                                  // the back
    { { 1, 2, 5 } }, { { 1, 5, 4 } } };                                // the slope
  // (The flat-pair rule alone gave 3: the wedge was drawn as a loaf.)
  EXPECT_EQ(flatSidedCreases(wedge, faces, 65.0).size(), 9u);
  // A lone triangle needs a flat neighbour: the octahedron above has none,
  // and neither has a tetrahedron (every edge sharp, every face one
  // triangle), which stays a coarse smooth surface.
  const std::vector<glm::dvec3> tetrahedron{ { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 } };
  const std::vector<Triangle> four{ { { 0, 1, 2 } }, { { 0, 3, 1 } }, { { 0, 2, 3 } },
    { { 1, 3, 2 } } };
  EXPECT_TRUE(flatSidedCreases(tetrahedron, four, 65.0).empty());
}

namespace
{

// A solid of revolution about z with `sides` sides: the profile's points
// (radius, height) from the bottom's centre (radius 0) to the top's (radius
// 0), fans at both ends and two triangles between neighbouring rings.
void revolve(const std::vector<glm::dvec2>& profile, int sides, std::vector<glm::dvec3>& points,
  std::vector<Triangle>& triangles)
{
  points.clear();
  triangles.clear();
  const auto rings = static_cast<Id>(profile.size()) - 2;
  points.emplace_back(0.0, 0.0, profile.front().y);
  for (Id r = 1; r <= rings; ++r)
  {
    for (int s = 0; s < sides; ++s)
    {
      const double a = 2.0 * 3.14159265358979 * s / sides;
      points.emplace_back(profile[r].x * std::cos(a), profile[r].x * std::sin(a), profile[r].y);
    }
  }
  points.emplace_back(0.0, 0.0, profile.back().y);
  const Id top = static_cast<Id>(points.size()) - 1;
  auto at = [sides](Id ring, int s) {
    return 1 + (ring - 1) * sides + (s % sides);
  };
  for (int s = 0; s < sides; ++s)
  {
    triangles.push_back({ { 0, at(1, s + 1), at(1, s) } });
    for (Id r = 1; r < rings; ++r)
    {
      triangles.push_back({ { at(r, s), at(r, s + 1), at(r + 1, s + 1) } });
      triangles.push_back({ { at(r, s), at(r + 1, s + 1), at(r + 1, s) } });
    }
    triangles.push_back({ { at(rings, s), at(rings, s + 1), top } });
  }
}

} // namespace

TEST(FlatSidedCreases, TheOutlineOfAFlatFaceSharpAllRound)
{
  // A 16-sided cone: its flat base meets single side triangles at 117
  // degrees. The rim is a crease, the sides' 22-degree edges are not.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  revolve({ { 0, 0 }, { 1, 0 }, { 0, 2 } }, 16, points, triangles);
  const std::vector<FeatureEdge> rim = flatSidedCreases(points, triangles, 65.0);
  ASSERT_EQ(rim.size(), 16u);
  for (const FeatureEdge& edge : rim)
  {
    EXPECT_EQ(points[edge.first].z, 0.0);
    EXPECT_EQ(points[edge.second].z, 0.0);
    EXPECT_TRUE(edge.first != 0 && edge.second != 0); // not a spoke of the base
  }
  // The same base meeting a ring that rises at 20 degrees, then the cone:
  // the base's outline is gentle, so nothing is a crease.
  revolve({ { 0, 0 }, { 1, 0 }, { 2, 0.364 }, { 0, 2 } }, 16, points, triangles);
  EXPECT_TRUE(flatSidedCreases(points, triangles, 65.0).empty());
  // A base with a triangle missing has no closed outline.
  revolve({ { 0, 0 }, { 1, 0 }, { 0, 2 } }, 16, points, triangles);
  triangles.erase(triangles.begin());
  EXPECT_TRUE(flatSidedCreases(points, triangles, 65.0).empty());
  // Nor is a single triangle's outline a face's (the tetrahedron above).
}

TEST(FlatSidedCreases, AFaceOnANonManifoldEdgeHasNoOutline)
{
  // The 8-sided cone's base with a fin on one rim edge: that edge has three
  // triangles, so the base has no closed outline, whichever side the fin's
  // triangle is listed on (only two sides of an edge are kept per edge).
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  revolve({ { 0, 0 }, { 1, 0 }, { 0, 2 } }, 8, points, triangles);
  ASSERT_EQ(flatSidedCreases(points, triangles, 65.0).size(), 8u);
  points.emplace_back(1.0, 0.0, -1.0);
  const Triangle fin{ { 1, 2, static_cast<Id>(points.size()) - 1 } }; // on rim edge (1, 2)
  std::vector<Triangle> finFirst{ fin };
  finFirst.insert(finFirst.end(), triangles.begin(), triangles.end());
  std::vector<Triangle> finLast = triangles;
  finLast.push_back(fin);
  // The fin and the side triangles before the base's fan: the edge's first
  // two sides are then the fin and a side triangle, not the base.
  std::vector<Triangle> baseLast{ fin };
  for (const bool base : { false, true })
  {
    for (const Triangle& t : triangles)
    {
      if ((t[0] == 0) == base) // the base's fan starts at its centre, 0
      {
        baseLast.push_back(t);
      }
    }
  }
  for (const auto* order : { &finFirst, &finLast, &baseLast })
  {
    for (const FeatureEdge& edge : flatSidedCreases(points, *order, 65.0))
    {
      EXPECT_FALSE(points[edge.first].z == 0.0 && points[edge.second].z == 0.0)
        << "rim edge (" << edge.first << ", " << edge.second << ") taken as a crease";
    }
  }
}

TEST(WeldedSurface, CopiesThatDifferByRoundingAreOnePoint)
{
  // A torus sampled as vtkParametricFunctionSource samples it: both ends of
  // each angle's range, 0 and 2 pi, so the last row and column are copies
  // of the first, 1e-16 to 2e-15 away, joined to them by the wrap's
  // degenerate triangles. `apart` moves the last column (the copy of the
  // first) that much farther out.
  auto torus = [](double apart) {
    constexpr int nu = 12, nv = 8;
    std::vector<glm::dvec3> points;
    for (int i = 0; i < nu; ++i)
    {
      for (int j = 0; j < nv; ++j)
      {
        const double u = 2.0 * M_PI * i / (nu - 1), v = 2.0 * M_PI * j / (nv - 1);
        const double r = 1.0 + 0.4 * std::cos(v) + (i == nu - 1 ? apart : 0.0);
        points.emplace_back(r * std::cos(u), r * std::sin(u), 0.4 * std::sin(v));
      }
    }
    std::vector<Triangle> triangles;
    for (int i = 0; i < nu; ++i)
    {
      for (int j = 0; j < nv; ++j)
      {
        const Id a = i * nv + j, b = ((i + 1) % nu) * nv + j;
        const Id c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
        triangles.push_back({ a, b, c });
        triangles.push_back({ a, c, d });
      }
    }
    return std::make_pair(points, triangles);
  };
  const auto [points, triangles] = torus(0.0);
  const WeldedSurface surface(points, triangles, {}, {}, coretest::plainOptions());
  const SurfaceStatistics& welded = surface.statistics();
  EXPECT_GT(welded.RoundingCopyEdgeCount, 0u);
  EXPECT_EQ(welded.NearCopyEdgeCount, 0u);
  EXPECT_EQ(welded.InconsistentEdgeCount, 0u);
  EXPECT_EQ(welded.WeldedPointCount, 12u + 8u - 1u); // the last row and column
  // It smooths as the torus whose copies are exact.
  std::vector<glm::dvec3> exact = points;
  for (int i = 0; i < 12; ++i)
  {
    for (int j = 0; j < 8; ++j)
    {
      exact[static_cast<std::size_t>(i * 8 + j)] =
        points[static_cast<std::size_t>((i % 11) * 8 + j % 7)];
    }
  }
  const WeldedSurface exactSurface(exact, triangles, {}, {}, coretest::plainOptions());
  EXPECT_EQ(exactSurface.statistics().RoundingCopyEdgeCount, 0u);
  const ViewGeometry view = coretest::perspectiveFrom({ 1, 4, 2 });
  const SmoothingResult a = smoothSilhouettes(surface.prepared(), view, SmoothingParameters());
  const SmoothingResult b = smoothSilhouettes(exactSurface.prepared(), view, SmoothingParameters());
  ASSERT_GT(b.SilhouetteTriangleCount, 0u);
  EXPECT_EQ(a.SilhouetteTriangleCount, b.SilhouetteTriangleCount);
  EXPECT_EQ(surface.assemble(a).Triangles.size(), exactSurface.assemble(b).Triangles.size());
  // Copies 1e-7 of the mesh's size apart are not rounding: they stay apart,
  // reported as near copies (the last row's copies are welded still).
  const auto [apartPoints, apartTriangles] = torus(3e-7);
  const WeldedSurface apart(apartPoints, apartTriangles, {}, {}, coretest::plainOptions());
  EXPECT_GT(apart.statistics().NearCopyEdgeCount, 0u);
  EXPECT_EQ(apart.statistics().WeldedPointCount, 12u); // the last row, one a column
}
