// vtkStylizedStrokeFilter (Kim and Choe 3.5) on the smoothed silhouette of
// the coarse bunny: every brush offset within its amplitude, offsets in the
// view plane, zero amplitude gives the polylines back, the output repeats, a
// model matrix means model coordinates, lines that meet end to end are one
// stroke, and a missing camera is an error.
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSmartPointer.h"
#include "vtkStylizedStrokeFilter.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{

double Diagonal(vtkPolyData* data)
{
  double b[6];
  data->GetBounds(b);
  return std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

// Every brush at three amplitudes: one stroke per line, resampled, offsets
// within the amplitude and using its range, and the same output again.
bool CheckBrushes(vtkPolyData* silhouette, vtkCamera* camera, double diagonal)
{
  for (int brush = vtkStylizedStrokeFilter::CHARCOAL; brush <= vtkStylizedStrokeFilter::ROUGH;
       ++brush)
  {
    for (double amplitude : { 0.001, 0.01, 0.05 })
    {
      vtkNew<vtkStylizedStrokeFilter> strokes;
      strokes->SetInputData(silhouette);
      strokes->SetCamera(camera);
      strokes->SetBrush(brush);
      strokes->SetAmplitude(amplitude);
      strokes->Update();
      vtkPolyData* out = strokes->GetOutput();
      CHECK(out->GetNumberOfLines() == silhouette->GetNumberOfLines(), "one stroke per line");
      CHECK(out->GetNumberOfPoints() > silhouette->GetNumberOfPoints(), "resampled");
      vtkDataArray* offsets = out->GetPointData()->GetArray("BrushOffset");
      CHECK(offsets && offsets->GetNumberOfComponents() == 2, "BrushOffset");
      const double bound = amplitude * diagonal;
      double largest = 0.0;
      for (vtkIdType i = 0; i < offsets->GetNumberOfTuples(); ++i)
      {
        const double* v = offsets->GetTuple2(i);
        CHECK(std::abs(v[0]) <= bound && std::abs(v[1]) <= bound, "offset within amplitude");
        largest = std::max({ largest, std::abs(v[0]), std::abs(v[1]) });
      }
      std::printf("brush %d, amplitude %g: largest offset %.6g of bound %.6g\n", brush, amplitude,
        largest, bound);
      CHECK(largest > 0.5 * bound, "the brush uses its range");
      // Same again: seeded, so the output repeats exactly.
      vtkNew<vtkStylizedStrokeFilter> again;
      again->SetInputData(silhouette);
      again->SetCamera(camera);
      again->SetBrush(brush);
      again->SetAmplitude(amplitude);
      again->Update();
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double a[3];
        double b[3];
        out->GetPoint(i, a);
        again->GetOutput()->GetPoint(i, b);
        CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2], "repeatable");
      }
    }
  }
  return true;
}

bool CheckZeroAmplitude(vtkPolyData* silhouette, vtkCamera* camera)
{
  // Zero amplitude, no resampling: the polylines come back point for point.
  vtkNew<vtkStylizedStrokeFilter> still;
  still->SetInputData(silhouette);
  still->SetCamera(camera);
  still->SetBrushToRough();
  still->SetAmplitude(0.0);
  still->SetSpacing(0.0);
  still->Update();
  vtkPolyData* out = still->GetOutput();
  CHECK(out->GetNumberOfLines() == silhouette->GetNumberOfLines(), "same strokes");
  vtkIdType outIndex = 0;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (vtkIdType c = 0; c < silhouette->GetNumberOfLines(); ++c)
  {
    silhouette->GetLines()->GetCellAtId(c, n, ids);
    for (vtkIdType k = 0; k < n; ++k, ++outIndex)
    {
      double a[3];
      double b[3];
      silhouette->GetPoint(ids[k], a);
      out->GetPoint(outIndex, b);
      CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2], "zero amplitude gives the input back");
    }
  }
  CHECK(outIndex == out->GetNumberOfPoints(), "no extra points");

  // The camera moving re-runs the filter.
  const vtkMTimeType before = still->GetMTime();
  camera->Azimuth(10.0);
  CHECK(still->GetMTime() > before, "camera in MTime");
  return true;
}

