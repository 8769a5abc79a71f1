"""`silhouette render --style lines -o DRAWING.svg` (issue 16).

Checks, on the bundled torus seen from 60 degrees up (whose inner contour
the tube partly hides) and on a cube:
- the SVG parses as XML, has the --size, and one path per visible piece:
  the count equals VisiblePieceCount of the same pipeline run here through
  the Python package with the camera the program reports (--json);
- rasterised with rsvg-convert, it draws what the PNG of the same view
  draws: of the dark pixels of each image, at most 0.4% lie farther than
  2 pixels from the other's (the PNG's lines are aliased, the SVG's
  anti-aliased; measured 0 on the torus and the cube). The deliberately
  wrong variant, the SVG with the hidden lines drawn (--hidden dashed),
  must exceed that (measured: 0.8% on the torus, whose hidden parts are the
  inner contour's short tails, and 10% on the cube);
- a cube from a generic direction is exactly its 9 visible edges (creases),
  and with --hidden dashed its 3 hidden ones come out as hidden paths;
- the hidden lines' group comes before the visible one (painted under it);
- no path is a dot (a piece of line shorter than the paths' resolution),
  and none repeats another, forwards or backwards; lines that run over
  each other are drawn once: few pixels are inked by two paths (the
  bracket, assimp's regr01 and Wuson);
- lines that pass beside the eye are drawn up to the near plane (the PNG's
  lines all there), a drawing whose lines only cross the page is not
  called blank, and every point of a zoomed-in drawing lies on the page;
- --join-lines joins the cube's 9 edges into 3 paths or fewer, drawing the
  same segments;
- --width-by-depth draws filled outlines, thicker near the eye;
- --progressive 4 --svg writes 4 drawings at growing triangle counts, the
  last the drawing of the input itself, path for path;
- zoomed in on the coarse bunny (--zoom 3 and 5), no piece of the surface's
  contour is drawn beside the visible curve (the boxes of a user's trial);
- errors: an .svg with the shaded style, --width-by-depth with a PNG.
Usage: TestSvgDrawing.py SILHOUETTE_PROGRAM DATA_DIR WORK_DIR
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import cli_checks  # beside this script
import drawing_checks  # beside this script
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.vtkRenderingCore import vtkCamera

from silhouette_smoothing import (vtkCreaseAndBorderLines, vtkSilhouetteLineVisibility,
                                  vtkSilhouetteSmoothingFilter)

program, data, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = cli_checks.failures
check = cli_checks.check
SVG = "{http://www.w3.org/2000/svg}"
MAXIMUM_STRAY = 0.004
RADIUS = 2


def run(*args):
    return cli_checks.run(program, *args)


def paths(svg_file):
    root = ElementTree.parse(svg_file).getroot()
    return root, [p for p in root.iter(SVG + "path")]


def ink(png_file):
    return drawing_checks.ink(png_file)


def stray(a, b):
    """The share of a's pixels farther than RADIUS (in x and y) from any of b's."""
    return drawing_checks.stray(a, b, RADIUS)


def visible_pieces(mesh_file, camera_json, size):
    """VisiblePieceCount of the drawing's pipeline, run here."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(mesh_file)
    camera = vtkCamera()
    camera.SetPosition(camera_json["position"])
    camera.SetFocalPoint(camera_json["focal_point"])
    camera.SetViewUp(camera_json["view_up"])
    camera.SetViewAngle(camera_json["view_angle"])
    smoothing = vtkSilhouetteSmoothingFilter()
    smoothing.SetInputConnection(reader.GetOutputPort())
    smoothing.SetCamera(camera)
    smoothing.SetViewportSize(size)
    edges = vtkCreaseAndBorderLines()
    edges.SetInputConnection(smoothing.GetOutputPort(0))
    drawing = vtkAppendPolyData()
    drawing.AddInputConnection(smoothing.GetOutputPort(1))
    drawing.AddInputConnection(edges.GetOutputPort())
    visibility = vtkSilhouetteLineVisibility()
    visibility.SetInputConnection(drawing.GetOutputPort())
    visibility.SetSurfaceConnection(smoothing.GetOutputPort(0))
    visibility.SetCamera(camera)
    visibility.Update()
    return int(visibility.GetOutput().GetFieldData().GetArray("VisiblePieceCount").GetValue(0))


