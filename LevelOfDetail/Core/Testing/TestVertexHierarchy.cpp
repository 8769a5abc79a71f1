// View-dependent level of detail (issue 18): the vertex hierarchy built
// from the quadric simplifier's sequence, the cut that follows the view, and
// the view's criteria, with known answers.
#include "CoreTestMeshes.h"
#include "QuadricSimplifier.h"
#include "SelectiveRefinement.h"
#include "VertexHierarchy.h"
#include "ViewRefinementTest.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

using namespace silsmooth;

namespace
{

constexpr double Pi = 3.14159265358979323846;

struct Mesh
{
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
};

VertexHierarchy hierarchyOf(const Mesh& mesh, std::size_t target = 4,
  const std::vector<glm::dvec3>& normals = {}, bool rounds = true)
{
  SimplificationParameters parameters;
  parameters.TargetTriangles = target;
  parameters.RecordSequence = true;
  parameters.IndependentRounds = rounds;
  const SimplificationResult result = simplifyQuadric(mesh.Points, mesh.Triangles, parameters);
  return VertexHierarchy(mesh.Points, mesh.Triangles, result.Sequence, normals);
}

// A perspective view of the origin from `eye` (30 degrees, 800 x 600).
ViewGeometry viewFrom(const glm::dvec3& eye)
{
  ViewGeometry view;
  view.Eye = eye;
  const glm::dvec3 forward = glm::normalize(-eye);
  const glm::dvec3 up = std::abs(forward.z) > 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  view.ModelToClip = glm::perspective(30.0 * Pi / 180.0, 800.0 / 600.0, 0.1, 100.0) *
    glm::lookAt(eye, glm::dvec3(0.0), up);
  view.ViewportWidth = 800;
  view.ViewportHeight = 600;
  return view;
}

// Every vertex's triangles form one fan closed around it (so the mesh is a
// closed 2-manifold at its vertices, not only at its edges).
bool verticesAreDisks(const std::vector<Triangle>& triangles, std::size_t pointCount)
{
  std::vector<std::map<Id, Id>> next(pointCount); // around v: corner after v -> corner after that
  for (const Triangle& t : triangles)
  {
    for (std::size_t k = 0; k < 3; ++k)
    {
      auto& ring = next[static_cast<std::size_t>(t[k])];
      if (!ring.emplace(t[(k + 1) % 3], t[(k + 2) % 3]).second)
        return false;
    }
  }
  for (const auto& ring : next)
  {
    if (ring.empty())
      continue;
    std::size_t steps = 0;
    Id at = ring.begin()->first;
    do
    {
      const auto it = ring.find(at);
      if (it == ring.end())
        return false;
      at = it->second;
      ++steps;
    } while (at != ring.begin()->first && steps <= ring.size());
    if (steps != ring.size())
      return false;
  }
  return true;
}

struct CutCheck
{
  bool ClosedManifold = false;
  long Euler = 0;
};

CutCheck checkCut(const SelectiveRefinement& cut)
{
  ExtractedMesh mesh;
  cut.extract(mesh);
  const std::vector<glm::dvec3>& points = mesh.Points;
  const std::vector<Triangle>& triangles = mesh.Triangles;
  CutCheck check;
  check.ClosedManifold = coretest::checkManifold(triangles).closedManifold() &&
    verticesAreDisks(triangles, points.size());
  // V - E + F with E = 3F/2 on a closed mesh.
  check.Euler = static_cast<long>(points.size()) - static_cast<long>(triangles.size()) / 2;
  return check;
}

// A test that asks for nodes at random, the same answer for a node each time.
struct RandomTest : RefinementTest
{
  explicit RandomTest(unsigned seed, double share)
    : Seed(seed)
    , Share(share)
  {
  }
  bool needs(VertexHierarchy::Index node) const override
  {
    std::mt19937 generator(this->Seed * 1000003u + static_cast<unsigned>(node));
    return std::uniform_real_distribution<double>(0.0, 1.0)(generator) < this->Share;
  }
  unsigned Seed;
  double Share;
};

} // namespace

