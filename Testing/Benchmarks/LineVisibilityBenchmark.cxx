// Benchmark, not a test: hidden-line removal by ray casts
// (vtkSilhouetteLineVisibility) against a depth-buffer test, which issue 16
// names as the alternative, on the smoothed silhouette of tori of about 1k,
// 10k and 100k triangles seen obliquely (the inner contour partly hidden).
//
// The depth-buffer test: the smoothed surface is rendered offscreen, its
// depth buffer read back as distance along the view direction, and a line
// point is visible when some pixel of the 3 x 3 block around its projection
// holds the surface at or behind the point, less a bias of 1e-3 of the
// scene's depth. The block is the principled part: a silhouette point lies
// where the surface turns away, so its own pixel may hold the background or
// the surface beside it, and only a neighbour is sure to hold the sheet it
// lies on. Both methods are judged against the exact torus as
// module.TestLineVisibilityFilter judges points (the ray marched through
// its implicit function beyond the first tenth of the way to the eye; points
// whose ray comes within about 0.05 of the surface are not judged: near
// the cusps of the inner contour that verdict is unsure, since it ignores
// occluders nearer than a tenth of the way).
//
// A third column times the ray casts with OutlinePixels 1, as `silhouette
// render` draws, and judges them the same way.
//
// Per frame, both pay for the surface being new (the smoothing re-meshes it
// every frame): the ray casts build their triangle grid, the depth buffer
// uploads and renders the mesh. Times are medians of 5 runs.
//
//   line_visibility_benchmark [--size WxH] [--largest-ring N]
#include "BenchmarkTiming.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteLineVisibility.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkTorusSurfaceSource.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{

constexpr double Tube = 0.4; // vtkTorusSurfaceSource's default tube radius, ring 1

double Implicit(const double q[3])
{
  const double ring = std::sqrt(q[0] * q[0] + q[1] * q[1]) - 1.0;
  return ring * ring + q[2] * q[2] - Tube * Tube;
}

// The lowest implicit value along the ray from p to the eye beyond its
// first tenth (module.TestLineVisibilityFilter's point verdicts).
double Lowest(const double p[3], const double eye[3])
{
  double lowest = 1e9;
  for (double t = 0.1; t < 1.0; t += 0.0005)
  {
    const double q[3] = { p[0] + t * (eye[0] - p[0]), p[1] + t * (eye[1] - p[1]),
      p[2] + t * (eye[2] - p[2]) };
    lowest = std::min(lowest, Implicit(q));
  }
  return lowest;
}

struct Verdicts
{
  long Agree = 0;    ///< with the exact torus
  long Disagree = 0; ///< with the exact torus
  long Grazing = 0;  ///< not judged
};

struct Options
{
  int Width = 800;
  int Height = 600;
  int LargestRing = 320;
};

// Returns false after saying what is wrong.
bool ParseOptions(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc)
    {
      if (std::sscanf(argv[++i], "%dx%d", &options.Width, &options.Height) != 2 ||
        options.Width < 16 || options.Height < 16)
      {
        std::fprintf(stderr, "line_visibility_benchmark: --size needs WxH, 16 or more\n");
        return false;
      }
    }
    else if (!std::strcmp(argv[i], "--largest-ring") && i + 1 < argc)
    {
      options.LargestRing = std::atoi(argv[++i]);
      if (options.LargestRing < 8)
      {
        std::fprintf(stderr, "line_visibility_benchmark: --largest-ring needs 8 or more\n");
        return false;
      }
    }
    else
    {
      std::fprintf(stderr, "usage: line_visibility_benchmark [--size WxH] [--largest-ring N]\n");
      return false;
    }
  }
  return true;
}

// The ray casts (vtkSilhouetteLineVisibility), five timed runs; the lines
// split at the visibility changes with their Visible array stay in `rays`.
std::vector<double> TimeRayCasts(
  vtkSilhouetteLineVisibility* rays, vtkPolyData* lines, vtkPolyData* surface, vtkCamera* camera)
{
  rays->SetInputData(lines);
  rays->SetSurfaceData(surface);
  rays->SetCamera(camera);
  std::vector<double> times;
  for (int run = 0; run < 5; ++run)
  {
    rays->Modified();
    times.push_back(benchmark_timing::Milliseconds([&] { rays->Update(); }));
  }
  return times;
}

// Reads visibility off a rendered depth buffer: a line point is visible when
// it is nearer than the drawn depth (less a bias) at its pixel or one of its
// 8 neighbours.
struct DepthProbe
{
  vtkRenderer* Renderer;
  const float* Z;
  int Width;
  int Height;
  double Eye[3];
  double Direction[3];
  double Near;
  double Far;
  double Bias;

