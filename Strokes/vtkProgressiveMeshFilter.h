/**
 * @class   vtkProgressiveMeshFilter
 * @brief   progressive mesh (Kim and Choe; Hoppe 1996) at a chosen triangle count
 *
 * S.-S. Kim and S.-K. Choe, "Stylized Silhouette Rendering Using Progressive
 * Meshes" (3.1): the input triangles are coarsened by edge collapses in the
 * order of the paper's cost F_C = lambda F_vol d + (1 - lambda) L^2 F_boun
 * (lambda = 1/3; volume- and border-preserving; collapses that would flip a
 * triangle or break the manifold are refused), recorded as vertex splits.
 * The output is the mesh at the lowest level of that sequence with at least
 * TriangleCount triangles (or Fraction of the input's, when TriangleCount is
 * negative). The sequence is built once per input; changing the count only
 * applies splits or collapses. At the full count the output is the input
 * mesh exactly: same points (positions bit for bit, less points used by no
 * triangle), same triangles in the same order (a polygon's or strip's as
 * they are read, below). Strokes/Core/ProgressiveMesh.h
 * has the details.
 *
 * Points at one position are one vertex of the progressive mesh
 * (WeldCoincidentPoints, default on), so that a triangle soup or an asset
 * file cut along texture seams coarsens as the surface it stands for; each
 * corner is given back as its triangle's own input point wherever the
 * triangle still has that vertex, so the full level is still the input
 * exactly, and seams keep their copies (and point data) where the mesh is
 * at full resolution.
 *
 * Input: polygons and strips, as triangles the way the module's other
 * filters read them (a polygon as a fan, a concave one by ear clipping;
 * vtkTriangleFilter cuts some concave polygons into fewer triangles than
 * they take); verts and lines are ignored; points with NaN or infinite
 * coordinates are an error. Output: the active
 * points in input order with point data copied from the input point, the
 * active triangles in input order with cell data copied; point
 * `OriginalPointId` and cell `OriginalCellId` (vtkIdType, the input's ids);
 * field `BaseTriangleCount`, `FullTriangleCount`, `SplitCount`, `Level`.
 *
 * Progress is reported while the sequence is built (every 256 collapses);
 * AbortExecute stops the build there and leaves the output empty.
 */
#ifndef vtkProgressiveMeshFilter_h
#define vtkProgressiveMeshFilter_h

#include "SilhouetteSmoothingFiltersStrokesModule.h" // For export macro
#include "vtkSilhouettePolyDataAlgorithm.h"          // For the superclass

#include <memory> // For std::unique_ptr

class SILHOUETTESMOOTHINGFILTERSSTROKES_EXPORT vtkProgressiveMeshFilter
  : public vtkSilhouettePolyDataAlgorithm
{
public:
  static vtkProgressiveMeshFilter* New();
  vtkTypeMacro(vtkProgressiveMeshFilter, vtkSilhouettePolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Triangles wanted; negative (the default, -1) uses Fraction. */
  vtkSetMacro(TriangleCount, vtkIdType);
  vtkGetMacro(TriangleCount, vtkIdType);
  ///@}

  ///@{
  /** Fraction of the input's triangles wanted when TriangleCount < 0. Default 1. */
  virtual void SetFraction(double); ///< clamped to [0.0, 1.0] with a warning; NaN refused
  vtkGetMacro(Fraction, double);
  ///@}

  ///@{
  /**
   * Coarsen points at one position as one vertex (default on). Off, each
   * point is a vertex of its own: a triangle soup cannot coarsen. Changing
   * it builds the sequence again.
   */
  vtkSetMacro(WeldCoincidentPoints, bool);
  vtkGetMacro(WeldCoincidentPoints, bool);
  vtkBooleanMacro(WeldCoincidentPoints, bool);
  ///@}

protected:
  vtkProgressiveMeshFilter();
  ~vtkProgressiveMeshFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType TriangleCount = -1;
  double Fraction = 1.0;
  bool WeldCoincidentPoints = true;

private:
  vtkProgressiveMeshFilter(const vtkProgressiveMeshFilter&) = delete;
  void operator=(const vtkProgressiveMeshFilter&) = delete;

  struct Internal;
  std::unique_ptr<Internal> Cache;
};

#endif
