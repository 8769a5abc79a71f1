// Asset-file meshes: welding coincident points, normal seams, consistent
// orientation, and WeldedSurface's output on the input's own points.
#include "CoreTestMeshes.h"
#include "SurfaceOrientation.h"
#include "SurfaceWelding.h"
#include "TriangleGrid.h"
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

// Every corner its own point (what VTK's OBJ reader makes of a textured
// asset): corner 3t + k is point 3t + k.
void makeSoup(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
  std::vector<glm::dvec3>& soupPoints, std::vector<Triangle>& soupTriangles)
{
  soupPoints.clear();
  soupTriangles.clear();
  for (const Triangle& t : triangles)
  {
    const Id base = static_cast<Id>(soupPoints.size());
    for (const Id p : t)
    {
      soupPoints.push_back(points[static_cast<std::size_t>(p)]);
    }
    soupTriangles.push_back({ { base, base + 1, base + 2 } });
  }
}

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

SurfaceOptions plainOptions()
{
  SurfaceOptions options;
  options.DetectFlatCreases = false;
  return options;
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
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(6, 10, points, triangles);
  std::vector<glm::dvec3> soupPoints;
  std::vector<Triangle> soupTriangles;
  makeSoup(points, triangles, soupPoints, soupTriangles);
  const std::vector<glm::dvec3> soupNormals = soupPoints; // exact sphere normals
  for (const bool withNormals : { true, false })
  {
    const WeldedSurface welded(
      points, triangles, withNormals ? points : std::vector<glm::dvec3>{}, {}, plainOptions());
    const WeldedSurface soup(soupPoints, soupTriangles,
      withNormals ? soupNormals : std::vector<glm::dvec3>{}, {}, plainOptions());
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
  SurfaceOptions noWeld = plainOptions();
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
  const WeldedSurface surface(points, triangles, points, {}, plainOptions());
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

TEST(WeldedSurface, ReversedInputKeepsItsWindingAndSmoothsAsTheOrientedMesh)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(6, 10, points, triangles);
  std::vector<Triangle> mixed = triangles;
  std::mt19937 random(3);
  for (Triangle& t : mixed)
  {
    if (random() % 10 < 3)
    {
      t = oriented(t, true);
    }
  }
  const WeldedSurface clean(points, triangles, {}, {}, plainOptions());
  const WeldedSurface reversed(points, mixed, {}, {}, plainOptions());
  EXPECT_GT(reversed.statistics().ReversedTriangleCount, 0u);
  const ViewGeometry view = coretest::perspectiveFrom({ 3, -2, 1 });
  const SmoothingResult a = smoothSilhouettes(clean.prepared(), view, SmoothingParameters());
  const SmoothingResult b = smoothSilhouettes(reversed.prepared(), view, SmoothingParameters());
  EXPECT_EQ(a.SilhouetteTriangleCount, b.SilhouetteTriangleCount);
  const SurfaceFrame fa = clean.assemble(a);
  const SurfaceFrame fb = reversed.assemble(b);
  ASSERT_EQ(fa.Triangles.size(), fb.Triangles.size());
  // Same triangles; each wound as its own input triangle was.
  std::size_t turned = 0;
  for (std::size_t t = 0; t < fb.Triangles.size(); ++t)
  {
    const Id source = fb.SourceTriangle[t];
    const bool inputTurned =
      mixed[static_cast<std::size_t>(source)] != triangles[static_cast<std::size_t>(source)];
    const Triangle& x = fa.Triangles[t];
    const Triangle& y = fb.Triangles[t];
    const bool same = std::is_permutation(x.begin(), x.end(), y.begin());
    EXPECT_TRUE(same);
    const bool reversedWinding = y == oriented(x, true) || y == Triangle{ { x[1], x[0], x[2] } } ||
      y == Triangle{ { x[2], x[1], x[0] } };
    EXPECT_EQ(reversedWinding, inputTurned);
    turned += reversedWinding ? 1 : 0;
  }
  EXPECT_GT(turned, 0u);
  // The deliberately wrong variant: without orientation the silhouette
  // triangles are not those of the sphere.
  SurfaceOptions noOrient = plainOptions();
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
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(8, 12, points, triangles);
  std::vector<glm::dvec3> soupPoints;
  std::vector<Triangle> soupTriangles;
  makeSoup(points, triangles, soupPoints, soupTriangles);
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
    const WeldedSurface out(c.Points, c.Clean, outward, {}, plainOptions());
    WeldedSurface in(c.Points, c.Triangles, inward, {}, plainOptions());
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
    ASSERT_TRUE(in.movePoints(moved, movedInward, {}, plainOptions())) << c.Name;
    std::vector<glm::dvec3> movedOutward;
    for (const glm::dvec3& n : movedInward)
    {
      movedOutward.push_back(-n);
    }
    const WeldedSurface anew(moved, c.Clean, movedOutward, {}, plainOptions());
    EXPECT_EQ(in.prepared().normals(), anew.prepared().normals()) << c.Name;
    // The comparison can fail: left unoriented, the inward normals stay.
    SurfaceOptions keep = plainOptions();
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
  const WeldedSurface surface(points, triangles, {}, { { 0, 1 }, { 1, 2 } }, plainOptions());
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
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(6, 10, points, triangles);
  std::vector<glm::dvec3> soupPoints;
  std::vector<Triangle> soupTriangles;
  makeSoup(points, triangles, soupPoints, soupTriangles);
  std::vector<glm::dvec3> faceNormals;
  for (const Triangle& t : soupTriangles)
  {
    const glm::dvec3 n = glm::normalize(
      glm::cross(soupPoints[t[1]] - soupPoints[t[0]], soupPoints[t[2]] - soupPoints[t[0]]));
    faceNormals.insert(faceNormals.end(), 3, n);
  }
  const WeldedSurface surface(soupPoints, soupTriangles, faceNormals, {}, plainOptions());
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

namespace
{

// The base mesh (assemble() of an empty result) with each of the changes'
// ReplacedTriangles replaced by its triangles: what assemble() gives.
void ExpectChangesComposeToTheWholeFrame(
  const WeldedSurface& surface, const SmoothingResult& result)
{
  const SurfaceFrame whole = surface.assemble(result);
  const SurfaceFrame base = surface.assemble(SmoothingResult());
  const SurfaceFrame changes = surface.assembleChanges(result);
  ASSERT_TRUE(std::is_sorted(changes.ReplacedTriangles.begin(), changes.ReplacedTriangles.end()));
  ASSERT_EQ(changes.Triangles.size(), changes.SourceTriangle.size());
  std::vector<Triangle> composed;
  std::vector<Id> composedSource;
  std::size_t r = 0;
  std::size_t c = 0;
  for (std::size_t t = 0; t < base.Triangles.size(); ++t)
  {
    if (r < changes.ReplacedTriangles.size() && changes.ReplacedTriangles[r] == static_cast<Id>(t))
    {
      for (; c < changes.Triangles.size() && changes.SourceTriangle[c] == static_cast<Id>(t); ++c)
      {
        composed.push_back(changes.Triangles[c]);
        composedSource.push_back(changes.SourceTriangle[c]);
      }
      ++r;
      continue;
    }
    composed.push_back(base.Triangles[t]);
    composedSource.push_back(static_cast<Id>(t));
  }
  EXPECT_EQ(r, changes.ReplacedTriangles.size());
  EXPECT_EQ(c, changes.Triangles.size());
  EXPECT_EQ(composed, whole.Triangles);
  EXPECT_EQ(composedSource, whole.SourceTriangle);
  ASSERT_EQ(changes.Added.size(), whole.Added.size());
  for (std::size_t a = 0; a < whole.Added.size(); ++a)
  {
    EXPECT_EQ(changes.Added[a].NewPoint, whole.Added[a].NewPoint);
    EXPECT_EQ(changes.Added[a].Sources, whole.Added[a].Sources);
  }
  EXPECT_EQ(changes.Moved, whole.Moved);
  EXPECT_EQ(changes.Polylines, whole.Polylines);
}

} // namespace

TEST(WeldedSurface, ChangesComposeToTheWholeFrame)
{
  // A torus seen obliquely has concave silhouette segments, so the
  // perturbation moves points and kept triangles around them change too.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(24, 12, 0.35, points, triangles);
  const WeldedSurface torus(points, triangles, {}, {}, plainOptions());
  std::size_t moved = 0;
  std::size_t keptButChanged = 0;
  for (const glm::dvec3 eye : { glm::dvec3(0, -3, 1.2), glm::dvec3(2.5, 0.4, 2.0) })
  {
    const SmoothingResult result =
      smoothSilhouettes(torus.prepared(), coretest::perspectiveFrom(eye), SmoothingParameters());
    moved += result.MovedPoints.size();
    const SurfaceFrame changes = torus.assembleChanges(result);
    keptButChanged += changes.ReplacedTriangles.size() - result.RemeshedTriangles.size();
    ExpectChangesComposeToTheWholeFrame(torus, result);
  }
  // The case the test is for happened.
  EXPECT_GT(moved, 0u);
  EXPECT_GT(keptButChanged, 0u);

  // A sphere of triangle-soup corners (every point copied per triangle),
  // where added points exist once per side of every edge.
  coretest::unitSphere(6, 10, points, triangles);
  std::vector<glm::dvec3> soupPoints;
  std::vector<Triangle> soupTriangles;
  for (const Triangle& t : triangles)
  {
    Triangle own;
    for (std::size_t k = 0; k < 3; ++k)
    {
      own[k] = static_cast<Id>(soupPoints.size());
      soupPoints.push_back(points[static_cast<std::size_t>(t[k])]);
    }
    soupTriangles.push_back(own);
  }
  const WeldedSurface soup(soupPoints, soupTriangles, soupPoints, {}, plainOptions());
  ExpectChangesComposeToTheWholeFrame(soup,
    smoothSilhouettes(
      soup.prepared(), coretest::perspectiveFrom({ 0, 0.3, 4 }), SmoothingParameters()));
}

TEST(WeldedSurface, MovedPointsGiveTheSurfaceBuiltAnew)
{
  // A triangle-soup torus (every corner its own point: welding matters),
  // deformed smoothly: the moved surface smooths exactly as one built from
  // the moved points.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(24, 12, 0.35, points, triangles);
  std::vector<glm::dvec3> soup;
  std::vector<Triangle> soupTriangles;
  for (const Triangle& t : triangles)
  {
    Triangle own;
    for (std::size_t k = 0; k < 3; ++k)
    {
      own[k] = static_cast<Id>(soup.size());
      soup.push_back(points[static_cast<std::size_t>(t[k])]);
    }
    soupTriangles.push_back(own);
  }
  WeldedSurface moved(soup, soupTriangles, {}, {}, plainOptions());
  std::vector<glm::dvec3> deformed = soup;
  for (glm::dvec3& p : deformed)
  {
    p = glm::dvec3(p.x * 1.2, p.y + 0.1 * std::sin(3.0 * p.x), p.z * 0.9);
  }
  ASSERT_TRUE(moved.movePoints(deformed, {}, {}, plainOptions()));
  const WeldedSurface fresh(deformed, soupTriangles, {}, {}, plainOptions());
  EXPECT_EQ(moved.prepared().points(), fresh.prepared().points());
  EXPECT_EQ(moved.prepared().normals(), fresh.prepared().normals());
  EXPECT_EQ(moved.prepared().triangles(), fresh.prepared().triangles());
  for (const glm::dvec3 eye : { glm::dvec3(0, -3, 1.2), glm::dvec3(2.5, 0.4, 2.0) })
  {
    const ViewGeometry view = coretest::perspectiveFrom(eye);
    const SurfaceFrame a = moved.assemble(smoothSilhouettes(moved.prepared(), view, {}));
    const SurfaceFrame b = fresh.assemble(smoothSilhouettes(fresh.prepared(), view, {}));
    EXPECT_EQ(a.Triangles, b.Triangles);
    EXPECT_EQ(a.Moved, b.Moved);
    ASSERT_EQ(a.Added.size(), b.Added.size());
    EXPECT_GT(a.Added.size(), 0u);
  }

  // What the kept topology cannot take: a welded point torn from its
  // partners; the surface stays as it was.
  std::vector<glm::dvec3> torn = deformed;
  torn[0].x += 0.01;
  EXPECT_FALSE(moved.movePoints(torn, {}, {}, plainOptions()));
  EXPECT_EQ(moved.prepared().points(), fresh.prepared().points());
  // Another point count.
  EXPECT_FALSE(moved.movePoints(std::vector<glm::dvec3>(3), {}, {}, plainOptions()));
}

TEST(WeldedSurface, SmallMovesKeepTheFoldGuardsGridAndSmoothAsAFreshSurface)
{
  // A torus deformed a little each frame, as a time series is: the moved
  // surface keeps the fold guard's grid (with a slack) while the points
  // move under half a grid cell in all, and every frame smooths exactly as a
  // surface built from the moved points (whose grid is fresh). When the
  // small moves add up past half a cell, the next frame builds the grid
  // anew; after a single large move, frames scan instead.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(48, 24, 0.35, points, triangles);
  WeldedSurface moving(points, triangles, {}, {}, plainOptions());
  const ViewGeometry view = coretest::perspectiveFrom(glm::dvec3(0.3, -2.5, 1.4));
  smoothSilhouettes(moving.prepared(), view, {}); // scans for the fold checks
  EXPECT_FALSE(moving.prepared().hasTriangleGrid());
  smoothSilhouettes(moving.prepared(), view, {}); // the second frame builds the grid
  EXPECT_TRUE(moving.prepared().hasTriangleGrid());
  int adopted = 0;
  int rebuilt = 0;
  for (int frame = 1; frame <= 20; ++frame)
  {
    std::vector<glm::dvec3> moved = points;
    for (glm::dvec3& p : moved)
    {
      p +=
        0.004 * frame * glm::dvec3(std::sin(5.0 * p.y), std::cos(4.0 * p.x), std::sin(3.0 * p.x));
    }
    ASSERT_TRUE(moving.movePoints(moved, {}, {}, plainOptions()));
    const bool adopting = moving.prepared().triangleGridSlack() > 0.0;
    adopted += adopting ? 1 : 0;
    const WeldedSurface fresh(moved, triangles, {}, {}, plainOptions());
    EXPECT_EQ(fresh.prepared().triangleGridSlack(), 0.0);
    const SurfaceFrame a = moving.assemble(smoothSilhouettes(moving.prepared(), view, {}));
    EXPECT_TRUE(moving.prepared().hasTriangleGrid()) << "frame " << frame;
    rebuilt += adopting ? 0 : 1;
    const SurfaceFrame b = fresh.assemble(smoothSilhouettes(fresh.prepared(), view, {}));
    ASSERT_EQ(a.Triangles, b.Triangles) << "frame " << frame;
    EXPECT_EQ(a.Moved, b.Moved);
    EXPECT_GT(a.Added.size(), 0u);
  }
  EXPECT_GE(adopted, 2); // the first small moves keep the grid
  EXPECT_GE(rebuilt, 1); // and they add up past it
  std::vector<glm::dvec3> far = points;
  for (glm::dvec3& p : far)
  {
    p *= 1.5;
  }
  ASSERT_TRUE(moving.movePoints(far, {}, {}, plainOptions()));
  EXPECT_EQ(moving.prepared().triangleGridSlack(), 0.0);
  // Moves that outran the grid: later frames scan instead of building it
  // again, and smooth as a fresh surface does.
  for (int frame = 0; frame < 2; ++frame)
  {
    for (glm::dvec3& p : far)
    {
      p *= 1.2;
    }
    ASSERT_TRUE(moving.movePoints(far, {}, {}, plainOptions()));
    const SurfaceFrame a = moving.assemble(smoothSilhouettes(moving.prepared(), view, {}));
    EXPECT_FALSE(moving.prepared().hasTriangleGrid());
    const WeldedSurface fresh(far, triangles, {}, {}, plainOptions());
    const SurfaceFrame b = fresh.assemble(smoothSilhouettes(fresh.prepared(), view, {}));
    EXPECT_EQ(a.Triangles, b.Triangles) << "outrun frame " << frame;
  }
}

TEST(EdgeTable, EdgesAreTheSortedDistinctSidesWhateverTheIds)
{
  // The table numbers the distinct (low, high) sides in sorted order, and
  // gives every side its edge. Checked against a map on random triangles
  // (repeated corners among them) with point ids of a mesh's range (the
  // bucketed path), with a negative id and with a huge one (the sorted
  // path).
  std::mt19937 rng(11);
  for (const Id offset : { Id{ 0 }, Id{ -5 }, Id{ 3000000000 } })
  {
    std::uniform_int_distribution<Id> id(0, 60);
    std::vector<Triangle> triangles;
    for (int t = 0; t < 400; ++t)
    {
      triangles.push_back({ { id(rng), id(rng), id(rng) } });
    }
    triangles[7][2] = offset; // one corner out of the common range
    const EdgeTable table(triangles);
    std::map<std::pair<Id, Id>, Id> numbers;
    for (const Triangle& t : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Id a = t[static_cast<std::size_t>(k)];
        const Id b = t[static_cast<std::size_t>((k + 1) % 3)];
        numbers.emplace(std::make_pair(std::min(a, b), std::max(a, b)), 0);
      }
    }
    Id next = 0;
    for (auto& [key, number] : numbers)
    {
      number = next++;
    }
    ASSERT_EQ(table.edgeCount(), numbers.size()) << "offset " << offset;
    for (const auto& [key, number] : numbers)
    {
      EXPECT_EQ(table.edge(number).low, key.first);
      EXPECT_EQ(table.edge(number).high, key.second);
    }
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Id a = triangles[t][static_cast<std::size_t>(k)];
        const Id b = triangles[t][static_cast<std::size_t>((k + 1) % 3)];
        EXPECT_EQ(table.sideEdge(static_cast<Id>(t), k),
          numbers.at(std::make_pair(std::min(a, b), std::max(a, b))));
      }
    }
  }
}

