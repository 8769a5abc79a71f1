// Saddle accuracy (the feature issue; paper III-E, Fig. 14): the inner
// silhouette of a torus, the contour of its hole, lies in the saddle region,
// where the smoothed silhouette segments are concave and the neighbouring
// triangles of the coarse mesh hide them ("silhouette blocking"). Vertex
// perturbation is meant to uncover them.
//
// Tori of 32 x 16 and 24 x 12 (R = 1, r = 0.4, points on the torus, exact
// normals) are seen in perspective from 16 oblique views (elevations 30 to 60
// degrees: below asin(r / R) = 23.6 degrees the hole closes; azimuths 0 to 7.5
// degrees, which with the meshes' symmetry covers the cases) at 1024 x 1024,
// zoomed so that the hole is about as large in the image as the sphere of the
// sphere test (700 to 780 px across). Each output is rendered as a flat mask;
// the hole regions are its background components that do not touch the
// image's border, and their outline samples (midpoints between a hole pixel
// and a covered 4-neighbour, as in the sphere test) are measured against the
// exact contour of the analytic torus.
//
// The exact contour: the torus point X(u, v) = C(u) + r N(u, v), with C(u) on
// the centre circle, is on the contour when N . (E - X) = 0, that is
// N . (E - C(u)) = r: for every u two solutions v, found in closed form, so
// the contour is two closed curves in u, sampled densely and projected with
// the camera's own matrix. Only the parts that border the hole count: a
// contour point is kept when the line of sight from the eye does not enter the
// solid torus before it (visible; the near side of the ring hides the ends of
// the far side's contour at low elevations) nor after it (nothing behind: the
// outline is against background), and one of the pixels around its
// projection is a hole pixel of a very fine torus (720 x 360) rendered the
// same way. An outline sample's deviation is its distance to the nearest of
// these exact polyline pieces (mean and max per view); "back" is the other
// way, the largest distance of an exact sample to the nearest outline sample
// (it catches a hole that is smaller than the exact one or missing in places;
// about 1.5 px at the sharp tips of the lens-shaped holes at 30 degrees, where
// the pixel grid cuts the tip off). "curve" is the largest distance of an
// exact sample to the smoothed silhouette polylines (the filter's second
// output): what the outline would be if nothing hid the curves.
//
// The measure is checked on the fine torus itself: its hole's outline
// measures 0.22 / 0.50 px (worst view mean / max), the pixel grid's share
// (asserted <= 0.3 / 1.0).
//
// Measured (worst view, mean / max px; the raw coarse mesh, smoothing
// without perturbation, with it):
//   32 x 16: coarse 2.18 / 5.24, unperturbed 0.57 / 2.28, perturbed 0.27 / 1.28
//   24 x 12: coarse 3.07 / 8.82, unperturbed 1.21 / 3.39, perturbed 0.32 / 1.99
// Asserted: with perturbation, the sphere test's limits (worst view mean
// <= 0.5 px, max <= 1.5 px) on the 32 x 16 torus; on the 24 x 12 torus the
// mean limit and a max of 2.5 px: there the curves are within 0.72 px of the
// exact contour, but at the ends of the hole's oval (elevation 40 to 60) fans
// of neighbouring silhouette triangles, whose corners the perturbation's
// guards leave in place, still hide up to 2 px of it. Without perturbation
// the deviation must be clearly larger (mean at least 1.5 times, max at least
// 0.5 px more), which is the blocking this test is about.
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyData.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSmartPointer.h"
#include "vtkTorusSurfaceSource.h"
#include "vtkUnsignedCharArray.h"

