// Exact accuracy (issue 2; docs/testing.md, "What the tests show"): an 80-triangle icosphere with its points
// on the unit sphere and exact normals, seen in perspective from 24 directions
// at 1024 x 1024. The true outline is the projection of the sphere's contour
// circle: a circle about the image centre of radius
//   tan(asin(1 / d)) / tan(viewAngle / 2) * (height / 2)  pixels
// for an eye at distance d. The output is rendered as a flat mask and the
// boundary's distance to that circle is measured, beside the raw coarse mesh's.
#include "vtkCamera.h"
#include "vtkIcosphereSource.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include "SilhouetteMasks.h"
#include "SilhouetteTestSupport.h"

#include <cmath>
#include <cstdio>

int TestSphereAccuracy(int, char*[])
{
  constexpr int size = 1024;
  constexpr double distance = 5.0;
  constexpr double viewAngle = 30.0;
  constexpr double tolerance = 0.5;
  const double radius = std::tan(std::asin(1.0 / distance)) /
    std::tan(vtkMath::RadiansFromDegrees(viewAngle / 2.0)) * (size / 2.0);

  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(1);
  sphere->Update();
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputConnection(sphere->GetOutputPort());
  smoother->SetViewportSize(size, size);
  smoother->SetTolerance(tolerance);

  silhouette_eval::MaskRenderer renderer(size, size);
  std::printf("sphere of %lld triangles, %.1f px across, tolerance %.2f px\n",
    static_cast<long long>(sphere->GetOutput()->GetNumberOfCells()), 2.0 * radius, tolerance);
  std::printf("%4s %12s %12s | %12s %12s %10s\n", "view", "coarse mean", "coarse max",
    "smooth mean", "smooth max", "triangles");
  double worstMean = 0.0;
  double worstMax = 0.0;
  double sumMean = 0.0;
  double coarseSumMean = 0.0;
  const auto directions = silhouette_test::SphereDirections(24);
  for (std::size_t v = 0; v < directions.size(); ++v)
  {
    auto camera = silhouette_test::CameraLookingAtOrigin(directions[v], distance, viewAngle);
    smoother->SetCamera(camera);
    smoother->Update();
    const auto coarse = silhouette_eval::DistanceToCircle(
      renderer.Render(sphere->GetOutput(), camera), size / 2.0, size / 2.0, radius);
    const auto smooth = silhouette_eval::DistanceToCircle(
      renderer.Render(smoother->GetOutput(), camera), size / 2.0, size / 2.0, radius);
    std::printf("%4zu %12.3f %12.3f | %12.3f %12.3f %10lld\n", v, coarse.Mean, coarse.Max,
      smooth.Mean, smooth.Max, static_cast<long long>(smoother->GetOutput()->GetNumberOfPolys()));
    if (smooth.Samples < 1000)
    {
      std::printf("FAIL: view %zu has only %ld boundary samples\n", v, smooth.Samples);
      return EXIT_FAILURE;
    }
    worstMean = std::max(worstMean, smooth.Mean);
    worstMax = std::max(worstMax, smooth.Max);
    sumMean += smooth.Mean;
    coarseSumMean += coarse.Mean;
  }
  std::printf("smoothed: worst mean %.3f px (limit 0.5), worst max %.3f px (limit 1.5), average "
              "mean %.3f px; coarse average mean %.3f px\n",
    worstMean, worstMax, sumMean / directions.size(), coarseSumMean / directions.size());
  if (worstMean > 0.5 || worstMax > 1.5)
  {
    std::printf("FAIL: the smoothed outline is off the exact circle\n");
    return EXIT_FAILURE;
  }

  // The sampling choice: the paper's eq. 8, measured the same way, is why the default
  // rule is the arc bound.
  smoother->SetSamplingRuleToWangEquation8();
  double eq8WorstMean = 0.0;
  double eq8WorstMax = 0.0;
  for (const auto& direction : directions)
  {
    auto camera = silhouette_test::CameraLookingAtOrigin(direction, distance, viewAngle);
    smoother->SetCamera(camera);
    smoother->Update();
    const auto eq8 = silhouette_eval::DistanceToCircle(
      renderer.Render(smoother->GetOutput(), camera), size / 2.0, size / 2.0, radius);
    eq8WorstMean = std::max(eq8WorstMean, eq8.Mean);
    eq8WorstMax = std::max(eq8WorstMax, eq8.Max);
  }
  std::printf("eq. 8 sampling: worst mean %.3f px, worst max %.3f px\n", eq8WorstMean, eq8WorstMax);
  if (!(eq8WorstMax > worstMax))
  {
    std::printf(
      "FAIL: eq. 8 is expected to under-sample (it no longer does: revisit the default)\n");
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
