"""Renders with Debian's VTK from Python, libsilhouette_osmesa.so preloaded
and no DISPLAY: the script is plain VTK, nothing in it knows about OSMesa.

Usage: LD_PRELOAD=.../libsilhouette_osmesa.so python3 TestPythonPreload.py OUT.png
Prints the render window's class; exits 1 if the image is blank.
"""
import sys

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL2 factory, as usual)

sphere = vtkSphereSource()
sphere.SetThetaResolution(32)
sphere.SetPhiResolution(32)
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(sphere.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(1, 1, 1)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(200, 150)
window.AddRenderer(renderer)
window.Render()
print("render window:", window.GetClassName())

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
writer = vtkPNGWriter()
writer.SetInputConnection(grab.GetOutputPort())
writer.SetFileName(sys.argv[1])
writer.Write()

low, high = grab.GetOutput().GetPointData().GetScalars().GetRange(0)
print("red channel from", low, "to", high)
sys.exit(0 if low < high else 1)
