// Helpers shared by the module's tests: mesh topology reports, cameras, data
// files, and a CHECK macro. Silhouette masks and outline distances come from
// the evaluation library (Apps/Evaluation/SilhouetteMasks.h). Test-only code;
// not part of the module.
#pragma once

#include <cstdio>

/// In a test function returning bool: print what failed and return false.
#define CHECK(condition, message)                                                                  \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::printf("FAIL: %s (%s, line %d)\n", message, #condition, __LINE__);                      \
      return false;                                                                                \
    }                                                                                              \
  } while (false)

#include "vtkSmartPointer.h"

class vtkActor;
class vtkAlgorithm;
class vtkPolyDataMapper;

#include <array>
#include <string>
#include <vector>

class vtkCamera;
class vtkPolyData;

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

/// The layout every uniform tessellation (PN triangles, Phong tessellation)
/// of a closed `input` at `level` must have: (level + 1)^2 triangles per
/// input triangle, a closed manifold without flipped or degenerate
/// triangles, the input's points first and unmoved. Prints what failed.
bool IsUniformTessellationOf(vtkPolyData* input, vtkPolyData* output, int level);

/// The layout a uniform tessellation of FlatGrid() (open, flat, the plane's
/// normal everywhere) at `level` must have: (level + 1)^2 triangles per
/// input triangle, every point in the plane with the plane's normal, no
/// non-manifold or conflicting edges, and each of the grid's 14 boundary
/// edges cut in level + 1. Prints what failed.
bool IsUniformTessellationOfFlatGrid(vtkPolyData* flat, vtkPolyData* output, int level);

/// A copy of vtkIcosphereSource's sphere at `level` (exact normals), free to modify.
vtkSmartPointer<vtkPolyData> Icosphere(int level);

/// A triangle soup of `mesh`'s triangles: each with three points of its own
/// (copies of its corners, double precision, in cell order: triangle c has
/// points 3c, 3c + 1, 3c + 2), no point or cell arrays. What VTK's OBJ
/// reader makes of a file with a texture coordinate per corner.
vtkSmartPointer<vtkPolyData> Soup(vtkPolyData* mesh);

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

/// The folder of Debian's assimp-testmodels meshes (/usr/share/assimp/models),
/// or an empty string when the package is not installed.
std::string AssetModelsFolder();

/// Reads a mesh by extension (.ply .vtp .obj .stl .vtk); nullptr on failure.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path);

/// The three meshes the image, mapper and topology tests run on:
/// vtkIcosphereSource's and vtkTorusSurfaceSource's defaults and the coarse
/// bunny (Data/bunny_coarse.ply).
struct SphereTorusBunny
{
  vtkSmartPointer<vtkPolyData> Sphere;
  vtkSmartPointer<vtkPolyData> Torus;
  vtkSmartPointer<vtkPolyData> Bunny; ///< nullptr (and a FAIL line printed) when unreadable
};
SphereTorusBunny MakeSphereTorusBunny(int argc, char* argv[]);

/// A flat, open mesh in the plane z = 0: a 4 x 3 grid of quads over
/// [-1, 1] x [-1, 1.5], each cut in two (24 triangles, 14 boundary edges),
/// with the plane's normal as every point's normal.
vtkSmartPointer<vtkPolyData> FlatGrid();

/// Two points and one triangle that names a third point, which does not exist.
vtkSmartPointer<vtkPolyData> MeshNamingAMissingPoint();

/// Updates `filter` with error observers on it and on its executive (so the
/// error is not printed as a failure); returns the update's result and sets
/// `message` to the filter's error, or "" when it reported none.
int UpdateReportingError(vtkAlgorithm* filter, std::string& message);

/// The image tests' two looks of a smoothed mesh. With `newGeometryKinds` > 0:
/// unlit wireframe coloured by the cell array NewGeometry, value 0 grey, 1
/// red, 2 blue (the first `newGeometryKinds` + 1 of them). Else: shaded light
/// grey-blue with a highlight.
void StyleImageActor(vtkPolyDataMapper* mapper, vtkActor* actor, int newGeometryKinds);

} // namespace silhouette_test
