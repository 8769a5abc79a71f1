#include "CommandHelp.h"

#include "CameraOptions.h"
#include "RenderingBackend.h"
#include "Smoothing.h"
#include "Viewer.h"

namespace cli
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
  render INPUT -o IMAGE.png|DRAWING.svg|DRAWING.pdf [--style STYLE]
         [--no-smoothing] [--hidden none|dashed] [--width-by-depth]
         [--join-lines] [--lod] [--json] [camera options]
  render INPUT --style STYLE --progressive N [--svg|--pdf] -o DIR [options]
      render INPUT offscreen to a PNG image (or a line style to an SVG or
      PDF drawing, or N drawings along its progressive mesh) and print the
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
      the four labelled panels of Fig. 1 of R. Xing's paper on smooth
      silhouettes (named in 'help figure'), and a time plot
  view [MODEL|MESH] [options]
      the interactive viewer (keys, overlays, a tolerance slider), or a
      headless orbit to numbered PNGs with per-frame figures
  help [COMMAND]
      show this help, or the help of COMMAND
  version, --version
      print the program's version

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
    "new_triangles, new_points, apex_triangles, fold_fallbacks {chord_triangles,\n"
    "straight_points, straight_feature_segments, pinned_points,\n"
    "crowded_triangles, unresolved}, prepare_ms,\n"
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
INPUT may also be a model of the evaluation set (bunny, sphere, torus,
ellipsoid, supertoroid, knot): its coarse version, the mesh 'silhouette view
MODEL' shows (quadric decimation of the original, as 'silhouette compare'
makes it).

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
  return R"(Usage: silhouette render INPUT -o IMAGE.png|DRAWING.svg|DRAWING.pdf
                        [--style STYLE] [--no-smoothing] [--hidden none|dashed]
                        [--width-by-depth] [--join-lines] [--lod] [--json]
                        [camera options]
       silhouette render INPUT --style STYLE --progressive N [--svg|--pdf] -o DIR
                        [the same options]

Reads INPUT like 'silhouette smooth', smooths its silhouette for the view of
the camera options, renders it offscreen at --size with that same camera
(no multisampling, so images are repeatable), writes a PNG image and prints
the same figures as 'silhouette smooth'. Where there is no X display it
renders through OSMesa (--backend). The line styles can also be written as
an SVG or PDF drawing: the same visible lines as paths in image coordinates
(pixels from the top-left corner, one path per visible piece; a PDF page
is the image's size at 96 pixels to the inch), projected with the same
camera and nothing rendered, so no display is needed. For a
pen plotter, each stretch of line is drawn once (of lines running within
three quarters of a line's width of each other, one keeps it), the lines
are clipped to the image, and the paths come in a short pen order from the
top-left corner.

Options:
  -o, --output FILE       the image to write; required: a .png, or an .svg
                          or .pdf drawing with a line style (lines,
                          charcoal, lazy, hand, rough)
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
                                        smoothed surface's creases, open
                                        borders and the curves where its
                                        parts pass through each other
                                        (vtkCreaseAndBorderLines: creases
                                        are where its normals jump, at the
                                        feature edges the filter found),
                                        with the parts that surface hides
                                        left out
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
                          (none), or drawn grey, dashed and thinner (dashed):
                          in a drawing with any line style, in a PNG
                          image with --style lines only (default: none)
  --width-by-depth        in a drawing, each visible line's width
                          follows its distance from the eye: 2 pixels at the
                          focal point's distance, times that distance over
                          the point's, within 0.5 to 8 pixels; each line is
                          then a filled outline, not a stroke (a pen
                          plotter traces its two sides) (default: 2 pixels
                          everywhere, stroked)
  --join-lines            in a drawing, lines that meet end to end are
                          one path, whatever their kinds (where more meet,
                          the two that continue each other most straightly),
                          so a pen plotter lifts its pen, and inks the
                          corner, once there (default: one path per visible
                          piece)
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
                          parents; a name ending in .png, .svg or .pdf is
                          refused) that gets sketch-01.png ... sketch-NN.png,
                          and one line of figures per drawing (a JSON array
                          with --json); drawings numbered past NN of an
                          earlier run are left there, with a warning
                          (default: one drawing)
  --svg, --pdf            with --progressive, write sketch-NN.svg or
                          sketch-NN.pdf drawings (default: PNG images)
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

An option of the other shape (--level with a torus, a torus option with a
sphere) is refused.
)";
}

std::string ViewHelp()
{
  return R"(Usage: silhouette view [MODEL|MESH] [options] [camera options]
       silhouette view [MODEL|MESH] --orbit DEG --frames N [--record DIR] [--json] ...
       silhouette view [MODEL|MESH] --play LOG [--screenshot-dir DIR] [--json] ...

Opens a VTK render window with trackball camera interaction on the mesh,
smoothed for the camera whenever it moves: in the shaded style by
vtkSilhouetteSmoothingMapper while it renders, in the other styles by
vtkSilhouetteSmoothingFilter fed the window's renderer (through the pipeline
and its MTime). The window needs an X display; the headless modes
(--orbit, --play) render through OSMesa where there is none (--backend).

MODEL|MESH: a model of the evaluation set (bunny, sphere, torus, ellipsoid,
supertoroid, knot), shown as its coarse version (quadric decimation of the
original, as 'silhouette compare' makes it), or a mesh file (.ply .obj .stl
.vtp .vtk). Default: the bundled coarse bunny, bunny_coarse.ply of --data. The
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
to 5 px. r frames the mesh again from the camera options' direction,
keeping the projection: the start camera when the fine reference is hidden;
while it is shown, the framing of the narrower left half, so the camera
stands farther back than at the start. c writes silhouette_view_NNNN.png (the first free number) to the
screenshot folder and prints where. VTK's other trackball keys (3 stereo,
j/t joystick, u user, fly-to, pick) do nothing here.

The overlay (top left) shows the mesh, the style, the triangles in and out,
the silhouette triangles and new triangles of the last smoothing (and those
left whole, their smoothing below the tolerance), the tolerance, and the
times: frames per second from the wall time between the
ends of the last 20 renders of the main view (a gap of over a second starts
the count again, so idle time is not averaged in), the renderer's own time
for the last render (vtkRenderer::GetLastRenderTimeInSeconds, which includes
the smoothing when the view moved) and the smoothing's time (the mapper's
for the last view change in the shaded style, the filter's last execution
in the others; filter_ms in --orbit's table). With smoothing off nothing is
smoothed: the output is the input and the silhouette and new triangles show
as 0.

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
                         bunny_coarse.ply (default: the one installed with
                         the program, share/SilhouetteSmoothing/Data beside
                         its bin folder)
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
                         offscreen; -36000 to 36000 (default 360)
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

} // namespace cli
