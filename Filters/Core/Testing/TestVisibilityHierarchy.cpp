// The hierarchical visibility pass must make exactly the decisions of the
// plain per-vertex pass, for every vertex and view, at any scale; and the
// triangle hierarchy must find exactly the silhouette triangles a scan finds.
#include "CoreTestMeshes.h"
#include "SilhouetteSmoother.h"
#include "SilhouetteTriangleHierarchy.h"
#include "SmoothingResultCheck.h"
#include "VisibilityCones.h"
#include "VisibilityHierarchy.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>

using namespace silsmooth;

namespace
{

struct Cloud
{
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Normals;
};

glm::dvec3 randomUnit(std::mt19937_64& random)
{
  std::normal_distribution<double> normal;
  for (;;)
  {
    const glm::dvec3 v(normal(random), normal(random), normal(random));
    const double length = glm::length(v);
    if (length > 1e-6)
    {
      return v / length;
    }
  }
}

// Points on the unit sphere with their exact normals, some of them on the
// equators z = 0 and x = 0 exactly (g exactly 0 for axis views), some a
// hair off them.
Cloud sphere(std::size_t count, std::mt19937_64& random)
{
  Cloud cloud;
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  for (std::size_t i = 0; i < count; ++i)
  {
    glm::dvec3 p = randomUnit(random);
    if (i % 7 == 0)
    {
      const double a = angle(random);
      p = glm::dvec3(std::cos(a), std::sin(a), 0.0);
    }
    else if (i % 11 == 0)
    {
      p.x = (i % 2 ? 1.0 : -1.0) * 1e-300;
    }
    cloud.Points.push_back(p);
    cloud.Normals.push_back(p);
  }
  return cloud;
}

// A bumpy closed surface: a sphere with a radial wave, outward normals
// approximated by a finite difference (not radial), as on a real mesh.
Cloud bumpy(std::size_t count, std::mt19937_64& random)
{
  Cloud cloud;
  auto radius = [](const glm::dvec3& d) {
    return 1.0 + 0.2 * std::sin(5.0 * d.x) * std::cos(4.0 * d.y + 3.0 * d.z);
  };
  for (std::size_t i = 0; i < count; ++i)
  {
    const glm::dvec3 d = randomUnit(random);
    const glm::dvec3 t1 = glm::normalize(
      glm::cross(d, std::abs(d.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 t2 = glm::cross(d, t1);
    const double h = 1e-4;
    const glm::dvec3 p = radius(d) * d;
    const glm::dvec3 d1 = glm::normalize(d + h * t1);
    const glm::dvec3 d2 = glm::normalize(d + h * t2);
    const glm::dvec3 n = glm::normalize(glm::cross(radius(d1) * d1 - p, radius(d2) * d2 - p));
    cloud.Points.push_back(p);
    cloud.Normals.push_back(glm::dot(n, d) < 0.0 ? -n : n);
  }
  return cloud;
}

// Unstructured: random points in a box with random unit normals.
Cloud noise(std::size_t count, std::mt19937_64& random)
{
  Cloud cloud;
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (std::size_t i = 0; i < count; ++i)
  {
    cloud.Points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
    cloud.Normals.push_back(randomUnit(random));
  }
  return cloud;
}

// Tight bundles: 100 directions, 50 normals each within 1e-3 .. 1e-14 of it,
// at nearby points; clusters with a tiny cone straddle grazing views.
Cloud bundles(std::size_t count, std::mt19937_64& random)
{
  Cloud cloud;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  glm::dvec3 centre(0.0);
  glm::dvec3 direction(0.0, 0.0, 1.0);
  for (std::size_t i = 0; i < count; ++i)
  {
    if (i % 50 == 0)
    {
      centre = randomUnit(random);
      direction = randomUnit(random);
    }
    const double spread = std::pow(10.0, -3.0 - 11.0 * unit(random));
    cloud.Points.push_back(centre + spread * randomUnit(random));
    cloud.Normals.push_back(glm::normalize(direction + spread * randomUnit(random)));
  }
  return cloud;
}

Cloud transformed(Cloud cloud, double scale, const glm::dvec3& offset)
{
  for (glm::dvec3& p : cloud.Points)
  {
    p = p * scale + offset;
  }
  return cloud;
}

// Eyes of every kind around a cloud of the given scale and offset.
glm::dvec3 randomEye(
  const Cloud& cloud, double scale, const glm::dvec3& offset, std::mt19937_64& random, int kind)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<std::size_t> pick(0, cloud.Points.size() - 1);
  switch (kind % 8)
  {
    case 6:
    case 7: // grazing a vertex's tangent plane, a hair above or below it
    {
      const std::size_t i = pick(random);
      const glm::dvec3 n = cloud.Normals[i];
      const glm::dvec3 t = glm::cross(n, randomUnit(random));
      const double h = (kind % 2 ? 1.0 : -1.0) * scale * std::pow(10.0, -16.0 * unit(random));
      return cloud.Points[i] + scale * (0.5 + 5.0 * unit(random)) * t + h * n;
    }
    case 0: // ordinary distance
      return offset + scale * (1.5 + 10.0 * unit(random)) * randomUnit(random);
    case 1: // far, up to 1e20 times the size
      return offset + scale * std::pow(10.0, 20.0 * unit(random)) * randomUnit(random);
    case 2: // exactly on a vertex
      return cloud.Points[pick(random)];
    case 3: // a hair above or below a vertex
    {
      const std::size_t i = pick(random);
      const double h = (unit(random) - 0.5) * scale * std::pow(10.0, -15.0 * unit(random));
      return cloud.Points[i] + h * cloud.Normals[i];
    }
    case 4: // inside
      return offset + scale * 0.5 * unit(random) * randomUnit(random);
    default: // on an axis, ordinary distance (exact zeros on the equators)
      return offset + scale * glm::dvec3(0.0, 0.0, unit(random) < 0.5 ? 3.0 : -3.0);
  }
}

glm::dvec3 randomDirection(const Cloud& cloud, std::mt19937_64& random, int kind)
{
  static const glm::dvec3 axes[] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, 1, 0 } };
  if (kind % 3 == 0)
  {
    // Grazing a vertex: perpendicular to its normal, tilted by a tiny angle.
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::size_t> pick(0, cloud.Points.size() - 1);
    const glm::dvec3 n = cloud.Normals[pick(random)];
    const glm::dvec3 t = glm::cross(n, randomUnit(random));
    const double tilt = (kind % 2 ? 1.0 : -1.0) * std::pow(10.0, -16.0 * unit(random));
    return t + tilt * glm::length(t) * n;
  }
  kind /= 3;
  if (kind % 4 == 0)
  {
    return axes[static_cast<std::size_t>(kind / 4) % 4];
  }
  // Not unit on purpose sometimes: visibility() does not normalise it.
  return randomUnit(random) * (kind % 4 == 1 ? 3.7 : 1.0);
}

// Counts vertices whose decision differs; checks undecided values are exact.
std::size_t mismatches(const Cloud& cloud, const VisibilityHierarchy& hierarchy,
  const ViewGeometry& view, VisibilityHierarchy::Statistics* statistics = nullptr)
{
  std::vector<double> g;
  hierarchy.classify(view, g, nullptr, statistics);
  EXPECT_EQ(g.size(), cloud.Points.size());
  std::size_t bad = 0;
  for (std::size_t i = 0; i < cloud.Points.size(); ++i)
  {
    const glm::dvec3 normal = i < cloud.Normals.size() ? cloud.Normals[i] : glm::dvec3(0.0);
    const double exact = view.visibility(cloud.Points[i], normal);
    const bool sameValue = g[i] == exact || (std::isnan(g[i]) && std::isnan(exact));
    if ((g[i] >= 0.0) != (exact >= 0.0) || !(sameValue || g[i] == 1.0 || g[i] == -1.0))
    {
      ++bad;
    }
  }
  return bad;
}

struct Totals
{
  std::size_t Views = 0;
  std::size_t Decided = 0;
  std::size_t Exact = 0;
};

void checkManyViews(const Cloud& cloud, double scale, const glm::dvec3& offset, std::uint64_t seed,
  int views, Totals& totals)
{
  const VisibilityHierarchy hierarchy(cloud.Points, cloud.Normals);
  std::mt19937_64 random(seed);
  for (int v = 0; v < views; ++v)
  {
    ViewGeometry view;
    view.Parallel = v % 2 == 1;
    if (view.Parallel)
    {
      view.TowardViewer = randomDirection(cloud, random, v / 2);
    }
    else
    {
      view.Eye = randomEye(cloud, scale, offset, random, v / 2);
    }
    VisibilityHierarchy::Statistics statistics;
    ASSERT_EQ(mismatches(cloud, hierarchy, view, &statistics), 0u)
      << "view " << v << (view.Parallel ? " parallel" : " perspective") << " scale " << scale;
    ++totals.Views;
    totals.Decided += statistics.DecidedVertices;
    totals.Exact += statistics.ExactVertices;
  }
}

} // namespace

