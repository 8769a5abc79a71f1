#include "SilhouetteComparison.h"

#include "SilhouetteMasks.h"

#include "vtkActor.h"
#include "vtkBoundaryCurveSmoothingFilter.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNTriangleFilter.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
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

// The exact outline of a model, to measure masks against, view by view: the
// unit sphere's projected circle in closed form, or the outline of the mask
// of its exact surface's stand-in (ExactSurface: a very fine sampling of the
// analytic surface), rendered once per view and kept.
class ExactOutline
{
public:
  ExactOutline(const ModelVersions& model, const ComparisonOptions& options)
    : Shape(model.Exact)
    , Width(options.Width)
    , Height(options.Height)
    , Surface(model.Exact == ExactShape::Surface ? ExactSurface(model.Name) : nullptr)
  {
  }

  bool Exists() const { return this->Shape != ExactShape::None; }

  /// Makes the view-th camera's outline the current one (`camera` is that
  /// camera; the stand-in is rendered the first time a view is asked for).
  void SetView(MaskRenderer& masks, int view, vtkCamera* camera)
  {
    this->View = view;
    if (this->Shape == ExactShape::UnitSphere)
    {
      // Eye at distance d from the centre: the contour's projection is a
      // circle of radius tan(asin(1 / d)) / tan(angle / 2) * height / 2.
      this->Radius = std::tan(std::asin(1.0 / camera->GetDistance())) /
        std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle() / 2.0)) * this->Height / 2.0;
    }
    else if (this->Shape == ExactShape::Surface && this->SurfaceMasks.count(view) == 0)
    {
      this->SurfaceMasks.emplace(view, masks.Render(this->Surface, camera));
    }
  }

  /// The distance of `mask`'s outline to the current view's exact outline.
  BoundaryDistance From(const Mask& mask) const
  {
    return this->Shape == ExactShape::UnitSphere
      ? DistanceToCircle(mask, this->Width / 2.0, this->Height / 2.0, this->Radius)
      : OutlineDeviation(mask, this->SurfaceMasks.at(this->View));
  }

private:
  ExactShape Shape;
  int Width;
  int Height;
  vtkSmartPointer<vtkPolyData> Surface;
  std::map<int, Mask> SurfaceMasks;
  int View = -1;
  double Radius = 0.0;
};

} // namespace

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

int NearestPNLevel(double triangles, double target)
{
  int best = 1;
  for (int k = 2; k <= 16; ++k)
  {
    if (std::abs(triangles * (k + 1) * (k + 1) - target) <
      std::abs(triangles * (best + 1) * (best + 1) - target))
    {
      best = k;
    }
  }
  return best;
}

FrameTiming OrbitTimer::Time(vtkPolyData* mesh, FrameFilter filter)
{
  vtkRenderer* renderer = this->Renderer;
  renderer->RemoveAllViewProps();
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  vtkNew<vtkBoundaryCurveSmoothingFilter> curves;
  vtkPolyDataAlgorithm* running = nullptr;
  if (filter == FrameFilter::Smoothing2008)
  {
    smoother->SetInputData(mesh);
    smoother->SetRenderer(renderer);
    smoother->SetTolerance(this->Options.Tolerance);
    running = smoother;
  }
  else if (filter == FrameFilter::BoundaryCurves2003)
  {
    curves->SetInputData(mesh);
    curves->SetRenderer(renderer);
    curves->SetTolerance(this->Options.Tolerance);
    running = curves;
  }
  if (running)
  {
    mapper->SetInputConnection(running->GetOutputPort());
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
    if (running)
    {
      running->Update();
      filterMs.push_back(Since(start));
    }
    this->Window->Render();
    this->Window->WaitForCompletion();
    frameMs.push_back(Since(start));
  }
  FrameTiming timing;
  timing.FrameMilliseconds = Median(frameMs);
  timing.FilterMilliseconds = Median(filterMs);
  timing.Triangles = running ? Count(running->GetOutput(), "OutputTriangleCount")
                             : static_cast<double>(mesh->GetNumberOfPolys());
  renderer->RemoveAllViewProps();
  return timing;
}