#include "SilhouetteMasks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace
{

constexpr double RingRadius = 1.0;
constexpr double TubeRadius = 0.4;
constexpr int ImageSize = 1024;
constexpr double EyeDistance = 6.0;
constexpr double ViewAngle = 15.0;

using Vec3 = std::array<double, 3>;
using Point2 = std::array<double, 2>;

double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Negative inside the solid torus, positive outside.
double TorusFunction(const Vec3& x)
{
  const double s = Dot(x, x) + RingRadius * RingRadius - TubeRadius * TubeRadius;
  return s * s - 4.0 * RingRadius * RingRadius * (x[0] * x[0] + x[1] * x[1]);
}

// Whether the line from `from` along unit `direction` enters the solid torus
// for a parameter in [begin, end], sampled every `step` (far finer than the
// tube: a miss needs a line grazing another part of the torus).
bool EntersTorus(const Vec3& from, const Vec3& direction, double begin, double end)
{
  constexpr double step = 0.002;
  for (double t = begin; t <= end; t += step)
  {
    const Vec3 x = { from[0] + t * direction[0], from[1] + t * direction[1],
      from[2] + t * direction[2] };
    if (TorusFunction(x) < 0.0)
    {
      return true;
    }
  }
  return false;
}

vtkSmartPointer<vtkCamera> ObliqueCamera(double elevation, double azimuth)
{
  const double e = vtkMath::RadiansFromDegrees(elevation);
  const double a = vtkMath::RadiansFromDegrees(azimuth);
  auto camera = vtkSmartPointer<vtkCamera>::New();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(EyeDistance * std::cos(e) * std::cos(a),
    EyeDistance * std::cos(e) * std::sin(a), EyeDistance * std::sin(e));
  camera->SetViewUp(0, 0, 1);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(ViewAngle);
  camera->SetClippingRange(0.1, 20.0);
  return camera;
}

// Pixel coordinates (pixel (i, j) has its centre at (i + 0.5, j + 0.5), row 0
// at the bottom), as OpenGL maps the camera's projection to the viewport.
struct Projector
{
  double M[16];
  explicit Projector(vtkCamera* camera)
  {
    vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
    for (int i = 0; i < 16; ++i)
    {
      this->M[i] = m->GetElement(i / 4, i % 4);
    }
  }
  Point2 operator()(const Vec3& x) const
  {
    double h[4];
    for (int r = 0; r < 4; ++r)
    {
      h[r] = this->M[4 * r] * x[0] + this->M[4 * r + 1] * x[1] + this->M[4 * r + 2] * x[2] +
        this->M[4 * r + 3];
    }
    return { (h[0] / h[3] + 1.0) * 0.5 * ImageSize, (h[1] / h[3] + 1.0) * 0.5 * ImageSize };
  }
};

// 1 on background pixels enclosed by the mesh (4-connected background
// components that do not touch the image's border).
std::vector<unsigned char> HolePixels(const silhouette_eval::Mask& mask)
{
  const int w = mask.Width;
  const int h = mask.Height;
  std::vector<unsigned char> outside(mask.Covered.size(), 0);
  std::vector<int> stack;
  auto push = [&](int i, int j) {
    const std::size_t k = static_cast<std::size_t>(j) * w + i;
    if (!mask.Covered[k] && !outside[k])
    {
      outside[k] = 1;
      stack.push_back(static_cast<int>(k));
    }
  };
  for (int i = 0; i < w; ++i)
  {
    push(i, 0);
    push(i, h - 1);
  }
  for (int j = 0; j < h; ++j)
  {
    push(0, j);
    push(w - 1, j);
  }
  while (!stack.empty())
  {
    const int k = stack.back();
    stack.pop_back();
    const int i = k % w;
    const int j = k / w;
    if (i > 0)
      push(i - 1, j);
    if (i + 1 < w)
      push(i + 1, j);
    if (j > 0)
      push(i, j - 1);
    if (j + 1 < h)
      push(i, j + 1);
  }
  std::vector<unsigned char> hole(mask.Covered.size(), 0);
  for (std::size_t k = 0; k < hole.size(); ++k)
  {
    hole[k] = !mask.Covered[k] && !outside[k] ? 1 : 0;
  }
  return hole;
}

// Midpoints between a hole pixel and a covered 4-neighbour.
std::vector<Point2> HoleOutline(const silhouette_eval::Mask& mask)
{
  const std::vector<unsigned char> hole = HolePixels(mask);
  const int w = mask.Width;
  auto isHole = [&](int i, int j) {
    return hole[static_cast<std::size_t>(j) * w + i] != 0;
  };
  std::vector<Point2> points;
  for (int j = 0; j < mask.Height; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      if (i + 1 < w && ((isHole(i, j) && mask.at(i + 1, j)) || (isHole(i + 1, j) && mask.at(i, j))))
      {
        points.push_back({ i + 1.0, j + 0.5 });
      }
      if (j + 1 < mask.Height &&
        ((isHole(i, j) && mask.at(i, j + 1)) || (isHole(i, j + 1) && mask.at(i, j))))
      {
        points.push_back({ i + 0.5, j + 1.0 });
      }
    }
  }
  return points;
}