TEST(VisibilityHierarchy, SameDecisionsAsThePlainPassAtEveryScale)
{
  std::mt19937_64 random(7);
  const std::pair<double, glm::dvec3> frames[] = { { 1.0, glm::dvec3(0.0) },
    { 1e-30, glm::dvec3(0.0) }, { 1e30, glm::dvec3(0.0) },
    { 1e-30, glm::dvec3(3e-25, -1e-26, 2e-24) }, { 1e30, glm::dvec3(1e33, 0.0, -5e32) },
    { 1e-3, glm::dvec3(1e6, 2e6, -3e5) }, { 250.0, glm::dvec3(-7.0, 3.0, 1e3) } };
  Totals totals;
  std::uint64_t seed = 100;
  for (const auto& frame : frames)
  {
    for (int shape = 0; shape < 4; ++shape)
    {
      const Cloud base = shape == 0 ? sphere(3000, random)
        : shape == 1                ? bumpy(3000, random)
        : shape == 2                ? bundles(3000, random)
                                    : noise(3000, random);
      const Cloud cloud = transformed(base, frame.first, frame.second);
      checkManyViews(cloud, frame.first, frame.second, seed++, 200, totals);
      if (HasFatalFailure())
      {
        return;
      }
    }
  }
  EXPECT_EQ(totals.Views, 7u * 4u * 200u);
  // The test means something only if clusters were decided, and exactly
  // evaluated vertices were compared too.
  EXPECT_GT(totals.Decided, totals.Exact);
  EXPECT_GT(totals.Exact, 0u);
}

