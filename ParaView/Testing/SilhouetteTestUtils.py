"""Helpers shared by the pvbatch tests of the SilhouetteSmoothing plugin."""
import os
import sys

from paraview import simple


def setting(name):
    """A test setting, passed by ctest in the environment."""
    value = os.environ.get(name)
    if not value:
        sys.exit("test setting %s is not set (run the test through ctest)" % name)
    return value


def load_plugin():
    """Loads the plugin on every rank (remote=True: the server side, which in
    pvbatch is all the MPI ranks) and returns the filter's constructor, as
    paraview.simple makes it from the server-manager XML."""
    names = {"__name__": __name__}  # not empty: LoadPlugin takes an empty one for "none given"
    simple.LoadPlugin(setting("SILHOUETTE_PLUGIN"), remote=True, ns=names)
    if "SilhouetteSmoothing" not in names:
        sys.exit("the plugin loaded but did not define SilhouetteSmoothing")
    return names["SilhouetteSmoothing"]


def copy_camera(view, smoother):
    """Copies the render view's camera and size into the filter's properties:
    ParaView does not hand the view's vtkCamera to a filter."""
    smoother.CameraPosition = list(view.CameraPosition)
    smoother.CameraFocalPoint = list(view.CameraFocalPoint)
    smoother.CameraViewUp = list(view.CameraViewUp)
    smoother.CameraViewAngle = view.CameraViewAngle
    smoother.CameraParallelProjection = view.CameraParallelProjection
    smoother.CameraParallelScale = view.CameraParallelScale
    smoother.ViewportSize = list(view.ViewSize)


def load_representation_plugin():
    """Loads the plugin on every rank for its representation (Smooth
    Silhouette Surface): nothing to return, the representation is a value of
    a display's Representation property."""
    names = {"__name__": __name__}
    simple.LoadPlugin(setting("SILHOUETTE_PLUGIN"), remote=True, ns=names)


def image_error(image, baseline):
    """vtkImageDifference's thresholded error between two PNG files:
    per-pixel threshold 16 (its default, 105, forgives too much here),
    one-pixel shifts and averaging allowed, as the plugin's image tests
    compare."""
    from vtkmodules.vtkImagingCore import vtkImageDifference
    from vtkmodules.vtkIOImage import vtkPNGReader

    readers = []
    for name in (image, baseline):
        png = vtkPNGReader()
        png.SetFileName(name)
        png.Update()
        readers.append(png)
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[0].GetOutputPort())
    difference.SetImageConnection(readers[1].GetOutputPort())
    difference.SetThreshold(16)
    difference.AllowShiftOn()
    difference.AveragingOn()
    difference.Update()
    return difference.GetThresholdedError()


def field_value(polydata, name):
    array = polydata.GetFieldData().GetArray(name)
    return int(array.GetTuple1(0)) if array is not None else None


def triangle_count(polydata):
    cells = polydata.GetPolys()
    return cells.GetNumberOfCells() if cells is not None else 0


def finish(failures):
    """Prints the verdict; on failures, raises: pvbatch 5.11 then exits with
    code 1, where sys.exit with a non-zero code after rendering crashes it
    (SIGSEGV) and os._exit loses the captured output."""
    for failure in failures:
        print("FAILED: " + failure)
    if failures:
        raise RuntimeError("%d check(s) failed" % len(failures))
    print("passed")