def compare_raster(name, svg_file, hidden_file, png_file):
    """The rasterised SVG against the PNG, and the wrong variant's."""
    raster, raster_hidden = (os.path.join(work, name + suffix)
                             for suffix in ("_svg.png", "_hidden_svg.png"))
    for source, target in ((svg_file, raster), (hidden_file, raster_hidden)):
        subprocess.run([rsvg, "-b", "white", source, "-o", target], check=True, timeout=120)
    reference = ink(png_file)
    drawn_ink = ink(raster)
    wrong_ink = ink(raster_hidden)
    right = max(stray(drawn_ink, reference), stray(reference, drawn_ink))
    wrong = max(stray(wrong_ink, reference), stray(reference, wrong_ink))
    print("%s: stray dark pixels %.4f for the SVG, %.4f with the hidden lines (limit %.3f)"
          % (name, right, wrong, MAXIMUM_STRAY))
    check(right <= MAXIMUM_STRAY, name + ": the rasterised SVG draws what the PNG draws")
    check(wrong > MAXIMUM_STRAY, name + ": the check fails with the hidden lines drawn")


rsvg = shutil.which("rsvg-convert")
check(rsvg is not None, "rsvg-convert is installed (scripts/setup.sh installs librsvg2-bin)")

# --- The torus: paths against pieces, raster against the PNG -----------------
torus = os.path.join(data, "torus_24x12.vtp")
view = ["--style", "lines", "--size", "500x400", "--elevation", "60"]
svg_file, png_file = os.path.join(work, "torus.svg"), os.path.join(work, "torus.png")
hidden_file = os.path.join(work, "torus_hidden.svg")
code, out, err = run("render", torus, *view, "-o", svg_file, "--json")
check(code == 0, "render -o .svg succeeds (%s)" % err.strip())
code, _, err = run("render", torus, *view, "-o", png_file)
check(code == 0, "render -o .png succeeds (%s)" % err.strip())
code, _, err = run("render", torus, *view, "-o", hidden_file, "--hidden", "dashed")
check(code == 0, "render -o .svg --hidden dashed succeeds (%s)" % err.strip())
if not failures:
    figures = json.loads(out)
    root, drawn = paths(svg_file)
    check(root.tag == SVG + "svg" and root.get("width") == "500" and root.get("height") == "400",
          "an <svg> of the --size")
    visible = [p for p in drawn if "hidden" not in p.get("class", "")]
    expected = visible_pieces(torus, figures["camera"], [500, 400])
    print("torus: %d paths, %d visible pieces in the pipeline" % (len(visible), expected))
    check(len(visible) == len(drawn) == expected > 2, "one path per visible piece")
    check(all(p.get("class") == "silhouette" for p in visible),
          "a torus's lines are silhouettes")
    _, with_hidden = paths(hidden_file)
    hidden = [p for p in with_hidden if "hidden" in p.get("class", "")]
    check(len(hidden) > 0, "--hidden dashed adds hidden paths (%d)" % len(hidden))
    if rsvg:
        compare_raster("torus", svg_file, hidden_file, png_file)

# --- The cube: its 9 visible edges ---------------------------------------------
cube_file = drawing_checks.write_cube(work)
cube_view = drawing_checks.CUBE_VIEW
cube_svg, cube_hidden, cube_png = (os.path.join(work, name)
                                   for name in ("cube.svg", "cube_hidden.svg", "cube.png"))
code, _, err = run("render", cube_file, *cube_view, "-o", cube_hidden, "--hidden", "dashed")
check(code == 0, "render the cube (%s)" % err.strip())
for target in (cube_svg, cube_png):
    check(run("render", cube_file, *cube_view, "-o", target)[0] == 0, "render the cube to " + target)
if rsvg and not failures:
    compare_raster("cube", cube_svg, cube_hidden, cube_png)