TEST(VisibilityHierarchy, ZeroTinyHugeAndNonFiniteNormalsAndPoints)
{
  std::mt19937_64 random(11);
  Cloud cloud = sphere(2000, random);
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < cloud.Points.size(); i += 13)
  {
    switch ((i / 13) % 7)
    {
      case 0:
        cloud.Normals[i] = glm::dvec3(0.0);
        break;
      case 1:
        cloud.Normals[i] *= 1e-200;
        break;
      case 2:
        cloud.Normals[i] *= 1e200;
        break;
      case 3:
        cloud.Normals[i].y = nan;
        break;
      case 4:
        cloud.Points[i].x = inf;
        break;
      case 5:
        cloud.Points[i] *= 1e200;
        break;
      default:
        cloud.Normals[i] *= 3.5; // not unit
        break;
    }
  }
  Totals totals;
  checkManyViews(cloud, 1.0, glm::dvec3(0.0), 5, 600, totals);
  EXPECT_GT(totals.Decided, 0u);

  // Views the trees cannot take: evaluated directly, still identical.
  const VisibilityHierarchy hierarchy(cloud.Points, cloud.Normals);
  for (const glm::dvec3& eye :
    { glm::dvec3(inf, 0, 0), glm::dvec3(nan), glm::dvec3(1e200, 0, 0), glm::dvec3(0.0) })
  {
    ViewGeometry view;
    view.Eye = eye;
    EXPECT_EQ(mismatches(cloud, hierarchy, view), 0u);
    view.Parallel = true;
    view.TowardViewer = eye;
    EXPECT_EQ(mismatches(cloud, hierarchy, view), 0u);
  }
}