// The exact contour pieces that bound the hole, projected: segments between
// consecutive samples of one contour curve that both qualify.
struct ExactContour
{
  std::vector<std::array<Point2, 2>> Segments;
  std::vector<Point2> Samples;
};

ExactContour ExactHoleContour(vtkCamera* camera, const silhouette_eval::Mask& fineMask)
{
  constexpr int samples = 16384;
  const std::vector<unsigned char> fineHole = HolePixels(fineMask);
  const Projector project(camera);
  Vec3 eye;
  camera->GetPosition(eye.data());
  const double bound = RingRadius + TubeRadius;
  ExactContour contour;
  for (int branch = 0; branch < 2; ++branch)
  {
    std::vector<Point2> projected(samples);
    std::vector<unsigned char> keep(samples, 0);
    for (int s = 0; s < samples; ++s)
    {
      const double u = 2.0 * vtkMath::Pi() * s / samples;
      const Vec3 radial = { std::cos(u), std::sin(u), 0.0 };
      const Vec3 w = { eye[0] - RingRadius * radial[0], eye[1] - RingRadius * radial[1], eye[2] };
      const double a = Dot(w, radial);
      const double b = w[2];
      const double rho = std::hypot(a, b);
      if (!(rho > TubeRadius))
      {
        continue;
      }
      // cos(v) a + sin(v) b = r.
      const double v = std::atan2(b, a) + (branch == 0 ? 1.0 : -1.0) * std::acos(TubeRadius / rho);
      const Vec3 x = { (RingRadius + TubeRadius * std::cos(v)) * radial[0],
        (RingRadius + TubeRadius * std::cos(v)) * radial[1], TubeRadius * std::sin(v) };
      projected[s] = project(x);
      // The line of sight: no entry into the solid before x (visible) nor
      // after it within the torus's bounding sphere (against background).
      Vec3 direction = { x[0] - eye[0], x[1] - eye[1], x[2] - eye[2] };
      const double length = std::sqrt(Dot(direction, direction));
      for (double& c : direction)
      {
        c /= length;
      }
      const double centre = -Dot(eye, direction);
      const double half =
        std::sqrt(std::max(0.0, bound * bound - (Dot(eye, eye) - centre * centre)));
      constexpr double margin = 1e-3;
      if (EntersTorus(eye, direction, centre - half, length - margin) ||
        EntersTorus(eye, direction, length + margin, centre + half))
      {
        continue;
      }
      // Next to the fine torus's hole.
      const int ci = static_cast<int>(std::floor(projected[s][0]));
      const int cj = static_cast<int>(std::floor(projected[s][1]));
      bool nearHole = false;
      for (int j = cj - 1; j <= cj + 1; ++j)
      {
        for (int i = ci - 1; i <= ci + 1; ++i)
        {
          if (i >= 0 && j >= 0 && i < fineMask.Width && j < fineMask.Height &&
            fineHole[static_cast<std::size_t>(j) * fineMask.Width + i])
          {
            nearHole = true;
          }
        }
      }
      keep[s] = nearHole ? 1 : 0;
    }
    for (int s = 0; s < samples; ++s)
    {
      if (keep[s])
      {
        contour.Samples.push_back(projected[s]);
        const int next = (s + 1) % samples;
        if (keep[next])
        {
          contour.Segments.push_back({ projected[s], projected[next] });
        }
      }
    }
  }
  return contour;
}

