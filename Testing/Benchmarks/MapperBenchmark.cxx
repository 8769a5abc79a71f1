// Render-time smoothing against the alternatives (issue 15), measured side
// by side in one run: over an orbit, each frame is rendered by four
// windows in turn, with
//   plain   the mesh drawn by vtkPolyDataMapper (no smoothing),
//   mapper  vtkSilhouetteSmoothingMapper (which leaves out the silhouette
//           triangles whose smoothing would move the image by less than the
//           tolerance, SkipSubpixelSmoothing: on these spheres, all of them),
//   mapall  the mapper smoothing every silhouette triangle (that option off),
//   filter  vtkSilhouetteSmoothingFilter + vtkPolyDataMapper,
// on icospheres of about 80k, 330k and 1.3M triangles, offscreen, without
// multisampling. For each it prints the median whole frame (camera move,
// render, wait for completion) and its ratio to plain's, and the median
// time of the smoothing's own work before drawing: the mapper's
// GetLastPrepareSeconds, and the filter's Update. The per-frame upload of
// the filter's output is part of its frame, not of this column. Then the
// slowest frame of each (a frame that waited for a one-time build), and the
// mapper's first four frames with their smoothing, where the whole-mesh
// indexes' builds start (on threads of their own).
//
// Then a deforming mesh (new points every frame, the same cells, as a time
// series gives), with the camera still: the plain mapper; the mapper, which
// keeps the topology (WeldedSurface::movePoints) and its index buffers; and
// the mapper made to build everything anew every frame (its cells changed
// too: one triangle's corners turned round), which is what every such frame
// cost before. Each frame stretches
// the mesh along x by 1 + S and back, S = --deform-step (0.01 unless given):
// a small step lets the fold guard keep its grid of the triangles' boxes
// from frame to frame (PreparedMesh::adoptTriangleGrid), a large one does
// not. Besides the whole frame and its ratio to building anew, it prints the
// smoothing mappers' own work before drawing (GetLastPrepareSeconds: the
// preparation and the view's changes; the upload is the drawing's) and its
// ratio to that of building anew. The first three deforming frames are
// rendered but not counted (one-off work: the kept buffers' first fill, the
// fold guard's grid).
//
// Then new point values every frame on the still mesh (a time series of
// values): the plain mapper colouring by them, the mapper (whose patches
// take the new values without smoothing again) and the mapper made to build
// everything anew, with the same columns. Both still-camera sections also
// run filter + vtkPolyDataMapper ("filter"; its smoothing column is the
// filter's update).
//
// Usage: mapper_benchmark [--frames N] [--levels L1,L2,...] [--size WxH]
//                         [--deform-step S]
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIcosphereSource.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSilhouetteSmoothingMapper.h"

#include "BenchmarkTiming.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace
{

struct Options
{
  int Frames = 20;
  std::vector<int> Levels{ 6, 7, 8 };
  int Width = 1024;
  int Height = 768;
  double DeformStep = 0.01;
};

void Usage()
{
  std::fprintf(stderr,
    "usage: mapper_benchmark [--frames N] [--levels 6,7,8] [--size WxH] [--deform-step S]\n");
  std::exit(2);
}

Options ParseOptions(int argc, char* argv[])
{
  Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (i + 1 >= argc)
    {
      Usage();
    }
    const std::string value = argv[++i];
    if (option == "--frames")
    {
      options.Frames = std::atoi(value.c_str());
    }
    else if (option == "--levels")
    {
      options.Levels.clear();
      std::stringstream list(value);
      std::string item;
      while (std::getline(list, item, ','))
      {
        options.Levels.push_back(std::atoi(item.c_str()));
      }
    }
    else if (option == "--deform-step")
    {
      options.DeformStep = std::atof(value.c_str());
    }
    else if (option == "--size")
    {
      if (std::sscanf(value.c_str(), "%dx%d", &options.Width, &options.Height) != 2)
      {
        Usage();
      }
    }
    else
    {
      Usage();
    }
  }
  if (options.Frames < 1 || options.Levels.empty() || options.Width < 16 || options.Height < 16 ||
    !(options.DeformStep > 0.0 && options.DeformStep < 1.0))
  {
    Usage();
  }
  return options;
}

