// The silhouette triangle hierarchy and the fold guard's grid built on
// threads of their own (PreparedMesh::IndexBuild::Background): until each is
// done the passes scan, afterwards it answers, and either way a frame's
// output is the scan's. A mesh may go while they are still being built.
#include "CoreTestMeshes.h"
#include "HeldBackgroundBuilds.h"
#include "PreparedMesh.h"
#include "SilhouetteSmoother.h"
#include "SmoothingResultCheck.h"
#include "TriangleGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <thread>

using namespace silsmooth;

namespace
{

// A view on a circle around the unit sphere, tilted so that the silhouette
// crosses the sphere's rings obliquely.
ViewGeometry orbitView(int step)
{
  const double angle = 0.05 * step;
  return coretest::perspectiveFrom(
    glm::dvec3(4.0 * std::cos(angle), 4.0 * std::sin(angle), 1.3 + 0.02 * step));
}

} // namespace

// The mesh searched twice starts the build and is then dropped, while the
// build is held at its start: its copy (which shares the tree) goes on. The thread works on copies
// of the arrays (one that read the dropped mesh's would read freed memory, which the
// AddressSanitizer run sees when the build outlives the mesh). The copy's
// frames equal a scanning pass's before and after the tree is ready, and the
// tree becomes ready.
TEST(SilhouetteTriangleHierarchy, BuiltInTheBackgroundAnswersAsTheScanDoes)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(150, 300, points, triangles); // about 90,000 triangles
  coretest::HeldBackgroundBuilds held;
  auto original = std::make_unique<PreparedMesh>(points, triangles, points);
  const PreparedMesh copy = *original;

  SmoothingParameters background; // the default: the tree built on a thread
  SmoothingParameters scanning;
  scanning.SilhouetteTriangleHierarchy = false;
  ASSERT_TRUE(background.IndexesInBackground);

  int step = 0;
  for (; step < 2; ++step) // the second search starts the build
  {
    coretest::expectSameSmoothing(smoothSilhouettes(*original, orbitView(step), scanning),
      smoothSilhouettes(*original, orbitView(step), background), "view " + std::to_string(step));
  }
  original.reset(); // while the builds are held: the mesh goes first
  for (; step < 4; ++step)
  {
    EXPECT_FALSE(copy.silhouetteTreeReady(false)) << "held";
    coretest::expectSameSmoothing(smoothSilhouettes(copy, orbitView(step), scanning),
      smoothSilhouettes(copy, orbitView(step), background), "view " + std::to_string(step));
  }
  held.release();

  int answeredByTree = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (answeredByTree < 5 && std::chrono::steady_clock::now() < deadline)
  {
    const bool ready = copy.silhouetteTreeReady(false) && copy.hasTriangleGrid();
    coretest::expectSameSmoothing(smoothSilhouettes(copy, orbitView(step), scanning),
      smoothSilhouettes(copy, orbitView(step), background), "view " + std::to_string(step));
    if (ready)
    {
      ++answeredByTree;
    }
    else
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ++step;
  }
  EXPECT_EQ(answeredByTree, 5) << "the tree or the grid was not ready within a minute";
  EXPECT_FALSE(copy.silhouetteTreeReady(true)) << "no parallel view was searched";
}

// Built in the call (IndexBuild::InCall), the tree answers from the second
// search on, as the other tree tests need.
TEST(SilhouetteTriangleHierarchy, BuiltInTheCallIsReadyAfterTheSecondSearch)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(20, 40, points, triangles);
  const PreparedMesh mesh(points, triangles, points);
  SmoothingParameters inCall;
  inCall.IndexesInBackground = false;
  smoothSilhouettes(mesh, orbitView(0), inCall);
  EXPECT_FALSE(mesh.silhouetteTreeReady(false));
  smoothSilhouettes(mesh, orbitView(1), inCall);
  EXPECT_TRUE(mesh.silhouetteTreeReady(false));
}

// The fold guard's grid, asked for by a mesh's second frame, is built on a
// thread: that frame and the next ones get no grid (they scan) until it is
// built, then the grid, which answers as one built in the call. A deforming
// mesh's frames build it in the call, for the next frames to adopt. The
// build is held at its start until the test lets it go, so no frame can find
// it done early.
TEST(PreparedMeshGrid, FramesScanUntilTheBackgroundGridIsBuilt)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(40, 80, points, triangles);
  coretest::HeldBackgroundBuilds held;
  const PreparedMesh mesh(points, triangles, points);
  EXPECT_EQ(mesh.foldGuardGridForFrame(), nullptr) << "the first frame scans";
  EXPECT_EQ(mesh.foldGuardGridForFrame(), nullptr) << "the second starts the build, not waiting";
  EXPECT_EQ(mesh.foldGuardGridForFrame(), nullptr) << "the third scans while it runs";
  EXPECT_FALSE(mesh.hasTriangleGrid());

  PreparedMesh before(points, triangles, points);
  EXPECT_EQ(before.foldGuardGridForFrame(), nullptr);
  std::vector<glm::dvec3> moved = points;
  for (glm::dvec3& p : moved)
  {
    p *= 1.001;
  }
  PreparedMesh after(moved, triangles, moved);
  EXPECT_FALSE(after.adoptTriangleGrid(before)) << "no grid to adopt yet";
  EXPECT_NE(after.foldGuardGridForFrame(), nullptr) << "a deforming mesh's second frame";
  EXPECT_TRUE(after.hasTriangleGrid());

  held.release();
  const TriangleGrid* grid = nullptr;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (grid == nullptr && std::chrono::steady_clock::now() < deadline)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    grid = mesh.foldGuardGridForFrame();
  }
  ASSERT_NE(grid, nullptr) << "the grid was not built within a minute";
  EXPECT_TRUE(mesh.hasTriangleGrid());
  EXPECT_EQ(grid, &mesh.triangleGrid());
  const TriangleGrid inCall(points, triangles);
  std::vector<Id> a;
  std::vector<Id> b;
  for (const glm::dvec3& centre : { glm::dvec3(1, 0, 0), glm::dvec3(0, -0.6, 0.8) })
  {
    grid->query(centre - 0.05, centre + 0.05, a);
    inCall.query(centre - 0.05, centre + 0.05, b);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b);
  }
}
