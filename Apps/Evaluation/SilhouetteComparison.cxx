#include "SilhouetteComparison.h"

#include "SilhouetteMasks.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkTorusSurfaceSource.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>
#include <vector>

namespace silhouette_eval
{
namespace
{

using Clock = std::chrono::steady_clock;

double Since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The view-th camera of an orbit around the model: the framing camera turned
// by azimuth, with the elevation swinging between -25 and +25 degrees.
void PlaceCamera(vtkRenderer* renderer, vtkPolyData* mesh, int view, int views)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 1);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  renderer->ResetCamera(mesh->GetBounds());
  camera->Azimuth(360.0 * view / views);
  camera->Elevation(25.0 * std::sin(2.0 * vtkMath::Pi() * view / views));
  camera->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();
}

void Accumulate(VariantFigures& figures, const BoundaryDistance& d, bool exact, int views)
{
  double& mean = exact ? figures.MeanExact : figures.MeanDeviation;
  double& max = exact ? figures.MaxExact : figures.MaxDeviation;
  if (mean < 0)
  {
    mean = 0;
    max = 0;
  }
  mean += d.Mean / views;
  max = std::max(max, d.Max);
}

double Count(vtkPolyData* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : 0.0;
}

} // namespace

OrbitTimer::OrbitTimer(const ComparisonOptions& options)
  : Options(options)
  , Window(vtkSmartPointer<vtkRenderWindow>::New())
  , Renderer(vtkSmartPointer<vtkRenderer>::New())
{
  this->Window->SetOffScreenRendering(1);
  this->Window->SetMultiSamples(0);
  this->Window->SetSize(options.Width, options.Height);
  this->Renderer->SetBackground(1, 1, 1);
  this->Window->AddRenderer(this->Renderer);
}

OrbitTimer::~OrbitTimer() = default;

FrameTiming OrbitTimer::Time(vtkPolyData* mesh, bool smoothing)
{
  vtkRenderer* renderer = this->Renderer;
  renderer->RemoveAllViewProps();
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  if (smoothing)
  {
    smoother->SetInputData(mesh);
    smoother->SetRenderer(renderer);
    smoother->SetTolerance(this->Options.Tolerance);
    mapper->SetInputConnection(smoother->GetOutputPort());
  }
  else
  {
    mapper->SetInputData(mesh);
  }
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.8, 0.8, 0.82);
  renderer->AddActor(actor);
  PlaceCamera(renderer, mesh, 0, 1);
  this->Window->Render(); // first frame: caches, shaders, buffer upload
  this->Window->WaitForCompletion();

  std::vector<double> frameMs, filterMs;
  for (int frame = 1; frame <= this->Options.TimedFrames; ++frame)
  {
    const Clock::time_point start = Clock::now();
    renderer->GetActiveCamera()->Azimuth(360.0 / this->Options.TimedFrames);
    renderer->ResetCameraClippingRange();
    if (smoothing)
    {
      smoother->Update();
      filterMs.push_back(Since(start));
    }
    this->Window->Render();
    this->Window->WaitForCompletion();
    frameMs.push_back(Since(start));
  }
  FrameTiming timing;
  timing.FrameMilliseconds = Median(frameMs);
  timing.FilterMilliseconds = Median(filterMs);
  timing.Triangles = smoothing ? Count(smoother->GetOutput(), "OutputTriangleCount")
                               : static_cast<double>(mesh->GetNumberOfPolys());
  renderer->RemoveAllViewProps();
  return timing;
}

