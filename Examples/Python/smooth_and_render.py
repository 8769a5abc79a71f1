"""Smooth the silhouette of a mesh for one camera and render it offscreen.

    python3 smooth_and_render.py MESH.ply OUT.png

Any mesh VTK reads will do; this reads PLY. Run with Debian's /usr/bin/python3
and PYTHONPATH at the folder that holds the silhouette_smoothing package.
"""
import sys

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)

from silhouette_smoothing import vtkSilhouetteSmoothingFilter

reader = vtkPLYReader()
reader.SetFileName(sys.argv[1])

renderer = vtkRenderer()
renderer.SetBackground(1.0, 1.0, 1.0)
window = vtkRenderWindow()
window.SetSize(640, 480)
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.AddRenderer(renderer)

smoother = vtkSilhouetteSmoothingFilter()
smoother.SetInputConnection(reader.GetOutputPort())
smoother.SetRenderer(renderer)  # the camera and viewport come from here, every frame
smoother.SetTolerance(0.5)      # pixels

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(smoother.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetColor(0.75, 0.78, 0.85)
renderer.AddActor(actor)
renderer.ResetCamera()
window.Render()

image = vtkWindowToImageFilter()
image.SetInput(window)
writer = vtkPNGWriter()
writer.SetFileName(sys.argv[2])
writer.SetInputConnection(image.GetOutputPort())
writer.Write()
counts = smoother.GetOutput().GetFieldData()
print("silhouette triangles:", counts.GetArray("SilhouetteTriangleCount").GetValue(0),
      "new triangles:", counts.GetArray("NewTriangleCount").GetValue(0))