TEST(TriangleGrid, BoxesWithoutExtentGetSmallCells)
{
  // Points as boxes (the fold guard asks about the triangles around moved
  // points): cells as small as the budget of 4 per box allows, not one cell
  // for the whole extent, where every query would test every box.
  std::vector<glm::dvec3> points;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 1000; ++i)
  {
    points.emplace_back(u(rng), u(rng), u(rng));
  }
  const TriangleGrid grid(points, points);
  EXPECT_LT(grid.cellSize(), 0.1); // about 1 / cbrt(4001)
  std::vector<Id> found;
  grid.query(points[17], points[17], found);
  EXPECT_EQ(found, std::vector<Id>{ 17 });
}

TEST(TriangleGrid, AGridOfEarlierBoxesNeedsItsSlack)
{
  // Why the slack: a triangle moved by 0.4 of a cell is missed by a query at
  // its new far corner unless the query is widened by the move.
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 5, 5, 0 },
    { 6, 5, 0 }, { 5, 6, 0 } };
  const std::vector<Triangle> triangles{ { 0, 1, 2 }, { 3, 4, 5 } };
  const TriangleGrid grid(points, triangles);
  const double move = 0.4 * grid.cellSize();
  const glm::dvec3 farCorner(1.0 + move, 0.0, 0.0); // corner 1 moved along x
  std::vector<Id> found;
  grid.query(farCorner, farCorner, found);
  EXPECT_TRUE(found.empty());
  const glm::dvec3 slack(move);
  grid.query(farCorner - slack, farCorner + slack, found);
  EXPECT_EQ(found, std::vector<Id>{ 0 });
}