TEST(VisibilityHierarchy, DuplicateNormalsAndPoints)
{
  std::mt19937_64 random(13);
  Cloud cloud;
  // A flat grid: every normal the same; then a cube's worth of six normals,
  // and many copies of one point.
  for (int i = 0; i < 40; ++i)
  {
    for (int j = 0; j < 40; ++j)
    {
      cloud.Points.emplace_back(i * 0.025, j * 0.025, 0.0);
      cloud.Normals.emplace_back(0.0, 0.0, 1.0);
    }
  }
  const glm::dvec3 axes[] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int i = 0; i < 1200; ++i)
  {
    const glm::dvec3 n = axes[i % 6];
    glm::dvec3 p(coordinate(random), coordinate(random), coordinate(random));
    p += n * (1.0 - glm::dot(p, n)); // on the face
    cloud.Points.push_back(p);
    cloud.Normals.push_back(n);
  }
  for (int i = 0; i < 500; ++i)
  {
    cloud.Points.emplace_back(0.25, 0.5, 0.75);
    cloud.Normals.emplace_back(0.0, 0.6, 0.8);
  }
  Totals totals;
  checkManyViews(cloud, 1.0, glm::dvec3(0.0), 17, 1000, totals);
  EXPECT_GT(totals.Decided, 0u);

  // All points identical (zero extent) and all normals identical.
  Cloud same;
  same.Points.assign(300, glm::dvec3(1e20, -1e20, 3.0));
  same.Normals.assign(300, glm::dvec3(0.0, 1.0, 0.0));
  checkManyViews(same, 1e20, glm::dvec3(1e20, -1e20, 3.0), 19, 400, totals);
}

TEST(VisibilityHierarchy, EmptyAndSinglePoint)
{
  const VisibilityHierarchy empty({}, {});
  std::vector<double> g{ 1.0, 2.0 };
  ViewGeometry view;
  empty.classify(view, g);
  EXPECT_TRUE(g.empty());
  view.Parallel = true;
  empty.classify(view, g);
  EXPECT_TRUE(g.empty());

  const VisibilityHierarchy none;
  none.classify(view, g);
  EXPECT_TRUE(g.empty());

  Cloud one;
  one.Points.emplace_back(0.5, -2.0, 1e-3);
  one.Normals.emplace_back(0.0, 0.0, 1.0);
  Totals totals;
  checkManyViews(one, 1.0, one.Points[0], 23, 400, totals);

  // More points than normals: the missing normals count as zero.
  Cloud partial = one;
  partial.Points.emplace_back(1.0, 1.0, 1.0);
  const VisibilityHierarchy hierarchy(partial.Points, partial.Normals);
  view.Parallel = false;
  view.Eye = glm::dvec3(0.0, 0.0, -5.0);
  EXPECT_EQ(mismatches(partial, hierarchy, view), 0u);
}

TEST(VisibilityHierarchy, ResultDoesNotDependOnTheSplit)
{
  std::mt19937_64 random(29);
  const Cloud cloud = bumpy(20000, random);
  const VisibilityHierarchy hierarchy(cloud.Points, cloud.Normals);
  const VisibilityHierarchy::ParallelForFunction ones =
    [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
      for (std::size_t i = count; i > 0; --i)
      {
        body(i - 1, i);
      }
    };
  for (int v = 0; v < 50; ++v)
  {
    ViewGeometry view;
    view.Parallel = v % 2 == 0;
    view.TowardViewer = randomUnit(random);
    view.Eye = 4.0 * randomUnit(random);
    std::vector<double> serial;
    std::vector<double> split;
    VisibilityHierarchy::Statistics a;
    VisibilityHierarchy::Statistics b;
    hierarchy.classify(view, serial, nullptr, &a);
    hierarchy.classify(view, split, ones, &b);
    EXPECT_EQ(serial, split);
    EXPECT_EQ(a.DecidedVertices, b.DecidedVertices);
    EXPECT_EQ(a.DecidedVertices + a.ExactVertices, cloud.Points.size());
  }
}

