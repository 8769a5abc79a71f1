// Gaps in a drawing's outline closed with the surface's contour
// (Lines/Core/OutlineGaps.h), on scenes whose answers are exact: a cube's
// outline hexagon, drawn or not, and a fold whose contour has the surface
// just behind it.
#include "OutlineGaps.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace silsmooth;

namespace
{

// A parallel view along -toward on a 1000 x 1000 viewport, 100 pixels per
// unit, its image consistent with its lines of sight.
ViewGeometry parallelView(const glm::dvec3& toward)
{
  ViewGeometry view;
  view.Parallel = true;
  view.TowardViewer = glm::normalize(toward);
  view.ViewportWidth = view.ViewportHeight = 1000;
  const glm::dvec3 up =
    std::abs(view.TowardViewer.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  view.ModelToClip = glm::scale(glm::dmat4(1.0), glm::dvec3(0.2)) *
    glm::lookAt(5.0 * view.TowardViewer, glm::dvec3(0.0), up);
  return view;
}

OutlineGapParameters gapRule()
{
  OutlineGapParameters parameters;
  parameters.Visibility.Tolerance = 1e-9;
  parameters.Visibility.Contact = 1e-10;
  parameters.Visibility.Precision = 1e-9;
  parameters.Visibility.SampleSpacing = 0.01;
  return parameters;
}

double length(const std::vector<std::vector<glm::dvec3>>& lines)
{
  double total = 0.0;
  for (const std::vector<glm::dvec3>& line : lines)
  {
    for (std::size_t i = 1; i < line.size(); ++i)
    {
      total += glm::length(line[i] - line[i - 1]);
    }
  }
  return total;
}

// The cube [-1, 1]^3, outward.
OcclusionMesh cube()
{
  const std::vector<glm::dvec3> points{ { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
  const std::vector<Triangle> triangles{ { { 0, 2, 1 } }, { { 0, 3, 2 } }, { { 4, 5, 6 } },
    { { 4, 6, 7 } }, { { 0, 1, 5 } }, { { 0, 5, 4 } }, { { 1, 2, 6 } }, { { 1, 6, 5 } },
    { { 2, 3, 7 } }, { { 2, 7, 6 } }, { { 3, 0, 4 } }, { { 3, 4, 7 } } };
  return OcclusionMesh(points, triangles);
}

const glm::dvec3 Generic(1.0, 0.8, 0.6);

// The hexagon moved `pixels` towards its centre in the image (parallel:
// along the image plane, which holds the centre's line of sight).
std::vector<glm::dvec3> shrunk(const std::vector<glm::dvec3>& loop, double pixels)
{
  const glm::dvec3 toward = glm::normalize(Generic);
  std::vector<glm::dvec3> moved;
  for (const glm::dvec3& p : loop)
  {
    const glm::dvec3 inPlane = p - glm::dot(p, toward) * toward; // from the centre's sight line
    moved.push_back(p - (0.01 * pixels / glm::length(inPlane)) * inPlane);
  }
  return moved;
}

} // namespace

TEST(OutlineGaps, ACubesContourIsItsOutlineHexagon)
{
  // Three faces face the viewer: the contour is the six edges between them
  // and the three facing away, one closed loop through the six corners
  // that are neither the nearest nor the farthest.
  const OcclusionMesh surface = cube();
  const std::vector<std::vector<glm::dvec3>> contour =
    contourPolylines(surface, parallelView(Generic));
  ASSERT_EQ(contour.size(), 1u);
  ASSERT_EQ(contour[0].size(), 7u);
  EXPECT_EQ(contour[0].front(), contour[0].back());
  for (const glm::dvec3& corner : contour[0])
  {
    EXPECT_NE(corner, glm::dvec3(1, 1, 1));
    EXPECT_NE(corner, glm::dvec3(-1, -1, -1));
  }
  EXPECT_DOUBLE_EQ(length(contour), 12.0);
}

TEST(OutlineGaps, AnUndrawnOutlineIsOneGapAndADrawnOneNone)
{
  const OcclusionMesh surface = cube();
  const ViewGeometry view = parallelView(Generic);
  const std::vector<glm::dvec3> hexagon = contourPolylines(surface, view)[0];
  const OutlineGapParameters rule = gapRule();

  // Nothing drawn: the whole hexagon, as one loop.
  const std::vector<std::vector<glm::dvec3>> whole = outlineGaps(surface, view, {}, rule);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_NEAR(length(whole), 12.0, 1e-6);

  // Drawn on the outline, a pixel inside it, or 2.5 px inside it (a line
  // beside the outline, which the contour would double): no gap.
  EXPECT_TRUE(outlineGaps(surface, view, { hexagon }, rule).empty());
  EXPECT_TRUE(outlineGaps(surface, view, { shrunk(hexagon, 1.0) }, rule).empty());
  EXPECT_TRUE(outlineGaps(surface, view, { shrunk(hexagon, 2.5) }, rule).empty());

  // Six pixels inside it: the hexagon is a gap all round.
  EXPECT_NEAR(length(outlineGaps(surface, view, { shrunk(hexagon, 6.0) }, rule)), 12.0, 1e-6);

  // The wrong variants: with half a pixel allowed, the line a pixel inside
  // leaves the whole outline open; with a gap wherever no line is within
  // the join distance, the line 2.5 px inside is doubled all round.
  OutlineGapParameters narrow = rule;
  narrow.GapPixels = 0.5;
  EXPECT_NEAR(length(outlineGaps(surface, view, { shrunk(hexagon, 1.0) }, narrow)), 12.0, 1e-6);
  OutlineGapParameters doubling = rule;
  doubling.GapPixels = doubling.JoinPixels;
  EXPECT_NEAR(length(outlineGaps(surface, view, { shrunk(hexagon, 2.5) }, doubling)), 12.0, 1e-6);
}

TEST(OutlineGaps, AGapRunsOnToTheLinesAtItsEnds)
{
  // Five of the hexagon's six edges drawn: the sixth is the gap, on it, from
  // where it leaves the drawn edges by the join distance, not by GapPixels.
  const OcclusionMesh surface = cube();
  const ViewGeometry view = parallelView(Generic);
  const std::vector<glm::dvec3> hexagon = contourPolylines(surface, view)[0];
  const std::vector<glm::dvec3> fiveEdges(hexagon.begin() + 1, hexagon.end());
  const OutlineGapParameters rule = gapRule();
  const std::vector<std::vector<glm::dvec3>> gaps = outlineGaps(surface, view, { fiveEdges }, rule);
  ASSERT_EQ(gaps.size(), 1u);
  const glm::dvec3 edge = hexagon[1] - hexagon[0];
  for (const glm::dvec3& p : gaps[0])
  {
    EXPECT_LT(glm::length(glm::cross(p - hexagon[0], edge)), 1e-9); // on the undrawn edge
  }
  // Short of the corners by a few pixels (0.01 a pixel), 2 long.
  const double joined = length(gaps);
  EXPECT_GT(joined, 2.0 - 0.1);
  EXPECT_LT(joined, 2.0 - 0.01);
  // The wrong variant, which stops where it comes within GapPixels: shorter
  // by a pixel or more at each end.
  OutlineGapParameters unjoined = rule;
  unjoined.JoinPixels = unjoined.GapPixels;
  EXPECT_LT(length(outlineGaps(surface, view, { fiveEdges }, unjoined)), joined - 0.02);
}

TEST(OutlineGaps, AGapJoinedToTheLinesAtItsEndsLeavesNoBreak)
{
  // The gap of the test above stops 1.5 px short of the drawn edges' ends
  // (the corners); joined within 2.5 px, it runs from corner to corner,
  // exactly the sixth edge. Within 1 px (the wrong variant) nothing is
  // joined. With nothing drawn, the whole hexagon is a closed gap, which
  // has no ends to join.
  const OcclusionMesh surface = cube();
  const ViewGeometry view = parallelView(Generic);
  const std::vector<glm::dvec3> hexagon = contourPolylines(surface, view)[0];
  const std::vector<glm::dvec3> fiveEdges(hexagon.begin() + 1, hexagon.end());
  const std::vector<std::vector<glm::dvec3>> gaps =
    outlineGaps(surface, view, { fiveEdges }, gapRule());
  ASSERT_EQ(gaps.size(), 1u);
  const std::vector<std::vector<glm::dvec3>> joined =
    joinedToDrawnLines(gaps, view, { fiveEdges }, 2.5);
  ASSERT_EQ(joined.size(), 1u);
  ASSERT_EQ(joined[0].size(), gaps[0].size() + 2);
  const glm::dvec3& first = joined[0].front();
  const glm::dvec3& last = joined[0].back();
  const bool forward = glm::length(first - hexagon[0]) < glm::length(first - hexagon[1]);
  EXPECT_LT(glm::length(first - hexagon[forward ? 0 : 1]), 1e-9);
  EXPECT_LT(glm::length(last - hexagon[forward ? 1 : 0]), 1e-9);
  EXPECT_NEAR(length(joined), 2.0, 1e-9);
  EXPECT_EQ(joinedToDrawnLines(gaps, view, { fiveEdges }, 1.0), gaps);
  const std::vector<std::vector<glm::dvec3>> loop = outlineGaps(surface, view, {}, gapRule());
  EXPECT_EQ(joinedToDrawnLines(loop, view, { fiveEdges }, 2.5), loop);
}

TEST(OutlineGaps, AFoldWithTheSurfaceJustBehindIsNoOutline)
{
  // Seen from +z: a strip A facing the viewer (z = 0, y from 0 to 1), a
  // strip B folding back under it from its edge y = 0 (to y = 0.5, z =
  // -0.1, facing away) and a strip C facing the viewer again (z = -0.1,
  // y from 0.5 down to -1). Contour edges: A-B at y = 0, visible, with C
  // 0.1 behind it on its open side; and B-C at y = 0.5, hidden behind A.
  const std::vector<glm::dvec3> points{ { -1, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { -1, 1, 0 },
    { -1, 0.5, -0.1 }, { 1, 0.5, -0.1 }, { 1, -1, -0.1 }, { -1, -1, -0.1 } };
  const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 0, 2, 3 } }, // A, facing +z
    { { 0, 4, 5 } }, { { 0, 5, 1 } },                                      // B, facing -z
    { { 4, 7, 6 } }, { { 4, 6, 5 } } };                                    // C, facing +z
  const OcclusionMesh surface(points, triangles);
  const ViewGeometry view = parallelView(glm::dvec3(0, 0, 1));
  const std::vector<std::vector<glm::dvec3>> contour = contourPolylines(surface, view);
  ASSERT_EQ(contour.size(), 2u);
  EXPECT_DOUBLE_EQ(length(contour), 4.0);

  // C covers the fold's open side: no outline, so no gap.
  OutlineGapParameters rule = gapRule();
  EXPECT_TRUE(outlineGaps(surface, view, {}, rule).empty());

  // Counting only what lies within 0.05 behind, the fold is a depth jump:
  // its whole edge is a gap, and the hidden B-C edge is not.
  rule.DepthJump = 0.05;
  const std::vector<std::vector<glm::dvec3>> gaps = outlineGaps(surface, view, {}, rule);
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_NEAR(length(gaps), 2.0, 1e-6);
  for (const glm::dvec3& p : gaps[0])
  {
    EXPECT_EQ(p.y, 0.0);
    EXPECT_EQ(p.z, 0.0);
  }
}

TEST(OutlineGaps, AnotherPartJustBehindLeavesTheContourAnOutline)
{
  // The fold of the test above without C: A facing the viewer, B folding
  // back under it from its edge y = 0, and apart from them a strip D facing
  // the viewer 0.15 behind (z = -0.15, y from -1 to 0.4), joined to
  // nothing (a thorax under a head). Its depth jump at the A-B contour is
  // less than DepthJump (0.2), but D is not the contour's own sheet: the
  // whole edge (2 long) is an outline, and a gap. Counting every triangle
  // within DepthJump behind (the wrong variant, no contact distance to find
  // the contour's sheet by) gives none.
  const std::vector<glm::dvec3> points{ { -1, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { -1, 1, 0 },
    { -1, 0.5, -0.1 }, { 1, 0.5, -0.1 }, { -1, -1, -0.15 }, { 1, -1, -0.15 }, { 1, 0.4, -0.15 },
    { -1, 0.4, -0.15 } };
  const std::vector<Triangle> triangles{ { { 0, 1, 2 } }, { { 0, 2, 3 } }, // A, facing +z
    { { 0, 4, 5 } }, { { 0, 5, 1 } },                                      // B, facing -z
    { { 6, 7, 8 } }, { { 6, 8, 9 } } };                                    // D, facing +z
  const OcclusionMesh surface(points, triangles);
  const ViewGeometry view = parallelView(glm::dvec3(0, 0, 1));
  OutlineGapParameters rule = gapRule();
  rule.DepthJump = 0.2;
  const std::vector<std::vector<glm::dvec3>> gaps = outlineGaps(surface, view, {}, rule);
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_NEAR(length(gaps), 2.0, 1e-6);
  for (const glm::dvec3& p : gaps[0])
  {
    EXPECT_EQ(p.y, 0.0);
    EXPECT_EQ(p.z, 0.0);
  }
  rule.Visibility.Contact = 0.0;
  EXPECT_TRUE(outlineGaps(surface, view, {}, rule).empty());
}

TEST(OutlineGaps, OutlineBehindAnOccluderIsNoGap)
{
  // A strip 0.1 wide, facing the viewer, 2 in front of the middle of one
  // of the hexagon's edges, reaching 0.3 px beyond it: that much of the
  // edge is hidden, though the image a pixel beside it is open outside.
  const ViewGeometry view = parallelView(Generic);
  const std::vector<glm::dvec3> hexagon = contourPolylines(cube(), view)[0];
  const glm::dvec3 toward = view.TowardViewer;
  const glm::dvec3 along = glm::normalize(hexagon[1] - hexagon[0]);
  const glm::dvec3 across = glm::cross(toward, along);
  const glm::dvec3 middle = 0.5 * (hexagon[0] + hexagon[1]) + 2.0 * toward;
  std::vector<glm::dvec3> points{ { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
  std::vector<Triangle> triangles{ { { 0, 2, 1 } }, { { 0, 3, 2 } }, { { 4, 5, 6 } },
    { { 4, 6, 7 } }, { { 0, 1, 5 } }, { { 0, 5, 4 } }, { { 1, 2, 6 } }, { { 1, 6, 5 } },
    { { 2, 3, 7 } }, { { 2, 7, 6 } }, { { 3, 0, 4 } }, { { 3, 4, 7 } } };
  const glm::dvec3 edgeMiddle = 0.5 * (hexagon[0] + hexagon[1]);
  const glm::dvec3 inward = glm::dot(toward, edgeMiddle) * toward - edgeMiddle;
  const double in = glm::dot(inward, across) > 0.0 ? 1.0 : -1.0;
  for (const double a : { -0.05, 0.05 })
  {
    for (const double b : { -0.003, 0.3 })
    {
      points.push_back(middle + a * along + (in * b) * across);
    }
  }
  triangles.push_back({ { 8, 10, 11 } });
  triangles.push_back({ { 8, 11, 9 } });
  const OcclusionMesh surface(points, triangles);
  EXPECT_NEAR(length(outlineGaps(surface, view, {}, gapRule())), 11.9, 1e-6);
}

TEST(OutlineGaps, ALineAcrossTheOutlineCoversItOnlyWhereItMeetsIt)
{
  // Nothing drawn but a line 0.4 long (40 px) across the middle of one of
  // the hexagon's edges, square to it in the image: it covers the outline
  // within the join distance of it (1.5 px each side, 0.03 in all), not the
  // GapPixels (4 px) a line running alongside covers.
  const OcclusionMesh surface = cube();
  const ViewGeometry view = parallelView(Generic);
  const std::vector<glm::dvec3> hexagon = contourPolylines(surface, view)[0];
  const glm::dvec3 across = glm::normalize(glm::cross(view.TowardViewer, hexagon[1] - hexagon[0]));
  const glm::dvec3 middle = 0.5 * (hexagon[0] + hexagon[1]);
  const std::vector<glm::dvec3> crossing{ middle - 0.2 * across, middle + 0.2 * across };
  // A pixel along the edge is 0.01 / foreshortening of it.
  const glm::dvec3 edge = glm::normalize(hexagon[1] - hexagon[0]);
  const double foreshortening =
    glm::length(edge - glm::dot(edge, view.TowardViewer) * view.TowardViewer);
  const OutlineGapParameters rule = gapRule();
  const double open = length(outlineGaps(surface, view, { crossing }, rule));
  EXPECT_NEAR(open, 12.0 - 0.03 / foreshortening, 1e-6);
  // The wrong variant, any direction counting as alongside: 4 px each side.
  OutlineGapParameters anyDirection = rule;
  anyDirection.AlongsideCosine = 0.0;
  EXPECT_NEAR(length(outlineGaps(surface, view, { crossing }, anyDirection)),
    12.0 - 0.08 / foreshortening, 1e-6);
}

TEST(OutlineGaps, AGapBesideOneDrawnLineAllAlongIsADetourLeftOut)
{
  // Seen along z, 100 px a unit (y up in the model; distances in the image
  // are 100 times those in the plane z = 0). A drawn line along y = 0 from
  // x = -0.1 to 0.5, and gaps above it.
  const ViewGeometry view = parallelView(glm::dvec3(0, 0, 1));
  auto line = [](double y, double from, double to) {
    return std::vector<glm::dvec3>{ { from, y, 0.0 }, { to, y, 0.0 } };
  };
  const std::vector<glm::dvec3> drawn = line(0.0, -0.1, 0.5);
  // A box's side: from 3 px off the line out to 6 px, 30 px along it, and
  // back to 3 px (about 37 px long: a quarter is 9 px).
  const std::vector<std::vector<glm::dvec3>> box{ { { 0.0, 0.03, 0.0 }, { 0.02, 0.06, 0.0 },
    { 0.32, 0.06, 0.0 }, { 0.34, 0.03, 0.0 } } };
  const double pixels = 5.0; // what the program uses: OutlineGapPixels + 1
  EXPECT_TRUE(withoutDetours(box, view, { drawn }, pixels, 0.25).empty());
  // The wrong variant, a distance in pixels alone: the gap stays, and the
  // drawing gets its box.
  EXPECT_EQ(withoutDetours(box, view, { drawn }, pixels, 0.0).size(), 1u);
  // Its middle 20 px off the line, beyond the quarter: a bump of the
  // outline, kept.
  const std::vector<std::vector<glm::dvec3>> bump{ { { 0.0, 0.03, 0.0 }, { 0.02, 0.2, 0.0 },
    { 0.32, 0.2, 0.0 }, { 0.34, 0.03, 0.0 } } };
  EXPECT_EQ(withoutDetours(bump, view, { drawn }, pixels, 0.25).size(), 1u);
  // Two pieces of the line, one by each end, none by the middle (a hidden
  // stretch of the curve between them): the gap is the outline there.
  EXPECT_EQ(
    withoutDetours(box, view, { line(0.0, -0.1, 0.05), line(0.0, 0.29, 0.5) }, pixels, 0.25).size(),
    1u);
  // A line that passes 30 px from a gap 200 px long all along, but farther
  // than `pixels` from its ends (the other side of a thin part): within the
  // quarter (50 px), yet another part's outline, kept.
  const std::vector<std::vector<glm::dvec3>> longGap{ { { 0.0, 0.0, 0.0 }, { 2.0, 0.0, 0.0 } } };
  EXPECT_EQ(withoutDetours(longGap, view, { line(0.3, -0.1, 2.1) }, pixels, 0.25).size(), 1u);
  // A closed gap (a loop) has no ends, and stays.
  const std::vector<std::vector<glm::dvec3>> loop{ { { 0.0, 0.03, 0.0 }, { 0.34, 0.03, 0.0 },
    { 0.17, 0.06, 0.0 }, { 0.0, 0.03, 0.0 } } };
  EXPECT_EQ(withoutDetours(loop, view, { drawn }, pixels, 0.25).size(), 1u);

  // A break of 6 px in a silhouette (two visible pieces, the curve hidden
  // between them), its gap 1 px above and 1.5 px short of the pieces' ends,
  // and the other outline of a thin part 3 px above the gap all along: the
  // gap bridges the break, kept. That other line alone would make it a
  // detour (the wrong variant: the spider's legs had their breaks open).
  const std::vector<std::vector<glm::dvec3>> bridge{ { { 0.015, 0.01, 0.0 },
    { 0.045, 0.01, 0.0 } } };
  const std::vector<glm::dvec3> otherSide = line(0.04, -0.1, 0.5);
  EXPECT_EQ(withoutDetours(
              bridge, view, { line(0.0, -0.1, 0.0), line(0.0, 0.06, 0.5), otherSide }, pixels, 0.25)
              .size(),
    1u);
  EXPECT_TRUE(withoutDetours(bridge, view, { otherSide }, pixels, 0.25).empty());
}

TEST(OutlineGaps, ABreakOfAFewPixelsInALineBesideTheOutlineIsBridged)
{
  // The hexagon drawn a pixel inside the outline, with a break of 3.5 px in
  // the middle of one edge, a vertex half a pixel before each end of it (a
  // smoothed curve's samples are that close): as at the coarse bunny's ear
  // tip at 400 x 300, where the silhouette passes under a facet for a few
  // pixels.
  const OcclusionMesh surface = cube();
  const ViewGeometry view = parallelView(Generic);
  const std::vector<glm::dvec3> hexagon = shrunk(contourPolylines(surface, view)[0], 1.0);
  const glm::dvec3 toward = glm::normalize(Generic);
  const glm::dvec3 edge = hexagon[1] - hexagon[0];
  const double edgePixels = 100.0 * glm::length(edge - glm::dot(edge, toward) * toward);
  auto at = [&](double pixels) {
    return hexagon[0] + (0.5 + pixels / edgePixels) * edge;
  };
  std::vector<glm::dvec3> drawn{ at(1.75), at(2.25) };
  drawn.insert(drawn.end(), hexagon.begin() + 1, hexagon.end()); // round to hexagon[0]
  drawn.push_back(at(-2.25));
  drawn.push_back(at(-1.75));
  const OutlineGapParameters rule = gapRule();

  // One stretch of the contour, in the break, shorter than the join
  // distance: kept, since a line ends by each of its ends.
  const std::vector<std::vector<glm::dvec3>> gaps = outlineGaps(surface, view, { drawn }, rule);
  ASSERT_EQ(gaps.size(), 1u);
  const double stretch = 100.0 * length(gaps); // about the pixels in the image
  EXPECT_GT(stretch, 0.0);
  EXPECT_LT(stretch, 2.0 * rule.JoinPixels);
  // Joined to the line's two ends, it closes the drawing.
  const std::vector<std::vector<glm::dvec3>> joined =
    joinedToDrawnLines(withoutDetours(gaps, view, { drawn }, 5.0, 0.25), view, { drawn }, 5.0);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_LT(glm::length(joined[0].front() - drawn.back()), 1e-9);
  EXPECT_LT(glm::length(joined[0].back() - drawn.front()), 1e-9);

  // The wrong variant, the line unbroken: no gap (nothing to bridge, and
  // nothing open: the line runs alongside the whole outline).
  std::vector<glm::dvec3> whole(hexagon.begin(), hexagon.end());
  EXPECT_TRUE(outlineGaps(surface, view, { whole }, rule).empty());
}

TEST(OutlineGaps, AGapReachingALinesEndJoinsThatEndExactly)
{
  // Seen along z, 100 px a unit. A drawn line ends at the origin; a gap
  // starts 1 px beside it, 0.2 px short of its end: its nearest point on
  // the line is 0.2 px from the end, and joining there left the gap and the
  // line a hair apart, so a brush drew them as two strokes (the coarse
  // bunny's ear tip). Within half a pixel of the end, the end itself, bit
  // for bit; 0.8 px short, the nearest point.
  const ViewGeometry view = parallelView(glm::dvec3(0, 0, 1));
  const std::vector<glm::dvec3> line{ { -0.5, 0.0, 0.0 }, { 0.0, 0.0, 0.0 } };
  for (const double shortBy : { 0.002, 0.008 })
  {
    const std::vector<std::vector<glm::dvec3>> gap{ { { -shortBy, 0.01, 0.0 },
      { 0.05, 0.01, 0.0 } } };
    const std::vector<std::vector<glm::dvec3>> joined =
      joinedToDrawnLines(gap, view, { line }, 5.0);
    ASSERT_EQ(joined.size(), 1u);
    ASSERT_EQ(joined[0].size(), 3u) << "joined at its first end only";
    if (shortBy < 0.005)
    {
      EXPECT_EQ(joined[0].front(), line.back());
    }
    else
    {
      EXPECT_NEAR(joined[0].front().x, -shortBy, 1e-12);
      EXPECT_NEAR(joined[0].front().y, 0.0, 1e-12);
    }
  }
}