TEST(PreparedMesh, AGridIsNotAdoptedAcrossAPointThatWasNotFinite)
{
  // The grid leaves out triangles with a corner that is not finite; a mesh
  // whose point became finite again must build its own.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(12, 6, 0.35, points, triangles);
  std::vector<glm::dvec3> broken = points;
  broken[5] = glm::dvec3(std::nan(""), 0.0, 0.0);
  const PreparedMesh before(broken, triangles, {});
  before.triangleGrid();
  PreparedMesh after(points, triangles, {});
  EXPECT_FALSE(after.adoptTriangleGrid(before));
  EXPECT_EQ(after.triangleGridSlack(), 0.0);
  // The same mesh a hair away adopts it.
  const PreparedMesh finite(points, triangles, {});
  finite.triangleGrid();
  std::vector<glm::dvec3> nudged = points;
  nudged[5].x += 1e-6;
  PreparedMesh next(nudged, triangles, {});
  EXPECT_TRUE(next.adoptTriangleGrid(finite));
  EXPECT_GT(next.triangleGridSlack(), 0.0);
}

namespace
{

// Every part of a prepared mesh that the passes read, compared exactly.
void expectSamePreparedMesh(const PreparedMesh& a, const PreparedMesh& b)
{
  EXPECT_EQ(a.points(), b.points());
  EXPECT_EQ(a.triangles(), b.triangles());
  EXPECT_EQ(a.normals(), b.normals());
  ASSERT_EQ(a.inputPointCount(), b.inputPointCount());
  ASSERT_EQ(a.edges().edgeCount(), b.edges().edgeCount());
  for (Id e = 0; e < static_cast<Id>(a.edges().edgeCount()); ++e)
  {
    EXPECT_EQ(a.edges().edge(e).low, b.edges().edge(e).low);
    EXPECT_EQ(a.edges().edge(e).high, b.edges().edge(e).high);
    EXPECT_EQ(a.isBoundaryEdge(e), b.isBoundaryEdge(e));
    EXPECT_EQ(a.edgeFeature(e), b.edgeFeature(e));
  }
  for (Id t = 0; t < static_cast<Id>(a.triangles().size()); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(a.edges().sideEdge(t, k), b.edges().sideEdge(t, k));
    }
  }
  for (Id p = 0; p < static_cast<Id>(a.points().size()); ++p)
  {
    EXPECT_EQ(a.sourcePoint(p), b.sourcePoint(p));
    EXPECT_EQ(a.onFeature(p), b.onFeature(p));
    EXPECT_EQ(a.onBoundary(p), b.onBoundary(p));
  }
  ASSERT_EQ(a.features().edges(), b.features().edges());
  for (Id f = 0; f < static_cast<Id>(a.features().edges().size()); ++f)
  {
    EXPECT_EQ(a.features().isCurved(f), b.features().isCurved(f));
    EXPECT_EQ(a.features().curve(f).P0, b.features().curve(f).P0);
    EXPECT_EQ(a.features().curve(f).P1, b.features().curve(f).P1);
    EXPECT_EQ(a.features().curve(f).T0, b.features().curve(f).T0);
    EXPECT_EQ(a.features().curve(f).T1, b.features().curve(f).T1);
  }
  EXPECT_EQ(a.featureTriangles(), b.featureTriangles());
  EXPECT_EQ(a.featureSideTriangles(), b.featureSideTriangles());
  EXPECT_EQ(a.neighbourOffsets(), b.neighbourOffsets());
  EXPECT_EQ(a.neighbours(), b.neighbours());
}

} // namespace

