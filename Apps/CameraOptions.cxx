#include "CameraOptions.h"

#include "CliErrors.h"

#include <vtkCamera.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkRenderer.h>
#include <vtkTransform.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <regex>

namespace cli
{
namespace
{

double Length(const std::array<double, 3>& v)
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

std::array<double, 3> Difference(const double a[3], const double b[3])
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

// Whether `up` cannot orient a camera looking along `direction`.
// `v` divided by its largest component, so that products of huge or tiny
// coordinates neither overflow nor underflow.
std::array<double, 3> Scaled(const std::array<double, 3>& v)
{
  const double largest = std::max({ std::abs(v[0]), std::abs(v[1]), std::abs(v[2]) });
  return largest > 0.0 ? std::array<double, 3>{ v[0] / largest, v[1] / largest, v[2] / largest }
                       : v;
}

constexpr std::array<double, 3> DefaultViewUp{ 0, 1, 0 };

std::string ParallelViewUpMessage(const CameraOptions& camera)
{
  return camera.ViewUp
    ? "option '--view-up' is parallel to the viewing direction"
    : "the default view-up (0 1 0) is parallel to the viewing direction; give --view-up";
}

bool IsParallel(const std::array<double, 3>& up, const std::array<double, 3>& direction)
{
  const std::array<double, 3> u = Scaled(up);
  const std::array<double, 3> d = Scaled(direction);
  double cross[3];
  vtkMath::Cross(u.data(), d.data(), cross);
  return Length({ cross[0], cross[1], cross[2] }) <= 1e-9 * Length(u) * Length(d);
}

// vtkCamera::Elevation() keeps the view-up, so 90 degrees would leave it
// parallel to the view; turning the view-up with the camera keeps any angle valid.
void ElevateWithViewUp(vtkCamera* camera, double degrees)
{
  camera->OrthogonalizeViewUp();
  double up[3];
  camera->GetViewUp(up);
  double towardFocus[3];
  camera->GetDirectionOfProjection(towardFocus);
  double right[3];
  vtkMath::Cross(towardFocus, up, right);
  // vtkCamera::Elevation() turns the position about minus the camera's x axis.
  const double axis[3] = { -right[0], -right[1], -right[2] };
  vtkNew<vtkTransform> turn;
  turn->RotateWXYZ(degrees, axis);
  double turnedUp[3];
  turn->TransformVector(up, turnedUp);
  camera->Elevation(degrees);
  camera->SetViewUp(turnedUp);
  camera->OrthogonalizeViewUp();
}

} // namespace

std::array<int, 2> ParseViewportSize(const std::string& option, const std::string& text)
{
  static const std::regex widthByHeight(R"(([0-9]{1,9})[xX]([0-9]{1,9}))");
  std::smatch match;
  if (std::regex_match(text, match, widthByHeight))
  {
    const int width = std::stoi(match[1].str());
    const int height = std::stoi(match[2].str());
    if (width >= 1 && height >= 1 && width <= MaximumViewportSide && height <= MaximumViewportSide)
    {
      return { width, height };
    }
  }
  throw UsageError("option '" + option + "' needs WxH with sides from 1 to " +
    std::to_string(MaximumViewportSide) + " pixels, got '" + text + "'");
}

namespace
{

// The options that take no value and only switch a setting.
bool ParseSwitch(const Option& option, CameraOptions& camera)
{
  static const struct
  {
    const char* Name;
    bool CameraOptions::*Setting;
    bool Value;
  } switches[] = {
    { "--parallel", &CameraOptions::Parallel, true },
    { "--no-feature-lines", &CameraOptions::FeatureLines, false },
    { "--no-perturbation", &CameraOptions::PerturbVertices, false },
    { "--no-fold-guard", &CameraOptions::FoldPrevention, false },
    { "--round-apexes", &CameraOptions::KeepApexesPointed, false },
    { "--no-weld", &CameraOptions::Weld, false },
    { "--no-orientation", &CameraOptions::Orient, false },
    { "--no-normal-seams", &CameraOptions::NormalSeams, false },
    { "--no-flat-creases", &CameraOptions::FlatCreases, false },
    { "--double-precision", &CameraOptions::DoublePrecision, true },
  };
  for (const auto& entry : switches)
  {
    if (option.Name == entry.Name)
    {
      RejectInlineValue(option);
      camera.*entry.Setting = entry.Value;
      return true;
    }
  }
  return false;
}

// An angle of 0 to 180 degrees (a crease's, a feature's).
double TakeCreaseAngle(const Option& option, ArgumentList& arguments)
{
  const std::string text = arguments.TakeValue(option);
  const double angle = ParseNumber(option.Name, text);
  if (!(angle >= 0.0 && angle <= 180.0))
  {
    throw UsageError(
      "option '" + option.Name + "' needs degrees from 0 to 180, got '" + text + "'");
  }
  return angle;
}

// The view: image size, tolerance and camera.
bool ParseViewOption(const Option& option, ArgumentList& arguments, CameraOptions& camera)
{
  const std::string& name = option.Name;
  if (name == "--size")
  {
    camera.ViewportSize = ParseViewportSize(name, arguments.TakeValue(option));
  }
  else if (name == "--tolerance")
  {
    const std::string text = arguments.TakeValue(option);
    camera.Tolerance = ParseNumber(name, text);
    // The filter clamps anything smaller to 0.001; refuse rather than change it silently.
    if (camera.Tolerance < 1e-3)
    {
      throw UsageError("option '" + name + "' needs at least 0.001 pixels, got '" + text + "'");
    }
  }
  else if (name == "--azimuth")
  {
    camera.Azimuth = ParseNumber(name, arguments.TakeValue(option));
  }
  else if (name == "--elevation")
  {
    camera.Elevation = ParseNumber(name, arguments.TakeValue(option));
  }
  else if (name == "--zoom")
  {
    const std::string text = arguments.TakeValue(option);
    camera.Zoom = ParseNumber(name, text);
    if (camera.Zoom <= 0.0)
    {
      throw UsageError("option '" + name + "' needs a factor above 0, got '" + text + "'");
    }
  }
  else if (name == "--camera-position")
  {
    camera.CameraPosition = arguments.TakeTriple(option);
  }
  else if (name == "--focal-point")
  {
    camera.FocalPoint = arguments.TakeTriple(option);
  }
  else if (name == "--view-up")
  {
    camera.ViewUp = arguments.TakeTriple(option);
    if (Length(*camera.ViewUp) == 0.0)
    {
      throw UsageError("option '" + name + "' needs a non-zero vector");
    }
  }
  else if (name == "--view-angle")
  {
    const std::string text = arguments.TakeValue(option);
    camera.ViewAngle = ParseNumber(name, text);
    // vtkCamera clamps the angle to 179 degrees.
    if (camera.ViewAngle <= 0.0 || camera.ViewAngle > 179.0)
    {
      throw UsageError(
        "option '" + name + "' needs degrees above 0 and at most 179, got '" + text + "'");
    }
  }
  else
  {
    return false;
  }
  return true;
}

// How the surface is read: features, welding, creases, normals.
bool ParseSurfaceOption(const Option& option, ArgumentList& arguments, CameraOptions& camera)
{
  const std::string& name = option.Name;
  if (name == "--feature-angle")
  {
    camera.FeatureAngle = TakeCreaseAngle(option, arguments);
  }
  else if (name == "--flat-crease-angle")
  {
    camera.FlatCreaseAngle = TakeCreaseAngle(option, arguments);
  }
  else if (name == "--weld-tolerance")
  {
    const std::string text = arguments.TakeValue(option);
    camera.WeldTolerance = ParseNumber(name, text);
    if (!(camera.WeldTolerance >= 0.0) || !std::isfinite(camera.WeldTolerance))
    {
      throw UsageError("option '" + name + "' needs a distance of 0 or more, got '" + text + "'");
    }
  }
  else if (name == "--normals")
  {
    const std::string text = arguments.TakeValue(option);
    const char* names[] = { "angle", "area", "max", "fit" };
    int found = -1;
    for (int k = 0; k < 4; ++k)
    {
      found = text == names[k] ? k : found;
    }
    if (found < 0)
    {
      throw UsageError("option '" + name + "' needs angle, area, max or fit, got '" + text + "'");
    }
    camera.NormalEstimation = found;
  }
  else
  {
    return false;
  }
  return true;
}

} // namespace

bool ParseCameraOption(const Option& option, ArgumentList& arguments, CameraOptions& camera)
{
  return ParseSwitch(option, camera) || ParseViewOption(option, arguments, camera) ||
    ParseSurfaceOption(option, arguments, camera);
}

void CheckCameraOptions(const CameraOptions& camera)
{
  if (!camera.CameraPosition)
  {
    if (camera.FocalPoint)
    {
      throw UsageError("option '--focal-point' needs '--camera-position'");
    }
    if (camera.ViewUp)
    {
      throw UsageError("option '--view-up' needs '--camera-position'");
    }
    return;
  }
  if (camera.FocalPoint)
  {
    const auto direction = Difference(camera.FocalPoint->data(), camera.CameraPosition->data());
    if (Length(direction) == 0.0)
    {
      throw UsageError("options '--camera-position' and '--focal-point' give the same point");
    }
    // The default view-up as much as one given: either way the options do
    // not fit together, a usage error (exit 2), as SetUpCamera() says too.
    if (IsParallel(camera.ViewUp.value_or(DefaultViewUp), direction))
    {
      throw UsageError(ParallelViewUpMessage(camera));
    }
  }
}

std::string CameraOptionsHelp()
{
  return R"(Camera options (the same for every command that takes them):
  --size WxH               viewport and image size in pixels, each side 1 to
                           16384 (default 1024x768)
  --tolerance PX           the filter's Tolerance: the largest distance in
                           pixels between the sampled and the smooth
                           silhouette, at least 0.001 (default 0.5)
  --azimuth DEG            turn the camera about the view-up through the
                           focal point (default 0)
  --elevation DEG          turn the camera up or down over the focal point;
                           the view-up turns with it (default 0)
  --zoom F                 divide the view angle (the parallel scale with
                           --parallel) by F > 0 (default 1); a view angle
                           past 1e-8 to 179 degrees is clamped, with a warning
  --camera-position X Y Z  put the camera at X Y Z instead of the framing
                           camera (default: the framing camera, see below)
  --focal-point X Y Z      the point the explicit camera looks at; needs
                           --camera-position (default: the centre of the
                           mesh's bounding box)
  --view-up X Y Z          the explicit camera's up direction; needs
                           --camera-position (default 0 1 0)
  --view-angle DEG         vertical view angle, above 0 and at most 179
                           (default 30)
  --parallel               parallel projection instead of perspective
                           (default: perspective)

Smoothing options (with the camera options wherever those are taken):
  --feature-angle DEG      edges whose faces meet at more than DEG degrees
                           (0 to 180) are feature edges (creases): drawn as
                           smooth curves, with a shading normal per side
                           (default: no such detection; creases between
                           flat faces are found anyway, see
                           --flat-crease-angle). CAD parts with chamfers,
                           flutes or grooves between curved faces want 30:
                           without it such edges are rounded and can bend
                           the faces beside them
  --no-feature-lines       ignore the input's line cells; by default a line
                           segment along a triangle edge marks that edge as a
                           feature edge
  --no-perturbation        do not lower vertices around concave silhouette
                           segments (the paper's III-E; default: lowered)
  --no-fold-guard          keep re-meshed triangles that turn over or cut
                           through others (default: such triangles are
                           re-meshed along the chord, then on their straight
                           edges, and their lowered vertices left in place)
  --round-apexes           smooth the silhouette at cone apexes too (default:
                           kept on the mesh's edges there, so cones stay
                           pointed)
  --flat-crease-angle DEG  creases between flat faces (boxes, CAD parts) are
                           edges sharper than DEG (0 to 180) whose two
                           triangles each lie flat against another neighbour,
                           and the outlines of flat faces that sharp all
                           round, such as a cone's base (default 65)
  --no-flat-creases        do not detect creases between flat faces
                           (default: detected)
  --no-normal-seams        do not take points at one position with different
                           normals as a crease (default: taken, as asset
                           files mark hard edges)
  --weld-tolerance D       points within distance D are one vertex of the
                           surface (default 0: equal coordinates)
  --no-weld                only shared point ids join triangles (default:
                           points at one position are one vertex, so texture
                           seams and triangle soups smooth as one surface)
  --no-orientation         keep the triangles' orientation as given (default:
                           made consistent per connected part, closed parts
                           outward; the output keeps the input's winding)
  --normals angle|area|max|fit
                           how the normals the input does not give are
                           estimated: face normals weighted by corner angle,
                           by area, Max's weights, or a quadric fitted to the
                           neighbours (default: area; docs/fidelity.md
                           measures them)
  --double-precision       store the output points as doubles (default: the
                           input's type; float far from the origin rounds the
                           added points)

The framing camera is vtkRenderer::ResetCamera() on the mesh's bounds: it
looks along -Z at the centre of the bounding box, view-up +Y, from the
distance at which the bounding sphere fills the --view-angle. With
--camera-position the explicit camera replaces it (a parallel camera keeps
the framing parallel scale). Then --azimuth, --elevation and --zoom are
applied in that order, to either camera. The filter gets this camera and
the --size viewport before it first runs.
)";
}

namespace
{
// The angle, in radians, that vtkRenderer::ResetCamera() fits the bounding
// sphere into: the view angle, turned from vertical to horizontal (or back)
// where the viewport's aspect makes the other one the narrower, as VTK does.
double FittingAngle(vtkCamera* camera, double viewAngle, const double aspect[2])
{
  const double half = 0.5 * vtkMath::RadiansFromDegrees(viewAngle);
  const bool horizontal = camera->GetUseHorizontalViewAngle();
  if (aspect[0] >= 1.0)
  {
    return horizontal ? 2.0 * std::atan(std::tan(half) / aspect[0]) : 2.0 * half;
  }
  return horizontal ? 2.0 * half : 2.0 * std::atan(std::tan(half) * aspect[0]);
}
}

void WarnIfTooSmallOrLargeToDraw(const double bounds[6])
{
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  if (!std::isfinite(diagonal) || diagonal == 0.0)
  {
    return; // nothing to frame: reported elsewhere
  }
  char size[32];
  std::snprintf(size, sizeof size, "%.3g", diagonal);
  if (diagonal < 1e-21)
  {
    std::cerr << "silhouette: warning: the mesh is " << size
              << " across, too small for VTK to draw (its camera keeps the clipping planes at "
                 "least 1e-20 apart): the image will be blank; scale the mesh up\n";
  }
  else if (diagonal > 1e37)
  {
    std::cerr << "silhouette: warning: the mesh is " << size
              << " across, too large for OpenGL's single precision: the image will be blank or "
                 "cut; scale the mesh down\n";
  }
}

void SetUpCamera(vtkRenderer* renderer, const double bounds[6], const CameraOptions& options)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetParallelProjection(options.Parallel);
  camera->SetViewAngle(options.ViewAngle);
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);

