#include "CommandLine.h"

#include "EvaluationModels.h"

#include "CliErrors.h"
#include "Smoothing.h"
#include "Viewer.h"

#include <vector>

namespace cli
{
namespace
{

std::string MainHelp()
{
  return R"(Usage: silhouette COMMAND [ARGUMENTS]

View-dependent silhouette smoothing of coarse triangle meshes (L. Wang et
al., "Silhouette Smoothing for Real-Time Rendering of Mesh Surfaces", IEEE
TVCG 14(3), 2008), with vtkSilhouetteSmoothingFilter.

Commands:
  smooth INPUT [-o OUTPUT] [--lines-output LINES.vtp] [--json] [camera options]
      smooth the silhouette of INPUT for one view, optionally write the
      result, and print figures about it
  render INPUT -o IMAGE.png|DRAWING.svg [--style STYLE] [--no-smoothing]
         [--hidden none|dashed] [--width-by-depth] [--lod] [--json]
         [camera options]
  render INPUT --style STYLE --progressive N [--svg] -o DIR [options]
      render INPUT offscreen to a PNG image (or a line style to an SVG
      drawing, or N drawings along its progressive mesh) and print the
      same figures
  generate sphere|torus -o OUTPUT [shape options]
      write an analytic test mesh with exact normals
  simplify INPUT -o OUTPUT --triangles N [options] [camera options]
      quadric simplification to N triangles keeping more detail near the
      contour of one view (Mata et al.'s silhouette proximity)
  compare MODEL|MESH|all ... [options]
      coarse, coarse + smoothing and a fine OpenSubdiv reference, measured
      from the same cameras: outline deviations and whole-frame times
  figure MODEL|MESH -o FIGURE.png [--plot PLOT.png] [options]
      the four labelled panels of Xing's Fig. 1, and a time plot
  view [MODEL|MESH] [options]
      the interactive viewer (keys, overlays, a tolerance slider), or a
      headless orbit to numbered PNGs with per-frame figures
  help [COMMAND]
      show this help, or the help of COMMAND

Run 'silhouette COMMAND --help' for the options of a command.

Exit status: 0 on success, 1 when the work fails (a file, the data or VTK),
2 for a wrong command line.
)";
}

std::string FiguresHelp()
{
  return "Figures: the input's triangles (after triangulating polygons and strips),\n"
         "the output's triangles, the silhouette triangles that were re-meshed, the\n"
         "new triangles and new points that replaced them, and two times in\n"
         "milliseconds (std::chrono::steady_clock, the mesh already in memory):\n"
         "the filter's first Update(), which also prepares the view-independent\n"
         "data (triangles, edge table, normals) once per mesh, and the time of one\n"
         "frame after that (what each camera move costs): the median of " +
    std::to_string(TimedFilterRuns) +
    " runs.\n"
    "Reading, camera set-up, writing and rendering are not timed.\n"
    "With --json they are one JSON object on stdout with the keys input, output\n"
    "(a path or null), input_triangles, output_triangles, silhouette_triangles,\n"
    "new_triangles, new_points, fold_fallbacks {chord_triangles, straight_points,\n"
    "straight_feature_segments, pinned_points, unresolved}, prepare_ms,\n"
    "filter_ms, tolerance, viewport [w, h]\n"
    "and camera {position, focal_point, view_up, view_angle, parallel}.\n";
}

std::string SmoothHelp()
{
  return R"(Usage: silhouette smooth INPUT [-o OUTPUT] [--lines-output LINES.vtp] [--json]
                        [camera options]

Reads INPUT, smooths its silhouette for the view of the camera options with
vtkSilhouetteSmoothingFilter, writes the result if -o is given, and prints
figures about it. The extension of INPUT, in any letter case, picks the
reader: .ply (vtkPLYReader), .obj (vtkOBJReader), .stl (vtkSTLReader), .vtp
(vtkXMLPolyDataReader) or .vtk (vtkPolyDataReader; legacy POLYDATA only).

Options:
  -o, --output FILE   write the smoothed mesh to FILE: .vtp (VTK XML, binary,
                      zlib-compressed: every array) or .ply (binary: points,
                      polygons, normals, texture coordinates and colours; the
                      arrays it cannot hold are named on stderr) (default:
                      nothing is written)
  --lines-output FILE write the smoothed silhouette polylines (the filter's
                      second output, with normals) to FILE, a .vtp (default:
                      nothing is written)
  --json              print the figures as one JSON object instead of text
                      (default: text)
  -h, --help          show this help and exit

)" + CameraOptionsHelp() +
    "\n" + FiguresHelp();
}

std::string RenderHelp()
{
  return R"(Usage: silhouette render INPUT -o IMAGE.png|DRAWING.svg [--style STYLE]
                        [--no-smoothing] [--hidden none|dashed]
                        [--width-by-depth] [--lod] [--json] [camera options]
       silhouette render INPUT --style STYLE --progressive N [--svg] -o DIR
                        [the same options]

Reads INPUT like 'silhouette smooth', smooths its silhouette for the view of
the camera options, renders it offscreen at --size with that same camera
(no multisampling, so images are repeatable), writes a PNG image and prints
the same figures as 'silhouette smooth'. Where there is no X display it
renders through OSMesa (--backend). The line styles can also be written as
an SVG drawing: the same visible lines as paths in image coordinates
(pixels from the top-left corner, one path per visible piece), projected
with the same camera and nothing rendered, so no display is needed.

Options:
  -o, --output FILE       the image to write; required: a .png, or an .svg
                          with a line style (lines, charcoal, lazy, hand,
                          rough)
  --style STYLE           what to draw (default: shaded):
                          shaded        the smoothed mesh in light grey on
                                        white, Phong shading with the
                                        filter's normals
                          wireframe     the mesh's edges in black on white,
                                        hidden edges removed
                          new-geometry  like wireframe, with the edges of the
                                        triangles the smoothing made
                                        (NewGeometry > 0) in red and the
                                        others dark grey
                          lines         the visible parts of the lines of
                                        a drawing, in black, 2 pixels wide,
                                        on white, without the mesh: the
                                        smoothed silhouette polylines (the
                                        filter's second output) and the
                                        smoothed surface's creases and open
                                        borders (vtkCreaseAndBorderLines:
                                        creases are where its normals jump,
                                        at the feature edges the filter
                                        found), with the parts that surface
                                        hides left out
                                        (vtkSilhouetteLineVisibility)
                          charcoal, lazy, hand, rough
                                        the same visible lines drawn as
                                        stylized strokes (Kim and Choe,
                                        vtkStylizedStrokeFilter), black,
                                        2 pixels wide: charcoal a fine
                                        sawtooth across the stroke, lazy
                                        slow parabolic arcs, hand gentle
                                        noise along and across, rough
                                        larger noise along the stroke;
                                        seeded, so images repeat. With
                                        --no-smoothing the strokes follow
                                        the edges 'lines' draws then
  --no-smoothing          draw the unsmoothed input in the same style: shaded
                          still uses the filter's shading normals; lines draws
                          the visible parts of the face-based silhouette
                          (vtkFaceSilhouetteLines: in each silhouette
                          triangle the straight segment
                          between the zero crossings of the linearly
                          interpolated N.(E-V) on its two mixed edges, with
                          the filter's normals), and the input's creases
                          (where its point normals jump; without normals,
                          edges sharper than --feature-angle, else than
                          --flat-crease-angle) and open borders (default:
                          smoothed). The figures still describe the
                          smoothing.
  --hidden none|dashed    the parts of the lines the surface hides: left out
                          (none), or drawn in grey (dashed): dashed and
                          thinner in an SVG drawing, with any line style;
                          solid light grey in a PNG image, with --style
                          lines only (default: none)
  --width-by-depth        in an SVG drawing, each visible line's width
                          follows its distance from the eye: 2 pixels at the
                          focal point's distance, times that distance over
                          the point's, within 0.5 to 8 pixels (default: 2
                          pixels everywhere)
  --lod                   refine INPUT for the view first (view-dependent
                          level of detail, vtkViewDependentLevelOfDetail): a
                          hierarchy of its edge collapses is built once, and
                          the view keeps the splits whose error on screen is
                          over 0.5 pixels where the outline may be and over
                          1 pixel where the surface faces the viewer (back
                          faces stay coarse); the smoothing, the drawing and
                          the figures then take that mesh, and a line before
                          the figures (on stderr with --json) gives its
                          triangles and the time (default: the whole INPUT)
  --progressive N         Kim and Choe's progressive sketch: N drawings (2 to
                          64) of a line style along INPUT's progressive mesh
                          (vtkProgressiveMeshFilter), from its base mesh to
                          INPUT itself at triangle counts spaced
                          geometrically, each smoothed and its hidden lines
                          removed, all from the camera that frames INPUT;
                          -o names a directory (made if missing, not its
                          parents) that gets sketch-01.png ... sketch-NN.png,
                          and one line of figures per drawing (a JSON array
                          with --json) (default: one drawing)
  --svg                   with --progressive, write sketch-NN.svg drawings
                          (default: PNG images)
  --lines-output FILE     also write the smoothed silhouette polylines to
                          FILE, a .vtp (default: nothing is written)
  --json                  print the figures as one JSON object instead of text
                          (default: text); its "output" is the image
)" + RenderBackendHelp(26) +
    R"(  -h, --help              show this help and exit

)" + CameraOptionsHelp() +
    "\n" + FiguresHelp();
}