if code == 0:
    root, drawn = paths(cube_hidden)
    classes = sorted(p.get("class") for p in drawn)
    print("cube paths:", classes)
    # The hidden group comes first: visible lines are drawn over it.
    groups = [g.get("id") for g in root.iter(SVG + "g")]
    check(groups == ["hidden", "visible"], "the hidden lines are drawn first (%s)" % groups)
    check(classes == ["crease"] * 9 + ["hidden crease"] * 3,
          "a cube is its 9 visible edges, and its 3 hidden ones dashed")

# --- No dots, no line twice ---------------------------------------------------
# Pieces of silhouette a hundredth of a pixel long (where a bore's rim hides
# the bore's outline) were written as paths "M x yL x y", dots with round
# caps, which a pen plotter draws by lowering its pen: 4 in the first view of
# the bracket before 2026-12-04, and 3 in the second until 2026-12-05 (a
# user's trial: pieces 0.005 to 0.01 px long, written as one point). And a
# line drawn twice is inked twice: the Wuson's default view had 4 paths that
# repeated another path backwards (a user's trial, 2026-12-05).
def written_points(d):
    return tuple(re.findall(r"[ML]([-0-9.]+ [-0-9.]+)", d))


def pen_travel(lines):
    return sum(math.dist(a[-1], b[0]) for a, b in zip(lines, lines[1:]))


def nearest_tour(lines):
    """The pen travel of the greedy tour from the first line: each next line
    the one with an end nearest the pen, taken from that end."""
    if not lines:
        return 0.0
    left, pen, travel = list(lines[1:]), lines[0][-1], 0.0
    while left:
        ends = [(min(math.dist(pen, l[0]), math.dist(pen, l[-1])), i) for i, l in enumerate(left)]
        step, i = min(ends)
        line = left.pop(i)
        travel += step
        pen = line[0] if math.dist(pen, line[-1]) < math.dist(pen, line[0]) else line[-1]
    return travel


def inked_twice(name, svg_file):
    """Of the pixels a drawing inks, the share inked by two paths or more:
    each path painted black at half opacity, a pixel covered by one path
    has ink 0.5 at most, by two 0.75."""
    half = os.path.join(work, name + "_half.svg")
    with open(svg_file) as source, open(half, "w") as target:
        target.write(source.read().replace('stroke="black"', 'stroke="black" stroke-opacity="0.5"'))
    raster = os.path.join(work, name + "_half.png")
    subprocess.run([rsvg, "-b", "white", half, "-o", raster], check=True, timeout=120)
    reader = vtkPNGReader()
    reader.SetFileName(raster)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    ink = [1.0 - scalars.GetComponent(i, 0) / 255.0 for i in range(scalars.GetNumberOfTuples())]
    inked = sum(1 for v in ink if v > 0.3)
    return sum(1 for v in ink if v > 0.6) / max(inked, 1)


