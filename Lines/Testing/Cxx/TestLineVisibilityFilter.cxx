// vtkSilhouetteLineVisibility (issue 16) on the smoothed silhouette of a
// torus seen obliquely, against the smoothed surface: the outer contour is
// visible, part of the inner one is hidden by the near side of the tube, and
// every point's verdict is the exact torus's (its ray to the eye marched
// through the torus's implicit function; points whose ray comes within about
// 0.045 of the surface are left out). Each change point is measured in
// pixels against the exact torus's nearest change along the same line
// (within 0.5 px, the limit). Also: the arrays,
// PassHiddenLines off, a line with nothing in front of it, and the errors
// (no camera, a negative tolerance).
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSilhouetteLineVisibility.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkTestErrorObserver.h"
#include "vtkTorusSurfaceSource.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

namespace
{

constexpr double Tube = 0.4;
// The limit. Measured: 0.012 and 0.017 px where the inner contour
// passes under the tube's far side, 0.054 and 0.208 px where its near part
// comes out from behind the near side of the tube (the contour ends behind
// itself there, near a cusp). The wrong variant, each change put at the
// line's vertex before it (no bisection), is up to 1.05 px off.
constexpr double MaximumChangeErrorPixels = 0.5;
// Where the exact change is looked for, the ray is marched from this far
// from the line's point (about 2 px here): the point lies within about
// 0.003 of the exact torus, and near a cusp the occluder comes arbitrarily
// close, so a longer gap would move the exact change along the line (a
// tenth of the way to the eye, 0.47, put it 5.3 px away).
constexpr double ChangeRayStart = 0.01;
// Points whose ray to the eye passes this near the exact torus (in its
// implicit function, about 0.045 in distance) are not judged: the smoothed
// surface differs from the torus by that much near the contour's ends
// (three points at 0.030 to 0.032 differ).
constexpr double GrazingMargin = 0.036;

double Implicit(const double q[3])
{
  const double ring = std::sqrt(q[0] * q[0] + q[1] * q[1]) - 1.0;
  return ring * ring + q[2] * q[2] - Tube * Tube;
}

// The lowest value of the torus's implicit function along the ray from p to
// the eye, from `start` (a fraction of the way; by default its first tenth,
// beyond the surface p lies on): negative when the exact torus hides p.
double Lowest(const double p[3], const double eye[3], double start = 0.1)
{
  double lowest = 1e9;
  for (double t = start; t < 1.0; t += 0.0005)
  {
    const double q[3] = { p[0] + t * (eye[0] - p[0]), p[1] + t * (eye[1] - p[1]),
      p[2] + t * (eye[2] - p[2]) };
    lowest = std::min(lowest, Implicit(q));
  }
  return lowest;
}

bool Fail(const char* what)
{
  std::printf("FAIL: %s\n", what);
  return false;
}

// Every point against the exact torus.
bool CheckPointsAgainstTorus(
  vtkPolyData* out, vtkUnsignedCharArray* pointVisible, const double* eye)
{
  bool ok = true;
  long agree = 0;
  long disagree = 0;
  long grazing = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double x[3];
    out->GetPoint(p, x);
    const double lowest = Lowest(x, eye);
    if (std::abs(lowest) < GrazingMargin)
    {
      ++grazing;
      continue;
    }
    const bool same = (lowest < 0.0) == (pointVisible->GetValue(p) == 0);
    (same ? agree : disagree) += 1;
    if (!same)
    {
      std::printf("  point %lld (%.4f %.4f %.4f): %s here, the exact torus's ray reaches %.4f\n",
        static_cast<long long>(p), x[0], x[1], x[2],
        pointVisible->GetValue(p) ? "visible" : "hidden", lowest);
    }
  }
  std::printf("torus: %ld points as the exact torus says, %ld not, %ld near grazing left out\n",
    agree, disagree, grazing);
  if (disagree > 0 || agree < 200)
  {
    ok = Fail("points classified against the exact torus");
  }
  return ok;
}