  DepthProbe(vtkRenderer* renderer, const float* z, int width, int height, double bias)
    : Renderer(renderer)
    , Z(z)
    , Width(width)
    , Height(height)
    , Bias(bias)
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->GetPosition(this->Eye);
    camera->GetDirectionOfProjection(this->Direction);
    camera->GetClippingRange(this->Near, this->Far);
  }

  // Window depth to distance along the view direction (perspective).
  double Distance(double windowDepth) const
  {
    const double ndc = 2.0 * windowDepth - 1.0;
    return 2.0 * this->Near * this->Far / (this->Far + this->Near - ndc * (this->Far - this->Near));
  }

  bool Visible(const double x[3]) const
  {
    this->Renderer->SetWorldPoint(x[0], x[1], x[2], 1.0);
    this->Renderer->WorldToDisplay();
    const double* d = this->Renderer->GetDisplayPoint();
    const double toPoint[3] = { x[0] - this->Eye[0], x[1] - this->Eye[1], x[2] - this->Eye[2] };
    const double own = vtkMath::Dot(toPoint, this->Direction);
    const int px = static_cast<int>(std::floor(d[0]));
    const int py = static_cast<int>(std::floor(d[1]));
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        const int qx = px + dx;
        const int qy = py + dy;
        if (qx < 0 || qy < 0 || qx >= this->Width || qy >= this->Height)
        {
          return true; // off the window: nothing drawn there
        }
        const float w = this->Z[static_cast<std::size_t>(qy) * this->Width + qx];
        if (w >= 1.0f || this->Distance(w) >= own - this->Bias)
        {
          return true;
        }
      }
    }
    return false;
  }
};

// The depth buffer's verdicts, five timed runs (each uploads the surface
// anew, renders it and reads the depth back).
std::vector<double> TimeDepthBuffer(vtkRenderWindow* window, vtkRenderer* renderer,
  vtkPolyData* surface, vtkPolyData* lines, std::vector<unsigned char>& visible)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->RemoveAllViewProps();
  renderer->AddActor(actor);
  vtkNew<vtkFloatArray> depth;
  const vtkIdType count = lines->GetNumberOfPoints();
  visible.assign(static_cast<std::size_t>(count), 1);
  double clipping[2];
  renderer->GetActiveCamera()->GetClippingRange(clipping);
  const double bias = 1e-3 * (clipping[1] - clipping[0]);
  const int* size = window->GetSize();
  const int width = size[0];
  const int height = size[1];
  std::vector<double> times;
  for (int run = 0; run < 5; ++run)
  {
    surface->Modified(); // a new surface every frame: upload it
    times.push_back(benchmark_timing::Milliseconds([&] {
      window->Render();
      window->GetZbufferData(0, 0, width - 1, height - 1, depth);
      const DepthProbe probe(renderer, depth->GetPointer(0), width, height, bias);
      for (vtkIdType p = 0; p < count; ++p)
      {
        double x[3];
        lines->GetPoint(p, x);
        visible[static_cast<std::size_t>(p)] = probe.Visible(x) ? 1 : 0;
      }
    }));
  }
  return times;
}

// Both methods' verdicts against the exact torus, point by point; returns
// how many points the two methods disagree on. The ray casts' output holds
// the input's points in order; they are matched by position.
long JudgeAgainstTorus(vtkPolyData* lines, vtkPolyData* split,
  const std::vector<unsigned char>& bufferVisible, const double eye[3], Verdicts& rayVerdicts,
  Verdicts& bufferVerdicts)
{
  auto* splitVisible =
    vtkUnsignedCharArray::SafeDownCast(split->GetPointData()->GetArray("Visible"));
  long disagree = 0;
  vtkIdType out = 0;
  for (vtkIdType p = 0; p < lines->GetNumberOfPoints(); ++p)
  {
    double x[3];
    lines->GetPoint(p, x);
    // The next output point at this position (change points are skipped).
    bool rayVisible = true;
    for (; out < split->GetNumberOfPoints(); ++out)
    {
      double y[3];
      split->GetPoint(out, y);
      if (vtkMath::Distance2BetweenPoints(x, y) == 0.0)
      {
        rayVisible = splitVisible->GetValue(out) != 0;
        ++out;
        break;
      }
    }
    const bool bufferSays = bufferVisible[static_cast<std::size_t>(p)] != 0;
    disagree += rayVisible != bufferSays ? 1 : 0;
    const double lowest = Lowest(x, eye);
    if (std::abs(lowest) < 0.04)
    {
      ++rayVerdicts.Grazing;
      ++bufferVerdicts.Grazing;
      continue;
    }
    const bool exactVisible = lowest > 0.0;
    (rayVisible == exactVisible ? rayVerdicts.Agree : rayVerdicts.Disagree) += 1;
    (bufferSays == exactVisible ? bufferVerdicts.Agree : bufferVerdicts.Disagree) += 1;
  }
  return disagree;
}

} // namespace

