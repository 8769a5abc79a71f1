"""Test of the Smooth Silhouette Surface representation in the ParaView GUI
(issue 15). Debian's paraview is started on the X server of the test run
(scripts/paraview.sh runs ctest under xvfb-run, screen 1280x1024x24) with
--script=RepresentationGUIScene.py --exit. That script, inside the GUI, loads
the plugin, opens the coarse bunny, picks the representation in the
Representation list, fixes the view's size and camera, and saves the view's
pixels and a capture of the whole screen, for the representation and for two
wrong variants: smoothing off (the chord outline) and plain Surface.

Here, run by pvpython, both captures are compared with their baselines
(Baseline/TestRepresentationGUI.png, the view; Baseline/
TestRepresentationGUI_window.png, the screen, with the status bar's memory
indicator painted over, the one part of the window that changes from run to
run), and both wrong variants must fail the same limit. The GUI gets
SILHOUETTE_GUI_TIMEOUT seconds (default 120): a GUI that does not start,
hangs or dies fails the test with what the scene script wrote and the GUI's
last output. Settings come from ctest through the environment."""
import os
import signal
import subprocess

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

from SilhouetteTestUtils import finish, image_error, setting

# The screen of scripts/paraview.sh's xvfb-run. ParaView's main window (1152
# x 762 with no window manager) sits at its top left, the memory indicator
# ("vm: 1.0 GiB/23.5 GiB 4.4%") at the right of the window's status bar:
# left, top, right, bottom, from the screen's top left.
screen = (1280, 1024)
memory_indicator = (752, 732, 1130, 761)
view_size = (640, 480)
# Measured (image_error, vtkImageDifference as the pvbatch tests use it):
# three reruns score 0.000 for the view and for the screen; the chord outline
# 4.451 for both, plain Surface 289.2 (view) and 733.1 (screen: the
# Representation lists read Surface, too). The limit is the pvbatch image
# tests'.
limit = 0.8


def read_png(path):
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    return png.GetOutput()


def spread(image):
    """The largest range of any channel: 0 for an image of one colour."""
    scalars = image.GetPointData().GetScalars()
    return max(scalars.GetRange(c)[1] - scalars.GetRange(c)[0] for c in range(scalars.GetNumberOfComponents()))


def blank_memory_indicator(path, masked):
    """Writes to `masked` a copy of a screen capture with the memory
    indicator painted black (the machine's memory in use: over three runs,
    every other pixel of the screen was equal); the baseline is stored so
    painted. Returns `masked`."""
    image = read_png(path)
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)
    left, top, right, bottom = memory_indicator
    pixels[height - 1 - bottom:height - top, left:right + 1] = 0  # VTK's rows go up
    image.Modified()
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(masked)
    writer.Write()
    return masked


output_dir = setting("SILHOUETTE_OUTPUT_DIR")
os.makedirs(output_dir, exist_ok=True)
baseline_dir = setting("SILHOUETTE_BASELINE_DIR")
status_file = os.path.join(output_dir, "TestRepresentationGUI_status.txt")
gui_log = os.path.join(output_dir, "TestRepresentationGUI_paraview.log")
timeout = float(os.environ.get("SILHOUETTE_GUI_TIMEOUT", "120"))
names = ["TestRepresentationGUI", "TestRepresentationGUI_chord", "TestRepresentationGUI_surface"]
failures = []

for name in names:
    for suffix in (".png", "_window.png", "_window_masked.png"):
        path = os.path.join(output_dir, name + suffix)
        if os.path.exists(path):
            os.remove(path)
if os.path.exists(status_file):
    os.remove(status_file)
if not os.environ.get("DISPLAY"):
    failures.append("no DISPLAY: run the test under an X server (scripts/paraview.sh runs ctest under xvfb-run)")
    finish(failures)

# The GUI, with no saved settings (--dr); in a session of its own, so that a
# hung GUI is killed with all it started.
command = [setting("SILHOUETTE_PARAVIEW"), "--dr",
    "--script=" + os.path.join(os.path.dirname(os.path.abspath(__file__)), "RepresentationGUIScene.py"), "--exit"]
print("the GUI: " + " ".join(command))
with open(gui_log, "w") as log:
    gui = subprocess.Popen(command, env=dict(os.environ, SILHOUETTE_GUI_STATUS=status_file),
        stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        exit_code = gui.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(gui.pid, signal.SIGKILL)
        gui.wait()
        exit_code = None
with open(gui_log) as log:
    gui_output = log.read()
status = []
if os.path.exists(status_file):
    with open(status_file) as written:
        status = written.read().splitlines()


def gui_failure(what):
    return "%s\n  the scene script wrote: %s\n  the GUI's last output (%s):\n    %s" % (
        what, "\n    ".join(status) if status else "nothing", gui_log,
        "\n    ".join(gui_output.splitlines()[-30:]))


if exit_code is None:
    failures.append(gui_failure("the GUI did not exit within %g s (killed)" % timeout))
elif exit_code < 0:
    failures.append(gui_failure("the GUI died of signal %d" % -exit_code))
elif exit_code != 0:
    failures.append(gui_failure("the GUI exited with code %d" % exit_code))
elif not status or status[-1] != "done":
    failures.append(gui_failure("the scene script did not finish in the GUI"))
if failures:
    finish(failures)
for line in status:
    if line.startswith("view size"):
        print("GUI " + line)

for name in names:
    for suffix, want in ((".png", view_size), ("_window.png", screen)):
        image = read_png(os.path.join(output_dir, name + suffix))
        size = tuple(image.GetDimensions()[:2])
        if suffix != ".png":
            print("GUI screen capture %s%s: %d x %d" % ((name, suffix) + size))
        if size != want or spread(image) == 0:
            failures.append("%s%s is %d x %d, spread %d (want %d x %d, not one colour; the screen is the one "
                "xvfb-run -s '-screen 0 1280x1024x24' makes)" % ((name, suffix) + size + (spread(image),) + want))
if failures:
    finish(failures)

for kind, suffix in (("view", ".png"), ("screen", "_window.png")):
    baseline = os.path.join(baseline_dir, "TestRepresentationGUI" + suffix)
    images = [os.path.join(output_dir, name + suffix) for name in names]
    reference = baseline
    if kind == "screen":
        images = [blank_memory_indicator(image, image[:-len(".png")] + "_masked.png") for image in images]
    if not os.path.exists(baseline):
        failures.append("no baseline %s (look at %s and copy it there if it is right)" % (baseline, images[0]))
        continue
    if kind == "screen":
        reference = blank_memory_indicator(baseline, os.path.join(output_dir, "TestRepresentationGUI_baseline_masked.png"))
    error, chord_error, surface_error = [image_error(image, reference) for image in images]
    print("image difference (GUI %s): %.3f (limit %g); the chord outline %.3f, plain Surface %.3f (must exceed it)"
        % (kind, error, limit, chord_error, surface_error))
    if error > limit:
        failures.append("the GUI's %s differs from %s by %.3f (%s)" % (kind, baseline, error, images[0]))
    if chord_error <= limit or surface_error <= limit:
        failures.append("the limit does not tell the smooth outline from the coarse one in the GUI's %s "
            "(chord %.3f, Surface %.3f)" % (kind, chord_error, surface_error))
finish(failures)
