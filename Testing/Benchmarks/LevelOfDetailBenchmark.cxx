// View-dependent level of detail (issue 18) against the full mesh and a
// uniform decimation, measured side by side in one run. The meshes are the
// Stanford bunny (Data/bunny.ply, 3,674 triangles) refined by Loop
// subdivision (levels 2, 3, 4: 58,784, 235,136 and 940,544 triangles), with
// vtkPolyDataNormals' point normals. Over an orbit, each frame is rendered by
// four windows in turn (offscreen, no multisampling):
//   full      the refined mesh, vtkPolyDataMapper
//   uniform   vtkSilhouetteQuadricDecimation of it to the LOD's mean count
//   lod       vtkViewDependentLevelOfDetail (default tolerances) + mapper
//   lod+smooth  the same, then vtkSilhouetteSmoothingFilter + mapper
// For each: triangles drawn (median), the view-dependent work before drawing
// (median ms: the LOD filter's update, or LOD and smoothing), the outline's
// distance to the full mesh's (silhouette masks: mean over frames of the
// mean, and the largest), the outline's change from the previous frame next
// to the full mesh's own, and the whole frame (median ms, camera move to
// finished drawing, the view-dependent work included) with its ratio to the
// full mesh's. The hierarchy's one-off build is printed first.
//
// --mesh FILE.ply takes another closed mesh instead of the bunny (the fidelity
// evaluation's CGAL meshes: bash scripts/real-meshes.sh).
//
// Usage: lod_benchmark [--levels 2,3,4] [--frames N] [--size WxH] [--data DIR | --mesh FILE.ply]
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteQuadricDecimation.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkViewDependentLevelOfDetail.h"

#include "BenchmarkTiming.h"
#include "SilhouetteMasks.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using benchmark_timing::Median;
using benchmark_timing::Milliseconds;

struct Options
{
  std::vector<int> Levels{ 2, 3, 4 };
  int Frames = 36;
  int Width = 1024;
  int Height = 768;
  std::string Data = SILHOUETTE_DATA_DIR;
  std::string Mesh; ///< a .ply to refine instead of DATA/bunny.ply
};

[[noreturn]] void Usage()
{
  std::fprintf(stderr,
    "usage: lod_benchmark [--levels 2,3,4] [--frames N] [--size WxH] [--data DIR | --mesh "
    "FILE.ply]\n");
  std::exit(2);
}

Options Parse(int argc, char* argv[])
{
  Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (i + 1 >= argc)
      Usage();
    const std::string value = argv[++i];
    if (arg == "--levels")
    {
      options.Levels.clear();
      std::stringstream list(value);
      std::string item;
      while (std::getline(list, item, ','))
        options.Levels.push_back(std::atoi(item.c_str()));
    }
    else if (arg == "--frames")
      options.Frames = std::atoi(value.c_str());
    else if (arg == "--size")
    {
      if (std::sscanf(value.c_str(), "%dx%d", &options.Width, &options.Height) != 2)
        Usage();
    }
    else if (arg == "--data")
      options.Data = value;
    else if (arg == "--mesh")
      options.Mesh = value;
    else
      Usage();
  }
  if (options.Frames < 2 || options.Width < 16 || options.Height < 16 || options.Levels.empty())
    Usage();
  return options;
}

std::string MeshPath(const Options& options)
{
  return options.Mesh.empty() ? options.Data + "/bunny.ply" : options.Mesh;
}

vtkSmartPointer<vtkPolyData> Refined(const std::string& path, int level)
{
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkLoopSubdivisionFilter> loop;
  loop->SetInputConnection(reader->GetOutputPort());
  loop->SetNumberOfSubdivisions(level);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(loop->GetOutputPort());
  normals->SplittingOff();
  normals->ComputeCellNormalsOff();
  normals->Update();
  if (normals->GetOutput()->GetNumberOfPolys() == 0)
  {
    std::fprintf(stderr, "lod_benchmark: cannot read %s\n", path.c_str());
    std::exit(1);
  }
  return normals->GetOutput();
}

struct Variant
{
  const char* Name;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkPolyDataMapper> Mapper;
  vtkAlgorithm* Work = nullptr; // the view-dependent filter to update first, if any
  std::vector<double> Triangles, WorkMs, FrameMs, Mean, Max, Change;
  // Where the largest distance was: frame, pixel, and whether this outline
  // lies outside the full mesh's there (else inside: a shrink or a gap).
  int WorstFrame = -1, WorstX = -1, WorstY = -1;
  bool WorstOutside = false;
  silhouette_eval::Mask Previous;
};

void SetUp(Variant& v, const Options& options)
{
  v.Window->SetOffScreenRendering(1);
  v.Window->SetMultiSamples(0);
  v.Window->SetSize(options.Width, options.Height);
  v.Window->AddRenderer(v.Renderer);
  v.Actor->SetMapper(v.Mapper);
  v.Renderer->AddActor(v.Actor);
}

void PlaceCamera(vtkCamera* camera, vtkPolyData* mesh, int frame, int frames)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double radius = 0.5 *
    std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) +
      std::pow(bounds[5] - bounds[4], 2));
  const double a = 2.0 * 3.14159265358979 * frame / frames;
  const double d = 3.0 * radius;
  camera->SetFocalPoint(center);
  camera->SetPosition(
    center[0] + d * std::cos(a), center[1] + 0.35 * d, center[2] + d * std::sin(a));
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30.0);
  camera->SetClippingRange(0.1 * d, 3.0 * d);
}

