// The silhouette triangle hierarchy built on a thread of its own
// (PreparedMesh::TreeBuild::Background): until it is done the passes scan,
// afterwards the tree answers, and either way a frame's output is the
// scan's. A mesh may go while its tree is still being built.
#include "CoreTestMeshes.h"
#include "PreparedMesh.h"
#include "SilhouetteSmoother.h"
#include "SmoothingResultCheck.h"

#include <gtest/gtest.h>

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

// The mesh searched twice starts the build and is then dropped: its copy
// (which shares the tree) goes on. The thread works on copies of the arrays
// (one that read the dropped mesh's would read freed memory, which the
// AddressSanitizer run sees when the build outlives the mesh). The copy's
// frames equal a scanning pass's before and after the tree is ready, and the
// tree becomes ready.
TEST(SilhouetteTriangleHierarchy, BuiltInTheBackgroundAnswersAsTheScanDoes)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(150, 300, points, triangles); // about 90,000 triangles
  auto original = std::make_unique<PreparedMesh>(points, triangles, points);
  const PreparedMesh copy = *original;

  SmoothingParameters background; // the default: the tree built on a thread
  SmoothingParameters scanning;
  scanning.SilhouetteTriangleHierarchy = false;
  ASSERT_TRUE(background.TriangleHierarchyInBackground);

  int step = 0;
  for (; step < 2; ++step) // the second search starts the build
  {
    coretest::expectSameSmoothing(smoothSilhouettes(*original, orbitView(step), scanning),
      smoothSilhouettes(*original, orbitView(step), background), "view " + std::to_string(step));
  }
  original.reset();

  int answeredByTree = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (answeredByTree < 5 && std::chrono::steady_clock::now() < deadline)
  {
    const bool ready = copy.silhouetteTreeReady(false);
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
  EXPECT_EQ(answeredByTree, 5) << "the tree was not ready within a minute";
  EXPECT_FALSE(copy.silhouetteTreeReady(true)) << "no parallel view was searched";
}

// Built in the call (TreeBuild::InCall), the tree answers from the second
// search on, as the other tree tests need.
TEST(SilhouetteTriangleHierarchy, BuiltInTheCallIsReadyAfterTheSecondSearch)
{
  std::vector<glm::dvec3> points;
  std::vector<Triangle> triangles;
  coretest::unitSphere(20, 40, points, triangles);
  const PreparedMesh mesh(points, triangles, points);
  SmoothingParameters inCall;
  inCall.TriangleHierarchyInBackground = false;
  smoothSilhouettes(mesh, orbitView(0), inCall);
  EXPECT_FALSE(mesh.silhouetteTreeReady(false));
  smoothSilhouettes(mesh, orbitView(1), inCall);
  EXPECT_TRUE(mesh.silhouetteTreeReady(false));
}
