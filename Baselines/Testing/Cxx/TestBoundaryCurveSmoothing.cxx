// vtkBoundaryCurveSmoothingFilter (Wang et al. 2003, the baseline) against a
// known answer: the 80-triangle icosphere with exact normals, 24 perspective
// views at 1024x1024. The smoothed silhouette (output port 1) is measured in
// the image against the exact contour circle (the camera looks at the centre,
// so a pixel's distance from the image centre is f tan(angle off the axis)),
// and compared with the straight silhouette edges. The output must stay a
// closed manifold with consistent orientation in every view, and new
// triangles must be marked.
#include "vtkBoundaryCurveSmoothingFilter.h"
#include "vtkCamera.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNTriangleFilter.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{

// Pixel distance of `p` from the exact contour, for a camera at `eye` looking
// at the origin (unit sphere), focal length `f` pixels.
double ContourDistance(const double p[3], const double eye[3], double f)
{
  double ray[3] = { p[0] - eye[0], p[1] - eye[1], p[2] - eye[2] };
  double axis[3] = { -eye[0], -eye[1], -eye[2] };
  vtkMath::Normalize(ray);
  const double d = vtkMath::Normalize(axis);
  const double angle = std::acos(std::clamp(vtkMath::Dot(ray, axis), -1.0, 1.0));
  const double contour = std::asin(1.0 / d);
  return std::abs(f * std::tan(angle) - f * std::tan(contour));
}

struct Accuracy
{
  double WorstMean = 0.0;
  double WorstMax = 0.0;
  double CoarseMean = 0.0;
  double CoarseMax = 0.0;
};

bool MeasureSphere(int level, Accuracy& result)
{
  auto sphere = silhouette_test::Icosphere(level);
  vtkNew<vtkBoundaryCurveSmoothingFilter> filter;
  filter->SetInputData(sphere);
  filter->SetViewportSize(1024, 1024);
  const double viewAngle = 30.0;
  const double f = 512.0 / std::tan(vtkMath::RadiansFromDegrees(viewAngle / 2.0));
  const auto directions = silhouette_test::SphereDirections(24);
  double worstMean = 0.0;
  double worstMax = 0.0;
  double coarseMean = 0.0;
  for (const auto& direction : directions)
  {
    auto camera = silhouette_test::CameraLookingAtOrigin(direction, 4.0, viewAngle);
    filter->SetCamera(camera);
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    const auto report = silhouette_test::AnalyzeTopology(out);
    CHECK(report.closedManifold(), report.summary().c_str());
    CHECK(report.DegenerateTriangles == 0, report.summary().c_str());
    CHECK(out->GetNumberOfPolys() > sphere->GetNumberOfPolys(), "re-meshing adds triangles");
    auto* kinds = vtkUnsignedCharArray::SafeDownCast(out->GetCellData()->GetArray("NewGeometry"));
    CHECK(kinds && kinds->GetNumberOfTuples() == out->GetNumberOfCells(), "NewGeometry array");
    CHECK(kinds->GetRange()[1] == 1.0, "new triangles are marked 1");
    CHECK(out->GetCellData()->GetArray("OriginalCellId"), "OriginalCellId array");

    double eye[3];
    camera->GetPosition(eye);
    vtkPolyData* lines = filter->GetSilhouetteOutput();
    CHECK(lines->GetNumberOfLines() >= 5, "a silhouette loop of edges");
    double sum = 0.0;
    double worst = 0.0;
    double coarseSum = 0.0;
    long count = 0;
    long coarseCount = 0;
    auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k < n; ++k)
      {
        double p[3];
        lines->GetPoint(ids[k], p);
        const double d = ContourDistance(p, eye, f);
        sum += d;
        worst = std::max(worst, d);
        ++count;
      }
      // The straight edge, for comparison.
      double a[3];
      double b[3];
      lines->GetPoint(ids[0], a);
      lines->GetPoint(ids[n - 1], b);
      for (int s = 0; s <= 10; ++s)
      {
        const double u = s / 10.0;
        const double p[3] = { (1 - u) * a[0] + u * b[0], (1 - u) * a[1] + u * b[1],
          (1 - u) * a[2] + u * b[2] };
        const double d = ContourDistance(p, eye, f);
        coarseSum += d;
        result.CoarseMax = std::max(result.CoarseMax, d);
        ++coarseCount;
      }
    }
    worstMean = std::max(worstMean, sum / count);
    worstMax = std::max(worstMax, worst);
    coarseMean += coarseSum / coarseCount / directions.size();
  }
  std::printf("boundary curves (Wang 2003), sphere of %lld triangles, 24 views, 1024 px: "
              "curves: worst view mean %.2f px, max %.2f px; straight silhouette edges: mean "
              "%.2f px, max %.2f px\n",
    static_cast<long long>(sphere->GetNumberOfPolys()), worstMean, worstMax, coarseMean,
    result.CoarseMax);
  result.WorstMean = worstMean;
  result.WorstMax = worstMax;
  result.CoarseMean = coarseMean;
  CHECK(worstMean < coarseMean, "the curves are nearer the contour than the edges");
  CHECK(worstMax < result.CoarseMax, "the curves' worst is nearer than the edges' worst");

  // A fixed sample count, as in the paper (5 points per curve).
  filter->SetSamplesPerCurve(5);
  filter->Update();
  vtkPolyData* lines = filter->GetSilhouetteOutput();
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    CHECK(n == 5, "five samples per curve");
  }
  CHECK(silhouette_test::AnalyzeTopology(filter->GetOutput()).closedManifold(),
    "closed with fixed sampling");
  return true;
}