TEST(VertexHierarchy, AllNodesGiveTheInputExactlyAndNoneTheBase)
{
  Mesh torus;
  coretest::torus(40, 20, 0.35, torus.Points, torus.Triangles);
  SimplificationParameters parameters;
  parameters.TargetTriangles = 4;
  parameters.RecordSequence = true;
  const SimplificationResult coarse = simplifyQuadric(torus.Points, torus.Triangles, parameters);
  const VertexHierarchy hierarchy(torus.Points, torus.Triangles, coarse.Sequence);
  EXPECT_EQ(hierarchy.nodeCount(), coarse.Sequence.size());
  SelectiveRefinement cut(hierarchy);
  EXPECT_EQ(cut.triangleCount(), coarse.Triangles.size());

  // Zero tolerances everywhere ask for every node: the input, bit for bit.
  ViewRefinementTolerances zero;
  zero.ContourPixels = zero.InteriorPixels = zero.BackPixels = 0.0;
  zero.CullOutsideFrustum = false;
  cut.adapt(ViewRefinementTest(hierarchy, viewFrom({ 4.0, 1.0, 2.0 }), zero));
  EXPECT_EQ(cut.appliedCount(), hierarchy.nodeCount());
  ExtractedMesh mesh;
  cut.extract(mesh);
  std::vector<glm::dvec3>& points = mesh.Points;
  std::vector<Triangle>& triangles = mesh.Triangles;
  std::vector<Id>& pointIds = mesh.PointIds;
  std::vector<Id>& triangleIds = mesh.TriangleIds;
  ASSERT_EQ(triangles.size(), torus.Triangles.size());
  ASSERT_EQ(points.size(), torus.Points.size());
  std::vector<int> seen(torus.Triangles.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& input = torus.Triangles[static_cast<std::size_t>(triangleIds[t])];
    ++seen[static_cast<std::size_t>(triangleIds[t])];
    for (std::size_t k = 0; k < 3; ++k)
    {
      const Id p = pointIds[static_cast<std::size_t>(triangles[t][k])];
      EXPECT_EQ(p, input[k]);
      EXPECT_EQ(points[static_cast<std::size_t>(triangles[t][k])],
        torus.Points[static_cast<std::size_t>(p)]);
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size()));

  // Undoing everything comes back to the simplifier's output: the same
  // positions and triangles (up to the renumbering of points).
  cut.undoAll();
  EXPECT_EQ(cut.appliedCount(), 0u);
  cut.extract(mesh);
  std::multiset<std::array<double, 9>> fromCut;
  std::multiset<std::array<double, 9>> fromSimplifier;
  const auto corners = [](const std::vector<glm::dvec3>& p, const Triangle& t) {
    // Rotated so that the lexicographically least corner comes first.
    std::array<glm::dvec3, 3> c{ p[static_cast<std::size_t>(t[0])],
      p[static_cast<std::size_t>(t[1])], p[static_cast<std::size_t>(t[2])] };
    const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    while (less(c[1], c[0]) || less(c[2], c[0]))
      std::rotate(c.begin(), c.begin() + 1, c.end());
    return std::array<double, 9>{ c[0].x, c[0].y, c[0].z, c[1].x, c[1].y, c[1].z, c[2].x, c[2].y,
      c[2].z };
  };
  for (const Triangle& t : triangles)
    fromCut.insert(corners(points, t));
  for (const Triangle& t : coarse.Triangles)
    fromSimplifier.insert(corners(coarse.Points, t));
  EXPECT_EQ(fromCut, fromSimplifier);
}

