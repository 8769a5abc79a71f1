/**
 * @class   vtkViewDependentLevelOfDetail
 * @brief   a big mesh refined per view: fine where its outline is, coarse elsewhere
 *
 * View-dependent level of detail (Hoppe 1997's selective refinement of a
 * progressive mesh), with the criteria of Mata et al. (a smaller error allowed
 * near the external contour) and Kim and Choe (normal cones: refine what may
 * hold the contour, coarsen what faces the viewer or away from it):
 *
 * - Once per input, the mesh is simplified by quadric edge collapses (in
 *   rounds of independent collapses) down to BaseTriangles, and the collapses
 *   become a vertex hierarchy with bounds per split (a sphere, a cone of
 *   normals, an error in model units).
 * - Every time the view changes, the previous frame's mesh is refined where a
 *   split's error on screen exceeds its tolerance and coarsened where it has
 *   fallen below it (times Hysteresis): a frame costs the change and the front
 *   of the hierarchy, not the input. The tolerance is ContourTolerance (pixels)
 *   where the split's normals may be orthogonal to a line of sight through it
 *   (widened by ContourMargin degrees), InteriorTolerance where they all face
 *   the viewer, BackFacingTolerance where none does; splits outside the view
 *   frustum are never refined (FrustumCulling).
 *
 * Every extracted mesh is a valid mesh of the input's topology: a closed
 * manifold input gives closed manifolds of the same genus; tolerances of 0
 * everywhere (and no culling) give the input's triangles back exactly.
 *
 * Input: a surface (polygons and strips are read as triangles; vertex and line
 * cells are left out, with a warning). Points on borders or non-manifold edges
 * never move. Output: the extracted triangles; the points they use, with the
 * input's point data and `OriginalPointId`, and the input's point normals:
 * its own, or, when it has none, `Normals` computed on the whole input
 * (angle-weighted), so that a coarse part is shaded as the fine surface is and
 * a smoothing filter downstream uses the fine normals; the input cell's data
 * and `OriginalCellId` per triangle. Field data: `LevelOfDetailSplits` (splits
 * applied, of the hierarchy's), `LevelOfDetailChanges` (applied and undone in
 * this update) and `LevelOfDetailInputTriangles`.
 *
 * The view is given as for the module's other view filters (a camera or a
 * renderer, optionally a prop or model matrix, the viewport).
 * @sa vtkSilhouetteSmoothingFilter vtkSilhouetteQuadricDecimation vtkProgressiveMeshFilter
 */
#ifndef vtkViewDependentLevelOfDetail_h
#define vtkViewDependentLevelOfDetail_h

#include "SilhouetteSmoothingFiltersLevelOfDetailModule.h" // For export macro
#include "vtkSilhouetteViewAlgorithm.h"

#include <memory> // For the hierarchy

namespace silsmooth
{
struct ViewRefinementTolerances;
}

class SILHOUETTESMOOTHINGFILTERSLEVELOFDETAIL_EXPORT vtkViewDependentLevelOfDetail
  : public vtkSilhouetteViewAlgorithm
{
public:
  static vtkViewDependentLevelOfDetail* New();
  vtkTypeMacro(vtkViewDependentLevelOfDetail, vtkSilhouetteViewAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The error allowed on screen, in pixels, where the contour may be (default
   * 0.5), where the surface faces the viewer (default 1) and where it faces
   * away (default VTK_DOUBLE_MAX: never refined). 0 asks for full resolution.
   */
  virtual void SetContourTolerance(double pixels);
  vtkGetMacro(ContourTolerance, double);
  virtual void SetInteriorTolerance(double pixels);
  vtkGetMacro(InteriorTolerance, double);
  virtual void SetBackFacingTolerance(double pixels);
  vtkGetMacro(BackFacingTolerance, double);
  ///@}

  ///@{
  /**
   * Degrees by which the contour's band is widened (Mata's distance interval
   * as an angle between the normals and the line of sight). Default 0.
   */
  virtual void SetContourMargin(double degrees);
  vtkGetMacro(ContourMargin, double);
  ///@}

  ///@{
  /**
   * A split stays applied until its error falls below Hysteresis times its
   * tolerance (default 0.8, in (0, 1]) and it has left the contour's band by
   * HysteresisAngle degrees (default 2): no flicker between two frames.
   */
  virtual void SetHysteresis(double ratio);
  vtkGetMacro(Hysteresis, double);
  virtual void SetHysteresisAngle(double degrees);
  vtkGetMacro(HysteresisAngle, double);
  ///@}

  ///@{
  /**
   * Never refine outside the view frustum's four side planes. Default on.
   */
  vtkSetMacro(FrustumCulling, vtkTypeBool);
  vtkGetMacro(FrustumCulling, vtkTypeBool);
  vtkBooleanMacro(FrustumCulling, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The hierarchy's coarsest mesh: the simplification stops at this many
   * triangles (or where it cannot go on). Default 0: as far as it goes.
   * Changing it rebuilds the hierarchy.
   */
  virtual void SetBaseTriangles(vtkIdType count);
  vtkGetMacro(BaseTriangles, vtkIdType);
  ///@}

  ///@{
  /**
   * Points at one position are one vertex of the hierarchy (default on), so
   * that the copies asset files keep along texture seams and hard edges, and
   * triangle soups, do not cut the surface into pieces that cannot be
   * simplified. Where the mesh is at full resolution each triangle keeps its
   * own copies (and their point data); where it is coarser a corner may be
   * another copy of the same position. Changing it rebuilds the hierarchy.
   */
  vtkSetMacro(WeldCoincidentPoints, bool);
  vtkGetMacro(WeldCoincidentPoints, bool);
  vtkBooleanMacro(WeldCoincidentPoints, bool);
  ///@}

protected:
  vtkViewDependentLevelOfDetail();
  ~vtkViewDependentLevelOfDetail() override;

  int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) override;

  double ContourTolerance = 0.5;
  double InteriorTolerance = 1.0;
  double BackFacingTolerance = VTK_DOUBLE_MAX;
  double ContourMargin = 0.0;
  double Hysteresis = 0.8;
  double HysteresisAngle = 2.0;
  vtkTypeBool FrustumCulling = 1;
  vtkIdType BaseTriangles = 0;
  bool WeldCoincidentPoints = true;

private:
  vtkViewDependentLevelOfDetail(const vtkViewDependentLevelOfDetail&) = delete;
  // Builds the hierarchy unless it is the input's already: 1 ready, 0 failed
  // (reported), -1 aborted.
  int EnsureHierarchy(vtkPolyData* input);
  silsmooth::ViewRefinementTolerances Tolerances() const;
  void operator=(const vtkViewDependentLevelOfDetail&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