double DistanceToSegment(const Point2& p, const std::array<Point2, 2>& segment)
{
  const double dx = segment[1][0] - segment[0][0];
  const double dy = segment[1][1] - segment[0][1];
  const double length2 = dx * dx + dy * dy;
  double t = 0.0;
  if (length2 > 0.0)
  {
    t = std::clamp(((p[0] - segment[0][0]) * dx + (p[1] - segment[0][1]) * dy) / length2, 0.0, 1.0);
  }
  return std::hypot(p[0] - segment[0][0] - t * dx, p[1] - segment[0][1] - t * dy);
}

// Segments bucketed in square cells of the image, for nearest-distance
// queries (a point's distance to the nearest segment, exactly: the search
// widens ring by ring until the best distance found is within the rings).
class SegmentIndex
{
public:
  explicit SegmentIndex(std::vector<std::array<Point2, 2>> segments)
    : Segments(std::move(segments))
    , Cells(static_cast<std::size_t>(Side) * Side)
  {
    for (std::size_t k = 0; k < this->Segments.size(); ++k)
    {
      const auto& s = this->Segments[k];
      const int i0 = Clamp(std::min(s[0][0], s[1][0]));
      const int i1 = Clamp(std::max(s[0][0], s[1][0]));
      const int j0 = Clamp(std::min(s[0][1], s[1][1]));
      const int j1 = Clamp(std::max(s[0][1], s[1][1]));
      for (int j = j0; j <= j1; ++j)
      {
        for (int i = i0; i <= i1; ++i)
        {
          this->Cells[static_cast<std::size_t>(j) * Side + i].push_back(k);
        }
      }
    }
  }

  double Nearest(const Point2& p) const
  {
    double best = std::numeric_limits<double>::infinity();
    if (this->Segments.empty())
    {
      return best;
    }
    const int ci = Clamp(p[0]);
    const int cj = Clamp(p[1]);
    for (int ring = 0; ring < Side; ++ring)
    {
      for (int j = cj - ring; j <= cj + ring; ++j)
      {
        for (int i = ci - ring; i <= ci + ring; ++i)
        {
          const bool onRing = std::abs(i - ci) == ring || std::abs(j - cj) == ring;
          if (!onRing || i < 0 || j < 0 || i >= Side || j >= Side)
          {
            continue;
          }
          for (const std::size_t k : this->Cells[static_cast<std::size_t>(j) * Side + i])
          {
            best = std::min(best, DistanceToSegment(p, this->Segments[k]));
          }
        }
      }
      if (best <= ring * CellSize)
      {
        break;
      }
    }
    return best;
  }

private:
  static constexpr double CellSize = 16.0;
  static constexpr int Side = static_cast<int>(ImageSize / CellSize) + 2;
  // Cells cover [-16, ImageSize + 16) so that points just outside the image
  // are bucketed too.
  static int Clamp(double x)
  {
    return std::clamp(static_cast<int>(std::floor(x / CellSize)) + 1, 0, Side - 1);
  }
  std::vector<std::array<Point2, 2>> Segments;
  std::vector<std::vector<std::size_t>> Cells;
};

struct Deviation
{
  double Mean = 0.0;    ///< outline samples to the exact contour
  double Max = 0.0;     ///< outline samples to the exact contour
  double Reverse = 0.0; ///< largest distance from an exact sample to the outline
  long Samples = 0;     ///< outline samples of the hole
  Point2 WorstAt = { 0.0, 0.0 };
};