std::string GenerateHelp()
{
  return R"(Usage: silhouette generate sphere|torus -o OUTPUT [shape options]

Writes an analytic mesh whose points lie exactly on the surface, with the
exact surface normals as point normals: the meshes whose true silhouette is
known, for measuring accuracy. OUTPUT is .vtp (keeps the normals) or .ply.

  sphere   an icosphere (vtkIcosphereSource): an icosahedron whose triangles
           are split into four per level, new points pushed onto the sphere
  torus    a torus about +Z (vtkTorusSurfaceSource): a regular grid of
           ring x tube samples, two triangles per quad, seams joined

Options:
  -o, --output FILE        the file to write (.vtp or .ply); required
  --level N                sphere: subdivision level, 0 to 8; 20 * 4^N
                           triangles (default 1: 80 triangles)
  --radius R               the sphere's radius, or the torus's ring radius
                           (distance from the axis to the tube's centre)
                           (default 1)
  --tube-radius R          torus: the tube's radius (default 0.4)
  --ring-resolution N      torus: samples around the ring, at least 3
                           (default 24)
  --tube-resolution N      torus: samples around the tube, at least 3
                           (default 12); the torus has 2 * ring * tube
                           triangles
  -h, --help               show this help and exit
)";
}

std::string ViewHelp()
{
  return R"(Usage: silhouette view [MODEL|MESH] [options] [camera options]
       silhouette view [MODEL|MESH] --orbit DEG --frames N [--record DIR] [--json] ...
       silhouette view [MODEL|MESH] --play LOG [--screenshot-dir DIR] [--json] ...

Opens a VTK render window with trackball camera interaction on the mesh,
smoothed by vtkSilhouetteSmoothingFilter. The filter is fed the window's
renderer, so it re-runs by itself whenever the camera moves (through the
pipeline and its MTime). The window needs an X display; the headless modes
(--orbit, --play) render through OSMesa where there is none (--backend).

MODEL|MESH: a model of the evaluation set (bunny, sphere, torus, ellipsoid,
supertoroid, knot), shown as its coarse version (quadric decimation of the
original, as 'silhouette compare' makes it), or a mesh file (.ply .obj .stl
.vtp .vtk). Default: the bundled coarse bunny, Data/bunny_coarse.ply. The
side-by-side fine reference is OpenSubdiv Loop refinement of the original
(of the file itself for a mesh file), made the first time it is shown.

)" + std::string("Keys (in the window, where h shows them too):\n") +
    ViewerKeysHelp() +
    R"(
