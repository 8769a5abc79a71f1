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
// Per frame, both pay for the surface being new (the smoothing re-meshes it
// every frame): the ray casts build their triangle grid, the depth buffer
// uploads and renders the mesh. Times are medians of 5 runs.
//
//   line_visibility_benchmark [--size WxH] [--largest-ring N]
#include "BenchmarkTiming.h"

#include "vtkActor.h"
#include "vtkCamera.h"
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

} // namespace

int main(int argc, char* argv[])
{
  int width = 800;
  int height = 600;
  int largestRing = 320;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--size") && i + 1 < argc)
    {
      if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 16 || height < 16)
      {
        std::fprintf(stderr, "line_visibility_benchmark: --size needs WxH, 16 or more\n");
        return 2;
      }
    }
    else if (!std::strcmp(argv[i], "--largest-ring") && i + 1 < argc)
    {
      largestRing = std::atoi(argv[++i]);
      if (largestRing < 8)
      {
        std::fprintf(stderr, "line_visibility_benchmark: --largest-ring needs 8 or more\n");
        return 2;
      }
    }
    else
    {
      std::fprintf(stderr, "usage: line_visibility_benchmark [--size WxH] [--largest-ring N]\n");
      return 2;
    }
  }

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -4.0, 2.5);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetClippingRange(1.0, 10.0);
  const double* eye = camera->GetPosition();
  double direction[3];
  camera->GetDirectionOfProjection(direction);

  std::printf("| triangles | line points | ray casts ms | depth buffer ms | ray casts wrong | "
              "depth buffer wrong | judged | methods disagree |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  // ring x ring / 2 quads: about 1k, 10k and 100k triangles for 320.
  const std::vector<int> rings{ std::max(8, largestRing / 10), std::max(8, largestRing * 10 / 32),
    largestRing };
  for (const int ring : rings)
  {
    vtkNew<vtkTorusSurfaceSource> torus;
    torus->SetRingResolution(ring);
    torus->SetTubeResolution(std::max(4, ring / 2));
    vtkNew<vtkSilhouetteSmoothingFilter> smoother;
    smoother->SetInputConnection(torus->GetOutputPort());
    smoother->SetCamera(camera);
    smoother->SetViewportSize(width, height);
    smoother->Update();
    vtkNew<vtkPolyData> surface;
    surface->ShallowCopy(smoother->GetOutput(0));
    vtkNew<vtkPolyData> lines;
    lines->ShallowCopy(smoother->GetOutput(1));

    // Ray casts.
    vtkNew<vtkSilhouetteLineVisibility> rays;
    rays->SetInputData(lines);
    rays->SetSurfaceData(surface);
    rays->SetCamera(camera);
    std::vector<double> rayTimes;
    for (int run = 0; run < 5; ++run)
    {
      rays->Modified();
      rayTimes.push_back(benchmark_timing::Milliseconds([&] { rays->Update(); }));
    }
    // Per input point: the ray casts' verdict (each input vertex is in the
    // output, in order, with change points between).
    vtkPolyData* split = rays->GetOutput();
    auto* splitVisible =
      vtkUnsignedCharArray::SafeDownCast(split->GetPointData()->GetArray("Visible"));

    // The depth buffer.
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->RemoveAllViewProps();
    renderer->AddActor(actor);
    vtkNew<vtkFloatArray> depth;
    const vtkIdType count = lines->GetNumberOfPoints();
    std::vector<unsigned char> bufferVisible(static_cast<std::size_t>(count), 1);
    double clipping[2];
    camera->GetClippingRange(clipping);
    const double bias = 1e-3 * (clipping[1] - clipping[0]);
    std::vector<double> bufferTimes;
    for (int run = 0; run < 5; ++run)
    {
      surface->Modified(); // a new surface every frame: upload it
      bufferTimes.push_back(benchmark_timing::Milliseconds([&] {
        window->Render();
        window->GetZbufferData(0, 0, width - 1, height - 1, depth);
        const float* z = depth->GetPointer(0);
        double near = 0.0;
        double far = 0.0;
        camera->GetClippingRange(near, far);
        // Window depth to distance along the view direction (perspective).
        auto distance = [&](double windowDepth) {
          const double ndc = 2.0 * windowDepth - 1.0;
          return 2.0 * near * far / (far + near - ndc * (far - near));
        };
        for (vtkIdType p = 0; p < count; ++p)
        {
          double x[3];
          lines->GetPoint(p, x);
          renderer->SetWorldPoint(x[0], x[1], x[2], 1.0);
          renderer->WorldToDisplay();
          const double* d = renderer->GetDisplayPoint();
          const double toPoint[3] = { x[0] - eye[0], x[1] - eye[1], x[2] - eye[2] };
          const double own = vtkMath::Dot(toPoint, direction);
          const int px = static_cast<int>(std::floor(d[0]));
          const int py = static_cast<int>(std::floor(d[1]));
          bool visible = false;
          const int reach = std::getenv("SIL_BLOCK1") ? 0 : 1;
          for (int dy = -reach; dy <= reach && !visible; ++dy)
          {
            for (int dx = -reach; dx <= reach && !visible; ++dx)
            {
              const int qx = px + dx;
              const int qy = py + dy;
              if (qx < 0 || qy < 0 || qx >= width || qy >= height)
              {
                visible = true; // off the window: nothing drawn there
                continue;
              }
              const float w = z[static_cast<std::size_t>(qy) * width + qx];
              visible = w >= 1.0f || distance(w) >= own - bias;
            }
          }
          bufferVisible[static_cast<std::size_t>(p)] = visible ? 1 : 0;
        }
      }));
    }

    // Both against the exact torus, point by point. The ray casts' output
    // holds the input's points in order; match them by position.
    Verdicts rayVerdicts;
    Verdicts bufferVerdicts;
    long disagree = 0;
    vtkIdType out = 0;
    for (vtkIdType p = 0; p < count; ++p)
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
      if (std::getenv("SIL_DEBUG") && rayVisible != exactVisible)
      {
        std::printf("  ray casts wrong at (%.4f %.4f %.4f): %s, lowest %.4f\n", x[0], x[1], x[2],
          rayVisible ? "visible" : "hidden", lowest);
      }
      (bufferSays == exactVisible ? bufferVerdicts.Agree : bufferVerdicts.Disagree) += 1;
    }
    std::printf("| %lld | %lld | %.2f | %.2f | %ld | %ld | %ld | %ld |\n",
      static_cast<long long>(surface->GetNumberOfPolys()), static_cast<long long>(count),
      benchmark_timing::Median(rayTimes), benchmark_timing::Median(bufferTimes),
      rayVerdicts.Disagree, bufferVerdicts.Disagree, rayVerdicts.Agree + rayVerdicts.Disagree,
      disagree);
  }
  return EXIT_SUCCESS;
}
