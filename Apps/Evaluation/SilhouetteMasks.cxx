#include "SilhouetteMasks.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace silhouette_eval
{

MaskRenderer::MaskRenderer(int width, int height)
  : Width(width)
  , Height(height)
  , Window(vtkSmartPointer<vtkRenderWindow>::New())
  , Renderer(vtkSmartPointer<vtkRenderer>::New())
{
  this->Window->SetOffScreenRendering(1);
  this->Window->SetMultiSamples(0);
  this->Window->SetSize(width, height);
  this->Window->AddRenderer(this->Renderer);
  this->Renderer->SetBackground(0, 0, 0);
}

MaskRenderer::~MaskRenderer() = default;

Mask MaskRenderer::Render(vtkPolyData* mesh, vtkCamera* camera)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1, 1, 1);
  actor->GetProperty()->LightingOff();
  this->Renderer->RemoveAllViewProps();
  this->Renderer->AddActor(actor);
  this->Renderer->SetActiveCamera(camera);
  this->Renderer->ResetCameraClippingRange();
  this->Window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(this->Window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkUnsignedCharArray* rgb =
    vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  Mask mask;
  mask.Width = this->Width;
  mask.Height = this->Height;
  mask.Covered.assign(static_cast<std::size_t>(this->Width) * this->Height, 0);
  for (std::size_t i = 0; i < mask.Covered.size(); ++i)
  {
    mask.Covered[i] = rgb->GetValue(static_cast<vtkIdType>(3 * i)) > 127 ? 1 : 0;
  }
  this->Renderer->RemoveAllViewProps();
  return mask;
}

std::vector<std::array<double, 2>> OutlinePoints(const Mask& mask)
{
  std::vector<std::array<double, 2>> points;
  for (int j = 0; j < mask.Height; ++j)
  {
    for (int i = 0; i < mask.Width; ++i)
    {
      const unsigned char here = mask.at(i, j);
      if (i + 1 < mask.Width && here != mask.at(i + 1, j))
      {
        points.push_back({ i + 1.0, j + 0.5 });
      }
      if (j + 1 < mask.Height && here != mask.at(i, j + 1))
      {
        points.push_back({ i + 0.5, j + 1.0 });
      }
    }
  }
  return points;
}

namespace
{

// Mean and max of distance samples, built one sample at a time.
struct DistanceAccumulator
{
  BoundaryDistance Result;
  void add(double value)
  {
    this->Result.Mean += value;
    this->Result.Max = std::max(this->Result.Max, value);
    ++this->Result.Samples;
  }
  BoundaryDistance finish() const
  {
    BoundaryDistance d = this->Result;
    if (d.Samples > 0)
    {
      d.Mean /= static_cast<double>(d.Samples);
    }
    return d;
  }
};

} // namespace

BoundaryDistance DistanceToCircle(const Mask& mask, double cx, double cy, double r)
{
  DistanceAccumulator d;
  for (const auto& p : OutlinePoints(mask))
  {
    d.add(std::abs(std::hypot(p[0] - cx, p[1] - cy) - r));
  }
  return d.finish();
}

std::vector<unsigned char> BoundaryPixels(const Mask& mask)
{
  std::vector<unsigned char> boundary(mask.Covered.size(), 0);
  for (int j = 0; j < mask.Height; ++j)
  {
    for (int i = 0; i < mask.Width; ++i)
    {
      if (!mask.at(i, j))
      {
        continue;
      }
      const bool edge = i == 0 || j == 0 || i + 1 == mask.Width || j + 1 == mask.Height ||
        !mask.at(i - 1, j) || !mask.at(i + 1, j) || !mask.at(i, j - 1) || !mask.at(i, j + 1);
      boundary[static_cast<std::size_t>(j) * mask.Width + i] = edge ? 1 : 0;
    }
  }
  return boundary;
}