// Each change point X (the end of a piece followed by a piece of the same
// line) against the nearest exact change along the same two pieces: where
// Lowest crosses 0. Both projected to pixels.
bool CheckChangePoints(
  vtkPolyData* out, vtkIdTypeArray* original, vtkCamera* camera, int width, int height)
{
  bool ok = true;
  const double* eye = camera->GetPosition();
  double worstPixels = 0.0;
  double wrongPixels = 0.0;
  int changes = 0;
  vtkCellArray* lines = out->GetLines();
  std::vector<std::vector<vtkIdType>> pieces;
  for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
  {
    vtkNew<vtkIdList> ids;
    lines->GetCellAtId(c, ids);
    pieces.emplace_back(ids->begin(), ids->end());
  }
  auto toPixels = [&](const double w[3], double px[2]) {
    // The camera's composite projection for the viewport's aspect.
    vtkMatrix4x4* m =
      camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1, 1);
    double in[4] = { w[0], w[1], w[2], 1.0 };
    double clip[4];
    m->MultiplyPoint(in, clip);
    px[0] = (clip[0] / clip[3] + 1.0) * 0.5 * width;
    px[1] = (clip[1] / clip[3] + 1.0) * 0.5 * height;
  };
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k)
  {
    if (original->GetValue(static_cast<vtkIdType>(k)) !=
        original->GetValue(static_cast<vtkIdType>(k + 1)) ||
      pieces[k].size() < 2 || pieces[k + 1].size() < 2)
    {
      continue; // the next piece is another line's
    }
    // The two pieces as one polyline through X; the exact change nearest
    // to X along it (a sign change of Lowest between consecutive points,
    // bisected).
    std::vector<vtkIdType> around(pieces[k].begin(), pieces[k].end());
    around.insert(around.end(), pieces[k + 1].begin() + 1, pieces[k + 1].end());
    const std::size_t xAt = pieces[k].size() - 1;
    double x[3];
    out->GetPoint(around[xAt], x);
    double px[2];
    toPixels(x, px);
    // The wrong variant: the change at the vertex before it (no bisection).
    double v[3];
    out->GetPoint(around[xAt - 1], v);
    double pv[2];
    toPixels(v, pv);
    double nearest = 1e9;
    double nearestToVertex = 1e9;
    for (std::size_t i = 0; i + 1 < around.size(); ++i)
    {
      double a[3];
      double b[3];
      out->GetPoint(around[i], a);
      out->GetPoint(around[i + 1], b);
      auto lowest = [&](const double q[3]) {
        return Lowest(q, eye, ChangeRayStart / std::sqrt(vtkMath::Distance2BetweenPoints(q, eye)));
      };
      const double la = lowest(a);
      if ((la < 0.0) == (lowest(b) < 0.0))
      {
        continue;
      }
      double low = 0.0;
      double high = 1.0;
      for (int step = 0; step < 50; ++step)
      {
        const double mid = 0.5 * (low + high);
        const double q[3] = { a[0] + mid * (b[0] - a[0]), a[1] + mid * (b[1] - a[1]),
          a[2] + mid * (b[2] - a[2]) };
        ((lowest(q) < 0.0) == (la < 0.0) ? low : high) = mid;
      }
      const double t = 0.5 * (low + high);
      const double exact[3] = { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
        a[2] + t * (b[2] - a[2]) };
      double pe[2];
      toPixels(exact, pe);
      nearest = std::min(nearest, std::hypot(pe[0] - px[0], pe[1] - px[1]));
      nearestToVertex = std::min(nearestToVertex, std::hypot(pe[0] - pv[0], pe[1] - pv[1]));
    }
    worstPixels = std::max(worstPixels, nearest);
    wrongPixels = std::max(wrongPixels, nearestToVertex);
    std::printf("  change at (%.4f %.4f %.4f): %.3f px from the exact one (the vertex before "
                "it: %.3f px)\n",
      x[0], x[1], x[2], nearest, nearestToVertex);
    ++changes;
  }
  std::printf("torus: %d change points, the farthest %.3f px from the exact torus's (limit %.1f); "
              "the vertices before them up to %.3f px\n",
    changes, worstPixels, MaximumChangeErrorPixels, wrongPixels);
  if (changes == 0 || worstPixels > MaximumChangeErrorPixels)
  {
    ok = Fail("change points against the exact torus");
  }
  if (!(wrongPixels > MaximumChangeErrorPixels))
  {
    ok = Fail("the change-point check cannot fail: the vertices before the changes pass it");
  }
  return ok;
}

