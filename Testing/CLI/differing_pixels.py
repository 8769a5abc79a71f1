"""Prints how many pixels of two PNG images of one size differ in any channel.

Usage: differing_pixels.py A.png B.png (exit 2 when they cannot be compared).
Also imported (differing) by Testing/Python/TestExampleImage.py.
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGReader


def pixels(path):
    reader = vtkPNGReader()
    if not reader.CanReadFile(path):
        raise ValueError("cannot read '%s'" % path)
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    return image.GetDimensions(), scalars


def differing(a_path, b_path):
    """The count of pixels that differ in any channel; ValueError when the
    images cannot be read or differ in size or channels."""
    (size_a, a), (size_b, b) = pixels(a_path), pixels(b_path)
    if size_a != size_b or a.GetNumberOfComponents() != b.GetNumberOfComponents():
        raise ValueError("the images differ in size or channels")
    components = a.GetNumberOfComponents()
    count = 0
    for i in range(a.GetNumberOfTuples()):
        if any(a.GetComponent(i, c) != b.GetComponent(i, c) for c in range(components)):
            count += 1
    return count


if __name__ == "__main__":
    try:
        print(differing(sys.argv[1], sys.argv[2]))
    except ValueError as error:
        print("differing_pixels: %s" % error, file=sys.stderr)
        sys.exit(2)
