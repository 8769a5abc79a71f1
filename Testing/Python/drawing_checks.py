"""What the drawing tests share: a cube and the generic view of it whose
drawing is its 9 visible edges, the inked pixels of a PNG image, and how
many of one image's inked pixels lie away from another's."""

import os

from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

# Three faces seen, three hidden: 9 visible edges, 3 hidden ones.
CUBE_VIEW = ["--style", "lines", "--size", "400x400", "--camera-position", "2.5", "1.85", "2.15"]


def write_cube(work):
    """A unit cube (vtkCubeSource) written to WORK/cube.vtp; returns the path."""
    path = os.path.join(work, "cube.vtp")
    cube = vtkCubeSource()  # kept alive while the writer pulls from it
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(cube.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    return path


def ink(png_file):
    """The pixels darker than light grey in any channel, as a set of (x, y)."""
    reader = vtkPNGReader()
    reader.SetFileName(png_file)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    components = min(3, scalars.GetNumberOfComponents())
    dark = set()
    for i in range(width * height):
        if min(scalars.GetComponent(i, c) for c in range(components)) < 200:
            dark.add((i % width, i // width))
    return dark


def stray(a, b, radius):
    """The share of a's pixels farther than `radius` (in x and y) from any of b's."""
    if not a:
        return 1.0
    near = {(x + dx, y + dy) for (x, y) in b
            for dx in range(-radius, radius + 1) for dy in range(-radius, radius + 1)}
    return sum(1 for p in a if p not in near) / len(a)