// The wrong variant: no tolerance, so a silhouette is hidden by the
// surface it lies on.
// Then: hidden pieces left out; errors for a negative tolerance and no camera.
bool CheckOptions(
  vtkSilhouetteLineVisibility* visibility, vtkIdType visiblePieces, const double* eye)
{
  bool ok = true;
  visibility->SetTolerance(1e-9);
  visibility->Update();
  long selfHidden = 0;
  {
    auto* wrong = vtkUnsignedCharArray::SafeDownCast(
      visibility->GetOutput()->GetPointData()->GetArray("Visible"));
    for (vtkIdType p = 0; p < visibility->GetOutput()->GetNumberOfPoints(); ++p)
    {
      double x[3];
      visibility->GetOutput()->GetPoint(p, x);
      const double lowest = Lowest(x, eye);
      selfHidden += lowest > GrazingMargin && wrong->GetValue(p) == 0 ? 1 : 0;
    }
  }
  std::printf(
    "torus: with no tolerance, %ld points the exact torus shows are hidden\n", selfHidden);
  if (selfHidden == 0)
  {
    ok = Fail("the classification check cannot fail");
  }
  visibility->SetTolerance(0.0);

  // Hidden pieces left out.
  visibility->PassHiddenLinesOff();
  visibility->Update();
  if (visibility->GetOutput()->GetNumberOfLines() != visiblePieces)
  {
    ok = Fail("PassHiddenLines off keeps other than the visible pieces");
  }
  visibility->PassHiddenLinesOn();

  // Errors: a negative tolerance; no camera.
  vtkNew<vtkTest::ErrorObserver> errors;
  visibility->AddObserver(vtkCommand::ErrorEvent, errors);
  visibility->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  visibility->SetTolerance(-1.0);
  visibility->Update();
  if (!errors->GetError())
  {
    ok = Fail("a negative tolerance was accepted");
  }
  errors->Clear();
  visibility->SetTolerance(0.0);
  visibility->SetOutlinePixels(-1.0);
  visibility->Update();
  if (!errors->GetError())
  {
    ok = Fail("a negative OutlinePixels was accepted");
  }
  errors->Clear();
  visibility->SetOutlinePixels(0.0);
  // Infinity too (it drew stray contour pieces, a user's trial): for every
  // setting, and for each a large finite value is taken (the wrong variant).
  const double infinity = std::numeric_limits<double>::infinity();
  using Setter = void (vtkSilhouetteLineVisibility::*)(double);
  const std::pair<const char*, Setter> settings[] = {
    { "Tolerance", &vtkSilhouetteLineVisibility::SetTolerance },
    { "EdgeTolerance", &vtkSilhouetteLineVisibility::SetEdgeTolerance },
    { "OutlinePixels", &vtkSilhouetteLineVisibility::SetOutlinePixels },
    { "OutlineGapPixels", &vtkSilhouetteLineVisibility::SetOutlineGapPixels },
  };
  for (const auto& [name, set] : settings)
  {
    for (const double wrong : { -1.0, std::nan(""), infinity })
    {
      (visibility->*set)(wrong);
      visibility->Update();
      if (!errors->GetError() ||
        std::string(errors->GetErrorMessage()).find(std::string(name) + " must be") ==
          std::string::npos)
      {
        ok = Fail((std::string(name) + " took a negative, NaN or infinite value").c_str());
      }
      errors->Clear();
    }
    (visibility->*set)(1e6);
    visibility->Update();
    if (errors->GetError())
    {
      ok = Fail((std::string(name) + " refused a large finite value").c_str());
    }
    errors->Clear();
    (visibility->*set)(0.0);
  }
  visibility->SetCamera(nullptr);
  visibility->Update();
  if (!errors->GetError())
  {
    ok = Fail("no camera was accepted");
  }
  return ok;
}