TEST(VertexHierarchy, EveryCutIsAClosedManifoldOfTheSameGenus)
{
  Mesh torus;
  coretest::torus(36, 18, 0.4, torus.Points, torus.Triangles);
  const VertexHierarchy hierarchy = hierarchyOf(torus);
  SelectiveRefinement cut(hierarchy);
  // Random closed sets of nodes, changed incrementally from one to the next.
  for (unsigned seed = 1; seed <= 40; ++seed)
  {
    cut.adapt(RandomTest(seed, (seed % 10) / 10.0 + 0.05));
    const CutCheck check = checkCut(cut);
    ASSERT_TRUE(check.ClosedManifold) << "seed " << seed;
    ASSERT_EQ(check.Euler, 0) << "seed " << seed;
  }
}

TEST(VertexHierarchy, OrbitKeepsAClosedManifoldAndFollowsTheView)
{
  Mesh sphere;
  coretest::unitSphere(40, 80, sphere.Points, sphere.Triangles);
  const VertexHierarchy hierarchy = hierarchyOf(sphere);
  SelectiveRefinement cut(hierarchy);
  ViewRefinementTolerances tolerances;
  tolerances.ContourPixels = 0.5;
  tolerances.InteriorPixels = 8.0;
  std::size_t fewest = sphere.Triangles.size();
  std::size_t most = 0;
  for (int frame = 0; frame < 360; frame += 3)
  {
    const double a = frame * Pi / 180.0;
    const glm::dvec3 eye(5.0 * std::cos(a), 5.0 * std::sin(a), 1.5 * std::sin(3.0 * a));
    cut.adapt(ViewRefinementTest(hierarchy, viewFrom(eye), tolerances));
    const CutCheck check = checkCut(cut);
    ASSERT_TRUE(check.ClosedManifold) << "frame " << frame;
    ASSERT_EQ(check.Euler, 2) << "frame " << frame;
    fewest = std::min(fewest, cut.triangleCount());
    most = std::max(most, cut.triangleCount());
  }
  // The sphere looks the same from every side: the cut's size barely moves,
  // and is well under the input's.
  EXPECT_LT(most, sphere.Triangles.size() / 2);
  EXPECT_LT(static_cast<double>(most - fewest), 0.25 * static_cast<double>(most));
}

namespace
{

struct SphereCut
{
  int SilhouetteTriangles = 0; // input triangles the contour crosses
  int SilhouetteNotFull = 0;   // of those, not active in their input version
  int CapTriangles = 0;        // active triangles wholly within the cap round the view axis
  int CapNotBase = 0;          // of those, not base triangles
};

SphereCut cutSphere(const Mesh& sphere, const VertexHierarchy& hierarchy, const glm::dvec3& eye,
  const ViewRefinementTolerances& tolerances, double capDegrees)
{
  SelectiveRefinement cut(hierarchy);
  cut.adapt(ViewRefinementTest(hierarchy, viewFrom(eye), tolerances));
  std::vector<char> full(sphere.Triangles.size(), 0);
  const glm::dvec3 axis = glm::normalize(eye);
  SphereCut result;
  const std::vector<VertexHierarchy::Index>& base = hierarchy.baseFaces();
  for (const VertexHierarchy::Index face : cut.activeFaces())
  {
    const Triangle& corners = cut.corners(face);
    const std::size_t f = static_cast<std::size_t>(face);
    bool atInput = corners == sphere.Triangles[f];
    bool atBase =
      corners == hierarchy.baseCorners()[f] && std::binary_search(base.begin(), base.end(), face);
    bool inCap = true;
    for (const Id p : corners)
    {
      const glm::dvec3& now = cut.positions()[static_cast<std::size_t>(p)];
      atInput = atInput && now == sphere.Points[static_cast<std::size_t>(p)];
      atBase = atBase && now == hierarchy.basePositions()[static_cast<std::size_t>(p)];
      inCap = inCap && glm::dot(glm::normalize(now), axis) > std::cos(capDegrees * Pi / 180.0);
    }
    full[f] = atInput ? 1 : 0;
    result.CapTriangles += inCap ? 1 : 0;
    result.CapNotBase += inCap && !atBase ? 1 : 0;
  }
  // The input's own contour: a triangle whose corners see the eye on both
  // sides (g = N . (E - P) with the sphere's exact normals N = P).
  for (std::size_t t = 0; t < sphere.Triangles.size(); ++t)
  {
    int front = 0;
    for (const Id p : sphere.Triangles[t])
    {
      const glm::dvec3& q = sphere.Points[static_cast<std::size_t>(p)];
      front += glm::dot(q, eye - q) >= 0.0 ? 1 : 0;
    }
    if (front == 1 || front == 2)
    {
      ++result.SilhouetteTriangles;
      result.SilhouetteNotFull += full[t] ? 0 : 1;
    }
  }
  return result;
}

} // namespace

