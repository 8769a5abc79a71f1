"""What `silhouette smooth` writes for real asset files (issue 12).

Runs the program on Debian's assimp-testmodels spider (texture charts,
normal seams) and on a vtkCubeSource box (flat-shaded normals), then checks:
- `-o .ply` keeps the shading normals and the texture coordinates: they equal
  the `.vtp`'s point for point, and stderr names the arrays PLY cannot hold;
- `--lines-output` writes the silhouette polylines with normals;
- a flat-shaded input gets a one-line warning and still smooths.
Usage: TestCliOutputs.py SILHOUETTE_PROGRAM WORK_DIR
"""
import os
import sys

import cli_checks  # beside this script
from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

program, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
spider = "/usr/share/assimp/models/OBJ/spider.obj"
failures = cli_checks.failures
check = cli_checks.check


def run(*args):
    return cli_checks.run(program, *args)


def read(path):
    reader = vtkPLYReader() if path.endswith(".ply") else vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


check(os.path.exists(spider), "assimp-testmodels is installed (scripts/setup.sh installs it)")
ply, vtp, lines = (os.path.join(work, name) for name in ("spider.ply", "spider.vtp", "lines.vtp"))
code, _, err_ply = run("smooth", spider, "-o", ply, "--lines-output", lines, "--azimuth", "40")
check(code == 0, "smooth -o .ply --lines-output succeeds")
code, _, _ = run("smooth", spider, "-o", vtp, "--azimuth", "40")
check(code == 0, "smooth -o .vtp succeeds")
a, b = read(ply), read(vtp)
check(a.GetNumberOfPoints() == b.GetNumberOfPoints() > 4104, "the PLY has every output point")
check(a.GetNumberOfPolys() == b.GetNumberOfPolys(), "and every triangle")
na, nb = a.GetPointData().GetNormals(), b.GetPointData().GetNormals()
check(na is not None and nb is not None, "the PLY keeps the normals")
if na is not None and nb is not None:
    worst = max(abs(na.GetComponent(i, k) - nb.GetComponent(i, k))
                for i in range(a.GetNumberOfPoints()) for k in range(3))
    check(worst < 1e-6, "PLY normals equal the VTP's (worst %.1e)" % worst)
ta, tb = a.GetPointData().GetTCoords(), b.GetPointData().GetTCoords()
check(ta is not None and tb is not None, "and the texture coordinates")
if ta is not None and tb is not None:
    worst = max(abs(ta.GetComponent(i, k) - tb.GetComponent(i, k))
                for i in range(a.GetNumberOfPoints()) for k in range(2))
    check(worst < 1e-6, "PLY texture coordinates equal the VTP's (worst %.1e)" % worst)
check("PLY holds points, polygons, normals" in err_ply and "OriginalPointId" in err_ply,
      "stderr names what PLY cannot hold")
silhouette = read(lines)
check(silhouette.GetNumberOfLines() > 0 and silhouette.GetPointData().GetNormals() is not None,
      "--lines-output writes polylines with normals (%d lines)" % silhouette.GetNumberOfLines())

cube = vtkCubeSource()
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(cube.GetOutputPort())
box = os.path.join(work, "box.vtp")
writer.SetFileName(box)
writer.Write()
code, out, err = run("smooth", box, "--azimuth", "30", "--elevation", "20")
warnings = [line for line in err.splitlines() if line.startswith("silhouette: warning:")]
check(code == 0 and len(warnings) == 1 and "flat shading" in warnings[0],
      "a flat-shaded box gets one warning line: " + (warnings[0] if warnings else err.strip()))
check("silhouette triangles:" in out, "and is still smoothed")

print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