// The lines' length in pixels: (visible pieces, added outline pieces).
std::pair<double, double> PixelLengths(vtkPolyData* lines, vtkCamera* camera, int width, int height)
{
  vtkNew<vtkMatrix4x4> toClip;
  toClip->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0));
  auto toPixels = [&](const double p[3], double pixel[2]) {
    const double in[4] = { p[0], p[1], p[2], 1.0 };
    double clip[4];
    toClip->MultiplyPoint(in, clip);
    pixel[0] = (clip[0] / clip[3] + 1.0) * 0.5 * width;
    pixel[1] = (clip[1] / clip[3] + 1.0) * 0.5 * height;
  };
  vtkDataArray* visible = lines->GetCellData()->GetArray("Visible");
  vtkDataArray* original = lines->GetCellData()->GetArray("OriginalCellId");
  double lengths[2] = { 0.0, 0.0 };
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
  {
    if (visible->GetComponent(c, 0) == 0.0)
    {
      continue;
    }
    lines->GetCellPoints(c, ids);
    for (vtkIdType k = 1; k < ids->GetNumberOfIds(); ++k)
    {
      double a[2];
      double b[2];
      toPixels(lines->GetPoint(ids->GetId(k - 1)), a);
      toPixels(lines->GetPoint(ids->GetId(k)), b);
      lengths[original->GetComponent(c, 0) < 0.0 ? 1 : 0] += std::hypot(b[0] - a[0], b[1] - a[1]);
    }
  }
  return { lengths[0], lengths[1] };
}

// OutlineGapPixels: with the torus's smoothed silhouettes, which draw its
// outline, nothing is added; with none of them (a stub far off the torus
// instead), the surface's contour draws the outline, as long as the
// silhouettes' visible pieces, as pieces of no input cell with LineKind 4
// and null point data; with the setting 0 (the wrong variant), nothing.
bool CheckOutlineGaps(
  vtkSilhouetteSmoothingFilter* smoother, vtkCamera* camera, int width, int height)
{
  bool ok = true;
  vtkNew<vtkSilhouetteLineVisibility> visibility;
  visibility->SetSurfaceConnection(smoother->GetOutputPort(0));
  visibility->SetCamera(camera);
  visibility->SetViewportSize(width, height);
  visibility->SetOutlinePixels(1.0);
  visibility->SetOutlineGapPixels(3.0);
  visibility->SetInputConnection(smoother->GetOutputPort(1));
  visibility->Update();
  const auto [silhouettes, addedBeside] =
    PixelLengths(visibility->GetOutput(), camera, width, height);

  vtkNew<vtkPolyData> stub; // one line, far off the torus, with its arrays
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(10.0, 10.0, 10.0);
  points->InsertNextPoint(10.1, 10.0, 10.0);
  stub->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  const vtkIdType line[2] = { 0, 1 };
  cells->InsertNextCell(2, line);
  stub->SetLines(cells);
  vtkNew<vtkUnsignedCharArray> kind;
  kind->SetName("LineKind");
  kind->InsertNextValue(0);
  stub->GetCellData()->AddArray(kind);
  vtkNew<vtkDoubleArray> weight;
  weight->SetName("Weight");
  weight->InsertNextValue(5.0);
  weight->InsertNextValue(5.0);
  stub->GetPointData()->AddArray(weight);
  visibility->SetInputData(stub);
  visibility->Update();
  vtkPolyData* out = visibility->GetOutput();
  const auto [stubLength, added] = PixelLengths(out, camera, width, height);
  std::printf("outline gaps: %.1f px added beside %.1f px of silhouettes; without them %.1f px "
              "added\n",
    addedBeside, silhouettes, added);
  if (addedBeside != 0.0)
  {
    ok = Fail("the torus's silhouettes leave no gap in its outline");
  }
  if (!(std::abs(added - silhouettes) < 0.02 * silhouettes))
  {
    ok = Fail("without them, the contour draws as much outline as they do, to 2%");
  }
  vtkDataArray* kinds = out->GetCellData()->GetArray("LineKind");
  vtkDataArray* original = out->GetCellData()->GetArray("OriginalCellId");
  vtkDataArray* weights = out->GetPointData()->GetArray("Weight");
  if (!kinds || !weights || weights->GetNumberOfTuples() != out->GetNumberOfPoints())
  {
    return Fail("the output keeps LineKind and a point array for every point");
  }
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    if (original->GetComponent(c, 0) >= 0.0)
    {
      continue;
    }
    out->GetCellPoints(c, ids);
    if (kinds->GetComponent(c, 0) != 4.0 || weights->GetComponent(ids->GetId(0), 0) != 0.0)
    {
      ok = Fail("an added piece is LineKind 4 with null point data");
      break;
    }
  }
  visibility->SetOutlineGapPixels(0.0);
  visibility->Update();
  if (PixelLengths(visibility->GetOutput(), camera, width, height).second != 0.0)
  {
    ok = Fail("with OutlineGapPixels 0 nothing is added");
  }
  return ok;
}

} // namespace