int main(int argc, char* argv[])
{
  Options options;
  if (!ParseOptions(argc, argv, options))
  {
    return 2;
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(options.Width, options.Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -4.0, 2.5);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetClippingRange(1.0, 10.0);

  std::printf("| triangles | line points | ray casts ms | depth buffer ms | ray casts wrong | "
              "depth buffer wrong | judged | methods disagree | ray casts, outline rules ms | "
              "their wrong | with the gaps' contour ms | gap pieces |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  // ring x ring / 2 quads: about 1k, 10k and 100k triangles for 320.
  const int largest = options.LargestRing;
  const std::vector<int> rings{ std::max(8, largest / 10), std::max(8, largest * 10 / 32),
    largest };
  for (const int ring : rings)
  {
    vtkNew<vtkTorusSurfaceSource> torus;
    torus->SetRingResolution(ring);
    torus->SetTubeResolution(std::max(4, ring / 2));
    vtkNew<vtkSilhouetteSmoothingFilter> smoother;
    smoother->SetInputConnection(torus->GetOutputPort());
    smoother->SetCamera(camera);
    smoother->SetViewportSize(options.Width, options.Height);
    smoother->Update();
    vtkNew<vtkPolyData> surface;
    surface->ShallowCopy(smoother->GetOutput(0));
    vtkNew<vtkPolyData> lines;
    lines->ShallowCopy(smoother->GetOutput(1));

    vtkNew<vtkSilhouetteLineVisibility> rays;
    const std::vector<double> rayTimes = TimeRayCasts(rays, lines, surface, camera);
    // As `silhouette render` draws: OutlinePixels 1 (the outline within a
    // pixel drawn, a line inside the surface's image hidden).
    vtkNew<vtkSilhouetteLineVisibility> outlined;
    outlined->SetOutlinePixels(1.0);
    outlined->SetViewportSize(options.Width, options.Height);
    const std::vector<double> outlinedTimes = TimeRayCasts(outlined, lines, surface, camera);
    // And with the surface's contour where no line covers the outline
    // (OutlineGapPixels 4), as the program draws since 2026-12-05.
    vtkNew<vtkSilhouetteLineVisibility> gapped;
    gapped->SetOutlinePixels(1.0);
    gapped->SetOutlineGapPixels(4.0);
    gapped->SetViewportSize(options.Width, options.Height);
    const std::vector<double> gappedTimes = TimeRayCasts(gapped, lines, surface, camera);
    vtkDataArray* original = gapped->GetOutput()->GetCellData()->GetArray("OriginalCellId");
    long gapPieces = 0;
    for (vtkIdType c = 0; original && c < original->GetNumberOfTuples(); ++c)
    {
      gapPieces += original->GetComponent(c, 0) < 0.0 ? 1 : 0;
    }
    std::vector<unsigned char> bufferVisible;
    const std::vector<double> bufferTimes =
      TimeDepthBuffer(window, renderer, surface, lines, bufferVisible);
    Verdicts rayVerdicts;
    Verdicts bufferVerdicts;
    const long disagree = JudgeAgainstTorus(
      lines, rays->GetOutput(), bufferVisible, camera->GetPosition(), rayVerdicts, bufferVerdicts);
    Verdicts outlinedVerdicts;
    Verdicts unused;
    JudgeAgainstTorus(
      lines, outlined->GetOutput(), bufferVisible, camera->GetPosition(), outlinedVerdicts, unused);
    std::printf("| %lld | %lld | %.2f | %.2f | %ld | %ld | %ld | %ld | %.2f | %ld | %.2f | %ld |\n",
      static_cast<long long>(surface->GetNumberOfPolys()),
      static_cast<long long>(lines->GetNumberOfPoints()), benchmark_timing::Median(rayTimes),
      benchmark_timing::Median(bufferTimes), rayVerdicts.Disagree, bufferVerdicts.Disagree,
      rayVerdicts.Agree + rayVerdicts.Disagree, disagree, benchmark_timing::Median(outlinedTimes),
      outlinedVerdicts.Disagree, benchmark_timing::Median(gappedTimes), gapPieces);
  }
  return EXIT_SUCCESS;
}
