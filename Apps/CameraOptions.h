#ifndef CameraOptions_h
#define CameraOptions_h

#include "ArgumentList.h"

#include <array>
#include <optional>
#include <string>

class vtkCamera;
class vtkRenderer;

namespace cli
{

/// The view options shared by `smooth` and `render`: the filter must see the
/// very camera and viewport the renderer uses, so both come from here.
struct CameraOptions
{
  std::array<int, 2> ViewportSize{ 1024, 768 };
  double Tolerance = 0.5;
  double Azimuth = 0.0;
  double Elevation = 0.0;
  double Zoom = 1.0;
  std::optional<std::array<double, 3>> CameraPosition;
  std::optional<std::array<double, 3>> FocalPoint;
  std::optional<std::array<double, 3>> ViewUp;
  double ViewAngle = 30.0;
  bool Parallel = false;
  /// Smoothing options beside the tolerance (the filter's defaults).
  std::optional<double> FeatureAngle; ///< detect feature edges sharper than this
  bool FeatureLines = true;           ///< line cells mark feature edges
  bool PerturbVertices = true;
  bool FoldPrevention = true;
  bool KeepApexesPointed = true;
  bool Weld = true;                      ///< points at one position are one vertex
  double WeldTolerance = 0.0;            ///< 0: equal coordinates only
  bool Orient = true;                    ///< consistent orientation per component
  bool NormalSeams = true;               ///< normals split at a point mark a crease
  bool FlatCreases = true;               ///< creases between flat faces
  std::optional<double> FlatCreaseAngle; ///< the filter's default when unset
  bool DoublePrecision = false;          ///< output points in double
  int NormalEstimation = 1;              ///< vtkSilhouetteSmoothingFilter's enum (area)
};

/// Largest accepted viewport side, to keep images and buffers sane.
constexpr int MaximumViewportSide = 16384;

/// Consumes `option` (and its values) if it is a camera option; false if not.
/// Throws UsageError for bad values.
/// "WxH" with sides from 1 to MaximumViewportSide, or UsageError naming `option`.
std::array<int, 2> ParseViewportSize(const std::string& option, const std::string& text);

bool ParseCameraOption(const Option& option, ArgumentList& arguments, CameraOptions& camera);

/// Checks that need several options at once; throws UsageError.
void CheckCameraOptions(const CameraOptions& camera);

/// The help text of the camera options, with their defaults.
std::string CameraOptionsHelp();

/**
 * Sets the renderer's active camera: framed on `bounds` the way
 * vtkRenderer::ResetCamera() does (looking along -Z, view-up +Y), or the
 * explicit camera; then azimuth, elevation and zoom, in that order. The
 * renderer must already be in a window of the viewport size, as the framing
 * depends on the aspect ratio. Throws UsageError when the explicit camera does
 * not fit the mesh (the position at its centre, the view-up along the view).
 */
void SetUpCamera(vtkRenderer* renderer, const double bounds[6], const CameraOptions& options);

/**
 * Prints a warning when a mesh of these bounds is too small or too large for
 * VTK 9.1 to draw (an image of it comes out blank): below about 1e-21
 * across, its camera keeps the clipping planes farther apart than the mesh
 * is deep; above about 1e37, OpenGL's single precision overflows. Measured
 * on spheres: radius 1e-21 and 1e36 draw, 1e-22 and 1e38 come out blank.
 */
void WarnIfTooSmallOrLargeToDraw(const double bounds[6]);

} // namespace cli

#endif
