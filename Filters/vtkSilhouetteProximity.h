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
 * distance transform (Filters/Core/DistanceTransform.h says why that one)
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
 * exactly as for vtkSilhouetteSmoothingFilter; GetMTime() follows the view by
 * value.
 *
 * Errors: a missing camera, a degenerate view, NaN coordinates or cells naming
 * missing points fail the request.
 *
 * @sa vtkSilhouetteQuadricDecimation
 */
#ifndef vtkSilhouetteProximity_h
#define vtkSilhouetteProximity_h

#include "SilhouetteSmoothingFiltersSilhouetteModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkWeakPointer.h" // For the renderer and prop

#include <memory> // For the view tracker

class vtkCamera;
class vtkMatrix4x4;
class vtkProp3D;
class vtkRenderer;

class SILHOUETTESMOOTHINGFILTERSSILHOUETTE_EXPORT vtkSilhouetteProximity
  : public vtkPolyDataAlgorithm
{
public:
  static vtkSilhouetteProximity* New();
  vtkTypeMacro(vtkSilhouetteProximity, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The camera that defines the view. Required unless a renderer is set. */
  virtual void SetCamera(vtkCamera*);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /** Optional: the prop whose matrix takes the eye into model coordinates (weak). */
  virtual void SetProp3D(vtkProp3D*);
  vtkProp3D* GetProp3D();
  ///@}

  ///@{
  /** Optional: the model-to-world matrix, used when no prop is set. */
  virtual void SetModelMatrix(vtkMatrix4x4*);
  vtkGetObjectMacro(ModelMatrix, vtkMatrix4x4);
  ///@}

  ///@{
  /** Optional: a renderer for the camera and the viewport size (weak). */
  virtual void SetRenderer(vtkRenderer*);
  vtkRenderer* GetRenderer();
  ///@}

  ///@{
  /** Viewport size in pixels when no renderer is set. Default 1024 x 768. */
  vtkSetVector2Macro(ViewportSize, int);
  vtkGetVector2Macro(ViewportSize, int);
  ///@}

  ///@{
  /**
   * Grid cells along the longer side of the projected bounding box (the
   * paper's grid resolution). Default 128.
   */
  vtkSetClampMacro(Resolution, int, 1, 16384);
  vtkGetMacro(Resolution, int);
  ///@}

  /** Changes when the view changes (by value), besides the usual parameters. */
  vtkMTimeType GetMTime() override;

protected:
  vtkSilhouetteProximity();
  ~vtkSilhouetteProximity() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkCamera* Camera = nullptr;
  vtkWeakPointer<vtkProp3D> Prop3D;
  vtkMatrix4x4* ModelMatrix = nullptr;
  vtkWeakPointer<vtkRenderer> Renderer;
  int ViewportSize[2] = { 1024, 768 };
  int Resolution = 128;

private:
  vtkSilhouetteProximity(const vtkSilhouetteProximity&) = delete;
  void operator=(const vtkSilhouetteProximity&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
