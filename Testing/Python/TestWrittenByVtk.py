"""Files VTK's own writers make are read (the file pre-checks must not refuse
what the readers read well).

Writes an octahedron with a point data array of every type vtkPolyDataWriter
writes (bit, char, signed char, unsigned char, short, unsigned short, int,
unsigned int, vtkIdType, long long, unsigned long long, float, double,
string) and a six-component one, plus a string field array, as legacy VTK in
ASCII and in binary, in the 4.2 and 5.1 layouts; `silhouette smooth` must read
each (8 input triangles). Each binary file cut at 60% of its length, inside
its arrays, must be refused with one line (the check still checks). Then
the same mesh as VTK XML in every byte order, header width (UInt32,
UInt64), encoding (ASCII, binary, appended raw and base64) and compression
(none, zlib, LZ4, LZMA, in blocks of 64 bytes) vtkXMLPolyDataWriter
writes, and as PLY (ASCII, binary in either
byte order, with colours), STL (ASCII, binary) and OBJ: each must be read.
Usage: TestWrittenByVtk.py SILHOUETTE_PROGRAM WORK_DIR
"""
import os
import re
import sys

import cli_checks  # beside this script
from vtkmodules import vtkCommonCore as core
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlatonicSolidSource
from vtkmodules.vtkIOLegacy import vtkPolyDataWriter

program, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
check = cli_checks.check

solid = vtkPlatonicSolidSource()
solid.SetSolidTypeToOctahedron()
solid.Update()
mesh = vtkPolyData()
mesh.DeepCopy(solid.GetOutput())
mesh.GetPointData().Initialize()
mesh.GetCellData().Initialize()
points = mesh.GetNumberOfPoints()
array_types = [core.vtkBitArray, core.vtkCharArray, core.vtkSignedCharArray, core.vtkUnsignedCharArray,
    core.vtkShortArray, core.vtkUnsignedShortArray, core.vtkIntArray, core.vtkUnsignedIntArray,
    core.vtkIdTypeArray, core.vtkLongLongArray, core.vtkUnsignedLongLongArray, core.vtkFloatArray,
    core.vtkDoubleArray]
for make in array_types:
    array = make()
    array.SetName(make.__name__)
    for p in range(points):
        array.InsertNextTuple1(p % 2 if make is core.vtkBitArray else p)
    mesh.GetPointData().AddArray(array)
six = core.vtkFloatArray()
six.SetName("six components")
six.SetNumberOfComponents(6)
for p in range(points):
    six.InsertNextTuple([p + k / 10.0 for k in range(6)])
mesh.GetPointData().AddArray(six)
names = core.vtkStringArray()
names.SetName("point names")
for p in range(points):
    names.InsertNextValue("point %d, of %d" % (p, points))
mesh.GetPointData().AddArray(names)
author = core.vtkStringArray()
author.SetName("author")
author.InsertNextValue("Jane Doe")
mesh.GetFieldData().AddArray(author)