w, n and l switch to their style, or back to shaded when it is on already.
f makes the fine reference the first time (Loop level --fine-level of the
original; the status line says so, it takes a moment), then shows it on the
right, sharing the camera: shaded, or as its face-based silhouette lines in
the lines style. + and - double and halve the tolerance within the slider's 0.1
to 5 px. r goes back to the camera of the camera options, keeping the
projection. c writes silhouette_view_NNNN.png (the first free number) to the
screenshot folder and prints where. VTK's other trackball keys (3 stereo,
j/t joystick, u user, fly-to, pick) do nothing here.

The overlay (top left) shows the mesh, the style, the triangles in and out,
the silhouette triangles and new triangles of the last filter run, the
tolerance, and the times: frames per second from the wall time between the
ends of the last 20 renders of the main view (a gap of over a second starts
the count again, so idle time is not averaged in), the renderer's own time
for the last render (vtkRenderer::GetLastRenderTimeInSeconds, which includes
running the filter when the view moved) and the filter's time (wall time of
its last execution). With smoothing off the filter does not run: the output
is the input and the silhouette and new triangles show as 0.

Options:
  --style STYLE          the style to start in: shaded, wireframe,
                         new-geometry, lines, or a stroke style (charcoal,
                         lazy, hand, rough), as 'silhouette render' draws
                         them (default: shaded)
  --no-smoothing         start with smoothing off (default: on)
  --fine-reference       start with the side-by-side fine reference
                         (default: off; key f)
  --fine-level L         Loop level of the fine reference, 1 to 5
                         (default 3)
  --coarse-triangles N   triangles of a model's coarse version (default:
                         the model's own, as in 'silhouette compare')
  --data DIR             the folder that holds bunny.ply and
                         bunny_coarse.ply (default: the project's Data/)
  --help-overlay         start with the key help shown (default: hidden;
                         key h)
  --no-overlay           no text overlays and no slider (default: shown)
  --no-times             leave the frame rate and times out of the
                         overlay, so images repeat exactly (default: shown)
  --lod                  refine the mesh for every view before it is
                         smoothed and drawn (view-dependent level of
                         detail, as 'silhouette render --lod'); the
                         overlay's and the orbit's triangles in are the
                         refined mesh's (default: the whole mesh)
  --screenshot-dir DIR   where key c (and --play) write screenshots,
                         created if missing (default: the current folder)
  --orbit DEG            headless: turn the camera DEG degrees in all
                         about the view-up through the focal point
                         (vtkCamera::Azimuth), DEG / N per frame, rendering
                         offscreen (default 360)
  --frames N             headless: the number of frames, 1 to 100000;
                         frame i is at azimuth i * DEG / N (default 36)
  --record DIR           headless: write DIR/frame_0000.png, ...; DIR is
                         created if missing (default: no images)
                         Any of --orbit, --frames and --record selects the
                         headless orbit. It prints one line per frame:
                         frame, azimuth (degrees from the start camera),
                         input, output, silhouette and new triangles,
                         filter ms (0 when it did not run) and render ms.
  --play LOG             plays a vtkInteractorEventRecorder event log in an
                         offscreen window, then exits: after the start and
                         after each key and slider move it writes
                         step_NN_ACTION.png to the screenshot folder and
                         prints the figures and the viewer's state. The
                         log's positions are pixels: play it at the --size
                         it was made for (default: no log, the window)
  --json                 with --orbit or --play: one JSON object per line
                         instead of text (default: text)
)" + RenderBackendHelp(25) +
    R"(  -h, --help             show this help and exit

)" + CameraOptionsHelp() +
    "\nThe window has the --size of the camera options (default 1024x768); the\n"
    "--tolerance option sets the slider's start value (0.1 to 5 px on the slider).\n";
}