TEST(PreparedMesh, AMovedMeshIsTheMeshBuiltAnew)
{
  // An open torus (a few quads cut out) with two marked feature rings that
  // cross, split into smooth groups; one point of the outer ring is pulled
  // up far enough to make corners there, which changes the curves'
  // tangents and which ring edges are smoothed. Taking the earlier mesh's
  // topology must give the mesh built from the moved points, part for part.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::torus(24, 12, 0.35, points, triangles);
  triangles.erase(triangles.begin() + 200, triangles.begin() + 206);
  auto at = [](int i, int j) {
    return static_cast<Id>((i % 24) * 12 + j % 12);
  };
  std::vector<FeatureEdge> features;
  for (int i = 0; i < 24; ++i)
  {
    features.emplace_back(at(i, 0), at(i + 1, 0)); // the outer equator
  }
  for (int j = 0; j < 12; ++j)
  {
    features.emplace_back(at(0, j), at(0, j + 1)); // around the tube
  }
  const EdgeTable table(triangles);
  const auto weighting = NormalWeighting::Area;
  PreparedMesh earlier(points, triangles, {}, features, {}, &table, weighting);
  const PreparedMesh before(points, triangles, {}, features, {}, &table, weighting);
  earlier.triangleGrid();
  std::vector<glm::dvec3> pulled = points;
  pulled[static_cast<std::size_t>(at(6, 0))].z += 2.0;
  for (glm::dvec3& p : pulled)
  {
    p.z *= 1.1;
  }
  const std::unique_ptr<PreparedMesh> moved = PreparedMesh::moved(
    earlier, std::vector<glm::dvec3>(pulled), {}, features, {}, table, weighting);
  ASSERT_TRUE(moved);
  const PreparedMesh fresh(pulled, triangles, {}, features, {}, &table, weighting);
  ASSERT_GT(fresh.features().curvedCount(), 0u);
  EXPECT_GT(fresh.points().size(), points.size()); // split into smooth groups
  expectSamePreparedMesh(*moved, fresh);
  // What a move that kept the earlier curves or their smoothed edges would
  // get wrong: the pull changes both.
  EXPECT_NE(before.featureTriangles(), fresh.featureTriangles());
  EXPECT_NE(before.features().curvedCount(), fresh.features().curvedCount());
  // The pull is far beyond half a grid cell: the grid is not adopted.
  EXPECT_EQ(moved->triangleGridSlack(), 0.0);

  // Other features, or another point count: null, and the earlier mesh is
  // left as it was.
  PreparedMesh second(points, triangles, {}, features, {}, &table, weighting);
  std::vector<FeatureEdge> fewer(features.begin(), features.end() - 3);
  std::vector<glm::dvec3> same = points;
  EXPECT_FALSE(PreparedMesh::moved(second, std::move(same), {}, fewer, {}, table, weighting));
  EXPECT_EQ(same, points);
  EXPECT_FALSE(PreparedMesh::moved(
    second, std::vector<glm::dvec3>(points.size() - 1), {}, features, {}, table, weighting));
  expectSamePreparedMesh(second, before);
  // Feature edges that are no edge of the triangles do not count, as the
  // constructor drops them.
  std::vector<FeatureEdge> extra = features;
  extra.emplace_back(at(3, 0), at(9, 5));
  EXPECT_TRUE(
    PreparedMesh::moved(second, std::vector<glm::dvec3>(points), {}, extra, {}, table, weighting));
}