for binary in (False, True):
    for version in (42, 51):
        name = os.path.join(work, "octahedron_%s_%d.vtk" % ("binary" if binary else "ascii", version))
        writer = vtkPolyDataWriter()
        writer.SetInputData(mesh)
        writer.SetFileName(name)
        if version == 42:
            writer.SetFileVersion(writer.VTK_LEGACY_READER_VERSION_4_2)
        if binary:
            writer.SetFileTypeToBinary()
        check(writer.Write() == 1, "vtkPolyDataWriter wrote %s" % name)
        code, out, err = cli_checks.run(program, "smooth", name)
        check(code == 0 and re.search(r"^input triangles: +8$", out, re.M) and not err,
            "%s is read (exit %d, stderr %r)" % (os.path.basename(name), code, err.strip()))
        if binary:
            short = name.replace(".vtk", "_short.vtk")
            with open(name, "rb") as whole, open(short, "wb") as cut:
                data = whole.read()
                cut.write(data[:len(data) * 6 // 10])
            code, out, err = cli_checks.run(program, "smooth", short)
            check(code == 1 and err.count("\n") == 1 and err.startswith("silhouette: "),
                "%s, cut short, is refused with one line (exit %d: %r)"
                % (os.path.basename(short), code, err.strip()))

# XML: every byte order, header width, encoding and compression vtkXMLPolyDataWriter writes.
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

for order in ("BigEndian", "LittleEndian"):
    for header in ("UInt32", "UInt64"):
        for mode in ("ascii", "binary", "appended_raw", "appended_base64"):
            for compressor in ("None", "ZLib", "LZ4", "LZMA"):
                if mode == "ascii" and compressor != "None":
                    continue
                name = os.path.join(work, "octahedron_%s_%s_%s%s.vtp"
                    % (order, header, mode, "" if compressor == "None" else "_" + compressor))
                writer = vtkXMLPolyDataWriter()
                writer.SetInputData(mesh)
                writer.SetFileName(name)
                getattr(writer, "SetByteOrderTo" + order)()
                getattr(writer, "SetHeaderTypeTo" + header)()
                if mode == "ascii":
                    writer.SetDataModeToAscii()
                elif mode == "binary":
                    writer.SetDataModeToBinary()
                else:
                    writer.SetDataModeToAppended()
                    writer.SetEncodeAppendedData(mode == "appended_base64")
                getattr(writer, "SetCompressorTypeTo" + compressor)()
                writer.SetBlockSize(64)  # several blocks a compressed array
                check(writer.Write() == 1, "vtkXMLPolyDataWriter wrote %s" % os.path.basename(name))
                code, out, err = cli_checks.run(program, "smooth", name)
                check(code == 0 and re.search(r"^input triangles: +8$", out, re.M) and not err,
                    "%s is read (exit %d, stderr %r)" % (os.path.basename(name), code, err.strip()))

# PLY (ASCII, binary in either byte order, with point colours), STL (ASCII,
# binary) and OBJ as VTK writes them.
from vtkmodules.vtkIOGeometry import vtkOBJWriter, vtkSTLWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter

colours = core.vtkUnsignedCharArray()
colours.SetName("colours")
colours.SetNumberOfComponents(3)
for p in range(points):
    colours.InsertNextTuple3(40 * p, 255 - 40 * p, 128)
coloured = vtkPolyData()
coloured.ShallowCopy(solid.GetOutput())
coloured.GetPointData().SetScalars(colours)
others = []
for kind in ("ascii", "little", "big"):
    writer = vtkPLYWriter()
    writer.SetInputData(coloured)
    writer.SetArrayName("colours")
    if kind == "ascii":
        writer.SetFileTypeToASCII()
    else:
        writer.SetFileTypeToBinary()
        getattr(writer, "SetDataByteOrderTo" + ("LittleEndian" if kind == "little" else "BigEndian"))()
    others.append((writer, "octahedron_%s.ply" % kind))
for kind in ("ascii", "binary"):
    writer = vtkSTLWriter()
    writer.SetInputData(solid.GetOutput())
    getattr(writer, "SetFileTypeTo" + ("ASCII" if kind == "ascii" else "Binary"))()
    others.append((writer, "octahedron_%s.stl" % kind))
writer = vtkOBJWriter()
writer.SetInputData(solid.GetOutput())
others.append((writer, "octahedron.obj"))
for writer, base in others:
    name = os.path.join(work, base)
    writer.SetFileName(name)
    check(writer.Write() == 1, "%s wrote %s" % (writer.GetClassName(), base))
    code, out, err = cli_checks.run(program, "smooth", name)
    check(code == 0 and re.search(r"^input triangles: +8$", out, re.M) and not err,
        "%s is read (exit %d, stderr %r)" % (base, code, err.strip()))

sys.exit(1 if cli_checks.failures else 0)