// A whole number in [low, high] for `option`, or UsageError.
int ParseCount(const Option& option, const std::string& text, int low, int high)
{
  const double value = ParseNumber(option.Name, text);
  if (value != static_cast<double>(static_cast<long long>(value)) || value < low || value > high)
  {
    throw UsageError("option '" + option.Name + "' needs a whole number from " +
      std::to_string(low) + " to " + std::to_string(high) + ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

GenerateOptions ParseGenerate(ArgumentList& arguments)
{
  GenerateOptions options;
  bool haveShape = false;
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!LooksLikeOption(word))
    {
      if (haveShape)
      {
        throw UsageError("unexpected argument '" + word + "' (the shape is already given)");
      }
      if (word != "sphere" && word != "torus")
      {
        throw UsageError("'generate' makes a sphere or a torus, not '" + word + "'");
      }
      options.Shape = word == "sphere" ? GeneratedShape::Sphere : GeneratedShape::Torus;
      haveShape = true;
      continue;
    }
    const Option option = SplitOption(word);
    if (option.Name == "-o" || option.Name == "--output")
    {
      options.Output = arguments.TakeValue(option);
    }
    else if (option.Name == "--level")
    {
      options.Level = ParseCount(option, arguments.TakeValue(option), 0, 8);
    }
    else if (option.Name == "--ring-resolution")
    {
      options.RingResolution = ParseCount(option, arguments.TakeValue(option), 3, 100000);
    }
    else if (option.Name == "--tube-resolution")
    {
      options.TubeResolution = ParseCount(option, arguments.TakeValue(option), 3, 100000);
    }
    else if (option.Name == "--radius" || option.Name == "--tube-radius")
    {
      const std::string text = arguments.TakeValue(option);
      const double value = ParseNumber(option.Name, text);
      if (!(value > 0.0))
      {
        throw UsageError("option '" + option.Name + "' needs a number above 0, got '" + text + "'");
      }
      (option.Name == "--radius" ? options.Radius : options.TubeRadius) = value;
    }
    else
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'generate'; run 'silhouette generate --help'");
    }
  }
  if (!haveShape)
  {
    throw UsageError("'generate' needs a shape: sphere or torus");
  }
  if (options.Output.empty())
  {
    throw UsageError("'generate' needs '-o OUTPUT'");
  }
  return options;
}

