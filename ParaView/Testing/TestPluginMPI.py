"""pvbatch test on two MPI ranks: the bunny's point normals are computed on the
whole mesh, the mesh is split across the ranks (RedistributeDataSet), each
rank smooths its piece for the same camera, and the pieces' outputs together
must equal the output of smoothing the whole mesh in one process: the same
triangle count, the same triangles (compared by their corners' coordinates,
exactly), and no crack where the pieces meet (once coincident points are
merged with tolerance 0, no boundary edge, as on the closed whole)."""
import sys
from collections import Counter

from paraview import servermanager, simple
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData, vtkFeatureEdges
from vtkmodules.vtkParallelCore import vtkMultiProcessController

from SilhouetteTestUtils import copy_camera, field_value, load_plugin, setting, triangle_count

ranks = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()
print("ranks: %d" % ranks)
if ranks != 2:
    sys.exit("FAILED: run with mpirun -np 2 (got %d ranks)" % ranks)

SilhouetteSmoothing = load_plugin()
simple._DisableFirstRenderCameraReset()

view = simple.CreateView("RenderView")
view.ViewSize = [1024, 768]
view.CameraPosition = [16.0, 11.0, 22.0]
view.CameraFocalPoint = [0.0, 4.8, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 30.0

# The PLY reader reads on rank 0 only; the normals are computed there on the
# whole mesh, before partitioning, so both sides of a seam carry the same
# normals at the same points.
reader = simple.PLYReader(FileNames=[setting("SILHOUETTE_DATA")])
normals = simple.GenerateSurfaceNormals(Input=reader)
normals.Splitting = 0
normals.ComputeCellNormals = 0
pieces = simple.RedistributeDataSet(Input=normals)
surface = simple.ExtractSurface(Input=pieces)

split = SilhouetteSmoothing(Input=surface)
whole = SilhouetteSmoothing(Input=normals)
for smoother in (split, whole):
    copy_camera(view, smoother)

whole_output = servermanager.Fetch(whole)
piece_outputs = [servermanager.Fetch(split, rank) for rank in range(ranks)]


def closed_check(polydata):
    """Merges coincident points (tolerance 0) and counts boundary and
    non-manifold edges."""
    clean = vtkCleanPolyData()
    clean.SetInputData(polydata)
    clean.SetTolerance(0.0)
    clean.SetAbsoluteTolerance(0.0)
    clean.ToleranceIsAbsoluteOn()
    clean.ConvertPolysToLinesOff()
    clean.ConvertLinesToPointsOff()
    clean.ConvertStripsToPolysOff()
    edges = vtkFeatureEdges()
    edges.SetInputConnection(clean.GetOutputPort())
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.BoundaryEdgesOn()
    edges.NonManifoldEdgesOff()
    edges.Update()
    boundary = edges.GetOutput().GetNumberOfCells()
    edges.BoundaryEdgesOff()
    edges.NonManifoldEdgesOn()
    edges.Update()
    non_manifold = edges.GetOutput().GetNumberOfCells()
    return clean.GetOutput().GetNumberOfPoints(), boundary, non_manifold


def triangles(polydata):
    """The triangles as a multiset of their corners' coordinates, rotated to
    start at the smallest corner (orientation kept)."""
    points = polydata.GetPoints()
    result = Counter()
    cells = polydata.GetPolys()
    cells.InitTraversal()
    ids = vtkIdList()
    while cells.GetNextCell(ids):
        corners = [points.GetPoint(ids.GetId(i)) for i in range(ids.GetNumberOfIds())]
        start = corners.index(min(corners))
        result[tuple(corners[start:] + corners[:start])] += 1
    return result


merged = vtkAppendPolyData()
for output in piece_outputs:
    merged.AddInputData(output)
merged.Update()

whole_triangles = triangle_count(whole_output)
piece_triangles = [triangle_count(output) for output in piece_outputs]
piece_inputs = [field_value(output, "InputTriangleCount") or 0 for output in piece_outputs]
piece_silhouette = [field_value(output, "SilhouetteTriangleCount") or 0 for output in piece_outputs]
whole_points, whole_boundary, whole_non_manifold = closed_check(whole_output)
merged_points, merged_boundary, merged_non_manifold = closed_check(merged.GetOutput())
piece_boundary = [closed_check(output)[1] for output in piece_outputs]
difference = triangles(whole_output)
difference.subtract(triangles(merged.GetOutput()))
missing = sum(count for count in difference.values() if count > 0)
extra = sum(-count for count in difference.values() if count < 0)

print("whole mesh, one process: %d input triangles, %d silhouette triangles, %d output triangles"
    % (field_value(whole_output, "InputTriangleCount"), field_value(whole_output, "SilhouetteTriangleCount"),
        whole_triangles))
for rank in range(ranks):
    print("piece on rank %d: %d input triangles, %d silhouette triangles, %d output triangles, "
        "%d boundary edges (the seam)" % (rank, piece_inputs[rank], piece_silhouette[rank],
            piece_triangles[rank], piece_boundary[rank]))
print("pieces together: %d output triangles; merged (tolerance 0): %d points, %d boundary edges, "
    "%d non-manifold edges" % (sum(piece_triangles), merged_points, merged_boundary, merged_non_manifold))
print("whole, merged the same way: %d points, %d boundary edges, %d non-manifold edges"
    % (whole_points, whole_boundary, whole_non_manifold))
print("triangles of the whole not in the pieces: %d; in the pieces, not in the whole: %d" % (missing, extra))

failures = []
if min(piece_inputs) == 0:
    failures.append("the mesh was not split: input triangles per rank %s" % piece_inputs)
if min(piece_boundary) == 0:
    failures.append("a piece has no seam")
if sum(piece_triangles) != whole_triangles:
    failures.append("triangle counts differ: pieces %d, whole %d" % (sum(piece_triangles), whole_triangles))
if merged_boundary != whole_boundary or merged_non_manifold != whole_non_manifold:
    failures.append("cracks: the merged pieces have %d boundary and %d non-manifold edges, the whole %d and %d"
        % (merged_boundary, merged_non_manifold, whole_boundary, whole_non_manifold))
if missing or extra:
    failures.append("the pieces' triangles differ from the whole's")
if failures:
    for failure in failures:
        print("FAILED: " + failure)
    sys.exit(1)
print("passed")