namespace
{

// PN triangles at result.PNLevel (view-independent: made once, its time is
// the one-off tessellation), measured from the views.
vtkSmartPointer<vtkPolyData> MeasurePN(const ModelVersions& model, const ComparisonOptions& options,
  MaskRenderer& masks, vtkRenderer* framing, ExactOutline& exact, ModelComparison& result)
{
  vtkNew<vtkPNTriangleFilter> pnFilter;
  pnFilter->SetInputData(model.Coarse);
  pnFilter->SetLevel(result.PNLevel);
  const Clock::time_point pnStart = Clock::now();
  pnFilter->Update();
  result.PN.FilterMilliseconds = Since(pnStart);
  vtkSmartPointer<vtkPolyData> pn = pnFilter->GetOutput();
  result.PN.Triangles = static_cast<double>(pn->GetNumberOfPolys());
  for (int view = 0; view < options.Views; ++view)
  {
    PlaceCamera(framing, model.Original, view, options.Views);
    vtkCamera* camera = framing->GetActiveCamera();
    const Mask fine = masks.Render(model.Fine, camera);
    const Mask pnMask = masks.Render(pn, camera);
    Accumulate(result.PN, OutlineDeviation(pnMask, fine), false, options.Views);
    if (exact.Exists())
    {
      exact.SetView(masks, view, camera);
      Accumulate(result.PN, exact.From(pnMask), true, options.Views);
    }
  }
  return pn;
}

// Temporal coherence: an orbit of 1-degree steps from the first view; every
// variant's outline is compared with its own outline one step before.
void MeasureCoherence(const ModelVersions& model, const ComparisonOptions& options,
  MaskRenderer& masks, vtkRenderer* framing, vtkSilhouetteSmoothingFilter* smoother,
  vtkBoundaryCurveSmoothingFilter* curves, vtkPolyData* pn, ModelComparison& result)
{
  VariantFigures* figures[5] = { &result.Coarse, &result.Smoothed, &result.Wang2003, &result.PN,
    &result.Fine };
  std::array<Mask, 5> previous;
  std::array<double, 5> sum{};
  std::array<double, 5> largest{};
  std::array<double, 5> excess{};
  std::array<double, 5> stepMax{};
  PlaceCamera(framing, model.Original, 0, 1);
  for (int step = 0; step <= options.CoherenceSteps; ++step)
  {
    vtkCamera* camera = framing->GetActiveCamera();
    if (step > 0)
    {
      camera->Azimuth(1.0);
      framing->ResetCameraClippingRange();
    }
    smoother->Update();
    curves->Update();
    vtkPolyData* meshes[5] = { model.Coarse, smoother->GetOutput(), curves->GetOutput(), pn,
      model.Fine };
    for (int v = 0; v < 5; ++v)
    {
      Mask current = masks.Render(meshes[v], camera);
      if (step > 0)
      {
        const BoundaryDistance change = OutlineDeviation(previous[v], current);
        sum[v] += change.Mean;
        largest[v] = std::max(largest[v], change.Max);
        stepMax[v] = change.Max;
      }
      previous[v] = std::move(current);
    }
    for (int v = 0; step > 0 && v < 5; ++v)
    {
      excess[v] = std::max(excess[v], stepMax[v] - stepMax[4]);
    }
  }
  for (int v = 0; v < 5; ++v)
  {
    figures[v]->CoherenceMean = sum[v] / options.CoherenceSteps;
    figures[v]->CoherenceMax = largest[v];
    figures[v]->CoherenceExcess = excess[v];
  }
  for (int v = 0; v < 5; ++v)
  {
    figures[v]->CoherenceRatio =
      result.Fine.CoherenceMean > 0 ? figures[v]->CoherenceMean / result.Fine.CoherenceMean : -1;
  }
}

// The whole frame of each variant over an orbit.
void TimeVariants(const ModelVersions& model, const ComparisonOptions& options, vtkPolyData* pn,
  ModelComparison& result)
{
  OrbitTimer timer(options);
  for (auto [mesh, filter, figures] :
    { std::make_tuple(model.Coarse.Get(), FrameFilter::None, &result.Coarse),
      std::make_tuple(model.Coarse.Get(), FrameFilter::Smoothing2008, &result.Smoothed),
      std::make_tuple(model.Coarse.Get(), FrameFilter::BoundaryCurves2003, &result.Wang2003),
      std::make_tuple(pn, FrameFilter::None, &result.PN),
      std::make_tuple(model.Fine.Get(), FrameFilter::None, &result.Fine) })
  {
    const FrameTiming timing = timer.Time(mesh, filter);
    figures->FrameMilliseconds = timing.FrameMilliseconds;
    if (filter != FrameFilter::None)
    {
      figures->FilterMilliseconds = timing.FilterMilliseconds;
    }
  }
}

} // namespace

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
  vtkNew<vtkBoundaryCurveSmoothingFilter> curves; // Wang et al. 2003
  curves->SetInputData(model.Coarse);
  curves->SetCamera(framing->GetActiveCamera());
  curves->SetViewportSize(options.Width, options.Height);
  curves->SetTolerance(options.Tolerance);

  ExactOutline exact(model, options);

  progress("measuring outlines from " + std::to_string(options.Views) + " views");
  for (int view = 0; view < options.Views; ++view)
  {
    PlaceCamera(framing, model.Original, view, options.Views);
    vtkCamera* camera = framing->GetActiveCamera();
    smoother->Update();
    curves->Update();
    const Mask fine = masks.Render(model.Fine, camera);
    const Mask coarse = masks.Render(model.Coarse, camera);
    const Mask smoothed = masks.Render(smoother->GetOutput(), camera);
    const Mask wang2003 = masks.Render(curves->GetOutput(), camera);
    Accumulate(result.Coarse, OutlineDeviation(coarse, fine), false, options.Views);
    Accumulate(result.Smoothed, OutlineDeviation(smoothed, fine), false, options.Views);
    Accumulate(result.Wang2003, OutlineDeviation(wang2003, fine), false, options.Views);
    result.Wang2003.Triangles += Count(curves->GetOutput(), "OutputTriangleCount") / options.Views;
    result.Smoothed.Triangles +=
      Count(smoother->GetOutput(), "OutputTriangleCount") / options.Views;
    result.SilhouetteTriangles +=
      Count(smoother->GetOutput(), "SilhouetteTriangleCount") / options.Views;

    if (exact.Exists())
    {
      exact.SetView(masks, view, camera);
      for (const auto& [figures, mask] :
        { std::make_pair(&result.Coarse, &coarse), std::make_pair(&result.Smoothed, &smoothed),
          std::make_pair(&result.Wang2003, &wang2003), std::make_pair(&result.Fine, &fine) })
      {
        Accumulate(*figures, exact.From(*mask), true, options.Views);
      }
    }
  }
  result.Coarse.Triangles = static_cast<double>(model.Coarse->GetNumberOfPolys());
  result.Fine.Triangles = static_cast<double>(model.Fine->GetNumberOfPolys());

  result.PNLevel = NearestPNLevel(result.Coarse.Triangles, result.Smoothed.Triangles);
  progress("PN triangles at level " + std::to_string(result.PNLevel));
  vtkSmartPointer<vtkPolyData> pn = MeasurePN(model, options, masks, framing, exact, result);
  if (options.CoherenceSteps > 0)
  {
    progress("coherence over " + std::to_string(options.CoherenceSteps) + " 1-degree steps");
    MeasureCoherence(model, options, masks, framing, smoother, curves, pn, result);
  }
  progress("timing " + std::to_string(options.TimedFrames) + " orbit frames of each variant");
  TimeVariants(model, options, pn, result);
  return result;
}

} // namespace silhouette_eval