bool CheckModelMatrix(vtkPolyData* silhouette, vtkCamera* camera, double diagonal)
{
  // A model matrix (a quarter turn about z and a shift, which keeps the
  // bounding box's diagonal and so the brush's scale) gives the strokes of
  // the transformed data, transformed back: the view is taken into the data's
  // model coordinates. (Equal to float precision: the points are floats; a
  // view left in world coordinates is off by about the amplitude.)
  {
    vtkNew<vtkTransform> turn;
    turn->Translate(0.3, -0.2, 0.5);
    turn->RotateZ(90.0);
    vtkNew<vtkTransformPolyDataFilter> moved;
    moved->SetInputData(silhouette);
    moved->SetTransform(turn);
    moved->Update();
    vtkNew<vtkStylizedStrokeFilter> inWorld;
    inWorld->SetInputData(moved->GetOutput());
    inWorld->SetCamera(camera);
    inWorld->SetBrushToHand();
    inWorld->Update();
    vtkNew<vtkStylizedStrokeFilter> inModel;
    inModel->SetInputData(silhouette);
    inModel->SetCamera(camera);
    inModel->SetModelMatrix(turn->GetMatrix());
    inModel->SetBrushToHand();
    inModel->Update();
    vtkPolyData* world = inWorld->GetOutput();
    vtkPolyData* model = inModel->GetOutput();
    CHECK(
      world->GetNumberOfPoints() == model->GetNumberOfPoints() && world->GetNumberOfPoints() > 0,
      "same strokes with a model matrix");
    double worst = 0.0;
    for (vtkIdType i = 0; i < world->GetNumberOfPoints(); ++i)
    {
      double a[3];
      double b[3];
      world->GetPoint(i, a);
      model->GetPoint(i, b);
      turn->TransformPoint(b, b);
      worst = std::max(worst, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    }
    std::printf("strokes with a model matrix against transformed data: %.2e of the diagonal\n",
      worst / diagonal);
    CHECK(worst <= 1e-6 * diagonal, "the model matrix takes the view into model coordinates");
  }
  return true;
}

// A circle drawn as three lines that meet end to end (the middle one
// reversed, each with its own copies of the points where they meet), as
// vtkSilhouetteLineVisibility's pieces of one curve come: joined, one closed
// stroke along the circle; with JoinLines off (the wrong variant), three
// strokes, and the brush breaks the circle where they meet.
bool CheckJoinedLines()
{
  constexpr int Samples = 60;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const int cuts[4] = { 0, 20, 40, Samples };
  for (int part = 0; part < 3; ++part)
  {
    lines->InsertNextCell(cuts[part + 1] - cuts[part] + 1);
    for (int k = cuts[part]; k <= cuts[part + 1]; ++k)
    {
      const int i = part == 1 ? cuts[1] + cuts[2] - k : k; // the middle one reversed
      const double angle = 2.0 * vtkMath::Pi() * (i % Samples) / Samples;
      lines->InsertCellPoint(points->InsertNextPoint(std::cos(angle), std::sin(angle), 0.0));
    }
  }
  vtkNew<vtkPolyData> circle;
  circle->SetPoints(points);
  circle->SetLines(lines);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, 0.0, 5.0);

  auto strokes = [&](bool join, double amplitude) {
    auto filter = vtkSmartPointer<vtkStylizedStrokeFilter>::New();
    filter->SetInputData(circle);
    filter->SetCamera(camera);
    filter->SetBrushToHand();
    filter->SetAmplitude(amplitude);
    filter->SetSpacing(0.0);
    filter->SetJoinLines(join);
    filter->Update();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->DeepCopy(filter->GetOutput());
    return out;
  };
  // The biggest jump between consecutive points of a stroke, and between
  // the strokes' ends that meet on the circle.
  auto ends = [](vtkPolyData* out, vtkIdType cell, bool last) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    out->GetLines()->GetCellAtId(cell, n, ids);
    double p[3];
    out->GetPoint(ids[last ? n - 1 : 0], p);
    return std::array<double, 3>{ p[0], p[1], p[2] };
  };
  auto apart = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  };

  vtkSmartPointer<vtkPolyData> still = strokes(true, 0.0);
  CHECK(still->GetNumberOfLines() == 1, "three lines meeting end to end are one stroke");
  CHECK(still->GetNumberOfPoints() == Samples + 1, "each joint once");
  CHECK(apart(ends(still, 0, false), ends(still, 0, true)) == 0.0, "a closed stroke");
  for (vtkIdType i = 0; i < still->GetNumberOfPoints(); ++i)
  {
    double p[3];
    still->GetPoint(i, p);
    const double angle = 2.0 * vtkMath::Pi() * (i % Samples) / Samples;
    CHECK(std::hypot(p[0] - std::cos(angle), p[1] - std::sin(angle)) < 1e-6,
      "along the circle in order");
  }
  CHECK(strokes(false, 0.0)->GetNumberOfLines() == 3, "the wrong variant: three strokes");

  // With a brush: joined, the stroke stays closed; apart, the offsets of
  // the ends that meet differ and break the circle.
  vtkSmartPointer<vtkPolyData> joined = strokes(true, 0.02);
  CHECK(
    joined->GetNumberOfLines() == 1 && apart(ends(joined, 0, false), ends(joined, 0, true)) == 0.0,
    "the brushed circle is closed");
  vtkSmartPointer<vtkPolyData> separate = strokes(false, 0.02);
  const double broken = std::max({ apart(ends(separate, 0, true), ends(separate, 1, true)),
    apart(ends(separate, 1, false), ends(separate, 2, false)),
    apart(ends(separate, 2, true), ends(separate, 0, false)) });
  std::printf("brushed circle: %lld stroke(s) joined; apart, the widest break %.4f of the "
              "diameter\n",
    static_cast<long long>(joined->GetNumberOfLines()), broken / 2.0);
  CHECK(broken > 0.002, "the wrong variant breaks the brushed circle where the lines meet");
  return true;
}