// The known answer: with no error allowed at the contour and any
// elsewhere, a sphere seen from any side keeps the triangles its contour
// crosses at full resolution and the cap that faces the viewer at the base
// level (the hierarchy's coarsest mesh, 960 triangles here). The cap is the
// part within 20 degrees of the view axis (the contour is 77-80 degrees from
// it): nearer the contour, splits that the contour's splits depend on (Hoppe's
// forced splits, down a graded band) reach into it; within 30 degrees, 3 of 748
// triangles over these views.
TEST(VertexHierarchy, SphereKeepsItsContourFullAndItsCapAtTheBase)
{
  Mesh sphere;
  coretest::unitSphere(40, 80, sphere.Points, sphere.Triangles);
  // The exact normals (the points themselves), with which the contour is judged.
  const VertexHierarchy hierarchy = hierarchyOf(sphere, 960, sphere.Points);
  ViewRefinementTolerances exactContour;
  exactContour.ContourPixels = 0.0;
  exactContour.InteriorPixels = std::numeric_limits<double>::infinity();
  std::mt19937 generator(7);
  std::normal_distribution<double> normal;
  for (int view = 0; view < 20; ++view)
  {
    const glm::dvec3 eye = (4.5 + view % 4) *
      glm::normalize(glm::dvec3(normal(generator), normal(generator), normal(generator)));
    const SphereCut cut = cutSphere(sphere, hierarchy, eye, exactContour, 20.0);
    EXPECT_GT(cut.SilhouetteTriangles, 150) << "view " << view;
    EXPECT_EQ(cut.SilhouetteNotFull, 0) << "view " << view;
    EXPECT_GE(cut.CapTriangles, 5) << "view " << view;
    EXPECT_EQ(cut.CapNotBase, 0) << "view " << view;
  }
  // The wrong variants: an error allowed at the contour leaves some of its
  // triangles coarse; none allowed inside refines the cap.
  const glm::dvec3 eye(2.0, 3.0, -1.0);
  ViewRefinementTolerances looseContour = exactContour;
  looseContour.ContourPixels = 1.0;
  EXPECT_GT(cutSphere(sphere, hierarchy, eye, looseContour, 20.0).SilhouetteNotFull, 0);
  ViewRefinementTolerances exactInside = exactContour;
  exactInside.InteriorPixels = 0.0;
  EXPECT_GT(cutSphere(sphere, hierarchy, eye, exactInside, 20.0).CapNotBase, 0);
  // And a hierarchy from cheapest-first collapses alone, without independent
  // rounds, forces splits into the cap from the contour.
  const VertexHierarchy cheapestFirst = hierarchyOf(sphere, 960, sphere.Points, false);
  int capNotBase = 0;
  for (int view = 0; view < 20; ++view)
  {
    const glm::dvec3 around(std::cos(view * 0.9), std::sin(view * 0.9), std::cos(view * 1.7));
    capNotBase +=
      cutSphere(sphere, cheapestFirst, 5.0 * glm::normalize(around), exactContour, 20.0).CapNotBase;
  }
  EXPECT_GT(capNotBase, 20);
}

