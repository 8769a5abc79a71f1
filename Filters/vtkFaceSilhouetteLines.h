/**
 * @class   vtkFaceSilhouetteLines
 * @brief   the face-based silhouette of a triangle mesh: straight segments across its silhouette
 * triangles
 *
 * The silhouette of the linearly interpolated visibility g = N . (E - V)
 * (A. Hertzmann and D. Zorin, "Illustrating smooth surfaces", SIGGRAPH 2000;
 * the "face-based silhouette" of Xing's Fig. 6b). A vertex is visible when
 * g >= 0, with the same shading normals, eye and rule as
 * vtkSilhouetteSmoothingFilter; a triangle whose vertices differ is a
 * silhouette triangle, and g interpolated linearly over it is zero on one
 * straight segment between the zero crossings of its two mixed edges. This
 * filter outputs those segments, chained across triangles into polylines.
 * Nothing is re-meshed: it is the unsmoothed line drawing that the smoothed
 * silhouette of vtkSilhouetteSmoothingFilter's second port replaces.
 *
 * Unlike vtkPolyDataSilhouette, which outputs mesh edges between front- and
 * back-facing faces (a zig-zag along the triangles), these lines cross the
 * triangles, with one point per mixed edge computed once per edge: the two
 * triangles of an edge share it, so the polylines have no cracks, and on a
 * closed mesh every polyline is a closed loop (its last point id is its
 * first).
 *
 * Input: a vtkPolyData; polygons (as fans) and triangle strips are used,
 * vertices and lines ignored. Point normals (the active normals) are the
 * shading normals when present, otherwise angle-weighted vertex normals are
 * computed.
 *
 * The view: a camera (SetCamera, or the active camera of SetRenderer) and
 * optionally the prop (SetProp3D) or its matrix (SetModelMatrix), as for
 * vtkSilhouetteSmoothingFilter; GetMTime() changes when the camera or the
 * matrix changes by value (not when only the clipping range does). The
 * viewport size plays no part.
 *
 * Output: polylines. Point arrays:
 * - `Normals` (float): the normalised linear interpolation of the shading
 *   normals along the edge (the active normals);
 * - `EdgeEnds` (vtkIdType, 2 components): the input point ids of the edge the
 *   point lies on, lower id first;
 * - `EdgeParameter` (double): t such that the point is (1 - t) * first end +
 *   t * second end;
 * - every other input point array, interpolated linearly along the edge.
 * Field data `SilhouetteTriangleCount` (vtkIdType): how many triangles the
 * lines cross (one segment each).
 *
 * Awkward input: an empty input gives an empty output; NaN or infinite
 * coordinates, cells naming missing points, a missing camera or a degenerate
 * view fail the request with an error; triangles repeating a point id are
 * skipped; at an edge shared by more than two triangles a polyline ends.
 *
 * @sa vtkSilhouetteSmoothingFilter vtkPolyDataSilhouette
 */
#ifndef vtkFaceSilhouetteLines_h
#define vtkFaceSilhouetteLines_h

#include "SilhouetteSmoothingFiltersSilhouetteModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkWeakPointer.h" // For the renderer and prop

#include <memory> // For the cached core mesh

class vtkCamera;
class vtkMatrix4x4;
class vtkProp3D;
class vtkRenderer;

class SILHOUETTESMOOTHINGFILTERSSILHOUETTE_EXPORT vtkFaceSilhouetteLines
  : public vtkPolyDataAlgorithm
{
public:
  static vtkFaceSilhouetteLines* New();
  vtkTypeMacro(vtkFaceSilhouetteLines, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The camera that defines the view. Required unless a renderer is set.
   */
  virtual void SetCamera(vtkCamera*);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /**
   * Optional: the prop that renders the data; its matrix takes the eye into
   * the data's model coordinates. Takes precedence over ModelMatrix. Held by
   * a weak reference.
   */
  virtual void SetProp3D(vtkProp3D*);
  vtkProp3D* GetProp3D();
  ///@}

  ///@{
  /**
   * Optional: the model-to-world matrix of the data, used when no prop is set.
   */
  virtual void SetModelMatrix(vtkMatrix4x4*);
  vtkGetObjectMacro(ModelMatrix, vtkMatrix4x4);
  ///@}

  ///@{
  /**
   * Optional: a renderer whose active camera is used when no camera is set.
   * Held by a weak reference.
   */
  virtual void SetRenderer(vtkRenderer*);
  vtkRenderer* GetRenderer();
  ///@}

  /**
   * Changes when the view changes (compared by value), besides the usual
   * parameter changes.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkFaceSilhouetteLines();
  ~vtkFaceSilhouetteLines() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkCamera* Camera = nullptr;
  vtkWeakPointer<vtkProp3D> Prop3D;
  vtkMatrix4x4* ModelMatrix = nullptr;
  vtkWeakPointer<vtkRenderer> Renderer;

private:
  vtkFaceSilhouetteLines(const vtkFaceSilhouetteLines&) = delete;
  void operator=(const vtkFaceSilhouetteLines&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
