"""Progressive stylized silhouettes (Kim and Choe, Fig. 3 and 10): the bunny's
progressive mesh at a few triangle counts, each level's silhouette smoothed,
its hidden parts left out, and drawn with a brush, side by side.

    /usr/bin/python3 Examples/Python/progressive_strokes.py Data/bunny.ply out.png [brush]

brush: charcoal (default), lazy, hand or rough.
"""
import sys

from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCamera, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from silhouette_smoothing import (vtkProgressiveMeshFilter, vtkSilhouetteLineVisibility,
                                  vtkSilhouetteSmoothingFilter, vtkStylizedStrokeFilter)

source, output = sys.argv[1], sys.argv[2]
brush = sys.argv[3] if len(sys.argv) > 3 else "charcoal"
brushes = {"charcoal": vtkStylizedStrokeFilter.CHARCOAL, "lazy": vtkStylizedStrokeFilter.LAZY,
           "hand": vtkStylizedStrokeFilter.HAND, "rough": vtkStylizedStrokeFilter.ROUGH}

reader = vtkPLYReader()
reader.SetFileName(source)
reader.Update()
full = reader.GetOutput().GetNumberOfPolys()
counts = [100, 300, 1000, full]

width, height = 320, 300
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(width * len(counts), height)

# One camera for every panel, framing the full mesh.
bounds = reader.GetOutput().GetBounds()
centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
size = max(bounds[2 * i + 1] - bounds[2 * i] for i in range(3))
camera = vtkCamera()
camera.SetFocalPoint(centre)
camera.SetPosition(centre[0], centre[1], centre[2] + 2.6 * size)
camera.SetViewUp(0, 1, 0)
camera.SetClippingRange(0.5 * size, 5 * size)

keep = []  # VTK 9.1's wrappers: keep every pipeline object alive
for i, count in enumerate(counts):
    renderer = vtkRenderer()
    renderer.SetViewport(i / len(counts), 0, (i + 1) / len(counts), 1)
    renderer.SetBackground(1, 1, 1)
    renderer.SetActiveCamera(camera)
    window.AddRenderer(renderer)
    pm = vtkProgressiveMeshFilter()
    pm.SetInputConnection(reader.GetOutputPort())
    pm.SetTriangleCount(count)
    smoother = vtkSilhouetteSmoothingFilter()
    smoother.SetInputConnection(pm.GetOutputPort())
    smoother.SetCamera(camera)
    smoother.SetViewportSize(width, height)
    # The visible pieces only (Kim and Choe 3.3, step 2): the smoothed
    # silhouette against the smoothed surface.
    visible = vtkSilhouetteLineVisibility()
    visible.SetInputConnection(smoother.GetOutputPort(1))
    visible.SetSurfaceConnection(smoother.GetOutputPort(0))
    visible.SetCamera(camera)
    visible.PassHiddenLinesOff()
    strokes = vtkStylizedStrokeFilter()
    strokes.SetInputConnection(visible.GetOutputPort())
    strokes.SetCamera(camera)
    strokes.SetBrush(brushes[brush])
    strokes.SetAmplitude(0.004)
    strokes.SetWavelength(0.006)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(strokes.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0, 0, 0)
    actor.GetProperty().SetLineWidth(2)
    actor.GetProperty().LightingOff()
    renderer.AddActor(actor)
    pm.Update()
    label = vtkTextActor()
    label.SetInput("%d triangles" % pm.GetOutput().GetNumberOfPolys())
    label.GetTextProperty().SetColor(0, 0, 0)
    label.GetTextProperty().SetFontSize(16)
    label.SetPosition(10, 10)
    renderer.AddViewProp(label)
    keep += [renderer, pm, smoother, visible, strokes, mapper, actor, label]

window.Render()
capture = vtkWindowToImageFilter()
capture.SetInput(window)
capture.ReadFrontBufferOff()
writer = vtkPNGWriter()
writer.SetInputConnection(capture.GetOutputPort())
writer.SetFileName(output)
writer.Write()