TEST(WeldedSurface, MovedPointsThatMakeANewCreaseAskForARebuild)
{
  // A flat strip folded to a right angle: with flat creases detected, the
  // fold is a feature, which changes the points per smooth group.
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  for (int i = 0; i <= 4; ++i)
  {
    points.emplace_back(i, 0.0, 0.0);
    points.emplace_back(i, 1.0, 0.0);
  }
  for (int i = 0; i < 4; ++i)
  {
    const Id a = 2 * i;
    triangles.push_back({ a, a + 2, a + 3 });
    triangles.push_back({ a, a + 3, a + 1 });
  }
  SurfaceOptions options; // flat creases detected (the default)
  WeldedSurface strip(points, triangles, {}, {}, options);
  EXPECT_EQ(strip.statistics().FlatCreaseEdgeCount, 0u);
  std::vector<glm::dvec3> folded = points;
  for (glm::dvec3& p : folded)
  {
    if (p.x > 2.0)
    {
      p = glm::dvec3(2.0, p.y, p.x - 2.0); // the right half stands up
    }
  }
  const WeldedSurface fresh(folded, triangles, {}, {}, options);
  ASSERT_GT(fresh.statistics().FlatCreaseEdgeCount, 0u); // the case happens
  EXPECT_FALSE(strip.movePoints(folded, {}, {}, options));
  EXPECT_EQ(strip.statistics().FlatCreaseEdgeCount, 0u); // left as it was
}
