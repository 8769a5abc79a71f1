"""pvbatch test of the Smooth Silhouette Surface representation on a time
series: the coarse bunny written as four VTK files, the first three with the
same points and cells and new point values each (a simulation's field on a
still mesh), the last with its points moved. Read as one series and coloured
by the values, stepping through the first three must smooth nothing again
(SilhouetteSmoothingRuns stays) while the colours change, and each image must
equal the one a fresh reader and representation draw at that time; the
fourth step, whose points moved, must smooth again. (Until 2026-12-06 every
time step smoothed again: ParaView's reader gives new cell arrays each step,
and the smoothing took new arrays for new cells.) Settings come from ctest
through the environment."""
import math
import os

from paraview import simple
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from SilhouetteTestUtils import bunny_render_view, finish, image_error, load_representation_plugin, setting

load_representation_plugin()

size = [640, 480]
output_dir = setting("SILHOUETTE_OUTPUT_DIR")
series_dir = os.path.join(output_dir, "time_series")
os.makedirs(series_dir, exist_ok=True)

# The series: steps 0-2 new values on the same points, step 3 moved points.
ply = vtkPLYReader()
ply.SetFileName(setting("SILHOUETTE_DATA"))
ply.Update()
files = []
for step in range(4):
    mesh = ply.GetOutput().NewInstance()
    mesh.DeepCopy(ply.GetOutput())
    if step == 3:
        points = mesh.GetPoints()
        for p in range(points.GetNumberOfPoints()):
            x, y, z = points.GetPoint(p)
            points.SetPoint(p, x, 1.04 * y, z)
    wave = vtkFloatArray()
    wave.SetName("Wave")
    for p in range(mesh.GetNumberOfPoints()):
        wave.InsertNextValue(math.sin(2.0 * mesh.GetPoint(p)[0] + 2.0 * step))
    mesh.GetPointData().AddArray(wave)
    name = os.path.join(series_dir, "bunny_%d.vtp" % step)
    writer = vtkXMLPolyDataWriter()
    writer.SetDataModeToBinary()  # inline: bookworm's ParaView cannot read appended data
    writer.SetFileName(name)
    writer.SetInputData(mesh)
    writer.Write()
    files.append(name)


def show_series(view):
    """The series read anew, shown with the representation, coloured by Wave
    over a fixed range."""
    reader = simple.XMLPolyDataReader(FileName=files)
    display = simple.Show(reader, view)
    display.Representation = "Smooth Silhouette Surface"
    simple.ColorBy(display, ("POINTS", "Wave"))
    lut = simple.GetColorTransferFunction("Wave")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(-1.0, 1.0)
    return display


def smoothing_runs(display):
    display.SMProxy.UpdatePropertyInformation()
    return display.GetPropertyValue("SilhouetteSmoothingRuns")


def screenshot(view, name):
    simple.Render(view)
    path = os.path.join(output_dir, name)
    simple.SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=0)
    return path


failures = []
view = bunny_render_view(size)
display = show_series(view)
runs = []
images = []
for step in range(4):
    view.ViewTime = float(step)
    images.append(screenshot(view, "TestRepresentationTimeSeries_%d.png" % step))
    runs.append(smoothing_runs(display))
print("smoothing runs after each step: %s" % runs)
if runs[0] < 1:
    failures.append("the first step was not smoothed (runs %s)" % runs)
if runs[1] != runs[0] or runs[2] != runs[0]:
    failures.append("new values on the same points smoothed again (runs %s)" % runs)
if runs[3] <= runs[2]:
    failures.append("moved points were not smoothed again (runs %s)" % runs)

# The values did change from step to step (the check above cannot pass by a
# series that did not load): each image differs from the one before.
for step in (1, 2):
    change = image_error(images[step], images[step - 1])
    print("step %d against step %d: image difference %.3f (must exceed 0.8)" % (step, step - 1, change))
    if change <= 0.8:
        failures.append("step %d draws what step %d drew" % (step, step - 1))

# What was kept is what a fresh reader and representation draw.
for step in (2, 3):
    fresh_view = bunny_render_view(size)
    fresh_view.ViewTime = float(step)
    show_series(fresh_view)
    fresh = screenshot(fresh_view, "TestRepresentationTimeSeries_fresh_%d.png" % step)
    error = image_error(images[step], fresh)
    print("step %d against a fresh representation: image difference %.3f (limit 0.8)" % (step, error))
    if error > 0.8:
        failures.append("step %d differs from a fresh representation's (%.3f)" % (step, error))
    simple.Delete(fresh_view)

finish(failures)