Deviation Measure(const silhouette_eval::Mask& mask, const ExactContour& exact)
{
  Deviation d;
  const std::vector<Point2> outline = HoleOutline(mask);
  d.Samples = static_cast<long>(outline.size());
  if (outline.empty() || exact.Segments.empty())
  {
    d.Mean = d.Max = d.Reverse = std::numeric_limits<double>::infinity();
    return d;
  }
  const SegmentIndex exactIndex(exact.Segments);
  for (const Point2& p : outline)
  {
    const double nearest = exactIndex.Nearest(p);
    d.Mean += nearest;
    if (nearest > d.Max)
    {
      d.Max = nearest;
      d.WorstAt = p;
    }
  }
  d.Mean /= static_cast<double>(outline.size());
  std::vector<std::array<Point2, 2>> points;
  for (const Point2& p : outline)
  {
    points.push_back({ p, p });
  }
  const SegmentIndex outlineIndex(std::move(points));
  for (const Point2& q : exact.Samples)
  {
    d.Reverse = std::max(d.Reverse, outlineIndex.Nearest(q));
  }
  return d;
}

// The segments of `lines`' polylines, projected into the image.
std::vector<std::array<Point2, 2>> ProjectedSegments(vtkPolyData* lines, vtkCamera* camera)
{
  const Projector project(camera);
  std::vector<std::array<Point2, 2>> segments;
  vtkCellArray* cells = lines->GetLines();
  vtkIdType n;
  const vtkIdType* ids;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      Vec3 a, b;
      lines->GetPoint(ids[k], a.data());
      lines->GetPoint(ids[k + 1], b.data());
      segments.push_back({ project(a), project(b) });
    }
  }
  return segments;
}

// The largest distance from an exact sample to the smoothed silhouette
// polylines (the filter's second output), projected: how well the curves
// themselves follow the exact contour, blocked or not.
double CurveDeviation(vtkPolyData* lines, vtkCamera* camera, const ExactContour& exact)
{
  const SegmentIndex index(ProjectedSegments(lines, camera));
  double worst = 0.0;
  for (const Point2& q : exact.Samples)
  {
    worst = std::max(worst, index.Nearest(q));
  }
  return worst;
}

