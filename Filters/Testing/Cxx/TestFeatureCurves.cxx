// Feature curves (issue 6): a capped cylinder of 12 sides, whose rims are
// creases, and a half cylinder (a fandisk-like part: curved and straight
// creases meeting at corners of three surfaces). With the creases as feature
// edges (detected by angle, or the rims marked with line cells), in 24 views:
//   - every rim is drawn as a smooth curve: the projected rim polylines stay
//     within the tolerance (plus a small margin) of the exact projected circle,
//     where the coarse rim is several pixels off;
//   - the output is crack-free and, once coincident points are merged (the
//     two sides of a crease have their own points, like vtkPolyDataNormals'
//     splitting), a closed manifold; no triangle is flipped or degenerate;
//   - marking by lines and detecting by angle give the same mesh.
// Then an image: both parts shaded and as wireframes with the silhouette
// re-meshing in red and the feature re-meshing in blue, compared with
// Testing/Data/Baseline/TestFeatureCurves.png.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{

constexpr double Pi = 3.14159265358979323846;
constexpr int Sides = 12;
constexpr double HalfHeight = 1.0;
constexpr double Tolerance = 0.5;
constexpr int Width = 1024;
constexpr int Height = 768;

// A prism over a closed counter-clockwise profile in the xy plane, z from
// -HalfHeight to HalfHeight in `bands` rows of side quads, its caps fanned
// from `centre`; optionally the creases marked as line cells: the two rims,
// and the vertical lines through the profile points `verticalCreases`.
vtkSmartPointer<vtkPolyData> Prism(const std::vector<std::array<double, 2>>& profile,
  std::array<double, 2> centre, int bands, bool markCreases,
  const std::vector<vtkIdType>& verticalCreases = {})
{
  const vtkIdType n = static_cast<vtkIdType>(profile.size());
  vtkNew<vtkPoints> points;
  for (int ring = 0; ring <= bands; ++ring)
  {
    const double z = -HalfHeight + 2.0 * HalfHeight * ring / bands;
    for (const auto& p : profile)
    {
      points->InsertNextPoint(p[0], p[1], z);
    }
  }
  const vtkIdType bottomCentre = points->InsertNextPoint(centre[0], centre[1], -HalfHeight);
  const vtkIdType topCentre = points->InsertNextPoint(centre[0], centre[1], HalfHeight);
  vtkNew<vtkCellArray> polys;
  const vtkIdType top0 = static_cast<vtkIdType>(bands) * n;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType j = (i + 1) % n;
    for (vtkIdType r = 0; r < bands; ++r)
    {
      const vtkIdType lower = r * n;
      const vtkIdType upper = (r + 1) * n;
      const vtkIdType side0[3] = { lower + i, lower + j, upper + j };
      const vtkIdType side1[3] = { lower + i, upper + j, upper + i };
      polys->InsertNextCell(3, side0);
      polys->InsertNextCell(3, side1);
    }
    const vtkIdType top[3] = { topCentre, top0 + i, top0 + j };
    const vtkIdType bottom[3] = { bottomCentre, j, i };
    polys->InsertNextCell(3, top);
    polys->InsertNextCell(3, bottom);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  if (markCreases)
  {
    vtkNew<vtkCellArray> lines;
    for (int ring = 0; ring < 2; ++ring)
    {
      lines->InsertNextCell(n + 1);
      for (vtkIdType i = 0; i <= n; ++i)
      {
        lines->InsertCellPoint(ring * bands * n + i % n);
      }
    }
    for (const vtkIdType i : verticalCreases)
    {
      lines->InsertNextCell(bands + 1);
      for (vtkIdType ring = 0; ring <= bands; ++ring)
      {
        lines->InsertCellPoint(ring * n + i);
      }
    }
    mesh->SetLines(lines);
  }
  return mesh;
}

// The capped cylinder: unit radius, Sides sides.
vtkSmartPointer<vtkPolyData> CappedCylinder(bool markCreases, int bands)
{
  std::vector<std::array<double, 2>> circle;
  for (int i = 0; i < Sides; ++i)
  {
    circle.push_back({ std::cos(2.0 * Pi * i / Sides), std::sin(2.0 * Pi * i / Sides) });
  }
  return Prism(circle, { 0.0, 0.0 }, bands, markCreases);
}

// A fandisk-like part: a half cylinder (a D-shaped prism), whose rims are a
// curved crease and a straight one meeting at two corners where three
// smooth surfaces meet, and whose flat back meets the round side along two
// straight creases.
vtkSmartPointer<vtkPolyData> HalfCylinder(bool markCreases, int bands)
{
  std::vector<std::array<double, 2>> profile;
  for (int i = 0; i <= Sides / 2; ++i)
  {
    const double a = -0.5 * Pi + Pi * i / (Sides / 2);
    profile.push_back({ std::cos(a), std::sin(a) });
  }
  profile.push_back({ 0.0, 0.0 });
  return Prism(profile, { 0.4, 0.0 }, bands, markCreases, { 0, Sides / 2 });
}