# The share inked twice that a drawing may have: crossings, corners (the
# round caps of the lines that meet there) and lines that meet at a shallow
# angle are inked twice however they are drawn. Measured (2026-12-06): the
# bracket's two views 0.9% and 0.8% (corners), regr01 5.1%, the Wuson 5.9%
# (its tail tuft, a knot of intersection curves). With every line drawn, as
# before that day: 1.6%, 1.3%, 12.9% and 19.6% (a crease along an
# intersection curve, a border along a crease, specks under other lines).
# Not checked where that variant does not fail the limit (the bracket's
# second view).
most_inked_twice = {"bracket": 0.012, "bracket_2": None, "regr01": 0.08, "wuson": 0.08}
for name, mesh, view in (("bracket", os.path.join(data, "bracket.stl"), ("30", "25", "800x600")),
                         ("bracket_2", os.path.join(data, "bracket.stl"), ("35", "30", "1024x768")),
                         ("regr01", "/usr/share/assimp/models/OBJ/regr01.obj", None),
                         ("wuson", "/usr/share/assimp/models/OBJ/WusonOBJ.obj", None)):
    if not os.path.exists(mesh):
        print("%s: %s not installed, not checked" % (name, mesh))
        continue
    drawing = os.path.join(work, name + ".svg")
    camera = ["--azimuth", view[0], "--elevation", view[1], "--size", view[2]] if view else []
    code, _, err = run("render", mesh, "--style", "lines", *camera, "-o", drawing)
    check(code == 0, "render %s (%s)" % (name, err.strip()))
    if code != 0:
        continue
    _, drawn = paths(drawing)
    dots = [p.get("d") for p in drawn if len(set(written_points(p.get("d")))) < 2]
    seen = set()
    twice = []
    for p in drawn:
        points = written_points(p.get("d"))
        if points in seen or tuple(reversed(points)) in seen:
            twice.append(p.get("d"))
        seen.add(points)
    print("%s: %d paths, %d of them dots, %d drawn before" % (name, len(drawn), len(dots), len(twice)))
    check(drawn and not dots, "%s: no path is a dot: %s" % (name, dots[:3]))
    check(not twice, "%s: no path repeats another: %s" % (name, twice[:2]))
    # A pen plotter draws the paths in the file's order: the pen's travel
    # between them is within 1.5 times a nearest-neighbour tour's from the
    # same first path (measured 1.0; in the order the pieces came, before
    # 2026-12-05, 3 to 11 times, a user's trial).
    visible = [[tuple(float(v) for v in xy.split()) for xy in written_points(p.get("d"))]
               for p in drawn if not p.get("class").startswith("hidden")]
    in_file = pen_travel(visible)
    tour = nearest_tour(visible)
    print("%s: the pen travels %.0f px between paths, a nearest-neighbour tour %.0f px"
          % (name, in_file, tour))
    check(in_file <= 1.5 * tour + 1.0, "%s: the paths are in a short pen order" % name)
    if rsvg and most_inked_twice[name] is not None:
        twice = inked_twice(name, drawing)
        print("%s: %.1f%% of the ink under two paths or more" % (name, 100 * twice))
        check(twice <= most_inked_twice[name],
              "%s: lines that run over each other are drawn once (%.1f%% inked twice, at most %.1f%%)"
              % (name, 100 * twice, 100 * most_inked_twice[name]))

# --- The camera among the lines, and a page smaller than the drawing ----------
# A bar 20 long seen from above one end, looking along it: its long edges
# run from beside the eye to the far end. A line is cut where it crosses the
# near clipping plane, as the rendering cuts it; before 2026-12-06 a line
# with a point behind the eye lost everything from its last point in front
# (the SVG drew the far end alone: 2,944 of the PNG's pixels missing, a
# user's trial).
bar_file = os.path.join(work, "bar.vtp")
bar = vtkCubeSource()
bar.SetXLength(20.0)
bar.SetCenter(10.0, 0.5, 0.5)
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(bar.GetOutputPort())
writer.SetFileName(bar_file)
writer.Write()
close_view = ["--style", "lines", "--size", "400x300", "--camera-position", "5", "0.5", "2.5",
              "--focal-point", "12", "0.5", "0", "--view-up", "0", "0", "1"]
close_svg, close_png = os.path.join(work, "bar_close.svg"), os.path.join(work, "bar_close.png")
code_svg, _, err_svg = run("render", bar_file, *close_view, "-o", close_svg)
code_png, _, _ = run("render", bar_file, *close_view, "-o", close_png)
check(code_svg == 0 and code_png == 0, "render the bar from close (%s)" % err_svg.strip())
if rsvg and code_svg == 0 and code_png == 0:
    close_raster = os.path.join(work, "bar_close_svg.png")
    subprocess.run([rsvg, "-b", "white", close_svg, "-o", close_raster], check=True, timeout=120)
    missing = stray(ink(close_png), ink(close_raster))
    print("bar from close: %.4f of the PNG's line pixels missing from the SVG" % missing)
    check(missing <= MAXIMUM_STRAY, "lines that pass beside the eye are drawn up to the near plane")
    # Inside a cube, looking at a far face: lines cross the page with no
    # point on it. The drawing is not blank, and says nothing of the kind
    # (it warned that it showed nothing of the mesh).
    inside = os.path.join(work, "cube_inside.svg")
    code, _, err = run("render", cube_file, "--style", "lines", "--size", "400x300", "--camera-position",
                       "0.2", "0.1", "0.3", "--focal-point", "0.4", "0", "-1", "-o", inside)
    check(code == 0 and "shows nothing" not in err and len(paths(inside)[1]) > 0,
          "a drawing whose lines cross the page is not called blank (%s)" % err.strip())

