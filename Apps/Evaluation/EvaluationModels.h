// The model set of the evaluation (in the spirit of Xing's Table 1): each
// model has an original mesh, a coarse version made by quadric decimation, and
// a fine reference made by OpenSubdiv Loop refinement of the original; the
// analytic models (all but the bunny) also have an exact silhouette to measure
// against (ExactShapeOf, ExactSurface). Generated models are made here at run
// time; only the bunny is read from Data/.
#ifndef EvaluationModels_h
#define EvaluationModels_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace silhouette_eval
{

/// What exact silhouette a model has, for measuring against it.
enum class ExactShape
{
  None,       ///< no analytic surface (the bunny, mesh files)
  UnitSphere, ///< the unit sphere about the origin: the outline is a circle, in closed form
  Surface     ///< an analytic surface: ExactSurface(name), a very fine sampling of it, stands in
};

struct ModelVersions
{
  std::string Name;
  std::string Description;
  ExactShape Exact = ExactShape::None;
  vtkSmartPointer<vtkPolyData> Original;
  vtkSmartPointer<vtkPolyData> Coarse;
  vtkSmartPointer<vtkPolyData> Fine;
};

/// The names of the model set, in table order.
std::vector<std::string> ModelNames();
bool IsModelName(const std::string& name);
/// The one-line description of a model of the set.
std::string ModelDescription(const std::string& name);

/// The original mesh of a model of the set (dataDir holds bunny.ply), with
/// exact normals where the shape is analytic. Throws std::runtime_error.
vtkSmartPointer<vtkPolyData> MakeOriginal(const std::string& name, const std::string& dataDir);

/// The file MakeOriginal reads model `name` from (the bunny's PLY in
/// `dataDir`), or empty for a model made from its analytic shape.
std::string ModelFile(const std::string& name, const std::string& dataDir);
/// The default triangle count of a model's coarse version.
int DefaultCoarseTriangles(const std::string& name);
ExactShape ExactShapeOf(const std::string& name);

/// The stand-in for the exact surface of a model whose ExactShapeOf is
/// ExactShape::Surface (nullptr for any other name): the same analytic
/// definition as MakeOriginal's, sampled far more finely, every point on the
/// surface. Measured at 1024x768 with the evaluation's 12 cameras
/// (docs/exact-surfaces.md):
///
///   model        sampling                    triangles  mesh to surface  outline vs 2x finer
///   torus        720 x 360 (u, v) grid         518,400  0.007 px         0.0007 px
///   ellipsoid    icosphere level 7, scaled     327,680  0.007 px         0.0013 px
///   supertoroid  720 x 360 (u, v) grid         518,400  0.007 px         0.0026 px
///   knot         1440 x 180 (u, v) grid        518,400  0.015 px         0.0026 px
///
/// "mesh to surface": the largest distance of the mesh from the analytic
/// surface (sampled at 7 points per triangle), in pixels at the nearest depth
/// of the framing: a bound on how far the stand-in's outline is from the
/// true one. "outline vs 2x finer": the mean outline distance (OutlineDeviation)
/// between the masks of the stand-in and of the same surface sampled twice as
/// finely, over the views (the max is 1 px: a few single pixels flip, 14 to
/// 82 of 20,000 to 42,000 outline pixels). `finer` halves the sample spacing
/// that many times (twice the grid in u and v, one icosphere level more, at
/// most level 8), for measuring that bound.
vtkSmartPointer<vtkPolyData> ExactSurface(const std::string& name, int finer = 0);

/// Quadric decimation (vtkSilhouetteQuadricDecimation without its contour
/// rule: link condition kept, so closed stays closed) of `original` to at
/// most `triangles` triangles, then every point moved to the closest point of the
/// original surface and given the original's interpolated normal there:
/// silhouette smoothing assumes the coarse mesh samples the smooth surface,
/// and decimation's optimal placement does not (measured on the sphere: 3.1 px
/// from the fine outline before smoothing and 7.2 px after, against 7.7 and
/// 0.58 px with the projection). Throws std::runtime_error when the result is
/// not a closed manifold though the original was.
vtkSmartPointer<vtkPolyData> Decimate(vtkPolyData* original, int triangles);
/// Moves every point of `coarse` to the closest point of `surface` and gives
/// it `surface`'s normal there, interpolated over the closest triangle (the
/// surface's own normals, or vtkPolyDataNormals' when it has none).
void ProjectOntoSurface(vtkPolyData* coarse, vtkPolyData* surface);

/// The edges of `mesh`'s polygons (by point ids): how many there are, how
/// many one polygon uses (borders), and how many are not shared by exactly
/// two (borders and non-manifold edges).
struct EdgeUses
{
  long Edges = 0;
  long Borders = 0;
  long NotTwo = 0;
};
EdgeUses CountEdgeUses(vtkPolyData* mesh);

/// The edges of `mesh`'s polygons not shared by exactly two of them (0: a
/// closed manifold).
long CountBoundaryOrNonManifoldEdges(vtkPolyData* mesh);

/// The volume `mesh`'s triangles enclose, positive when they wind outward
/// (the divergence theorem over the triangles' cones from the origin; only
/// the first three corners of each polygon count).
double EnclosedVolume(vtkPolyData* mesh);

/// OpenSubdiv Loop refinement of `original` to `level`, projected to the
/// limit surface, with limit normals.
vtkSmartPointer<vtkPolyData> Refine(vtkPolyData* original, int level);

/// `input`'s polygons as triangles over points merged where they share a
/// position (vtkCleanPolyData, tolerance 0), wound consistently per
/// connected part (vtkPolyDataNormals), geometry only: what the
/// evaluation decimates and refines. An asset file's texture seams, hard
/// edges and triangle soups split points that one surface shares, and
/// decimation and Loop refinement join triangles by point ids: on the file
/// as read, the decimation cannot collapse across a seam and the refinement
/// refines each piece apart (the spider OBJ's "fine" version was its coarse
/// one). `merged`, when given, gets how many points went.
vtkSmartPointer<vtkPolyData> WeldedTriangles(vtkPolyData* input, vtkIdType* merged = nullptr);

/// All three versions of a model of the set, or of any mesh (name = its path).
ModelVersions MakeVersions(const std::string& name, vtkSmartPointer<vtkPolyData> original,
  int coarseTriangles, int fineLevel);

/// A closed torus-like mesh sampled on a periodic (u, v) grid, u and v in
/// [0, 2 pi): the torus, the super-toroid and the knot tube are made this way,
/// so they have no seam to weld.
vtkSmartPointer<vtkPolyData> PeriodicGridSurface(
  int uResolution, int vResolution, void (*surface)(double u, double v, double point[3]));

} // namespace silhouette_eval

#endif
