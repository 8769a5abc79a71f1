#!/usr/bin/python3
"""Make Data/bunny_coarse.ply (about 1,000 triangles) from Data/bunny.ply.

Usage (from the repository root):
    /usr/bin/python3 Data/scripts/make_bunny_coarse.py \
        [Data/bunny.ply] [Data/bunny_coarse.ply] [target_triangles]

Uses VTK's vtkQuadricDecimation with VolumePreservation on. The target
reduction is 1 - target/input; with the default target of 1000 and the
3,674-triangle input this gives exactly 1,000 triangles with VTK 9.1.
The output is cleaned (vtkCleanPolyData, exact point merging only, to drop
points no longer used) and written as binary little-endian PLY with points
and triangles only (no normals or other attributes).

Needs python3-vtk9 (Debian). Not used at build or test time.
"""

import sys

import vtk


def main(argv):
    src = argv[1] if len(argv) > 1 else "Data/bunny.ply"
    dst = argv[2] if len(argv) > 2 else "Data/bunny_coarse.ply"
    target = int(argv[3]) if len(argv) > 3 else 1000

    reader = vtk.vtkPLYReader()
    reader.SetFileName(src)
    reader.Update()
    n_in = reader.GetOutput().GetNumberOfPolys()
    if n_in == 0:
        raise RuntimeError(f"{src}: no triangles read")

    deci = vtk.vtkQuadricDecimation()
    deci.SetInputConnection(reader.GetOutputPort())
    deci.SetTargetReduction(1.0 - float(target) / n_in)
    deci.VolumePreservationOn()
    deci.AttributeErrorMetricOff()

    clean = vtk.vtkCleanPolyData()
    clean.SetInputConnection(deci.GetOutputPort())
    clean.SetTolerance(0.0)
    clean.PointMergingOn()
    clean.ConvertLinesToPointsOff()
    clean.ConvertPolysToLinesOff()
    clean.ConvertStripsToPolysOff()
    clean.Update()

    out = vtk.vtkPolyData()
    out.SetPoints(clean.GetOutput().GetPoints())
    out.SetPolys(clean.GetOutput().GetPolys())

    writer = vtk.vtkPLYWriter()
    writer.SetFileName(dst)
    writer.SetInputData(out)
    writer.SetFileTypeToBinary()
    writer.SetDataByteOrderToLittleEndian()
    if not writer.Write():
        raise RuntimeError(f"could not write {dst}")

    print(f"{src}: {reader.GetOutput().GetNumberOfPoints()} points, "
          f"{n_in} triangles")
    print(f"{dst}: {out.GetNumberOfPoints()} points, "
          f"{out.GetNumberOfPolys()} triangles "
          f"(target reduction {1.0 - float(target) / n_in:.6f})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