// One window of the comparison: offscreen, no multisampling, the camera
// fitted to the mesh and raised 20 degrees; rendered once (uploads, and a
// filter's first run).
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;

  void SetUp(vtkPolyData* mesh, const Options& options)
  {
    this->Window->SetSize(options.Width, options.Height);
    this->Window->SetMultiSamples(0);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->ResetCamera(mesh->GetBounds());
    this->Renderer->GetActiveCamera()->Elevation(20.0);
    this->Renderer->GetActiveCamera()->OrthogonalizeViewUp();
    this->Window->Render();
    this->Window->WaitForCompletion();
  }
};

struct Variant : Scene
{
  const char* Name;
  std::vector<double> FrameMs;
  std::vector<double> PrepareMs;

  explicit Variant(const char* name)
    : Name(name)
  {
  }
};

// The orbit: plain, mapper, mapall and filter + mapper, frame by frame in turn.
void MeasureOrbit(vtkPolyData* mesh, const Options& options)
{
  Variant plain("plain");
  Variant mapper("mapper");
  Variant filtered("filter");
  vtkNew<vtkPolyDataMapper> plainMapper;
  plainMapper->SetInputData(mesh);
  plainMapper->ScalarVisibilityOff();
  plain.Actor->SetMapper(plainMapper);
  vtkNew<vtkSilhouetteSmoothingMapper> smoothingMapper;
  smoothingMapper->SetInputData(mesh);
  smoothingMapper->ScalarVisibilityOff();
  mapper.Actor->SetMapper(smoothingMapper);
  Variant every("mapall");
  vtkNew<vtkSilhouetteSmoothingMapper> everyMapper;
  everyMapper->SetInputData(mesh);
  everyMapper->ScalarVisibilityOff();
  everyMapper->GetSmoothingFilter()->SkipSubpixelSmoothingOff();
  every.Actor->SetMapper(everyMapper);
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  filter->SetInputData(mesh);
  filter->SetRenderer(filtered.Renderer);
  filter->SetProp3D(filtered.Actor);
  vtkNew<vtkPolyDataMapper> filterMapper;
  filterMapper->SetInputConnection(filter->GetOutputPort());
  filterMapper->ScalarVisibilityOff();
  filtered.Actor->SetMapper(filterMapper);
  Variant* variants[4] = { &plain, &mapper, &every, &filtered };
  for (Variant* v : variants)
  {
    v->SetUp(mesh, options);
  }
  for (int f = 0; f < options.Frames; ++f)
  {
    for (Variant* v : variants)
    {
      double prepare = 0.0;
      const double frame = benchmark_timing::Milliseconds([&]() {
        v->Renderer->GetActiveCamera()->Azimuth(2.0);
        if (v == &filtered)
        {
          prepare = benchmark_timing::Milliseconds([&]() { filter->Update(); });
        }
        v->Window->Render();
        v->Window->WaitForCompletion();
      });
      if (v == &mapper || v == &every)
      {
        prepare = 1000.0 *
          (v == &mapper ? smoothingMapper.Get() : everyMapper.Get())->GetLastPrepareSeconds();
      }
      v->FrameMs.push_back(frame);
      v->PrepareMs.push_back(prepare);
    }
  }
  const double plainMs = benchmark_timing::Median(plain.FrameMs);
  for (Variant* v : variants)
  {
    const double ms = benchmark_timing::Median(v->FrameMs);
    char smoothing[32] = "-";
    if (v != &plain)
    {
      std::snprintf(smoothing, sizeof(smoothing), "%.2f", benchmark_timing::Median(v->PrepareMs));
    }
    std::printf("%10lld  %-7s %10.1f %10.2f %12s\n",
      static_cast<long long>(mesh->GetNumberOfPolys()), v->Name, ms, ms / plainMs, smoothing);
  }
  std::printf("%10s  mapper: %lld triangles replaced by %lld in the last frame, %lld silhouette"
              " triangles left as they are (sub-pixel); mapall: %lld replaced by %lld\n",
    "", static_cast<long long>(smoothingMapper->GetReplacedTriangleCount()),
    static_cast<long long>(smoothingMapper->GetPatchTriangleCount()),
    static_cast<long long>(smoothingMapper->GetSubpixelTriangleCount()),
    static_cast<long long>(everyMapper->GetReplacedTriangleCount()),
    static_cast<long long>(everyMapper->GetPatchTriangleCount()));
  // The orbit's first frame is the mesh's second view, where the
  // silhouette triangle tree's build starts (on a thread of its own, so no
  // frame should stand out).
  std::printf("%10s  slowest frame: plain %.1f, mapper %.1f, mapall %.1f, filter %.1f\n", "",
    *std::max_element(plain.FrameMs.begin(), plain.FrameMs.end()),
    *std::max_element(mapper.FrameMs.begin(), mapper.FrameMs.end()),
    *std::max_element(every.FrameMs.begin(), every.FrameMs.end()),
    *std::max_element(filtered.FrameMs.begin(), filtered.FrameMs.end()));
  std::printf("%10s  mapper's first frames (smoothing):", "");
  for (std::size_t f = 0; f < mapper.FrameMs.size() && f < 4; ++f)
  {
    std::printf(" %.1f (%.1f)", mapper.FrameMs[f], mapper.PrepareMs[f]);
  }
  std::printf("\n");
  std::fflush(stdout);
}