# Zoomed in, the drawing is larger than the page: every point lies on it
# (a pen plotter would draw the rest off the paper; they reached 2 px
# beyond it before 2026-12-06).
zoomed = os.path.join(work, "bracket_zoomed.svg")
code, _, err = run("render", os.path.join(data, "bracket.stl"), "--style", "lines", "--size", "300x200",
                   "--zoom", "3", "-o", zoomed)
check(code == 0, "render the bracket zoomed in (%s)" % err.strip())
if code == 0:
    xy = [tuple(float(v) for v in point.split()) for p in paths(zoomed)[1]
          for point in written_points(p.get("d"))]
    outside = [p for p in xy if not (0.0 <= p[0] <= 300.0 and 0.0 <= p[1] <= 200.0)]
    print("bracket zoomed in: %d points, %d off the page" % (len(xy), len(outside)))
    check(xy and not outside, "every point lies on the page: %s" % outside[:3])

# --- Joined paths ---------------------------------------------------------------
# --join-lines: lines that meet end to end are one path, so a
# plotter lifts its pen once at a corner (the cube's 9 edges meet at its 7
# visible corners). The same ink: the same segments, in fewer paths.
def segments(svg_file):
    found = set()
    for p in paths(svg_file)[1]:
        if p.get("class").startswith("hidden"):
            continue
        xy = written_points(p.get("d"))
        for a, b in zip(xy, xy[1:]):
            found.add((min(a, b), max(a, b)))
    return found


joined_svg = os.path.join(work, "cube_joined.svg")
code, _, err = run("render", cube_file, *cube_view, "-o", joined_svg, "--join-lines")
check(code == 0, "render --join-lines (%s)" % err.strip())
if code == 0:
    joined = paths(joined_svg)[1]
    print("cube: %d paths joined, from 9" % len(joined))
    check(len(joined) <= 3 and all(p.get("class") == "crease" for p in joined),
          "the cube's 9 edges make 3 paths or fewer")
    check(segments(joined_svg) == segments(cube_svg), "joined, the cube draws the same segments")
# Every kind is drawn alike, so lines of different kinds join too: on the
# Wuson a border ends where an intersection curve begins (until 2026-12-06
# only lines of one kind were joined, the wrong variant: no path names two
# kinds).
wuson_drawing = os.path.join(work, "wuson.svg")
if os.path.exists(wuson_drawing):
    wuson_joined = os.path.join(work, "wuson_joined.svg")
    code, _, err = run("render", "/usr/share/assimp/models/OBJ/WusonOBJ.obj", "--style", "lines",
                       "-o", wuson_joined, "--join-lines")
    check(code == 0, "render the Wuson --join-lines (%s)" % err.strip())
    if code == 0:
        joined = paths(wuson_joined)[1]
        mixed = [p.get("class") for p in joined if len(p.get("class").split()) > 1
                 and not p.get("class").startswith("hidden")]
        print("Wuson: %d paths joined, from %d; joining kinds: %s"
              % (len(joined), len(paths(wuson_drawing)[1]), mixed))
        check(mixed, "the Wuson's joined paths join lines of different kinds")
        check(segments(wuson_joined) == segments(wuson_drawing),
              "joined, the Wuson draws the same segments")
code, _, err = run("render", cube_file, *cube_view, "-o", os.path.join(work, "joined.png"), "--join-lines")
check(code == 2 and "--join-lines needs an .svg or .pdf drawing" in err, "--join-lines with a PNG is refused")

# A closed path (its last point its first) is entered at its point nearest
# the pen, where the last path left it (a plotter's pen rests at the top-left
# corner first), and left there. Until 2026-12-06 it was entered at its
# first point, the wrong variant: the torus's outer contour then cost 843 px
# of travel instead of 529.
def loops_entered_nearest(svg_file):
    """The closed visible paths, and those not entered at their point
    nearest the pen."""
    pen = (0.0, 0.0)
    loops, far = 0, []
    for p in paths(svg_file)[1]:
        if p.get("class").startswith("hidden"):
            continue
        xy = [tuple(float(v) for v in point.split()) for point in written_points(p.get("d"))]
        if len(xy) >= 4 and xy[0] == xy[-1]:
            loops += 1
            gap = lambda q: math.hypot(q[0] - pen[0], q[1] - pen[1])
            if gap(xy[0]) > min(gap(q) for q in xy) + 0.01:
                far.append((svg_file, xy[0], pen))
        pen = xy[-1]
    return loops, far