namespace
{

// A subdivided octahedron pushed onto a bumpy sphere, scaled and moved, with
// angle-weighted normals or, quantised, normals snapped to 26 directions (so
// that whole clusters share a normal and are decided next to silhouettes).
PreparedMesh bumpySphereMesh(int level, double scale, const glm::dvec3& offset, bool quantised)
{
  std::vector<glm::dvec3> points{ { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  std::vector<Triangle> triangles{ { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 },
    { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
  for (int l = 0; l < level; ++l)
  {
    coretest::splitInFour(points, triangles, true);
  }
  std::vector<glm::dvec3> normals;
  for (glm::dvec3& p : points)
  {
    if (quantised)
    {
      normals.push_back(glm::round(1.4 * p));
    }
    p *= 1.0 + 0.15 * std::sin(4.0 * p.x) * std::cos(3.0 * p.y + 2.0 * p.z);
    p = p * scale + offset;
  }
  return PreparedMesh(points, triangles, normals);
}

} // namespace

TEST(VisibilityHierarchy, WholePassIdenticalWithEitherMethod)
{
  std::mt19937_64 random(31);
  std::size_t differentG = 0;
  for (const int shape : { 0, 1, 2, 3, 4, 5 })
  {
    const double scale = shape % 3 == 0 ? 1.0 : shape % 3 == 1 ? 1e-30 : 1e30;
    const glm::dvec3 offset = scale * glm::dvec3(0.3, -2.0, 5.0);
    const PreparedMesh mesh = bumpySphereMesh(4, scale, offset, shape >= 3);
    for (int v = 0; v < 60; ++v)
    {
      ViewGeometry view;
      view.Parallel = v % 3 == 0;
      view.TowardViewer = randomUnit(random);
      view.Eye = offset + scale * (v % 5 == 0 ? 1.2 : 4.0) * randomUnit(random);
      if (v % 7 == 0)
      {
        view.Eye = mesh.points()[static_cast<std::size_t>(v) % mesh.points().size()];
      }
      // Only the sampling uses the projection; a crude one is enough.
      view.ModelToClip = glm::dmat4(1.0 / scale);
      view.ModelToClip[3] = glm::dvec4(-offset / scale, 1.0);
      SmoothingParameters plain;
      plain.Visibility = VisibilityMethod::PerVertex;
      plain.SilhouetteTriangleHierarchy = false; // scans, with G of every point
      SmoothingParameters hierarchical = plain;
      hierarchical.Visibility = VisibilityMethod::Hierarchical;
      SmoothingParameters triangleTree = plain;
      triangleTree.SilhouetteTriangleHierarchy = true;    // after this mesh's first search
      triangleTree.IndexesInBackground = false; // the tree answers from the second
      // Placeholders next to silhouette triangles: a pass reading G as values
      // would differ.
      const std::vector<double> gPlain = vertexVisibility(mesh, view, VisibilityMethod::PerVertex);
      const std::vector<double> gTree =
        vertexVisibility(mesh, view, VisibilityMethod::Hierarchical);
      for (const Triangle& t : mesh.triangles())
      {
        const bool mixed =
          (gPlain[t[0]] >= 0) != (gPlain[t[1]] >= 0) || (gPlain[t[1]] >= 0) != (gPlain[t[2]] >= 0);
        for (int k = 0; k < 3 && mixed; ++k)
        {
          differentG += gPlain[t[k]] != gTree[t[k]] ? 1 : 0;
        }
      }
      const SmoothingResult a = smoothSilhouettes(mesh, view, plain);
      for (const SmoothingParameters* other : { &hierarchical, &triangleTree })
      {
        coretest::expectSameSmoothing(
          a, smoothSilhouettes(mesh, view, *other), "view " + std::to_string(v));
      }
    }
  }
  EXPECT_GT(differentG, 0u);
}

namespace
{

// The silhouette triangles by the rule, scanning every triangle.
std::vector<Id> scanSilhouetteTriangles(const std::vector<glm::dvec3>& points,
  const std::vector<glm::dvec3>& normals, const std::vector<Triangle>& triangles,
  const ViewGeometry& view)
{
  std::vector<Id> found;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = triangles[t];
    if (hasRepeatedCorner(tri))
    {
      continue;
    }
    bool side[3];
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t c = static_cast<std::size_t>(tri[k]);
      side[k] = view.visibility(points[c], normals[c]) >= 0.0;
    }
    if (side[0] != side[1] || side[1] != side[2])
    {
      found.push_back(static_cast<Id>(t));
    }
  }
  return found;
}

ViewGeometry randomView(std::mt19937_64& random, int v, const glm::dvec3& centre, double scale,
  const std::vector<glm::dvec3>& points)
{
  ViewGeometry view;
  view.Parallel = v % 3 == 0;
  view.TowardViewer = randomUnit(random);
  view.Eye = centre + scale * (v % 5 == 0 ? 1.2 : 4.0) * randomUnit(random);
  if (v % 7 == 0)
  {
    view.Eye = points[static_cast<std::size_t>(v) % points.size()];
  }
  return view;
}

} // namespace

TEST(SilhouetteTriangleHierarchy, FindsExactlyWhatAScanFinds)
{
  // Scales from 1e-30 to 1e30, quantised normals (g exactly 0 at some
  // corners for axis views), eyes on the surface; and, in the last mesh,
  // corners no cone can hold (zero, NaN and huge normals, a huge point) and
  // triangles with a repeated corner.
  std::mt19937_64 random(2026);
  std::size_t found = 0;
  for (const int shape : { 0, 1, 2, 3, 4, 5, 6 })
  {
    const double scale = shape % 3 == 0 ? 1.0 : shape % 3 == 1 ? 1e-30 : 1e30;
    const glm::dvec3 offset = scale * glm::dvec3(0.3, -2.0, 5.0);
    const PreparedMesh mesh = bumpySphereMesh(4, scale, offset, shape >= 3);
    std::vector<glm::dvec3> points = mesh.points();
    std::vector<glm::dvec3> normals = mesh.normals();
    std::vector<Triangle> triangles = mesh.triangles();
    if (shape == 6)
    {
      normals[3] = glm::dvec3(0.0);
      normals[10] = glm::dvec3(std::nan(""), 0.0, 1.0);
      normals[20] = glm::dvec3(1e200, 0.0, 0.0);
      points[30] *= 1e150;
      triangles[40][1] = triangles[40][0];
    }
    const SilhouetteTriangleHierarchy trees[2] = { SilhouetteTriangleHierarchy(
                                                     points, normals, triangles, false),
      SilhouetteTriangleHierarchy(points, normals, triangles, true) };
    for (int v = 0; v < 80; ++v)
    {
      const ViewGeometry view = randomView(random, v, offset, scale, points);
      const std::vector<Id> expected = scanSilhouetteTriangles(points, normals, triangles, view);
      std::vector<Id> serial;
      std::vector<Id> parallel;
      const SilhouetteTriangleHierarchy& tree = trees[view.Parallel ? 0 : 1];
      ASSERT_TRUE(tree.find(view, points, normals, triangles, serialFor, serial));
      // Tasks handed out one at a time, in reverse: the answer is the same.
      const ParallelFor reversed = [](std::size_t count,
                                     const std::function<void(std::size_t, std::size_t)>& body) {
        for (std::size_t i = count; i-- > 0;)
        {
          body(i, i + 1);
        }
      };
      ASSERT_TRUE(tree.find(view, points, normals, triangles, reversed, parallel));
      ASSERT_EQ(serial, expected) << "shape " << shape << " view " << v;
      ASSERT_EQ(parallel, expected);
      // The other projection's tree does not answer.
      std::vector<Id> untouched{ 7 };
      EXPECT_FALSE(
        trees[view.Parallel ? 1 : 0].find(view, points, normals, triangles, serialFor, untouched));
      EXPECT_EQ(untouched, std::vector<Id>{ 7 });
      found += expected.size();
    }
  }
  EXPECT_GT(found, 10000u);
}

TEST(SilhouetteTriangleHierarchy, ReadsABandOfTheMeshNotAllOfIt)
{
  // On a smooth sphere of 131,072 triangles the tree evaluates the
  // triangles near the silhouette: under 10% of the mesh, and finds what a
  // scan finds (the next test shows the cones' caps are what makes it so).
  const PreparedMesh mesh = bumpySphereMesh(7, 1.0, glm::dvec3(0.0), false);
  const SilhouetteTriangleHierarchy tree(mesh.points(), mesh.normals(), mesh.triangles(), true);
  std::mt19937_64 random(5);
  for (int v = 0; v < 10; ++v)
  {
    ViewGeometry view;
    view.Eye = 3.0 * randomUnit(random);
    std::vector<Id> found;
    SilhouetteTriangleHierarchy::Statistics statistics;
    ASSERT_TRUE(tree.find(
      view, mesh.points(), mesh.normals(), mesh.triangles(), serialFor, found, &statistics));
    EXPECT_EQ(
      found, scanSilhouetteTriangles(mesh.points(), mesh.normals(), mesh.triangles(), view));
    EXPECT_LT(statistics.EvaluatedTriangles, mesh.triangles().size() / 10) << "view " << v;
    EXPECT_GT(statistics.EvaluatedTriangles, found.size());
  }
}

TEST(SilhouetteTriangleHierarchy, ConesWithoutTheCornersSpreadMissSilhouetteTriangles)
{
  // The wrong variant: cones built around each triangle's mean corner
  // direction alone (no cap radius). Some of its decided nodes hold
  // silhouette triangles, which a find() built on it would skip.
  using namespace visibility_cones;
  const PreparedMesh mesh = bumpySphereMesh(4, 1.0, glm::dvec3(0.0), false);
  const std::vector<glm::dvec3>& points = mesh.points();
  const std::vector<glm::dvec3>& normals = mesh.normals();
  glm::dvec3 lo = points[0];
  glm::dvec3 hi = points[0];
  for (const glm::dvec3& p : points)
  {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const Conditioning map = Conditioning::ofBox(lo, hi);
  std::vector<glm::dvec4> keys;
  for (const Triangle& t : mesh.triangles())
  {
    glm::dvec4 sum(0.0);
    for (const Id c : t)
    {
      sum += map.vectorOf(points[c], normals[c], true);
    }
    keys.push_back(glm::normalize(sum));
  }
  const ConeTree pointCones = buildConeTree(keys);
  std::mt19937_64 random(5);
  std::size_t missed = 0;
  for (int v = 0; v < 20; ++v)
  {
    ViewGeometry view;
    view.Eye = 3.0 * randomUnit(random);
    glm::dvec4 query;
    ASSERT_TRUE(map.queryOf(view, query));
    const std::vector<Id> silhouette =
      scanSilhouetteTriangles(points, normals, mesh.triangles(), view);
    for (const ConeNode& node : pointCones.Nodes)
    {
      if (decide(node.Axis, node.HalfAngle, query) == 0)
      {
        continue;
      }
      for (std::uint32_t k = node.Begin; k < node.End; ++k)
      {
        missed += std::binary_search(
          silhouette.begin(), silhouette.end(), static_cast<Id>(pointCones.Items[k]));
      }
    }
  }
  EXPECT_GT(missed, 0u);
}