// The deforming mesh: each variant moves the points of its own copy.
struct Deforming : Scene
{
  const char* Name;
  bool Rebuild;
  vtkNew<vtkPolyData> Mesh;
  vtkSilhouetteSmoothingMapper* Smoothing = nullptr; // null for the plain mapper
  vtkSilhouetteSmoothingFilter* Filter = nullptr;    // for filter + plain mapper
  std::vector<double> FrameMs;
  std::vector<double> PrepareMs;

  Deforming(const char* name, bool rebuild)
    : Name(name)
    , Rebuild(rebuild)
  {
  }

  // Stretches the copy along x by `scale` and renders it.
  double Frame(double scale)
  {
    return this->Render([&]() {
      vtkPoints* points = this->Mesh->GetPoints();
      for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
      {
        double x[3];
        points->GetPoint(p, x);
        points->SetPoint(p, x[0] * scale, x[1], x[2]);
      }
      points->Modified();
    });
  }

  // Writes new point values (a wave along x, shifted by `frame`) and renders
  // the mesh.
  double Recolour(int frame)
  {
    return this->Render([&]() {
      vtkDataArray* values = this->Mesh->GetPointData()->GetScalars();
      for (vtkIdType p = 0; p < values->GetNumberOfTuples(); ++p)
      {
        double x[3];
        this->Mesh->GetPoint(p, x);
        values->SetTuple1(p, std::sin(8.0 * x[0] + 0.3 * frame));
      }
      values->Modified();
    });
  }

  // The frame's time: `change`, then the render; with Rebuild, the cells
  // change too (the same triangles, so the same image).
  template<typename ChangeMesh>
  double Render(ChangeMesh change)
  {
    double filterMs = 0.0;
    const double ms = benchmark_timing::Milliseconds([&]() {
      change();
      if (this->Rebuild)
      {
        // New cells: the first triangle's corners turned round (the same
        // triangle, other bytes), since the cells count by their contents.
        vtkCellArray* polys = this->Mesh->GetPolys();
        vtkIdType size = 0;
        const vtkIdType* ids = nullptr;
        polys->GetCellAtId(0, size, ids);
        std::vector<vtkIdType> turned(ids, ids + size);
        std::rotate(turned.begin(), turned.begin() + 1, turned.end());
        polys->ReplaceCellAtId(0, size, turned.data());
        polys->Modified();
      }
      if (this->Filter)
      {
        filterMs = benchmark_timing::Milliseconds([&]() { this->Filter->Update(); });
      }
      this->Window->Render();
      this->Window->WaitForCompletion();
    });
    if (this->Smoothing)
    {
      this->PrepareMs.push_back(1000.0 * this->Smoothing->GetLastPrepareSeconds());
    }
    if (this->Filter)
    {
      this->PrepareMs.push_back(filterMs);
    }
    return ms;
  }
};

// What changes each frame of the still camera's measures.
enum class Change
{
  Points, // the mesh deforms
  Values  // new point values on the still mesh
};