CompareOptions ParseCompare(ArgumentList& arguments, RenderBackend& backend)
{
  CompareOptions options;
  bool coarsePointsGiven = false;
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!LooksLikeOption(word))
    {
      options.Inputs.push_back(word);
      continue;
    }
    const Option option = SplitOption(word);
    if (option.Name == "--coarse-triangles")
    {
      options.CoarseTriangles = ParseCount(option, arguments.TakeValue(option), 4, 10000000);
    }
    else if (option.Name == "--fine-level")
    {
      options.FineLevel = ParseCount(option, arguments.TakeValue(option), 1, 5);
    }
    else if (option.Name == "--views")
    {
      options.Views = ParseCount(option, arguments.TakeValue(option), 1, 1000);
    }
    else if (option.Name == "--frames")
    {
      options.Frames = ParseCount(option, arguments.TakeValue(option), 1, 100000);
    }
    else if (option.Name == "--size")
    {
      options.ViewportSize = ParseViewportSize(option.Name, arguments.TakeValue(option));
    }
    else if (option.Name == "--tolerance")
    {
      const std::string text = arguments.TakeValue(option);
      options.Tolerance = ParseNumber(option.Name, text);
      if (!(options.Tolerance >= 0.001))
      {
        throw UsageError(
          "option '--tolerance' needs a number of at least 0.001, got '" + text + "'");
      }
    }
    else if (option.Name == "--data")
    {
      options.DataDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--json" || option.Name == "--markdown")
    {
      RejectInlineValue(option);
      options.Format = option.Name == "--json" ? CompareFormat::Json : CompareFormat::Markdown;
    }
    else if (option.Name == "--truth")
    {
      RejectInlineValue(option);
      options.Truth = true;
    }
    else if (option.Name == "--coarse-points")
    {
      const std::string where = arguments.TakeValue(option);
      if (where != "original" && where != "reference")
      {
        throw UsageError(
          "option '--coarse-points' takes 'original' or 'reference', got '" + where + "'");
      }
      options.CoarsePointsOnReference = where == "reference";
      coarsePointsGiven = true;
    }
    else if (option.Name == "--backend")
    {
      backend = ParseRenderBackend(option.Name, arguments.TakeValue(option));
    }
    else
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'compare'; run 'silhouette compare --help'");
    }
  }
  if (options.Inputs.empty())
  {
    throw UsageError("'compare' needs a model name, 'all' or a mesh file");
  }
  if (coarsePointsGiven && !options.Truth)
  {
    throw UsageError("option '--coarse-points' needs '--truth'");
  }
  if (options.Truth)
  {
    for (const std::string& input : options.Inputs)
    {
      if (input == "all" || silhouette_eval::IsModelName(input))
      {
        throw UsageError("'compare --truth' takes mesh files, not the model '" + input + "'");
      }
    }
  }
  return options;
}