// Parallel projection: the contour is where the normals are orthogonal to the
// direction of view, and it is kept at full resolution there too.
TEST(VertexHierarchy, ParallelViewKeepsItsContourFull)
{
  Mesh sphere;
  coretest::unitSphere(40, 80, sphere.Points, sphere.Triangles);
  const VertexHierarchy hierarchy = hierarchyOf(sphere, 960, sphere.Points);
  const glm::dvec3 toward = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  ViewGeometry view;
  view.Parallel = true;
  view.TowardViewer = toward;
  view.ModelToClip = glm::ortho(-1.5, 1.5, -1.2, 1.2, 0.1, 20.0) *
    glm::lookAt(5.0 * toward, glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0));
  view.ViewportWidth = 800;
  view.ViewportHeight = 640;
  ViewRefinementTolerances exactContour;
  exactContour.ContourPixels = 0.0;
  exactContour.InteriorPixels = std::numeric_limits<double>::infinity();
  SelectiveRefinement cut(hierarchy);
  cut.adapt(ViewRefinementTest(hierarchy, view, exactContour));
  std::vector<char> full(sphere.Triangles.size(), 0);
  for (const VertexHierarchy::Index face : cut.activeFaces())
  {
    bool atInput = cut.corners(face) == sphere.Triangles[static_cast<std::size_t>(face)];
    for (const Id p : cut.corners(face))
      atInput = atInput &&
        cut.positions()[static_cast<std::size_t>(p)] == sphere.Points[static_cast<std::size_t>(p)];
    full[static_cast<std::size_t>(face)] = atInput ? 1 : 0;
  }
  int contour = 0;
  int notFull = 0;
  for (std::size_t t = 0; t < sphere.Triangles.size(); ++t)
  {
    int front = 0;
    for (const Id p : sphere.Triangles[t])
      front += glm::dot(sphere.Points[static_cast<std::size_t>(p)], toward) >= 0.0 ? 1 : 0;
    if (front == 1 || front == 2)
    {
      ++contour;
      notFull += full[t] ? 0 : 1;
    }
  }
  EXPECT_GT(contour, 150);
  EXPECT_EQ(notFull, 0);
  EXPECT_LT(cut.triangleCount(), sphere.Triangles.size() / 2);
}

// Frustum culling: a view zoomed on one side of a sphere leaves the part
// outside the frustum at the base level; without culling (the wrong variant)
// the contour there is refined too.
TEST(VertexHierarchy, OutsideTheFrustumStaysAtTheBase)
{
  Mesh sphere;
  coretest::unitSphere(40, 80, sphere.Points, sphere.Triangles);
  const VertexHierarchy hierarchy = hierarchyOf(sphere, 960, sphere.Points);
  ViewGeometry view = viewFrom({ 0.0, -4.0, 0.0 });
  // Look at (1, 0, 0) from (1, -4, 0) with a narrow field: x < 0.5 is off screen.
  view.Eye = { 1.0, -4.0, 0.0 };
  view.ModelToClip = glm::perspective(12.0 * Pi / 180.0, 800.0 / 600.0, 0.1, 100.0) *
    glm::lookAt(view.Eye, glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, 1.0));
  const auto refinedOffScreen = [&](bool cull) {
    ViewRefinementTolerances tolerances;
    tolerances.ContourPixels = 0.0;
    tolerances.CullOutsideFrustum = cull;
    SelectiveRefinement cut(hierarchy);
    cut.adapt(ViewRefinementTest(hierarchy, view, tolerances));
    int refined = 0;
    for (const VertexHierarchy::Index face : cut.activeFaces())
    {
      bool offScreen = true;
      for (const Id p : cut.corners(face))
        offScreen = offScreen && cut.positions()[static_cast<std::size_t>(p)].x < 0.0;
      const bool atBase =
        cut.corners(face) == hierarchy.baseCorners()[static_cast<std::size_t>(face)];
      refined += offScreen && !atBase ? 1 : 0;
    }
    return refined;
  };
  EXPECT_EQ(refinedOffScreen(true), 0);
  EXPECT_GT(refinedOffScreen(false), 50);
}
