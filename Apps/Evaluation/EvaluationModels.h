// The model set of the evaluation (in the spirit of Xing's Table 1): each
// model has an original mesh, a coarse version made by quadric decimation, and
// a fine reference made by OpenSubdiv Loop refinement of the original.
// Generated models are made here at run time; only the bunny is read from Data/.
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
  None,
  UnitSphere, ///< the unit sphere about the origin: the outline is a circle
  Torus       ///< ring radius 1, tube radius 0.4, axis +Z: a very fine rendering stands in
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
/// The default triangle count of a model's coarse version.
int DefaultCoarseTriangles(const std::string& name);
ExactShape ExactShapeOf(const std::string& name);

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
/// The edges of `mesh`'s polygons not shared by exactly two of them (0: a
/// closed manifold).
long CountBoundaryOrNonManifoldEdges(vtkPolyData* mesh);

/// OpenSubdiv Loop refinement of `original` to `level`, projected to the
/// limit surface, with limit normals.
vtkSmartPointer<vtkPolyData> Refine(vtkPolyData* original, int level);

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