namespace
{

// One-dimensional squared distance transform of f (lower envelope of
// parabolas), in place; f holds 0 at seeds and infinity elsewhere.
void SquaredDistance1D(
  std::vector<double>& f, std::vector<double>& d, std::vector<int>& v, std::vector<double>& z)
{
  const int n = static_cast<int>(f.size());
  const double inf = std::numeric_limits<double>::infinity();
  int k = -1;
  for (int q = 0; q < n; ++q)
  {
    if (f[q] == inf)
    {
      continue;
    }
    double s = -inf;
    while (k >= 0)
    {
      s = ((f[q] + q * static_cast<double>(q)) - (f[v[k]] + v[k] * static_cast<double>(v[k]))) /
        (2.0 * (q - v[k]));
      if (s > z[k])
      {
        break;
      }
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -inf : s;
    z[k + 1] = inf;
  }
  if (k < 0)
  {
    std::fill(d.begin(), d.end(), inf);
  }
  else
  {
    int j = 0;
    for (int q = 0; q < n; ++q)
    {
      while (z[j + 1] < q)
      {
        ++j;
      }
      const double dq = q - v[j];
      d[q] = dq * dq + f[v[j]];
    }
  }
  f.swap(d);
}

} // namespace

std::vector<float> DistanceTransform(const std::vector<unsigned char>& seeds, int width, int height)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> grid(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
  {
    grid[i] = seeds[i] ? 0.0 : inf;
  }
  const int longest = std::max(width, height);
  std::vector<double> f, d(longest), z(longest + 1);
  std::vector<int> v(longest);
  // Columns, then rows.
  for (int i = 0; i < width; ++i)
  {
    f.assign(height, 0.0);
    d.assign(height, 0.0);
    for (int j = 0; j < height; ++j)
    {
      f[j] = grid[static_cast<std::size_t>(j) * width + i];
    }
    SquaredDistance1D(f, d, v, z);
    for (int j = 0; j < height; ++j)
    {
      grid[static_cast<std::size_t>(j) * width + i] = f[j];
    }
  }
  std::vector<float> distance(seeds.size());
  for (int j = 0; j < height; ++j)
  {
    f.assign(grid.begin() + static_cast<std::ptrdiff_t>(j) * width,
      grid.begin() + static_cast<std::ptrdiff_t>(j + 1) * width);
    d.assign(width, 0.0);
    SquaredDistance1D(f, d, v, z);
    for (int i = 0; i < width; ++i)
    {
      distance[static_cast<std::size_t>(j) * width + i] = static_cast<float>(std::sqrt(f[i]));
    }
  }
  return distance;
}

BoundaryDistance OutlineDeviation(const Mask& a, const Mask& b)
{
  DistanceAccumulator d;
  const std::vector<unsigned char> boundaryA = BoundaryPixels(a);
  const std::vector<unsigned char> boundaryB = BoundaryPixels(b);
  const std::vector<float> toA = DistanceTransform(boundaryA, a.Width, a.Height);
  const std::vector<float> toB = DistanceTransform(boundaryB, b.Width, b.Height);
  for (std::size_t i = 0; i < boundaryA.size(); ++i)
  {
    for (const auto& [from, to] :
      { std::make_pair(&boundaryA, &toB), std::make_pair(&boundaryB, &toA) })
    {
      if ((*from)[i])
      {
        const double value = (*to)[i];
        if (!std::isfinite(value))
        {
          return BoundaryDistance{}; // one mask is empty: no outline to compare
        }
        if (value > d.Result.Max || d.Result.FarthestX < 0)
        {
          d.Result.FarthestX = static_cast<int>(i % static_cast<std::size_t>(a.Width));
          d.Result.FarthestY = static_cast<int>(i / static_cast<std::size_t>(a.Width));
          // A pixel of a's outline that b does not cover, or of b's that a
          // covers: a lies outside b there.
          d.Result.FarthestOutside = from == &boundaryA ? !b.Covered[i] : a.Covered[i] != 0;
        }
        d.add(value);
      }
    }
  }
  return d.finish();
}

} // namespace silhouette_eval