FigureOptions ParseFigure(ArgumentList& arguments, RenderBackend& backend)
{
  FigureOptions options;
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!LooksLikeOption(word))
    {
      if (!options.Input.empty())
      {
        throw UsageError(
          "unexpected argument '" + word + "' (INPUT is already '" + options.Input + "')");
      }
      options.Input = word;
      continue;
    }
    const Option option = SplitOption(word);
    if (option.Name == "-o" || option.Name == "--output")
    {
      options.Output = arguments.TakeValue(option);
    }
    else if (option.Name == "--plot")
    {
      options.Plot = arguments.TakeValue(option);
    }
    else if (option.Name == "--coarse-triangles")
    {
      options.CoarseTriangles = ParseCount(option, arguments.TakeValue(option), 4, 10000000);
    }
    else if (option.Name == "--fine-level")
    {
      options.FineLevel = ParseCount(option, arguments.TakeValue(option), 1, 5);
    }
    else if (option.Name == "--frames")
    {
      options.Frames = ParseCount(option, arguments.TakeValue(option), 1, 100000);
    }
    else if (option.Name == "--data")
    {
      options.DataDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--backend")
    {
      backend = ParseRenderBackend(option.Name, arguments.TakeValue(option));
    }
    else if (!ParseCameraOption(option, arguments, options.Camera))
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'figure'; run 'silhouette figure --help'");
    }
  }
  if (options.Input.empty())
  {
    throw UsageError("'figure' needs a model name or a mesh file");
  }
  if (options.Output.empty())
  {
    throw UsageError("'figure' needs '-o FIGURE.png'");
  }
  CheckCameraOptions(options.Camera);
  return options;
}

bool IsHelpWord(const std::string& word)
{
  return word == "--help" || word == "-h";
}

// The help of `command`, or UsageError if there is no such command.
std::string HelpOf(const std::string& command)
{
  if (command == "smooth")
  {
    return SmoothHelp();
  }
  if (command == "render")
  {
    return RenderHelp();
  }
  if (command == "generate")
  {
    return GenerateHelp();
  }
  if (command == "compare")
  {
    return CompareHelp();
  }
  if (command == "figure")
  {
    return FigureHelp();
  }
  if (command == "view")
  {
    return ViewHelp();
  }
  if (command == "simplify")
  {
    return SimplifyHelp();
  }
  if (command == "help")
  {
    return MainHelp();
  }
  throw UsageError("unknown command '" + command + "'; run 'silhouette --help'");
}

std::optional<RenderStyle> ParseRenderStyle(const std::string& name)
{
  for (RenderStyle style :
    { RenderStyle::Shaded, RenderStyle::Wireframe, RenderStyle::NewGeometry, RenderStyle::Lines,
      RenderStyle::Charcoal, RenderStyle::Lazy, RenderStyle::Hand, RenderStyle::Rough })
  {
    if (name == NameOf(style))
    {
      return style;
    }
  }
  return std::nullopt;
}

ViewOptions ParseView(ArgumentList& arguments, RenderBackend& backend)
{
  ViewOptions options;
  bool onlyOperands = false; // after "--"
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!onlyOperands && word == "--")
    {
      onlyOperands = true;
      continue;
    }
    if (onlyOperands || !LooksLikeOption(word))
    {
      if (!options.Input.empty())
      {
        throw UsageError(
          "unexpected argument '" + word + "' (the mesh is already '" + options.Input + "')");
      }
      options.Input = word;
      continue;
    }
    const Option option = SplitOption(word);
    const auto flag = [&option](bool& value) {
      RejectInlineValue(option);
      value = true;
    };
    if (option.Name == "--style")
    {
      const std::string name = arguments.TakeValue(option);
      const std::optional<RenderStyle> style = ParseRenderStyle(name);
      if (!style)
      {
        throw UsageError(
          "option '--style' needs shaded, wireframe, new-geometry, lines, charcoal, lazy, "
          "hand or rough, got '" +
          name + "'");
      }
      options.Style = *style;
    }
    else if (option.Name == "--no-smoothing")
    {
      flag(options.NoSmoothing);
    }
    else if (option.Name == "--fine-reference")
    {
      flag(options.FineReference);
    }
    else if (option.Name == "--fine-level")
    {
      options.FineLevel = ParseCount(option, arguments.TakeValue(option), 1, 5);
    }
    else if (option.Name == "--coarse-triangles")
    {
      options.CoarseTriangles = ParseCount(option, arguments.TakeValue(option), 4, 10000000);
    }
    else if (option.Name == "--data")
    {
      options.DataDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--help-overlay")
    {
      flag(options.HelpOverlay);
    }
    else if (option.Name == "--no-overlay")
    {
      flag(options.NoOverlay);
    }
    else if (option.Name == "--no-times")
    {
      flag(options.NoTimes);
    }
    else if (option.Name == "--lod")
    {
      flag(options.Lod);
    }
    else if (option.Name == "--screenshot-dir")
    {
      options.ScreenshotDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--orbit")
    {
      options.OrbitDegrees = ParseNumber(option.Name, arguments.TakeValue(option));
      options.Orbit = true;
    }
    else if (option.Name == "--frames")
    {
      options.Frames = ParseCount(option, arguments.TakeValue(option), 1, 100000);
      options.Orbit = true;
    }
    else if (option.Name == "--record")
    {
      options.RecordDirectory = arguments.TakeValue(option);
      options.Orbit = true;
    }
    else if (option.Name == "--play")
    {
      options.PlayLog = arguments.TakeValue(option);
    }
    else if (option.Name == "--json")
    {
      flag(options.Json);
    }
    else if (option.Name == "--backend")
    {
      backend = ParseRenderBackend(option.Name, arguments.TakeValue(option));
    }
    else if (!ParseCameraOption(option, arguments, options.Camera))
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'view'; run 'silhouette view --help'");
    }
  }
  if (options.Orbit && !options.PlayLog.empty())
  {
    throw UsageError("'--play' cannot be combined with '--orbit', '--frames' or '--record'");
  }
  CheckCameraOptions(options.Camera);
  return options;
}

