"""The scene of paraview.RepresentationGUI, run inside the ParaView GUI
(paraview --script=RepresentationGUIScene.py --exit; TestRepresentationGUI.py
starts it and judges what it leaves). paraview.simple here drives the GUI's
own session: the plugin is loaded as Tools > Manage Plugins would, the coarse
bunny is opened and shown in the GUI's render view, and Smooth Silhouette
Surface is picked in the Representation list (display.Representation, the
property the list edits). The view is given a fixed size on screen (the
layout's preview mode) and a fixed camera. Then, for the representation and
for the variants its limit must reject (smoothing off: the chord outline;
plain Surface), the script lets the GUI paint (Qt's events), saves the view's
pixels (SaveScreenshot) and captures the whole screen with ImageMagick's
import. The last line it writes to SILHOUETTE_GUI_STATUS is "done" only if
every step ran; an exception is written there instead (the GUI itself would
only log it and exit with 0)."""
import ctypes
import os
import subprocess
import time
import traceback

from paraview import simple

from SilhouetteTestUtils import load_representation_plugin, setting, show_bunny_view

size = [640, 480]
status_file = setting("SILHOUETTE_GUI_STATUS")
output_dir = setting("SILHOUETTE_OUTPUT_DIR")


def report(line):
    with open(status_file, "a") as status:
        status.write(line + "\n")


def process_gui_events(seconds):
    """Runs the GUI's event loop for a while from inside the script: the
    script runs in the GUI's main thread, so until it returns nothing is
    painted (the panels, and the render view's image, which a render only
    draws into the widget's framebuffer). ParaView gives Python no Qt
    binding, so QCoreApplication::processEvents(AllEvents) is called
    through ctypes, in the Qt library the GUI has already loaded."""
    qt_core = ctypes.CDLL("libQt5Core.so.5")
    process_events = qt_core["_ZN16QCoreApplication13processEventsE6QFlagsIN10QEventLoop17ProcessEventsFlagEE"]
    process_events.argtypes = [ctypes.c_int]
    process_events.restype = None
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        process_events(0)
        time.sleep(0.05)


def capture(name, view):
    """The view's pixels (SaveScreenshot) and the whole screen (import
    -window root), after the GUI has painted."""
    simple.Render(view)
    process_gui_events(1.5)
    view_image = os.path.join(output_dir, name + ".png")
    simple.SaveScreenshot(view_image, view, ImageResolution=size, TransparentBackground=0)
    process_gui_events(0.5)  # SaveScreenshot renders offscreen: let the widget repaint
    window_image = os.path.join(output_dir, name + "_window.png")
    grab = subprocess.run(["import", "-window", "root", window_image], timeout=60,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if grab.returncode != 0:
        raise RuntimeError("import -window root exited with %d: %s" % (grab.returncode, grab.stdout))
    report("captured %s %s" % (view_image, window_image))


def scene():
    load_representation_plugin()
    simple._DisableFirstRenderCameraReset()
    view = simple.GetActiveViewOrCreate("RenderView")
    # The view's size on screen: the layout's preview mode, as View >
    # Preview sets it (the rest of the window is the GUI's own).
    simple.GetLayout(view).PreviewMode = size
    show_bunny_view(view)

    reader = simple.PLYReader(registrationName="bunny_coarse.ply", FileNames=[setting("SILHOUETTE_DATA")])
    display = simple.Show(reader, view)
    available = list(display.Representation.Available)
    if "Smooth Silhouette Surface" not in available:
        raise RuntimeError("Smooth Silhouette Surface is not in the Representation list %s" % available)
    display.Representation = "Smooth Silhouette Surface"
    display.SilhouetteTolerance = 0.5
    display.Specular = 0.2
    simple.SetActiveSource(reader)  # the Properties panel and the toolbar show its display
    capture("TestRepresentationGUI", view)
    report("view size %d x %d" % tuple(view.ViewSize))

    display.SilhouetteSmoothing = 0
    capture("TestRepresentationGUI_chord", view)
    display.SilhouetteSmoothing = 1
    display.Representation = "Surface"
    capture("TestRepresentationGUI_surface", view)
    display.Representation = "Smooth Silhouette Surface"


try:
    scene()
    report("done")
except Exception:
    report("error: " + traceback.format_exc().replace("\n", "\n  "))
