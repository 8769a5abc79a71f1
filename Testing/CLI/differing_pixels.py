"""Prints how many pixels of two PNG images of one size differ in any channel.

Usage: differing_pixels.py A.png B.png (exit 2 when they cannot be compared).
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader


def pixels(path):
    reader = vtkPNGReader()
    if not reader.CanReadFile(path):
        sys.exit("differing_pixels: cannot read '%s'" % path)
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    return image.GetDimensions(), scalars


(size_a, a), (size_b, b) = pixels(sys.argv[1]), pixels(sys.argv[2])
if size_a != size_b or a.GetNumberOfComponents() != b.GetNumberOfComponents():
    print("differing_pixels: the images differ in size or channels", file=sys.stderr)
    sys.exit(2)
count = 0
components = a.GetNumberOfComponents()
for i in range(a.GetNumberOfTuples()):
    if any(a.GetComponent(i, c) != b.GetComponent(i, c) for c in range(components)):
        count += 1
print(count)
