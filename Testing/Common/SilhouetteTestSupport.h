// Measurements shared by the module's tests and benchmarks: mesh topology
// reports, offscreen silhouette masks, and the distance of a mask's boundary to
// an exact circle. Test-only code; not part of the module.
#pragma once

#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

class vtkCamera;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;

namespace silhouette_test
{

struct TopologyReport
{
  long Triangles = 0;
  long OtherCells = 0;           ///< polygons that are not triangles, strips
  long BoundaryEdges = 0;        ///< undirected edges in one triangle
  long NonManifoldEdges = 0;     ///< undirected edges in three or more triangles
  long OrientationConflicts = 0; ///< edges used twice in the same direction
  long DegenerateTriangles = 0;  ///< repeated point id or zero area
  long FlippedTriangles = 0;     ///< geometric normal against the summed point normals
  long NonFinitePoints = 0;

  bool closedManifold() const
  {
    return this->OtherCells == 0 && this->BoundaryEdges == 0 && this->NonManifoldEdges == 0 &&
      this->OrientationConflicts == 0;
  }
  std::string summary() const;
};

/// Analyses the polygons of `mesh`; flipped triangles need point normals.
TopologyReport AnalyzeTopology(vtkPolyData* mesh);

/// `count` directions spread evenly over the unit sphere (Fibonacci spiral),
/// deterministic.
std::vector<std::array<double, 3>> SphereDirections(int count);

/// A perspective camera at `distance` from the origin along `direction`,
/// looking at the origin, with the given vertical view angle.
vtkSmartPointer<vtkCamera> CameraLookingAtOrigin(
  const std::array<double, 3>& direction, double distance, double viewAngle = 30.0);

/// A camera looking at the centre of `mesh`'s bounding sphere from `direction`
/// at `distance` bounding radii; parallel projection when `parallel`.
vtkSmartPointer<vtkCamera> CameraAroundMesh(
  vtkPolyData* mesh, const std::array<double, 3>& direction, double distance, bool parallel);

/// The path of a file of the project's Data/ folder, given as `-D folder` on
/// the test's command line.
std::string DataFile(int argc, char* argv[], const std::string& name);

/// Reads a mesh by extension (.ply .vtp .obj .stl .vtk); nullptr on failure.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path);

/// Renders meshes flat white on black, unlit, without multisampling, and
/// reads back which pixels they cover. One window, reused.
class MaskRenderer
{
public:
  MaskRenderer(int width, int height);
  ~MaskRenderer();
  /// Row-major mask, row 0 at the bottom; 1 where the mesh covers the pixel.
  std::vector<unsigned char> Render(vtkPolyData* mesh, vtkCamera* camera);
  int Width() const { return this->W; }
  int Height() const { return this->H; }

private:
  int W;
  int H;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
};

struct BoundaryDistance
{
  double Mean = 0.0;
  double Max = 0.0;
  long Samples = 0;
};

/// Where the mask changes between two 4-neighbour pixels, the boundary point is
/// taken midway between their centres; returns the distances of those points
/// to the circle (centre cx, cy, radius r, in pixels; pixel (i, j) has its
/// centre at (i + 0.5, j + 0.5)).
BoundaryDistance DistanceToCircle(
  const std::vector<unsigned char>& mask, int width, int height, double cx, double cy, double r);

/// The same boundary points, measured against another mask's boundary points
/// (nearest-point distance, both ways, brute force over boundary points).
BoundaryDistance DistanceBetweenBoundaries(
  const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, int width, int height);

} // namespace silhouette_test
