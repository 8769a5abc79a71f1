/**
 * @class   vtkSilhouetteProximity
 * @brief   labels points and cells with their image distance to the mesh's external contour
 *
 * The silhouette proximity of S. Mata, L. Pastor and A. Rodriguez,
 * "Silhouette Detection for Adaptive Polygonal Mesh Simplification Using
 * Distance Transforms": for the view of a camera, the mesh's faces are
 * projected to the viewport and mapped to a grid of `Resolution` square cells
 * along the longer side of their projected bounding box (a cell is occupied
 * when a face overlaps it); unoccupied cells enclosed by the projection are
 * filled, so that only the external contour counts; a two-pass 3-4 chamfer
 * distance transform (Common/Core/DistanceTransform.h says why that one)
 * gives each occupied cell its distance in cells to the background; the
 * labels are back-projected to the mesh.
 *
 * Output: the input (shallow copy) with
 * - point array `SilhouetteDistance` (double): the label of the cell the point
 *   projects into, in cells; 1 on the contour; -1 where the point is on or
 *   behind the eye plane;
 * - cell array `SilhouetteDistance` (double): for polygons and strips, the
 *   least label of the cells the cell's triangles overlap (-1 when a point of
 *   it cannot be projected); -1 for vertices and lines;
 * - field data `ProximityGridSize` (int, 2 components): the grid's width and
 *   height in cells, and `ProximityCellSize` (double): a cell's side in
 *   viewport pixels.
 * Every face is projected, visible or not, as in the paper (no depth test).
 *
 * The view: SetCamera or SetRenderer, SetProp3D or SetModelMatrix, and the
 * viewport size (SetViewportSize, or the renderer's) for the aspect ratio,
 * exactly as for vtkSilhouetteSmoothingFilter (from
 * vtkSilhouetteViewAlgorithm); GetMTime() follows the view by value.
 *
 * Errors: a missing camera (also a renderer's that it has not created yet), a degenerate view, NaN
 * coordinates or cells naming missing points fail the request.
 *
 * @sa vtkSilhouetteQuadricDecimation vtkSilhouetteViewAlgorithm
 */
#ifndef vtkSilhouetteProximity_h
#define vtkSilhouetteProximity_h

#include "SilhouetteSmoothingFiltersSimplificationModule.h" // For export macro
#include "vtkSilhouetteViewAlgorithm.h"

class SILHOUETTESMOOTHINGFILTERSSIMPLIFICATION_EXPORT vtkSilhouetteProximity
  : public vtkSilhouetteViewAlgorithm
{
public:
  static vtkSilhouetteProximity* New();
  vtkTypeMacro(vtkSilhouetteProximity, vtkSilhouetteViewAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Grid cells along the longer side of the projected bounding box (the
   * paper's grid resolution). Default 128.
   */
  vtkSetClampMacro(Resolution, int, 1, 16384);
  vtkGetMacro(Resolution, int);
  ///@}

protected:
  vtkSilhouetteProximity();
  ~vtkSilhouetteProximity() override;

  int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) override;

  int Resolution = 128;

private:
  vtkSilhouetteProximity(const vtkSilhouetteProximity&) = delete;
  void operator=(const vtkSilhouetteProximity&) = delete;
};

#endif