// Awkward input: empty in, empty out; a missing camera and cells naming
// missing points are errors (for both baseline filters where they apply).
bool CheckAwkwardInput()
{
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkCamera> camera;
  vtkNew<vtkBoundaryCurveSmoothingFilter> curves;
  curves->SetInputData(empty);
  curves->SetCamera(camera);
  curves->Update();
  CHECK(curves->GetOutput()->GetNumberOfPoints() == 0, "empty in, empty out");

  vtkNew<vtkPNTriangleFilter> pn;
  pn->SetInputData(silhouette_test::MeshNamingAMissingPoint());
  std::string message;
  CHECK(silhouette_test::UpdateReportingError(pn, message) == 0 &&
      message.find("points that do not exist") != std::string::npos,
    "PN: cells naming missing points are an error");
  vtkNew<vtkBoundaryCurveSmoothingFilter> noCamera;
  noCamera->SetInputData(silhouette_test::Icosphere(1));
  CHECK(silhouette_test::UpdateReportingError(noCamera, message) == 0 &&
      message.find("No camera") != std::string::npos,
    "2003: a missing camera is an error");
  return true;
}

// Parallel projection: the contour of the unit sphere is the circle of radius
// 1 about the centre; the curves must come nearer it than the straight edges.
bool CheckParallel()
{
  auto sphere = silhouette_test::Icosphere(2);
  vtkNew<vtkBoundaryCurveSmoothingFilter> filter;
  filter->SetInputData(sphere);
  filter->SetViewportSize(1024, 1024);
  const double scale = 1.3; // half the viewport height in model units
  const double pixels = 512.0 / scale;
  double curveSum = 0.0;
  double edgeSum = 0.0;
  long curveCount = 0;
  long edgeCount = 0;
  for (const auto& direction : silhouette_test::SphereDirections(12))
  {
    auto camera = silhouette_test::CameraLookingAtOrigin(direction, 4.0);
    camera->ParallelProjectionOn();
    camera->SetParallelScale(scale);
    filter->SetCamera(camera);
    filter->Update();
    CHECK(silhouette_test::AnalyzeTopology(filter->GetOutput()).closedManifold(),
      "closed manifold in parallel projection");
    double d[3] = { direction[0], direction[1], direction[2] };
    vtkMath::Normalize(d);
    auto offContour = [&](const double p[3]) {
      const double along = vtkMath::Dot(p, d);
      return std::abs(std::sqrt(std::max(0.0, vtkMath::Dot(p, p) - along * along)) - 1.0) * pixels;
    };
    vtkPolyData* lines = filter->GetSilhouetteOutput();
    auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      double a[3];
      double b[3];
      lines->GetPoint(ids[0], a);
      lines->GetPoint(ids[n - 1], b);
      for (vtkIdType k = 0; k < n; ++k)
      {
        double p[3];
        lines->GetPoint(ids[k], p);
        curveSum += offContour(p);
        ++curveCount;
        const double u = static_cast<double>(k) / (n - 1);
        const double q[3] = { (1 - u) * a[0] + u * b[0], (1 - u) * a[1] + u * b[1],
          (1 - u) * a[2] + u * b[2] };
        edgeSum += offContour(q);
        ++edgeCount;
      }
    }
  }
  std::printf("parallel projection, 320-triangle sphere, 12 views: curves %.2f px, straight edges "
              "%.2f px from the contour on average\n",
    curveSum / curveCount, edgeSum / edgeCount);
  CHECK(curveCount > 0 && curveSum / curveCount < edgeSum / edgeCount,
    "parallel: the curves are nearer the contour than the edges");
  return true;
}

} // namespace

int TestBoundaryCurveSmoothing(int, char*[])
{
  if (!CheckAwkwardInput() || !CheckParallel())
  {
    return 1;
  }
  // The curves interpolate the projected vertices of the silhouette edges,
  // which zigzag inside the contour on a coarse mesh: the method is only as
  // near the contour as those vertices, and converges as the mesh is refined.
  Accuracy levels[3];
  for (int level = 1; level <= 3; ++level)
  {
    if (!MeasureSphere(level, levels[level - 1]))
    {
      return 1;
    }
  }
  bool ok = levels[2].WorstMean < levels[0].WorstMean / 3.0 && levels[2].WorstMax < 12.0;
  if (!ok)
  {
    std::printf("FAIL: the curves do not converge to the contour with refinement\n");
  }
  return ok ? 0 : 1;
}