loop_count, loops_far = 0, []
for drawing in ("torus.svg", "cube_joined.svg", "wuson_joined.svg"):
    if os.path.exists(os.path.join(work, drawing)):
        count, far = loops_entered_nearest(os.path.join(work, drawing))
        loop_count += count
        loops_far += far
print("closed paths: %d, %d not entered at their point nearest the pen" % (loop_count, len(loops_far)))
check(loop_count >= 2 and not loops_far,
      "closed paths are entered at their point nearest the pen: %s" % loops_far[:2])

# --- Width by depth ------------------------------------------------------------
depth_svg = os.path.join(work, "cube_depth.svg")
code, _, err = run("render", cube_file, *cube_view, "-o", depth_svg, "--width-by-depth")
check(code == 0, "render --width-by-depth (%s)" % err.strip())
if code == 0:
    root, drawn = paths(depth_svg)
    group = root.find(SVG + "g[@id='visible']")
    check(group is not None and group.get("fill") == "black" and group.get("stroke") == "none",
          "--width-by-depth draws filled outlines")
    check(len(drawn) == 9 and all(p.get("d").endswith("Z") for p in drawn),
          "one closed outline per visible edge")
    # Each with round ends, five points about each end of its line besides
    # its two sides' (an edge of two points: 14). With square ends (4 points)
    # a line stopped where another covers it left a white break (a user's
    # trial, 2026-12-06).
    counts = [len(re.findall(r"[ML]", p.get("d"))) for p in drawn]
    check(all(count >= 14 for count in counts), "the outlines have round ends: %s" % counts)

# --- The progressive sketch ----------------------------------------------------
bunny = os.path.join(data, "bunny.ply")
sketch = os.path.join(work, "sketch")
shutil.rmtree(sketch, ignore_errors=True)
code, out, err = run("render", bunny, "--style", "lines", "--size", "400x300", "--progressive", "4",
                     "--svg", "-o", sketch, "--json")
check(code == 0, "render --progressive 4 --svg (%s)" % err.strip())
if code == 0:
    levels = json.loads(out)
    counts = [level["input_triangles"] for level in levels]
    print("progressive sketch: triangle counts", counts)
    check(len(levels) == 4 and counts == sorted(set(counts)) and counts[-1] == 3674,
          "4 drawings at growing counts, the last the input's 3,674 triangles")
    files = sorted(os.listdir(sketch))
    check(files == ["sketch-%02d.svg" % k for k in range(1, 5)], "files sketch-01 to 04.svg")
    check(all(len(paths(os.path.join(sketch, f))[1]) > 0 for f in files), "each has paths")
    # At the full count the progressive mesh is the input's geometry exactly,
    # so its drawing is the single drawing's, but for rounding (the points
    # come in another order; measured: one coordinate of 5,900 off by 0.01).
    single = os.path.join(work, "bunny.svg")
    run("render", bunny, "--style", "lines", "--size", "400x300", "-o", single)

    def numbers(svg_file):
        """Each path's coordinates, from its smaller end, the paths sorted (the
        pen order may start or turn a path differently on a tie)."""
        found = []
        for p in paths(svg_file)[1]:
            xy = [float(x) for x in re.findall(r"-?[0-9]+(?:\.[0-9]+)?", p.get("d"))]
            pairs = [xy[i:i + 2] for i in range(0, len(xy), 2)]
            back = list(reversed(pairs))
            rounded = lambda ps: [round(v, 1) for pair in ps for v in pair]
            found.append(sum(min(pairs, back, key=rounded), []))
        return sorted(found, key=lambda xy: [round(v, 1) for v in xy])

    last, alone = numbers(os.path.join(sketch, files[-1])), numbers(single)
    same = len(last) == len(alone) and all(
        len(a) == len(b) and all(abs(x - y) <= 0.02 for x, y in zip(a, b))
        for a, b in zip(last, alone))
    check(same and len(last) > 0,
          "the last drawing is the input's drawing, path for path (within 0.02 px)")

