/**
 * @class   vtkSilhouetteViewAlgorithm
 * @brief   abstract superclass of the module's view-dependent polydata filters: the camera, the
 * model matrix and the viewport, and re-running when the view changes
 *
 * The view of vtkSilhouetteSmoothingFilter, vtkBoundaryCurveSmoothingFilter,
 * vtkFaceSilhouetteLines and vtkSilhouetteProximity, given the same way for
 * all of them:
 * - a camera (SetCamera), or a renderer (SetRenderer) whose active camera is
 *   used when no camera is set; the renderer's camera is taken only once the
 *   renderer has created it (asking for it would create one, and a renderer
 *   that already has a camera skips its first automatic reset);
 * - optionally the prop that renders the data (SetProp3D), whose matrix takes
 *   the eye into the data's model coordinates, or that matrix itself
 *   (SetModelMatrix), used when no prop is set;
 * - the viewport size in pixels: the renderer's size, else SetViewportSize
 *   (default 1024 x 768). A subclass whose output does not depend on the
 *   viewport ignores it (see ViewportDependent).
 *
 * The renderer and the prop are held by weak references (the usual renderer
 * -> actor -> mapper -> filter chain makes no reference loop); the camera and
 * the model matrix by ordinary ones.
 *
 * GetMTime() changes whenever the view changes in a way that changes the
 * result (the camera's model-view matrix and projection parameters, not its
 * clipping range; the prop's or model matrix; the viewport), compared by
 * value: a mapper fed by such a filter re-runs it when the view moves, and not
 * when a renderer only resets the clipping range before each frame.
 *
 * Subclasses implement RequestViewData(), which gets the view in the data's
 * model coordinates, and may say what to output while a renderer has not
 * created its camera yet (RequestDataWithoutCamera(): empty outputs by
 * default).
 *
 * @sa vtkSilhouetteSmoothingFilter vtkBoundaryCurveSmoothingFilter vtkFaceSilhouetteLines
 * vtkSilhouetteProximity
 */
#ifndef vtkSilhouetteViewAlgorithm_h
#define vtkSilhouetteViewAlgorithm_h

#include "SilhouetteSmoothingFiltersSilhouetteModule.h" // For export macro
#include "vtkSilhouettePolyDataAlgorithm.h"             // For the superclass
#include "vtkWeakPointer.h"                             // For the renderer and prop

#include <memory> // For the view tracker

class vtkCamera;
class vtkMatrix4x4;
class vtkProp3D;
class vtkRenderer;

namespace vtkSilhouetteFilterSupport
{
struct View;
}

class SILHOUETTESMOOTHINGFILTERSSILHOUETTE_EXPORT vtkSilhouetteViewAlgorithm
  : public vtkSilhouettePolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkSilhouetteViewAlgorithm, vtkSilhouettePolyDataAlgorithm);
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
   * the data's model coordinates. Takes precedence over ModelMatrix. Held by a
   * weak reference: the prop usually owns the mapper that owns this filter.
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
   * Optional: a renderer to take the camera (its active camera, when no camera
   * is set) and the viewport size from. Held by a weak reference, so the usual
   * renderer -> actor -> mapper -> filter chain makes no reference loop.
   */
  virtual void SetRenderer(vtkRenderer*);
  vtkRenderer* GetRenderer();
  ///@}

  ///@{
  /**
   * Viewport size in pixels, used when no renderer is set. Default 1024 x 768.
   */
  vtkSetVector2Macro(ViewportSize, int);
  vtkGetVector2Macro(ViewportSize, int);
  ///@}

  /**
   * Changes when the view changes in a way that changes the result (compared
   * by value), besides the usual parameter changes.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkSilhouetteViewAlgorithm();
  ~vtkSilhouetteViewAlgorithm() override;

  /**
   * Requests the view (RequestView) and runs RequestViewData with it. While a
   * renderer has not created its camera (it asks for its props' bounds before
   * it makes one, to reset it), runs RequestDataWithoutCamera instead, if
   * WaitForRenderer is on; else that is an error like a missing camera. A
   * view that cannot be made (no camera, a degenerate view or viewport) is
   * reported and fails the request.
   */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The subclass's work for `view`, the view in the data's model coordinates.
  /// The first input port and every output hold polydata (RequestData
  /// checked them).
  virtual int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) = 0;

  /// What to output before a renderer has created its camera. The default
  /// leaves the outputs empty, or with PassInputWithoutCamera gives the input
  /// on the first output, and succeeds.
  virtual int RequestDataWithoutCamera(
    vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  /// For RequestDataWithoutCamera: the input on the first output (the
  /// smoothing filters, whose output stands for their input). Set in the
  /// subclass's constructor.
  bool PassInputWithoutCamera = false;

  /// Whether a renderer without its camera yet means "wait"
  /// (RequestDataWithoutCamera), the default, or an error. Set in the
  /// subclass's constructor.
  bool WaitForRenderer = true;

  /// What RequestView() found.
  enum ViewStatus
  {
    VIEW_READY = 0,         ///< the view is filled in
    VIEW_NO_CAMERA_YET = 1, ///< a renderer is set but has not created its camera yet
    VIEW_FAILED = 2         ///< no camera at all, or a degenerate view or viewport
  };

  /**
   * For RequestData(): the view in the data's model coordinates (for the
   * camera, the model matrix and the viewport above). Returns VIEW_READY with
   * `view` filled in, or VIEW_FAILED after reporting the error. A renderer
   * asks for its props' bounds before it creates its camera (to reset it):
   * with `waitForRenderer` on, a renderer without a camera yet gives
   * VIEW_NO_CAMERA_YET (no error) and the subclass decides what to output
   * until the camera exists; with it off, that fails like a missing camera.
   */
  ViewStatus RequestView(vtkSilhouetteFilterSupport::View& view, bool waitForRenderer = true);

  vtkCamera* Camera = nullptr;
  vtkWeakPointer<vtkProp3D> Prop3D;
  vtkMatrix4x4* ModelMatrix = nullptr;
  vtkWeakPointer<vtkRenderer> Renderer;
  int ViewportSize[2] = { 1024, 768 };

  /// False in a subclass whose output does not depend on the viewport: the
  /// view then uses a fixed 1 x 1 viewport, so window resizes (and
  /// ViewportSize) do not re-run it. Set in the subclass's constructor, or
  /// by a setting that makes the output depend on the viewport
  /// (vtkSilhouetteLineVisibility::SetOutlinePixels).
  bool ViewportDependent = true;

private:
  vtkSilhouetteViewAlgorithm(const vtkSilhouetteViewAlgorithm&) = delete;
  void operator=(const vtkSilhouetteViewAlgorithm&) = delete;

  struct ViewInternals;
  std::unique_ptr<ViewInternals> ViewInternal;
};

#endif