// The parts both commands share: INPUT, --json and the camera options.
// `parseOwnOption` handles the command's other options and says whether it knew it.
template<typename Options, typename OwnOptionParser>
void ParseCommand(const std::string& command, ArgumentList& arguments, Options& options,
  OwnOptionParser parseOwnOption)
{
  bool onlyOperands = false; // after "--"
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!onlyOperands && word == "--")
    {
      onlyOperands = true;
    }
    else if (!onlyOperands && LooksLikeOption(word))
    {
      const Option option = SplitOption(word);
      if (option.Name == "--json")
      {
        RejectInlineValue(option);
        options.Json = true;
      }
      else if (!ParseCameraOption(option, arguments, options.Camera) &&
        !parseOwnOption(option, arguments))
      {
        throw UsageError("unknown option '" + option.Name + "' for '" + command +
          "'; run 'silhouette " + command + " --help'");
      }
    }
    else if (options.Input.empty())
    {
      options.Input = word;
    }
    else
    {
      throw UsageError(
        "unexpected argument '" + word + "' (INPUT is already '" + options.Input + "')");
    }
  }
  if (options.Input.empty())
  {
    throw UsageError(
      "'" + command + "' needs an INPUT mesh; run 'silhouette " + command + " --help'");
  }
  CheckCameraOptions(options.Camera);
}

bool IsOutputOption(const Option& option)
{
  return option.Name == "-o" || option.Name == "--output";
}

} // namespace

const char* NameOf(RenderStyle style)
{
  switch (style)
  {
    case RenderStyle::Wireframe:
      return "wireframe";
    case RenderStyle::NewGeometry:
      return "new-geometry";
    case RenderStyle::Lines:
      return "lines";
    case RenderStyle::Charcoal:
      return "charcoal";
    case RenderStyle::Lazy:
      return "lazy";
    case RenderStyle::Hand:
      return "hand";
    case RenderStyle::Rough:
      return "rough";
    case RenderStyle::Shaded:
    default:
      return "shaded";
  }
}

