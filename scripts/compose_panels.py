"""Puts PNG panels of one size into a grid, with an optional label at the top
of each, and writes a PNG (run with Debian's /usr/bin/python3 under a
display or xvfb-run; VTK does the drawing and the text).

Usage: compose_panels.py OUTPUT.png COLUMNS PANEL1.png LABEL1 PANEL2.png LABEL2 ...
(an empty LABEL draws none; panels fill rows left to right, top to bottom)."""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkImageActor, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the window)

out, columns = sys.argv[1], int(sys.argv[2])
pairs = list(zip(sys.argv[3::2], sys.argv[4::2]))
rows = (len(pairs) + columns - 1) // columns
readers = []
for path, _ in pairs:
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    readers.append(reader)
extent = readers[0].GetOutput().GetExtent()
w, h = extent[1] + 1, extent[3] + 1

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(columns * w, rows * h)
keep = []
for i, ((_, label), reader) in enumerate(zip(pairs, readers)):
    col, row = i % columns, i // columns
    actor = vtkImageActor()
    actor.GetMapper().SetInputConnection(reader.GetOutputPort())
    renderer = vtkRenderer()
    renderer.SetViewport(col / columns, (rows - 1 - row) / rows, (col + 1) / columns,
                         (rows - row) / rows)
    renderer.AddActor(actor)
    # A parallel camera that shows the image pixel for pixel.
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetFocalPoint((w - 1) / 2, (h - 1) / 2, 0)
    camera.SetPosition((w - 1) / 2, (h - 1) / 2, 1000)
    camera.SetParallelScale(h / 2)
    renderer.ResetCameraClippingRange()
    if label:
        text = vtkTextActor()
        text.SetInput(label.replace("\\n", "\n"))
        text.GetTextProperty().SetFontSize(15)
        text.GetTextProperty().SetColor(0, 0, 0)
        text.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
        text.GetPositionCoordinate().SetValue(0.02, 0.89)
        renderer.AddActor2D(text)
        keep.append(text)
    window.AddRenderer(renderer)
    keep += [actor, renderer]
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
writer = vtkPNGWriter()
writer.SetFileName(out)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", out)
