// A surface over moved points (a deforming mesh) and a frame's changes:
// what WeldedSurface::movePoints keeps and redoes, the prepared mesh's edge
// table and triangle grid, and assembleChanges against the whole frame.
#include "CoreTestMeshes.h"
#include "PlainSurfaceOptions.h"
#include "TriangleGrid.h"
#include "TriangleIntersection.h"
#include "WeldedSurface.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace silsmooth;

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
  const WeldedSurface torus(points, triangles, {}, {}, coretest::plainOptions());
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
  const WeldedSurface soup(soupPoints, soupTriangles, soupPoints, {}, coretest::plainOptions());
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
  WeldedSurface moved(soup, soupTriangles, {}, {}, coretest::plainOptions());
  std::vector<glm::dvec3> deformed = soup;
  for (glm::dvec3& p : deformed)
  {
    p = glm::dvec3(p.x * 1.2, p.y + 0.1 * std::sin(3.0 * p.x), p.z * 0.9);
  }
  ASSERT_TRUE(moved.movePoints(deformed, {}, {}, coretest::plainOptions()));
  const WeldedSurface fresh(deformed, soupTriangles, {}, {}, coretest::plainOptions());
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
  EXPECT_FALSE(moved.movePoints(torn, {}, {}, coretest::plainOptions()));
  EXPECT_EQ(moved.prepared().points(), fresh.prepared().points());
  // Another point count.
  EXPECT_FALSE(moved.movePoints(std::vector<glm::dvec3>(3), {}, {}, coretest::plainOptions()));
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
  WeldedSurface moving(points, triangles, {}, {}, coretest::plainOptions());
  const ViewGeometry view = coretest::perspectiveFrom(glm::dvec3(0.3, -2.5, 1.4));
  // Its first frames build the grid in the call, so that the next can be
  // seen to adopt it; the moved surfaces build theirs in the call anyway.
  SmoothingParameters inCall;
  inCall.IndexesInBackground = false;
  smoothSilhouettes(moving.prepared(), view, inCall); // scans for the fold checks
  EXPECT_FALSE(moving.prepared().hasTriangleGrid());
  smoothSilhouettes(moving.prepared(), view, inCall); // the second frame builds the grid
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
    ASSERT_TRUE(moving.movePoints(moved, {}, {}, coretest::plainOptions()));
    const bool adopting = moving.prepared().triangleGridSlack() > 0.0;
    adopted += adopting ? 1 : 0;
    const WeldedSurface fresh(moved, triangles, {}, {}, coretest::plainOptions());
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
  ASSERT_TRUE(moving.movePoints(far, {}, {}, coretest::plainOptions()));
  EXPECT_EQ(moving.prepared().triangleGridSlack(), 0.0);
  // Moves that outran the grid: later frames scan instead of building it
  // again, and smooth as a fresh surface does.
  for (int frame = 0; frame < 2; ++frame)
  {
    for (glm::dvec3& p : far)
    {
      p *= 1.2;
    }
    ASSERT_TRUE(moving.movePoints(far, {}, {}, coretest::plainOptions()));
    const SurfaceFrame a = moving.assemble(smoothSilhouettes(moving.prepared(), view, {}));
    EXPECT_FALSE(moving.prepared().hasTriangleGrid());
    const WeldedSurface fresh(far, triangles, {}, {}, coretest::plainOptions());
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

TEST(TriangleGrid, AThinTriangleFindsTheBoxesAlongItNotAcrossItsBox)
{
  // A disc cut into a fan of 2,000 slivers from one point on its rim, and a
  // small box at every rim point (as the fold guard asks about the new
  // triangles along an outline): each sliver's box covers a good part of
  // the disc, but the sliver itself passes only the boxes at its ends.
  const int n = 2000;
  const double pi = 3.14159265358979323846;
  std::vector<glm::dvec3> rim;
  for (int i = 0; i < n; ++i)
  {
    rim.emplace_back(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 0.0);
  }
  const double half = 0.3 * 2 * pi / n;
  std::vector<glm::dvec3> lows;
  std::vector<glm::dvec3> highs;
  for (const glm::dvec3& p : rim)
  {
    lows.push_back(p - half);
    highs.push_back(p + half);
  }
  const TriangleGrid boxes(lows, highs);
  std::size_t byTriangle = 0;
  std::size_t byBox = 0;
  std::vector<Id> found;
  TriangleGrid::TriangleQueryMarks marks;
  for (int i = 1; i + 1 < n; ++i)
  {
    const TriangleCorners sliver{ { rim[0], rim[i], rim[i + 1] } };
    boxes.queryTriangle(sliver.P[0], sliver.P[1], sliver.P[2], found, marks);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << "each once";
    for (int b = 0; b < n; ++b)
    {
      if (triangleMeetsBox(sliver, lows[b], highs[b]))
      {
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), Id{ b }))
          << "sliver " << i << " meets box " << b;
      }
    }
    byTriangle += found.size();
    boxes.query(glm::min(rim[0], glm::min(rim[i], rim[i + 1])),
      glm::max(rim[0], glm::max(rim[i], rim[i + 1])), found);
    byBox += found.size();
  }
  // The slivers' own boxes give about an eighth of all boxes each.
  EXPECT_GT(byBox, std::size_t(n) * n / 10);
  EXPECT_LT(byTriangle, std::size_t(n) * 40) << "by box: " << byBox;
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