// For looking at one view: the perturbed output's mask in grey, the
// unperturbed output's hole outline in green, the exact contour in red.
void WriteOverlay(const std::string& path, const silhouette_eval::Mask& on,
  const silhouette_eval::Mask& off, const ExactContour& exact, vtkPolyData* lines = nullptr,
  vtkCamera* camera = nullptr)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(on.Width, on.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (std::size_t k = 0; k < on.Covered.size(); ++k)
  {
    const unsigned char grey = on.Covered[k] ? 160 : 0;
    pixels[3 * k] = pixels[3 * k + 1] = pixels[3 * k + 2] = grey;
  }
  for (const Point2& p : HoleOutline(off))
  {
    const auto k = static_cast<std::size_t>(p[1]) * on.Width + static_cast<std::size_t>(p[0]);
    pixels[3 * k] = 0;
    pixels[3 * k + 1] = 255;
    pixels[3 * k + 2] = 0;
  }
  for (const Point2& p : exact.Samples)
  {
    const auto k = static_cast<std::size_t>(p[1]) * on.Width + static_cast<std::size_t>(p[0]);
    pixels[3 * k] = 255;
    pixels[3 * k + 1] = 0;
    pixels[3 * k + 2] = 0;
  }
  if (lines && camera)
  {
    for (const std::array<Point2, 2>& segment : ProjectedSegments(lines, camera))
    {
      const Point2& pa = segment[0];
      const Point2& pb = segment[1];
      for (int t = 0; t <= 20; ++t)
      {
        const double x = pa[0] + (pb[0] - pa[0]) * t / 20.0;
        const double y = pa[1] + (pb[1] - pa[1]) * t / 20.0;
        if (x >= 0 && y >= 0 && x < on.Width && y < on.Height)
        {
          const auto k2 = static_cast<std::size_t>(y) * on.Width + static_cast<std::size_t>(x);
          pixels[3 * k2] = 0;
          pixels[3 * k2 + 1] = 128;
          pixels[3 * k2 + 2] = 255;
        }
      }
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
}

struct Limits
{
  double Mean; ///< worst view's mean, perturbed
  double Max;  ///< worst view's max, perturbed
  double Back; ///< worst view's exact-to-outline distance, perturbed
};

struct View
{
  double Elevation;
  double Azimuth;
  vtkSmartPointer<vtkCamera> Camera;
  ExactContour Exact;
};

// Measures one torus mesh over the views; false when a limit is missed.
bool MeasureTorus(int ringResolution, int tubeResolution, const Limits& limits,
  const std::vector<View>& views, silhouette_eval::MaskRenderer& renderer,
  const std::string& temporary)
{
  constexpr double tolerance = 0.5;
  vtkNew<vtkTorusSurfaceSource> torus;
  torus->SetRingRadius(RingRadius);
  torus->SetTubeRadius(TubeRadius);
  torus->SetRingResolution(ringResolution);
  torus->SetTubeResolution(tubeResolution);
  torus->Update();
  vtkNew<vtkSilhouetteSmoothingFilter> perturbed;
  perturbed->SetInputConnection(torus->GetOutputPort());
  perturbed->SetViewportSize(ImageSize, ImageSize);
  perturbed->SetTolerance(tolerance);
  perturbed->PerturbVerticesOn();
  vtkNew<vtkSilhouetteSmoothingFilter> unperturbed;
  unperturbed->SetInputConnection(torus->GetOutputPort());
  unperturbed->SetViewportSize(ImageSize, ImageSize);
  unperturbed->SetTolerance(tolerance);
  unperturbed->PerturbVerticesOff();

  std::printf(
    "\n%d x %d torus, %lld triangles (R = %.1f, r = %.1f), %d x %d px, tolerance %.2f px\n",
    ringResolution, tubeResolution, static_cast<long long>(torus->GetOutput()->GetNumberOfCells()),
    RingRadius, TubeRadius, ImageSize, ImageSize, tolerance);
  std::printf("hole outline against the exact contour, px: mean / max of the outline samples' "
              "distances, and back: the largest distance of an exact sample to the outline\n");
  std::printf("%5s %5s | %20s | %20s | %20s | %6s\n", "elev", "azim", "coarse mean/max/back",
    "unperturbed", "perturbed", "curve");
  Deviation worstCoarse, worstOff, worstOn;
  auto keepWorst = [](Deviation& worst, const Deviation& d) {
    worst.Mean = std::max(worst.Mean, d.Mean);
    worst.Max = std::max(worst.Max, d.Max);
    worst.Reverse = std::max(worst.Reverse, d.Reverse);
  };
  for (const View& view : views)
  {
    perturbed->SetCamera(view.Camera);
    perturbed->Update();
    unperturbed->SetCamera(view.Camera);
    unperturbed->Update();
    const auto coarseMask = renderer.Render(torus->GetOutput(), view.Camera);
    const auto offMask = renderer.Render(unperturbed->GetOutput(), view.Camera);
    const auto onMask = renderer.Render(perturbed->GetOutput(), view.Camera);
    const Deviation coarse = Measure(coarseMask, view.Exact);
    const Deviation off = Measure(offMask, view.Exact);
    const Deviation on = Measure(onMask, view.Exact);
    // The smoothed curves themselves (port 1) against the exact samples:
    // what is left when nothing hides them.
    const double curve = CurveDeviation(perturbed->GetOutput(1), view.Camera, view.Exact);
    std::printf("%5.1f %5.1f | %6.3f %6.3f %6.3f | %6.3f %6.3f %6.3f | %6.3f %6.3f %6.3f | %6.3f\n",
      view.Elevation, view.Azimuth, coarse.Mean, coarse.Max, coarse.Reverse, off.Mean, off.Max,
      off.Reverse, on.Mean, on.Max, on.Reverse, curve);
    if (on.Samples < 500 || off.Samples < 500 || coarse.Samples < 500)
    {
      std::printf("FAIL: the hole's outline is barely in the image (%ld, %ld, %ld samples)\n",
        coarse.Samples, off.Samples, on.Samples);
      return false;
    }
    if (!temporary.empty() && view.Elevation == 30.0 && view.Azimuth == 0.0)
    {
      WriteOverlay(temporary + "/TestSaddleAccuracy_" + std::to_string(ringResolution) + "x" +
          std::to_string(tubeResolution) + "_30_0.png",
        onMask, offMask, view.Exact, perturbed->GetOutput(1), view.Camera);
    }
    keepWorst(worstCoarse, coarse);
    keepWorst(worstOff, off);
    keepWorst(worstOn, on);
  }
  std::printf("worst view, mean / max / back: coarse %.3f / %.3f / %.3f; without perturbation "
              "%.3f / %.3f / %.3f; with perturbation %.3f / %.3f / %.3f (limits %.2f / %.2f / "
              "%.2f)\n",
    worstCoarse.Mean, worstCoarse.Max, worstCoarse.Reverse, worstOff.Mean, worstOff.Max,
    worstOff.Reverse, worstOn.Mean, worstOn.Max, worstOn.Reverse, limits.Mean, limits.Max,
    limits.Back);
  bool ok = true;
  if (worstOn.Mean > limits.Mean || worstOn.Max > limits.Max || worstOn.Reverse > limits.Back)
  {
    std::printf("FAIL: with perturbation the hole's outline is off the exact contour\n");
    ok = false;
  }
  // Without perturbation the blocking shows: a clearly larger deviation.
  if (!(worstOff.Mean >= 1.5 * worstOn.Mean && worstOff.Max >= worstOn.Max + 0.5))
  {
    std::printf("FAIL: without perturbation the deviation is expected to be clearly larger "
                "(mean at least 1.5 times, max at least 0.5 px more)\n");
    ok = false;
  }
  return ok;
}

} // namespace

int TestSaddleAccuracy(int argc, char* argv[])
{
  std::string temporary;
  for (int i = 0; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-T")
    {
      temporary = argv[i + 1];
    }
  }
  vtkNew<vtkTorusSurfaceSource> fineTorus;
  fineTorus->SetRingRadius(RingRadius);
  fineTorus->SetTubeRadius(TubeRadius);
  fineTorus->SetRingResolution(720);
  fineTorus->SetTubeResolution(360);
  fineTorus->Update();
  silhouette_eval::MaskRenderer renderer(ImageSize, ImageSize);
  std::vector<View> views;
  double fineMean = 0.0;
  double fineMax = 0.0;
  for (const double elevation : { 30.0, 40.0, 50.0, 60.0 })
  {
    for (const double azimuth : { 0.0, 2.5, 5.0, 7.5 })
    {
      View view{ elevation, azimuth, ObliqueCamera(elevation, azimuth), {} };
      const auto fineMask = renderer.Render(fineTorus->GetOutput(), view.Camera);
      view.Exact = ExactHoleContour(view.Camera, fineMask);
      if (view.Exact.Samples.size() < 2000)
      {
        std::printf("FAIL: the exact hole contour is barely in view at elevation %g, azimuth %g "
                    "(%zu samples)\n",
          elevation, azimuth, view.Exact.Samples.size());
        return EXIT_FAILURE;
      }
      // The measure checked on the fine torus, whose outline is the exact
      // one up to the pixel grid.
      const Deviation fine = Measure(fineMask, view.Exact);
      fineMean = std::max(fineMean, fine.Mean);
      fineMax = std::max(fineMax, fine.Max);
      views.push_back(std::move(view));
    }
  }
  std::printf("720 x 360 torus (the pixel grid's share): worst view mean %.3f px, max %.3f px\n",
    fineMean, fineMax);
  if (fineMean > 0.3 || fineMax > 1.0)
  {
    std::printf("FAIL: the measure is off on the fine torus\n");
    return EXIT_FAILURE;
  }
  // 32 x 16: the sphere test's limits; 24 x 12: see the top of the file.
  bool ok = MeasureTorus(32, 16, { 0.5, 1.5, 2.0 }, views, renderer, temporary);
  ok = MeasureTorus(24, 12, { 0.5, 2.5, 2.5 }, views, renderer, temporary) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
