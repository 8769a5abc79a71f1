// Silhouette masks and the distances between their outlines: how the
// project measures silhouette accuracy (docs/testing.md, "What the tests show"). Meshes are rendered flat
// and unlit, without multisampling, and read back as coverage masks; outlines
// are compared by a Euclidean distance transform, or against an exact circle.
#ifndef SilhouetteMasks_h
#define SilhouetteMasks_h

#include "vtkSmartPointer.h"

#include <array>
#include <vector>

class vtkCamera;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;

namespace silhouette_eval
{

/// A coverage mask, row-major, row 0 at the bottom: 1 where the mesh covers
/// the pixel's centre.
struct Mask
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> Covered;

  unsigned char at(int i, int j) const
  {
    return this->Covered[static_cast<std::size_t>(j) * this->Width + i];
  }
};

/// Renders meshes flat white on black, unlit, without multisampling, into
/// one offscreen window that is reused.
class MaskRenderer
{
public:
  MaskRenderer(int width, int height);
  ~MaskRenderer();
  Mask Render(vtkPolyData* mesh, vtkCamera* camera);

private:
  int Width;
  int Height;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
};

struct BoundaryDistance
{
  double Mean = 0.0;
  double Max = 0.0;
  long Samples = 0;
  /// OutlineDeviation(a, b) only: the first boundary pixel (in row-major
  /// order, row 0 at the bottom) at distance Max, -1 when there is none, and
  /// which side of b's outline a's outline lies on there: true when the
  /// pixel is covered by a and not by b (a bulges out of b), false when it is
  /// covered by b and not by a (a lies inside b: a part of it shrank, or a
  /// gap opened through it where b is solid).
  int FarthestX = -1;
  int FarthestY = -1;
  bool FarthestOutside = false;
};

/// Sub-pixel outline samples: wherever two 4-neighbour pixels differ, the
/// point midway between their centres (pixel (i, j) has its centre at
/// (i + 0.5, j + 0.5)).
std::vector<std::array<double, 2>> OutlinePoints(const Mask& mask);

/// Distances of the outline samples to the circle of centre (cx, cy) and
/// radius r, in pixels.
BoundaryDistance DistanceToCircle(const Mask& mask, double cx, double cy, double r);

/// Boundary pixels: covered pixels with an uncovered 4-neighbour (or on the
/// image border).
std::vector<unsigned char> BoundaryPixels(const Mask& mask);

/// Exact Euclidean distance, in pixels, from every pixel to the nearest set
/// pixel of `seeds` (Felzenszwalb and Huttenlocher's separable transform);
/// infinity everywhere when no pixel is set.
std::vector<float> DistanceTransform(
  const std::vector<unsigned char>& seeds, int width, int height);

/// The distance between two masks' outlines: every boundary pixel of each
/// mask measured to the other's boundary by a distance transform; mean and
/// max over both sets (symmetric), and where the max is. Samples is 0 when
/// either mask is empty.
BoundaryDistance OutlineDeviation(const Mask& a, const Mask& b);

} // namespace silhouette_eval

#endif