struct Projector
{
  double Matrix[16];
  bool operator()(const double p[3], double pixel[2]) const
  {
    double in[4] = { p[0], p[1], p[2], 1.0 };
    double out[4];
    vtkMatrix4x4::MultiplyPoint(this->Matrix, in, out);
    if (!(out[3] > 0.0))
    {
      return false;
    }
    pixel[0] = (out[0] / out[3] + 1.0) * 0.5 * Width;
    pixel[1] = (out[1] / out[3] + 1.0) * 0.5 * Height;
    return true;
  }
};

// Largest pixel distance from points along the given rim segments to the
// exact projected rim circle at height z.
double RimDeviation(const std::vector<std::array<std::array<double, 3>, 2>>& segments, double z,
  const Projector& project)
{
  std::vector<std::array<double, 2>> circle;
  for (int i = 0; i <= 8192; ++i)
  {
    const double a = 2.0 * Pi * i / 8192;
    const double p[3] = { std::cos(a), std::sin(a), z };
    double pixel[2];
    if (project(p, pixel))
    {
      circle.push_back({ pixel[0], pixel[1] });
    }
  }
  auto distanceToCircle = [&circle](const double q[2]) {
    double best = 1e300;
    for (std::size_t i = 0; i + 1 < circle.size(); ++i)
    {
      const double dx = circle[i + 1][0] - circle[i][0];
      const double dy = circle[i + 1][1] - circle[i][1];
      const double len2 = dx * dx + dy * dy;
      double t = len2 > 0 ? ((q[0] - circle[i][0]) * dx + (q[1] - circle[i][1]) * dy) / len2 : 0;
      t = std::clamp(t, 0.0, 1.0);
      const double ex = circle[i][0] + t * dx - q[0];
      const double ey = circle[i][1] + t * dy - q[1];
      best = std::min(best, ex * ex + ey * ey);
    }
    return std::sqrt(best);
  };
  double worst = 0.0;
  for (const auto& segment : segments)
  {
    for (int k = 0; k <= 8; ++k)
    {
      double p[3];
      for (int c = 0; c < 3; ++c)
      {
        p[c] = segment[0][c] + (segment[1][c] - segment[0][c]) * k / 8.0;
      }
      double pixel[2];
      if (project(p, pixel))
      {
        worst = std::max(worst, distanceToCircle(pixel));
      }
    }
  }
  return worst;
}

// The polygon edges of `mesh` whose ends both lie on the rim at height z.
std::vector<std::array<std::array<double, 3>, 2>> RimSegments(vtkPolyData* mesh, double z)
{
  auto onRim = [z](const double p[3]) {
    return std::abs(p[2] - z) < 1e-6 && std::abs(std::hypot(p[0], p[1]) - 1.0) < 0.02;
  };
  std::vector<std::array<std::array<double, 3>, 2>> segments;
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    for (vtkIdType k = 0; k < npts; ++k)
    {
      std::array<std::array<double, 3>, 2> s;
      mesh->GetPoint(pts[k], s[0].data());
      mesh->GetPoint(pts[(k + 1) % npts], s[1].data());
      // Both ends on the circle, and not along the half cylinder's flat back.
      if (onRim(s[0].data()) && onRim(s[1].data()) &&
        !(std::abs(s[0][0]) < 1e-12 && std::abs(s[1][0]) < 1e-12))
      {
        segments.push_back(s);
      }
    }
  }
  return segments;
}

vtkIdType FieldCount(vtkPolyData* mesh, const char* name)
{
  auto* array = vtkIdTypeArray::SafeDownCast(mesh->GetFieldData()->GetArray(name));
  return array ? array->GetValue(0) : -1;
}