# --- A file name that is not UTF-8 -------------------------------------------
# The title holds the command line; a byte that is not UTF-8 (a Latin-1 name)
# is written as '?', so the drawing still parses (it did not).
# So is U+FFFF, which is UTF-8 but not an XML 1.0 character.
for name, shown in ((b"torus-\xe9.vtp", "torus-?.vtp"), (b"torus-\xef\xbf\xbf.vtp", "torus-???.vtp")):
    odd = os.path.join(os.fsencode(work), name)
    shutil.copyfile(torus, odd)
    odd_svg = os.path.join(work, "odd.svg")
    done = subprocess.run([program, "render", odd, "--style", "lines", "--size", "200x150",
                           "-o", odd_svg], capture_output=True, timeout=300)
    code, err = done.returncode, done.stderr.decode(errors="replace")
    check(code == 0, "a file name %r renders: %s" % (name, err.strip()))
    if code == 0:
        try:
            title = paths(odd_svg)[0].find(SVG + "title").text
        except ElementTree.ParseError as error:
            title = "does not parse: %s" % error
        check("/%s' --style lines --size 200x150 -o %s" % (shown, odd_svg) in title,
              "the title writes %r with a '?' a byte: %s" % (name, title))
    os.remove(odd)

# --- Zoomed in: no boxes beside the outline ------------------------------------
# Zoomed in on the coarse bunny's back, the smoothed surface's facets stand
# 4 to 6 px beyond its visible silhouette curve; their contour, drawn there
# as a gap of the outline and joined to the curve at both ends, made small
# boxes beside the outline (3 at --zoom 3, 2 at --zoom 5, a user's trial,
# 2026-12-06). A gap beside one drawn line all along is left out now.
bunny = os.path.join(data, "bunny_coarse.ply")
for zoom in ("3", "5"):
    zoomed = os.path.join(work, "bunny_zoom%s.svg" % zoom)
    code, _, err = run("render", bunny, "--style", "lines", "--zoom", zoom, "-o", zoomed)
    check(code == 0, "render the bunny at --zoom %s (%s)" % (zoom, err.strip()))
    if code == 0:
        _, drawn = paths(zoomed)
        outlines = [p for p in drawn if "outline" in p.get("class", "").split()]
        check(not outlines and drawn, "--zoom %s: %d paths, none of the surface's contour beside "
              "the curve (%d)" % (zoom, len(drawn), len(outlines)))

# --- Errors --------------------------------------------------------------------
code, _, err = run("render", torus, "--progressive", "3", "-o", os.path.join(work, "p"))
check(code == 2 and "--progressive draws a line style" in err, "--progressive needs a line style")
code, _, err = run("render", torus, "--style", "lines", "--svg", "-o", os.path.join(work, "x.svg"))
check(code == 2 and "'--svg' goes with '--progressive'" in err, "--svg alone is a usage error")
code, _, err = run("render", torus, "--style", "lines", "--progressive", "1", "-o", work)
check(code == 2, "--progressive 1 is refused (2 to 64)")
code, _, err = run("render", torus, "-o", os.path.join(work, "shaded.svg"))
check(code == 2 and "a drawing (.svg or .pdf) needs a line style" in err and err.count("\n") == 1,
      "an .svg with the shaded style is refused in one line")
code, _, err = run("render", torus, "--style", "lines", "--width-by-depth",
                   "-o", os.path.join(work, "depth.png"))
check(code == 2 and "--width-by-depth needs an .svg or .pdf drawing" in err,
      "--width-by-depth with a PNG is refused")
code, _, err = run("render", torus, "--style", "lines", "--hidden", "dotted",
                   "-o", os.path.join(work, "dotted.svg"))
check(code == 2 and "--hidden' needs none or dashed" in err, "--hidden dotted is a usage error")

if failures:
    print("FAILED: %d check(s)" % len(failures))
    sys.exit(1)