CommandLine ParseCommandLine(int argc, char* argv[])
{
  std::vector<std::string> words(argv + 1, argv + argc);
  CommandLine result;
  if (words.empty())
  {
    throw UsageError("no command given; run 'silhouette --help'");
  }
  const std::string command = words.front();
  if (IsHelpWord(command) || command == "help")
  {
    if (command == "help" && words.size() > 2)
    {
      throw UsageError("'help' takes at most one COMMAND");
    }
    result.HelpText = words.size() == 2 ? HelpOf(words[1]) : MainHelp();
    return result;
  }
  const std::string commandHelp = HelpOf(command); // also rejects unknown commands
  // "--help" anywhere before "--" wins over mistakes elsewhere on the line.
  for (std::size_t i = 1; i < words.size() && words[i] != "--"; ++i)
  {
    if (IsHelpWord(words[i]))
    {
      result.HelpText = commandHelp;
      return result;
    }
  }

  ArgumentList arguments({ words.begin() + 1, words.end() });
  if (command == "generate")
  {
    result.What = CommandLine::Action::Generate;
    result.Generate = ParseGenerate(arguments);
  }
  else if (command == "compare")
  {
    result.What = CommandLine::Action::Compare;
    result.Compare = ParseCompare(arguments, result.Backend);
  }
  else if (command == "figure")
  {
    result.What = CommandLine::Action::Figure;
    result.Figure = ParseFigure(arguments, result.Backend);
  }
  else if (command == "view")
  {
    result.What = CommandLine::Action::View;
    result.View = ParseView(arguments, result.Backend);
  }
  else if (command == "simplify")
  {
    result.What = CommandLine::Action::Simplify;
    SimplifyOptions& simplify = result.Simplify;
    ParseCommand(
      command, arguments, simplify, [&simplify](const Option& option, ArgumentList& args) {
        return ParseSimplifyOption(option, args, simplify);
      });
    CheckSimplifyOptions(simplify);
  }
  else if (command == "smooth")
  {
    result.What = CommandLine::Action::Smooth;
    SmoothOptions& smooth = result.Smooth;
    ParseCommand(command, arguments, smooth, [&smooth](const Option& option, ArgumentList& args) {
      if (option.Name == "--lines-output")
      {
        smooth.LinesOutput = args.TakeValue(option);
        return true;
      }
      if (!IsOutputOption(option))
      {
        return false;
      }
      smooth.Output = args.TakeValue(option);
      return true;
    });
  }
  else
  {
    result.What = CommandLine::Action::Render;
    RenderOptions& render = result.Render;
    RenderBackend& backend = result.Backend;
    ParseCommand(command, arguments, render, [&](const Option& option, ArgumentList& args) {
      if (IsOutputOption(option))
      {
        render.Output = args.TakeValue(option);
      }
      else if (option.Name == "--lines-output")
      {
        render.LinesOutput = args.TakeValue(option);
      }
      else if (option.Name == "--backend")
      {
        backend = ParseRenderBackend(option.Name, args.TakeValue(option));
      }
      else if (option.Name == "--style")
      {
        const std::string name = args.TakeValue(option);
        const std::optional<RenderStyle> style = ParseRenderStyle(name);
        if (!style)
        {
          throw UsageError(
            "option '--style' needs shaded, wireframe, new-geometry, lines, charcoal, lazy, "
            "hand or rough, got '" +
            name + "'");
        }
        render.Style = *style;
      }
      else if (option.Name == "--no-smoothing")
      {
        RejectInlineValue(option);
        render.NoSmoothing = true;
      }
      else if (option.Name == "--hidden")
      {
        const std::string value = args.TakeValue(option);
        if (value != "none" && value != "dashed")
        {
          throw UsageError("option '--hidden' needs none or dashed, got '" + value + "'");
        }
        render.HiddenLines = value == "dashed";
      }
      else if (option.Name == "--width-by-depth")
      {
        RejectInlineValue(option);
        render.WidthByDepth = true;
      }
      else if (option.Name == "--lod")
      {
        RejectInlineValue(option);
        render.Lod = true;
      }
      else if (option.Name == "--progressive")
      {
        render.ProgressiveLevels = ParseCount(option, args.TakeValue(option), 2, 64);
      }
      else if (option.Name == "--svg")
      {
        RejectInlineValue(option);
        render.ProgressiveSvg = true;
      }
      else
      {
        return false;
      }
      return true;
    });
    if (render.Output.empty())
    {
      throw UsageError(render.ProgressiveLevels > 0
          ? "'render --progressive' needs '-o DIR'"
          : "'render' needs '-o IMAGE.png' or '-o DRAWING.svg'");
    }
    if (render.Lod && render.ProgressiveLevels > 0)
    {
      throw UsageError("option '--lod' does not go with '--progressive' (each drawing is one "
                       "level of the progressive mesh already)");
    }
    if (render.ProgressiveSvg && render.ProgressiveLevels == 0)
    {
      throw UsageError("option '--svg' goes with '--progressive'; for one drawing write "
                       "'-o DRAWING.svg'");
    }
  }
  return result;
}

} // namespace cli