ModelComparison CompareModel(const ModelVersions& model, const ComparisonOptions& options)
{
  auto progress = [&](const std::string& what) {
    if (options.Progress)
    {
      options.Progress(model.Name + ": " + what);
    }
  };
  ModelComparison result;
  result.Name = model.Name;
  result.Description = model.Description;
  result.OriginalTriangles = static_cast<long>(model.Original->GetNumberOfPolys());

  MaskRenderer masks(options.Width, options.Height);
  vtkNew<vtkRenderer> framing; // only to place cameras with the right aspect
  vtkNew<vtkRenderWindow> framingWindow;
  framingWindow->SetOffScreenRendering(1);
  framingWindow->SetSize(options.Width, options.Height);
  framingWindow->AddRenderer(framing);

  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(model.Coarse);
  smoother->SetCamera(framing->GetActiveCamera());
  smoother->SetViewportSize(options.Width, options.Height);
  smoother->SetTolerance(options.Tolerance);

  vtkSmartPointer<vtkPolyData> exactTorus;
  if (model.Exact == ExactShape::Torus)
  {
    vtkNew<vtkTorusSurfaceSource> torus;
    torus->SetRingResolution(720);
    torus->SetTubeResolution(360);
    torus->Update();
    exactTorus = torus->GetOutput();
  }

  progress("measuring outlines from " + std::to_string(options.Views) + " views");
  for (int view = 0; view < options.Views; ++view)
  {
    PlaceCamera(framing, model.Original, view, options.Views);
    vtkCamera* camera = framing->GetActiveCamera();
    smoother->Update();
    const Mask fine = masks.Render(model.Fine, camera);
    const Mask coarse = masks.Render(model.Coarse, camera);
    const Mask smoothed = masks.Render(smoother->GetOutput(), camera);
    Accumulate(result.Coarse, OutlineDeviation(coarse, fine), false, options.Views);
    Accumulate(result.Smoothed, OutlineDeviation(smoothed, fine), false, options.Views);
    result.Smoothed.Triangles +=
      Count(smoother->GetOutput(), "OutputTriangleCount") / options.Views;
    result.SilhouetteTriangles +=
      Count(smoother->GetOutput(), "SilhouetteTriangleCount") / options.Views;

    if (model.Exact == ExactShape::UnitSphere)
    {
      // Eye at distance d from the centre: the contour's projection is a
      // circle of radius tan(asin(1 / d)) / tan(angle / 2) * height / 2.
      const double d = camera->GetDistance();
      const double radius = std::tan(std::asin(1.0 / d)) /
        std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle() / 2.0)) * options.Height / 2.0;
      const double cx = options.Width / 2.0;
      const double cy = options.Height / 2.0;
      Accumulate(result.Coarse, DistanceToCircle(coarse, cx, cy, radius), true, options.Views);
      Accumulate(result.Smoothed, DistanceToCircle(smoothed, cx, cy, radius), true, options.Views);
      Accumulate(result.Fine, DistanceToCircle(fine, cx, cy, radius), true, options.Views);
    }
    else if (model.Exact == ExactShape::Torus)
    {
      const Mask exact = masks.Render(exactTorus, camera);
      Accumulate(result.Coarse, OutlineDeviation(coarse, exact), true, options.Views);
      Accumulate(result.Smoothed, OutlineDeviation(smoothed, exact), true, options.Views);
      Accumulate(result.Fine, OutlineDeviation(fine, exact), true, options.Views);
    }
  }
  result.Coarse.Triangles = static_cast<double>(model.Coarse->GetNumberOfPolys());
  result.Fine.Triangles = static_cast<double>(model.Fine->GetNumberOfPolys());

  progress("timing " + std::to_string(options.TimedFrames) + " orbit frames of each variant");
  OrbitTimer timer(options);
  for (auto [mesh, smoothing, figures] :
    { std::make_tuple(model.Coarse.Get(), false, &result.Coarse),
      std::make_tuple(model.Coarse.Get(), true, &result.Smoothed),
      std::make_tuple(model.Fine.Get(), false, &result.Fine) })
  {
    const FrameTiming timing = timer.Time(mesh, smoothing);
    figures->FrameMilliseconds = timing.FrameMilliseconds;
    figures->FilterMilliseconds = timing.FilterMilliseconds;
  }
  return result;
}

} // namespace silhouette_eval