bool Run(int argc, char* argv[])
{
  auto bunny = silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bunny_coarse.ply"));
  CHECK(bunny, "bunny read");
  auto camera = silhouette_test::CameraAroundMesh(bunny, { 0.3, 0.2, 1.0 }, 3.0, false);
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(bunny);
  smoother->SetCamera(camera);
  smoother->SetViewportSize(800, 600);
  smoother->Update();
  vtkNew<vtkPolyData> silhouette;
  silhouette->DeepCopy(smoother->GetOutput(1));
  CHECK(silhouette->GetNumberOfLines() > 0, "smoothed silhouette polylines");
  const double diagonal = Diagonal(silhouette);
  CHECK(CheckBrushes(silhouette, camera, diagonal), "brushes");
  CHECK(CheckZeroAmplitude(silhouette, camera), "zero amplitude");
  CHECK(CheckModelMatrix(silhouette, camera, diagonal), "model matrix");
  CHECK(CheckJoinedLines(), "lines joined into strokes");

  // No camera: an error, not a crash.
  vtkNew<vtkStylizedStrokeFilter> blind;
  blind->SetInputData(silhouette);
  std::string message;
  CHECK(silhouette_test::UpdateReportingError(blind, message) == 0, "fails without a camera");
  CHECK(message.find("No camera") != std::string::npos, "says why");
  return true;
}

} // namespace

int TestStylizedStrokes(int argc, char* argv[])
{
  return Run(argc, argv) ? 0 : 1;
}