// Plain, mapper and anew under `change`, frame by frame in turn.
void MeasureChanges(vtkPolyData* mesh, const Options& options, Change change)
{
  Deforming still("plain", false);
  Deforming smoothing("mapper", false);
  Deforming filtered("filter", false);
  Deforming anew("anew", true);
  Deforming* variants[4] = { &still, &smoothing, &filtered, &anew };
  vtkNew<vtkPolyDataMapper> stillMapper;
  vtkNew<vtkSilhouetteSmoothingMapper> smoothingMapper;
  vtkNew<vtkPolyDataMapper> filterMapper;
  vtkNew<vtkSilhouetteSmoothingMapper> anewMapper;
  vtkPolyDataMapper* mappers[4] = { stillMapper, smoothingMapper, filterMapper, anewMapper };
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  for (int k = 0; k < 4; ++k)
  {
    Deforming* d = variants[k];
    d->Mesh->DeepCopy(mesh);
    if (d == &filtered)
    {
      filter->SetInputData(d->Mesh);
      filter->SetRenderer(d->Renderer);
      filter->SetProp3D(d->Actor);
      filterMapper->SetInputConnection(filter->GetOutputPort());
      d->Filter = filter;
    }
    else
    {
      mappers[k]->SetInputData(d->Mesh);
    }
    mappers[k]->ScalarVisibilityOff();
    if (change == Change::Values)
    {
      vtkNew<vtkFloatArray> values;
      values->SetName("Values");
      values->SetNumberOfValues(mesh->GetNumberOfPoints());
      values->FillValue(0.0f);
      d->Mesh->GetPointData()->SetScalars(values);
      mappers[k]->ScalarVisibilityOn();
      mappers[k]->SetScalarModeToUsePointData();
      mappers[k]->SetScalarRange(-1.0, 1.0);
    }
    d->Smoothing = vtkSilhouetteSmoothingMapper::SafeDownCast(mappers[k]);
    d->Actor->SetMapper(mappers[k]);
    d->SetUp(mesh, options);
  }
  // The first changes do one-off work (the kept buffers' first fill, the
  // fold guard's grid on the second frame): rendered, not counted, so the
  // medians are the steady frames a time series pays.
  const int warmUpFrames = 3;
  const int changeFrames = std::max(5, options.Frames / 2);
  for (int f = 0; f < warmUpFrames + changeFrames; ++f)
  {
    const double scale = f % 2 == 0 ? 1.0 + options.DeformStep : 1.0 / (1.0 + options.DeformStep);
    for (Deforming* d : variants)
    {
      const double ms = change == Change::Points ? d->Frame(scale) : d->Recolour(f);
      if (f < warmUpFrames)
      {
        d->PrepareMs.clear();
        continue;
      }
      d->FrameMs.push_back(ms);
    }
  }
  const double anewMs = benchmark_timing::Median(anew.FrameMs);
  const double stillMs = benchmark_timing::Median(still.FrameMs);
  const double anewPrepareMs = benchmark_timing::Median(anew.PrepareMs);
  for (Deforming* d : variants)
  {
    const double ms = benchmark_timing::Median(d->FrameMs);
    char work[32] = "-";
    char preparation[48] = "";
    if (d->Smoothing || d->Filter)
    {
      const double prepareMs = benchmark_timing::Median(d->PrepareMs);
      std::snprintf(work, sizeof(work), "%.2f", prepareMs);
    }
    if (d->Smoothing)
    {
      std::snprintf(preparation, sizeof(preparation), "; smoothing / anew's %.2f",
        benchmark_timing::Median(d->PrepareMs) / anewPrepareMs);
    }
    std::printf("%10lld  %-7s %10.1f %10.2f %12s   %s; / anew %.2f%s\n",
      static_cast<long long>(mesh->GetNumberOfPolys()), d->Name, ms, ms / stillMs, work,
      change == Change::Points ? "deforming" : "new values", ms / anewMs, preparation);
  }
  std::fflush(stdout);
}

} // namespace

int main(int argc, char* argv[])
{
  const Options options = ParseOptions(argc, argv);
  std::printf("%d frames of a 2-degree orbit, %dx%d offscreen; %d deforming frames (after 3 not"
              " counted) stretch by %g; medians in ms\n",
    options.Frames, options.Width, options.Height, std::max(5, options.Frames / 2),
    options.DeformStep);
  std::printf(
    "%10s  %-7s %10s %10s %12s\n", "triangles", "variant", "frame", "/ plain", "smoothing");
  for (const int level : options.Levels)
  {
    vtkNew<vtkIcosphereSource> sphere;
    sphere->SetSubdivisionLevel(level);
    sphere->Update();
    MeasureOrbit(sphere->GetOutput(), options);
    MeasureChanges(sphere->GetOutput(), options, Change::Points);
    MeasureChanges(sphere->GetOutput(), options, Change::Values);
  }
  return 0;
}