bool CheckViews(const char* name, vtkPolyData* detected, vtkPolyData* marked,
  vtkIdType featureEdges, vtkIdType featureTriangles, vtkIdType splitPoints)
{
  const auto directions = silhouette_test::SphereDirections(24);
  double worstSmooth = 0.0;
  double worstCoarse = 0.0;
  long flipped = 0;
  for (const auto& direction : directions)
  {
    auto camera = silhouette_test::CameraAroundMesh(detected, direction, 3.5, false);
    vtkNew<vtkSilhouetteSmoothingFilter> byAngle;
    byAngle->SetInputData(detected);
    byAngle->SetCamera(camera);
    byAngle->SetViewportSize(Width, Height);
    byAngle->SetTolerance(Tolerance);
    byAngle->FeatureEdgeDetectionOn();
    byAngle->SetFeatureAngle(60.0);
    byAngle->Update();
    vtkPolyData* out = byAngle->GetOutput();

    vtkNew<vtkSilhouetteSmoothingFilter> byLines;
    byLines->SetInputData(marked);
    byLines->SetCamera(camera);
    byLines->SetViewportSize(Width, Height);
    byLines->SetTolerance(Tolerance);
    byLines->Update();
    CHECK(byLines->GetOutput()->GetNumberOfPoints() == out->GetNumberOfPoints() &&
        byLines->GetOutput()->GetNumberOfPolys() == out->GetNumberOfPolys(),
      "marking the creases with lines gives the mesh that detecting them does");

    CHECK(FieldCount(out, "FeatureEdgeCount") == featureEdges, "the expected feature edges");
    CHECK(FieldCount(out, "FeatureTriangleCount") == featureTriangles, "the triangles at them");
    CHECK(FieldCount(out, "SplitPointCount") == splitPoints, "a copy per extra smooth group");

    const silhouette_test::TopologyReport report = silhouette_test::AnalyzeTopology(out);
    CHECK(report.NonFinitePoints == 0 && report.DegenerateTriangles == 0, report.summary().c_str());
    flipped += report.FlippedTriangles;

    vtkNew<vtkCleanPolyData> weld;
    weld->SetInputData(out);
    weld->PointMergingOn();
    weld->SetTolerance(0.0);
    weld->ConvertPolysToLinesOff();
    weld->ConvertLinesToPointsOff();
    weld->Update();
    const silhouette_test::TopologyReport welded =
      silhouette_test::AnalyzeTopology(weld->GetOutput());
    if (!welded.closedManifold() || welded.Triangles != report.Triangles)
    {
      std::printf("welded: %s\n", welded.summary().c_str());
    }
    CHECK(welded.closedManifold(), "closed manifold once the crease's coincident points merge");
    CHECK(welded.Triangles == report.Triangles, "merging loses no triangle");

    Projector project;
    vtkMatrix4x4::DeepCopy(
      project.Matrix, camera->GetCompositeProjectionTransformMatrix(double(Width) / Height, -1, 1));
    for (const double z : { -HalfHeight, HalfHeight })
    {
      worstSmooth = std::max(worstSmooth, RimDeviation(RimSegments(out, z), z, project));
      worstCoarse = std::max(worstCoarse, RimDeviation(RimSegments(detected, z), z, project));
    }
  }
  std::printf("%s: %zu views at %dx%d, tolerance %.2f px: rim deviation from the exact circle "
              "%.3f px smoothed, %.2f px coarse; %ld flipped triangles; %lld split points\n",
    name, directions.size(), Width, Height, Tolerance, worstSmooth, worstCoarse, flipped,
    static_cast<long long>(splitPoints));
  CHECK(flipped == 0, "no flipped triangles");
  CHECK(worstSmooth <= Tolerance + 0.05, "the rims are drawn within the tolerance of the circle");
  CHECK(worstCoarse > 4.0 * Tolerance, "the coarse rims are visibly polygonal (the test can fail)");
  return true;
}

void AddPanel(vtkRenderWindow* window, vtkPolyData* mesh, int row, int column, bool newGeometry)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(0.5 * column, 0.5 - 0.5 * row, 0.5 * (column + 1), 1.0 - 0.5 * row);
  renderer->SetBackground(1, 1, 1);
  window->AddRenderer(renderer);

  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(mesh);
  smoother->SetRenderer(renderer);
  smoother->FeatureEdgeDetectionOn();
  smoother->SetFeatureAngle(60.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(smoother->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  silhouette_test::StyleImageActor(mapper, actor, newGeometry ? 2 : 0);
  renderer->AddActor(actor);
  renderer->ResetCamera(mesh->GetBounds());
  renderer->GetActiveCamera()->Elevation(35);
  renderer->GetActiveCamera()->Azimuth(20);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->GetActiveCamera()->Zoom(1.05);
  renderer->ResetCameraClippingRange();
}

} // namespace

int TestFeatureCurves(int argc, char* argv[])
{
  // Expected counts, from the construction: every rim point has a copy per
  // extra smooth group (one at a plain rim point, two at a corner of three
  // surfaces); the half cylinder's vertical creases are smoothed only when
  // they have more than one edge (bands > 1).
  for (const int bands : { 1, 3 })
  {
    const std::string cylinderName = "cylinder, 12 sides, " + std::to_string(bands) + " bands";
    if (!CheckViews(cylinderName.c_str(), CappedCylinder(false, bands), CappedCylinder(true, bands),
          2 * Sides, 4 * Sides, 2 * Sides))
    {
      return EXIT_FAILURE;
    }
    const std::string halfName = "half cylinder, " + std::to_string(bands) + " bands";
    if (!CheckViews(halfName.c_str(), HalfCylinder(false, bands), HalfCylinder(true, bands),
          16 + 2 * bands, bands == 1 ? 32 : 40, 20 + 2 * (bands - 1)))
    {
      return EXIT_FAILURE;
    }
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 800);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  auto cylinder = CappedCylinder(false, 3);
  auto half = HalfCylinder(false, 3);
  AddPanel(window, cylinder, 0, 0, false);
  AddPanel(window, cylinder, 0, 1, true);
  AddPanel(window, half, 1, 0, false);
  AddPanel(window, half, 1, 1, true);
  window->Render();
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