  // A mesh with NaN coordinates has no frame; the filter reports those points.
  bool finiteBounds = true;
  for (int i = 0; i < 6; ++i)
  {
    finiteBounds = finiteBounds && std::isfinite(bounds[i]);
  }
  if (finiteBounds)
  {
    renderer->ResetCamera(bounds);
    // VTK 9.1's ResetCamera() also sets the view angle back to 30 degrees,
    // and frames the bounding sphere for that angle: put the given angle back
    // and move the camera to the distance at which the sphere fills it.
    const double framedAngle = camera->GetViewAngle();
    if (framedAngle != options.ViewAngle)
    {
      double aspect[2];
      renderer->GetAspect(aspect);
      camera->Dolly(std::sin(0.5 * FittingAngle(camera, options.ViewAngle, aspect)) /
        std::sin(0.5 * FittingAngle(camera, framedAngle, aspect)));
      camera->SetViewAngle(options.ViewAngle);
    }
  }

  if (options.CameraPosition)
  {
    const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
      0.5 * (bounds[4] + bounds[5]) };
    const double* focus = options.FocalPoint ? options.FocalPoint->data() : centre;
    const double* position = options.CameraPosition->data();
    const std::array<double, 3> up = options.ViewUp.value_or(DefaultViewUp);
    const auto direction = Difference(focus, position);
    // Without --focal-point the mesh decides the direction, but it is still
    // the options that do not fit: usage errors, as in CheckCameraOptions().
    if (Length(direction) == 0.0)
    {
      throw UsageError("the camera position is the focal point (the centre of the mesh's "
                       "bounding box); give another --camera-position or a --focal-point");
    }
    if (IsParallel(up, direction))
    {
      throw UsageError(ParallelViewUpMessage(options));
    }
    // Focal point last: vtkCamera moves the focal point when the position lands on it.
    camera->SetPosition(position);
    camera->SetFocalPoint(focus);
    camera->SetViewUp(up.data());
    camera->OrthogonalizeViewUp();
  }

  if (options.Azimuth != 0.0)
  {
    camera->Azimuth(options.Azimuth);
  }
  if (options.Elevation != 0.0)
  {
    ElevateWithViewUp(camera, options.Elevation);
  }
  if (options.Zoom != 1.0)
  {
    // VTK keeps a view angle within [1e-8, 179] degrees: a zoom past that
    // is clamped, which the user is told (it changes nothing more).
    const double wanted = camera->GetViewAngle() / options.Zoom;
    camera->Zoom(options.Zoom);
    if (!camera->GetParallelProjection() && camera->GetViewAngle() != wanted)
    {
      std::cerr << "silhouette: warning: --zoom " << options.Zoom << " asks for a view angle of "
                << wanted << " degrees; VTK keeps it within 1e-08 to 179, so it is "
                << camera->GetViewAngle() << "\n";
    }
  }
  if (finiteBounds)
  {
    renderer->ResetCameraClippingRange(bounds);
  }
}

} // namespace cli