double Mean(const std::vector<double>& values)
{
  double sum = 0.0;
  for (const double v : values)
    sum += v;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

double Largest(const std::vector<double>& values)
{
  double largest = 0.0;
  for (const double v : values)
    largest = std::max(largest, v);
  return largest;
}

void Measure(Variant& v, vtkPolyData* full, int frame, int frames,
  silhouette_eval::MaskRenderer& masks, const silhouette_eval::Mask& fullMask)
{
  PlaceCamera(v.Renderer->GetActiveCamera(), full, frame, frames);
  double work = 0.0;
  const double total = Milliseconds([&] {
    if (v.Work)
      work = Milliseconds([&] { v.Work->Update(); });
    v.Window->Render();
  });
  vtkPolyData* drawn = vtkPolyData::SafeDownCast(v.Mapper->GetInput());
  v.FrameMs.push_back(total);
  v.WorkMs.push_back(work);
  v.Triangles.push_back(static_cast<double>(drawn->GetNumberOfPolys()));
  const silhouette_eval::Mask mask = masks.Render(drawn, v.Renderer->GetActiveCamera());
  const silhouette_eval::BoundaryDistance d = silhouette_eval::OutlineDeviation(mask, fullMask);
  v.Mean.push_back(d.Mean);
  if (v.Max.empty() || d.Max > Largest(v.Max))
  {
    v.WorstFrame = frame;
    v.WorstX = d.FarthestX;
    v.WorstY = d.FarthestY;
    v.WorstOutside = d.FarthestOutside;
  }
  v.Max.push_back(d.Max);
  if (!v.Previous.Covered.empty())
    v.Change.push_back(silhouette_eval::OutlineDeviation(mask, v.Previous).Mean);
  v.Previous = mask;
}

void RunLevel(const Options& options, int level)
{
  vtkSmartPointer<vtkPolyData> mesh = Refined(MeshPath(options), level);
  const vtkIdType input = mesh->GetNumberOfPolys();

  Variant full{ "full" }, uniform{ "uniform" }, lod{ "lod" }, smooth{ "lod+smooth" };
  Variant* variants[4] = { &full, &uniform, &lod, &smooth };
  for (Variant* v : variants)
    SetUp(*v, options);
  full.Mapper->SetInputData(mesh);

  vtkNew<vtkViewDependentLevelOfDetail> lodFilter;
  lodFilter->SetInputData(mesh);
  lodFilter->SetRenderer(lod.Renderer);
  const double buildMs = Milliseconds([&] {
    PlaceCamera(lod.Renderer->GetActiveCamera(), mesh, 0, options.Frames);
    lodFilter->Update();
  });
  lod.Mapper->SetInputConnection(lodFilter->GetOutputPort());
  lod.Work = lodFilter;

  vtkNew<vtkViewDependentLevelOfDetail> lodForSmoothing;
  lodForSmoothing->SetInputData(mesh);
  lodForSmoothing->SetRenderer(smooth.Renderer);
  vtkNew<vtkSilhouetteSmoothingFilter> smoothing;
  smoothing->SetInputConnection(lodForSmoothing->GetOutputPort());
  smoothing->SetRenderer(smooth.Renderer);
  smooth.Mapper->SetInputConnection(smoothing->GetOutputPort());
  smooth.Work = smoothing;

  // The uniform decimation gets the LOD's mean count over the orbit.
  double counted = 0.0;
  for (int frame = 0; frame < options.Frames; ++frame)
  {
    PlaceCamera(lod.Renderer->GetActiveCamera(), mesh, frame, options.Frames);
    lodFilter->Update();
    counted += static_cast<double>(lodFilter->GetOutput()->GetNumberOfPolys());
  }
  vtkNew<vtkSilhouetteQuadricDecimation> decimation;
  decimation->SetInputData(mesh);
  decimation->SetTargetTriangles(static_cast<vtkIdType>(counted / options.Frames));
  decimation->Update();
  uniform.Mapper->SetInputConnection(decimation->GetOutputPort());

  std::printf("\n%s, Loop level %d: %lld triangles; hierarchy built in %.0f ms "
              "(simplification, splits, first cut)\n",
    MeshPath(options).c_str(), level, static_cast<long long>(input), buildMs);
  silhouette_eval::MaskRenderer masks(options.Width, options.Height);
  for (int frame = 0; frame < options.Frames; ++frame)
  {
    PlaceCamera(full.Renderer->GetActiveCamera(), mesh, frame, options.Frames);
    const silhouette_eval::Mask fullMask = masks.Render(mesh, full.Renderer->GetActiveCamera());
    for (Variant* v : variants)
      Measure(*v, mesh, frame, options.Frames, masks, fullMask);
  }
  const double fullFrame = Median(full.FrameMs);
  std::printf("%-11s %10s %10s %10s %9s %12s %10s %8s\n", "", "triangles", "work ms", "mean px",
    "max px", "change px", "frame ms", "x full");
  for (Variant* v : variants)
  {
    std::printf("%-11s %10.0f %10.2f %10.3f %9.1f %12.3f %10.1f %8.2f\n", v->Name,
      Median(v->Triangles), Median(v->WorkMs), Mean(v->Mean), Largest(v->Max), Mean(v->Change),
      Median(v->FrameMs), Median(v->FrameMs) / fullFrame);
  }
  for (Variant* v : variants)
  {
    if (v != &full && v->WorstFrame >= 0)
      std::printf("%s: largest distance at frame %d, pixel (%d, %d) from the bottom left, %s the "
                  "full mesh's outline\n",
        v->Name, v->WorstFrame, v->WorstX, v->WorstY, v->WorstOutside ? "outside" : "inside");
  }
}

} // namespace

int main(int argc, char* argv[])
{
  const Options options = Parse(argc, argv);
  std::printf("lod_benchmark: %d frames of an orbit at %dx%d; medians over the frames\n",
    options.Frames, options.Width, options.Height);
  for (const int level : options.Levels)
    RunLevel(options, level);
  return 0;
}
