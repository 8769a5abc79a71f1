/**
 * @class   vtkPVSilhouetteSmoothingFilter
 * @brief   vtkSilhouetteSmoothingFilter with its camera as plain properties, for ParaView
 *
 * ParaView cannot hand a server-side filter the view's vtkCamera: the camera
 * proxy lives on the client. This subclass owns a vtkCamera and fills it from
 * plain values (position, focal point, view-up, view angle, parallel projection
 * and scale), which the server-manager XML exposes as properties; a script
 * copies them from the render view (`view.CameraPosition` and so on), together
 * with the viewport size (`view.ViewSize`).
 *
 * Every rank of a parallel run gets the same values, so the pieces of a mesh
 * split across ranks are smoothed for the same view.
 */
#ifndef vtkPVSilhouetteSmoothingFilter_h
#define vtkPVSilhouetteSmoothingFilter_h

#include "SilhouetteSmoothingParaViewSilhouetteModule.h" // For export macro
#include "vtkNew.h"                                      // For the camera
#include "vtkSilhouetteSmoothingFilter.h"

class SILHOUETTESMOOTHINGPARAVIEWSILHOUETTE_EXPORT vtkPVSilhouetteSmoothingFilter
  : public vtkSilhouetteSmoothingFilter
{
public:
  static vtkPVSilhouetteSmoothingFilter* New();
  vtkTypeMacro(vtkPVSilhouetteSmoothingFilter, vtkSilhouetteSmoothingFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The view, copied into the internal camera (see vtkCamera for each).
   * Defaults are vtkCamera's: at (0, 0, 1) looking at the origin, +Y up, a
   * 30 degree view angle, perspective, parallel scale 1.
   */
  void SetCameraPosition(double x, double y, double z);
  void SetCameraFocalPoint(double x, double y, double z);
  void SetCameraViewUp(double x, double y, double z);
  void SetCameraViewAngle(double degrees);
  void SetCameraParallelProjection(int parallel);
  void SetCameraParallelScale(double scale);
  ///@}

protected:
  vtkPVSilhouetteSmoothingFilter();
  ~vtkPVSilhouetteSmoothingFilter() override;

  vtkNew<vtkCamera> ViewCamera; // what the properties set; also the superclass's Camera

private:
  vtkPVSilhouetteSmoothingFilter(const vtkPVSilhouetteSmoothingFilter&) = delete;
  void operator=(const vtkPVSilhouetteSmoothingFilter&) = delete;
};

#endif