int TestLineVisibilityFilter(int, char*[])
{
  bool ok = true;
  vtkNew<vtkTorusSurfaceSource> torus;
  torus->SetRingResolution(96);
  torus->SetTubeResolution(48);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, -4.0, 2.5);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  const int width = 800;
  const int height = 600;
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputConnection(torus->GetOutputPort());
  smoother->SetCamera(camera);
  smoother->SetViewportSize(width, height);
  vtkNew<vtkSilhouetteLineVisibility> visibility;
  visibility->SetInputConnection(smoother->GetOutputPort(1));
  visibility->SetSurfaceConnection(smoother->GetOutputPort(0));
  visibility->SetCamera(camera);
  visibility->Update();
  vtkPolyData* out = visibility->GetOutput();

  auto* pointVisible = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("Visible"));
  auto* cellVisible = vtkUnsignedCharArray::SafeDownCast(out->GetCellData()->GetArray("Visible"));
  auto* original = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("OriginalCellId"));
  if (!pointVisible || !cellVisible || !original || !out->GetPointData()->GetNormals())
  {
    return Fail("the output lacks Visible, OriginalCellId or the lines' normals") ? 0 : 1;
  }
  const vtkIdType visiblePieces =
    vtkIdTypeArray::SafeDownCast(out->GetFieldData()->GetArray("VisiblePieceCount"))->GetValue(0);
  const vtkIdType hiddenPieces =
    vtkIdTypeArray::SafeDownCast(out->GetFieldData()->GetArray("HiddenPieceCount"))->GetValue(0);
  std::printf("torus: %lld silhouette lines in, %lld visible and %lld hidden pieces out\n",
    static_cast<long long>(smoother->GetOutput(1)->GetNumberOfLines()),
    static_cast<long long>(visiblePieces), static_cast<long long>(hiddenPieces));
  if (hiddenPieces == 0 || visiblePieces == 0 ||
    out->GetNumberOfLines() != visiblePieces + hiddenPieces)
  {
    ok = Fail("expected visible and hidden pieces, one polyline each");
  }

  const double* eye = camera->GetPosition();
  ok = CheckPointsAgainstTorus(out, pointVisible, eye) && ok;
  ok = CheckChangePoints(out, original, camera, width, height) && ok;
  ok = CheckOptions(visibility, visiblePieces, eye) && ok;
  ok = CheckOutlineGaps(smoother, camera, width, height) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
