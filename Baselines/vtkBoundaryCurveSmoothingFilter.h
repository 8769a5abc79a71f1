/**
 * @class   vtkBoundaryCurveSmoothingFilter
 * @brief   silhouette smoothing by boundary curve interpolation (the 2003 baseline)
 *
 * The earlier method that the 2008 paper (vtkSilhouetteSmoothingFilter) is
 * compared with: B. Wang, W. Wang, J. Wu, J. Sun, "Silhouette Smoothing by
 * Boundary Curve Interpolation", CAD/Graphics 2003. For the current camera,
 * every silhouette *edge* (a mesh edge between a front- and a back-facing
 * triangle) is projected to the view plane and replaced by a 2D cubic Hermite
 * curve (tangents: the projected vertex normals turned by pi/2, magnitudes
 * from rho), which is back-projected to 3D and sampled; the two triangles of
 * the edge are fanned from their opposite vertices to the samples. New points
 * get linearly interpolated normals. Baselines/Core/BoundaryCurveSmoother.h
 * lists the choices the paper leaves open (and why rho is cos t / (1 + cos t)).
 *
 * It is kept for comparison (`silhouette compare`), not as an alternative:
 * the curves depend on which edges are silhouette edges, which changes in
 * jumps as the view moves (the paper says coherence is not ensured).
 *
 * The view is given as for vtkSilhouetteSmoothingFilter (SetCamera or
 * SetRenderer, SetViewportSize, SetProp3D or SetModelMatrix, from
 * vtkSilhouetteViewAlgorithm), and the filter re-runs when the view changes
 * by value. Before a renderer has created its camera, the input passes
 * through unchanged (port 1 empty). Output: the input's points (ids and
 * positions kept), then the added points; cell `NewGeometry` (0 kept, 1 made
 * by re-meshing), cell `OriginalCellId`, point `Normals` (the input's, or
 * angle-weighted; interpolated for added points), other point data
 * interpolated, cell data copied. Verts and lines pass through; polygons and
 * strips come out as triangles. Output port 1: the smoothed silhouette, one
 * polyline per silhouette edge. A closed manifold stays closed: each edge's
 * curve is computed once and shared by its two triangles.
 *
 * Errors: no camera, cells naming missing points, NaN/infinite points, a
 * degenerate view or viewport.
 */
#ifndef vtkBoundaryCurveSmoothingFilter_h
#define vtkBoundaryCurveSmoothingFilter_h

#include "SilhouetteSmoothingFiltersBaselinesModule.h" // For export macro
#include "vtkSilhouetteViewAlgorithm.h"

#include <memory> // For the internals

class SILHOUETTESMOOTHINGFILTERSBASELINES_EXPORT vtkBoundaryCurveSmoothingFilter
  : public vtkSilhouetteViewAlgorithm
{
public:
  static vtkBoundaryCurveSmoothingFilter* New();
  vtkTypeMacro(vtkBoundaryCurveSmoothingFilter, vtkSilhouetteViewAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Points per curve, both ends counted. 0 (default): adaptive, so that the
   * polyline stays within Tolerance pixels of the 2D curve (the bound the
   * 2008 filter uses); the paper uses fixed counts of 3 to 5.
   */
  vtkSetClampMacro(SamplesPerCurve, int, 0, 65536);
  vtkGetMacro(SamplesPerCurve, int);
  virtual void SetTolerance(double); ///< clamped to [1e-3, inf] with a warning; NaN refused
  vtkGetMacro(Tolerance, double);
  ///@}

  /** The smoothed silhouette polylines (output port 1). */
  vtkPolyData* GetSilhouetteOutput();

protected:
  vtkBoundaryCurveSmoothingFilter();
  ~vtkBoundaryCurveSmoothingFilter() override;

  int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) override;

  int SamplesPerCurve = 0;
  double Tolerance = 0.5;

private:
  vtkBoundaryCurveSmoothingFilter(const vtkBoundaryCurveSmoothingFilter&) = delete;
  void operator=(const vtkBoundaryCurveSmoothingFilter&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
