#ifndef Rendering_h
#define Rendering_h

#include "CommandLine.h"

#include <vtkSmartPointer.h>

#include <array>
#include <string>

class vtkActor;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;
class vtkSilhouetteSmoothingFilter;
class vtkSilhouetteSmoothingMapper;

namespace cli
{

class FileBatch;

/// An offscreen window of the viewport size with one renderer. `smooth`
/// uses it only to frame the camera, so both commands frame alike; nothing
/// touches the display until the first Render().
struct OffscreenView
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
};
OffscreenView MakeOffscreenView(const std::array<int, 2>& size);

/// Throws UsageError unless `path` ends in .png (any letter case), and
/// RuntimeError when its folder is missing.
void CheckImageOutputPath(const std::string& path);

/// `render`'s output: a .png, or an .svg or .pdf drawing with a line style;
/// throws UsageError otherwise, for --width-by-depth or --join-lines
/// without a drawing and for
/// --hidden dashed in a PNG of a style other than lines (all options that
/// do not go together), for a .pdf smaller than CheckPdfPageSize allows,
/// RuntimeError when the folder is missing.
void CheckRenderOutputPath(const RenderOptions& options);
/// Throws UsageError for a PDF page of fewer than 4 x 4 pixels: PDF's
/// smallest page is 3 x 3 points, and a pixel is 0.75 pt.
void CheckPdfPageSize(const std::array<int, 2>& size);
/// Whether `style` draws lines (lines and the brushes), not a surface.
bool IsLineStyle(RenderStyle style);

/// Throws RuntimeError when the program renders through X and there is no
/// X display (VTK would abort the program); does nothing with OSMesa.
void RequireDisplay();

/// The palette of the drawings.
inline constexpr double White[3] = { 1.0, 1.0, 1.0 };
inline constexpr double Black[3] = { 0.0, 0.0, 0.0 };
inline constexpr double LightGrey[3] = { 0.82, 0.82, 0.80 };
inline constexpr double DarkGrey[3] = { 0.30, 0.30, 0.30 };
inline constexpr double Red[3] = { 0.90, 0.0, 0.0 };

/// Edges over an unlit white fill, drawn in one pass: the fill hides the
/// edges behind the mesh without the z-fighting of a hidden-line pass.
void ShowEdges(vtkActor* actor, const double color[3]);

/// The shaded style's look: light grey, Phong interpolation, a little
/// specular.
void ShadeAsSurface(vtkActor* actor);

/// Writes the window's last frame to a PNG file (re-rendering only an
/// onscreen window), or adds it to `batch`; throws RuntimeError on failure.
/// Returns whether the frame is all its first renderer's background (nothing drawn).
bool WriteWindowPng(vtkRenderWindow* window, const std::string& path, FileBatch* batch = nullptr);

/**
 * Adds to `renderer` the actors that draw `style`: of the filter's output, or
 * of `input` when `smoothed` is false (shaded then uses the filter's shading
 * normals, so the two differ in geometry only). The actors are fed by the
 * filter's ports, so a renderer the filter follows (the viewer's) shows each
 * new view's smoothing. The filter must be up to date. The line styles draw
 * the visible parts of the lines; `hiddenLines` adds the hidden parts of the
 * lines style in light grey. With a `mapper` (its input set), the shaded
 * style smoothed draws through it instead of the filter's output: `render`
 * and the viewer draw that style at render time.
 */
void AddStyleActors(vtkRenderer* renderer, vtkSilhouetteSmoothingFilter* filter, vtkPolyData* input,
  RenderStyle style, bool smoothed, bool hiddenLines = false,
  vtkSilhouetteSmoothingMapper* mapper = nullptr);

/**
 * Draws `options.Style` of the filter's output (or of `input` with
 * --no-smoothing) into `view` with the camera already set up, and writes
 * the PNG image (or adds it to `batch`). Throws RuntimeError on any VTK error.
 * Returns whether the image is all background (nothing drawn).
 */
bool RenderToPng(const OffscreenView& view, vtkSilhouetteSmoothingFilter* filter,
  vtkPolyData* input, const RenderOptions& options, FileBatch* batch = nullptr);

/**
 * Writes the line style `options.Style` as an SVG or PDF drawing, as
 * `options.Output` names it (VectorDrawing.h):
 * the visible lines (or, for the brushes, their strokes) projected with the
 * view's camera, and with `options.HiddenLines` the hidden pieces, dashed.
 * Nothing is rendered: no display is needed. Throws RuntimeError on any VTK
 * error or a failed write. With a `batch`, the file is added to it.
 * Returns whether no visible line has a point in the image (a blank drawing).
 */
bool RenderToDrawing(const OffscreenView& view, vtkSilhouetteSmoothingFilter* filter,
  vtkPolyData* input, const RenderOptions& options, FileBatch* batch = nullptr);

} // namespace cli

#endif
