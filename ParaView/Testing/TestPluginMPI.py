"""pvbatch test on two MPI ranks: the bunny's point normals are computed on the
whole mesh, the mesh is split in two halves (by the cells' centroids, at the
median x) written as the two pieces of one parallel file (.pvtp), which the
two ranks read one piece each; each rank smooths its piece for the same
camera, and the pieces' outputs together are compared with the output of
smoothing the whole mesh in one process. Without vertex perturbation they
must be equal: the same triangle count, the same triangles (compared by their
corners' coordinates, exactly) and no crack where the pieces meet (once
coincident points are merged with tolerance 0, no boundary edge, as on the
closed whole). With it (the default), the same count and no crack."""
from collections import Counter
from types import SimpleNamespace

from paraview import servermanager, simple
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData, vtkFeatureEdges

from SilhouetteTestUtils import (cell_point_ids, copy_camera, field_value, finish, halves_at_median_x, load_plugin,
                                 read_with_point_normals, setting, triangle_count, two_ranks, write_pieces)

ranks = two_ranks()

SilhouetteSmoothing = load_plugin()

# The camera as a render view would give it (the image test copies a real
# view's): no view here, so no rank opens an X connection it does not need.
view = SimpleNamespace(CameraPosition=[16.0, 11.0, 22.0], CameraFocalPoint=[0.0, 4.8, 0.0],
    CameraViewUp=[0.0, 1.0, 0.0], CameraViewAngle=30.0, CameraParallelProjection=0, CameraParallelScale=1.0,
    ViewSize=[1024, 768])

# Normals on the whole mesh, before partitioning, so that both sides of the
# seam carry the same normals at the same points.
mesh = read_with_point_normals(setting("SILHOUETTE_DATA"))

# The two halves: cells whose centroid lies left of the median x go to piece
# 0, the others to piece 1. Each piece keeps the points it uses (same
# coordinates and normals).
pieces = [[(cell, 0) for cell in half] for half in halves_at_median_x(mesh, cell_point_ids(mesh))]
parallel_file, whole_file = write_pieces(mesh, pieces, setting("SILHOUETTE_OUTPUT_DIR"), "TestPluginMPI")

# Rank i reads piece i; the whole mesh, a one-piece file, is read by rank 0.
surface = simple.XMLPartitionedPolydataReader(FileName=[parallel_file])
split = SilhouetteSmoothing(Input=surface)
whole = SilhouetteSmoothing(Input=simple.XMLPolyDataReader(FileName=[whole_file]))
for smoother in (split, whole):
    copy_camera(view, smoother)


def closed_check(polydata):
    """Merges coincident points (tolerance 0) and counts the points and the
    boundary and non-manifold edges."""
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


def point_set(polydata):
    return {polydata.GetPoint(i) for i in range(polydata.GetNumberOfPoints())}


def compare(perturb):
    """Smooths the pieces and the whole with PerturbVertices = perturb; prints
    the figures and returns them."""
    for smoother in (split, whole):
        smoother.PerturbVertices = perturb
    whole_output = servermanager.Fetch(whole)
    piece_outputs = [servermanager.Fetch(split, rank) for rank in range(ranks)]
    merged = vtkAppendPolyData()
    for output in piece_outputs:
        merged.AddInputData(output)
    merged.Update()

    r = {}
    r["whole"] = triangle_count(whole_output)
    r["pieces"] = [triangle_count(output) for output in piece_outputs]
    r["inputs"] = [field_value(output, "InputTriangleCount") or 0 for output in piece_outputs]
    r["seams"] = [closed_check(output)[1] for output in piece_outputs]
    silhouette = [field_value(output, "SilhouetteTriangleCount") or 0 for output in piece_outputs]
    whole_points, r["whole_boundary"], r["whole_non_manifold"] = closed_check(whole_output)
    merged_points, r["boundary"], r["non_manifold"] = closed_check(merged.GetOutput())
    difference = triangles(whole_output)
    difference.subtract(triangles(merged.GetOutput()))
    r["missing"] = sum(count for count in difference.values() if count > 0)
    r["extra"] = sum(-count for count in difference.values() if count < 0)

    print("PerturbVertices %s:" % ("on" if perturb else "off"))
    print("  whole mesh, one process: %d input triangles, %d silhouette triangles, %d output triangles"
        % (field_value(whole_output, "InputTriangleCount"), field_value(whole_output, "SilhouetteTriangleCount"),
            r["whole"]))
    for rank in range(ranks):
        print("  piece on rank %d: %d input triangles, %d silhouette triangles, %d output triangles, "
            "%d boundary edges (the seam)" % (rank, r["inputs"][rank], silhouette[rank], r["pieces"][rank],
                r["seams"][rank]))
    print("  pieces together: %d output triangles; merged (tolerance 0): %d points, %d boundary edges, "
        "%d non-manifold edges" % (sum(r["pieces"]), merged_points, r["boundary"], r["non_manifold"]))
    print("  whole, merged the same way: %d points, %d boundary edges, %d non-manifold edges"
        % (whole_points, r["whole_boundary"], r["whole_non_manifold"]))
    print("  triangles of the whole not in the pieces: %d; in the pieces, not in the whole: %d"
        % (r["missing"], r["extra"]))
    whole_point_set = point_set(whole_output)
    stray = [p for p in point_set(merged.GetOutput()) if p not in whole_point_set]
    if stray:
        gap = max(min(sum((a - b) ** 2 for a, b in zip(p, q)) ** 0.5 for q in whole_point_set) for p in stray)
        print("  points of the pieces not in the whole: %d, at most %.3g from the whole's nearest point"
            % (len(stray), gap))
    return r


failures = []
# Without vertex perturbation the pieces must give the whole's output exactly:
# every silhouette point is computed from its edge alone (its two points and
# their normals), and each triangle is re-meshed from its own edges.
exact = compare(0)
if min(exact["inputs"]) == 0:
    failures.append("the mesh was not split: input triangles per rank %s" % exact["inputs"])
if min(exact["seams"]) == 0:
    failures.append("a piece has no seam")
if sum(exact["pieces"]) != exact["whole"]:
    failures.append("triangle counts differ: pieces %d, whole %d" % (sum(exact["pieces"]), exact["whole"]))
if exact["boundary"] != exact["whole_boundary"] or exact["non_manifold"] != exact["whole_non_manifold"]:
    failures.append("cracks: the merged pieces have %d boundary and %d non-manifold edges, the whole %d and %d"
        % (exact["boundary"], exact["non_manifold"], exact["whole_boundary"], exact["whole_non_manifold"]))
if exact["missing"] or exact["extra"]:
    failures.append("the pieces' triangles differ from the whole's")

# With vertex perturbation (the default), a point on a boundary edge never
# moves, so the seam's points stay put on both sides and the pieces must still
# meet without a crack, with the whole's triangle count. The whole mesh has no
# seam there and may lower those points, so the triangles by the seam may
# differ from the whole's: reported, not failed.
perturbed = compare(1)
if sum(perturbed["pieces"]) != perturbed["whole"]:
    failures.append("with perturbation, triangle counts differ: pieces %d, whole %d"
        % (sum(perturbed["pieces"]), perturbed["whole"]))
if (perturbed["boundary"] != perturbed["whole_boundary"]
        or perturbed["non_manifold"] != perturbed["whole_non_manifold"]):
    failures.append("with perturbation, cracks: the merged pieces have %d boundary and %d non-manifold edges, "
        "the whole %d and %d" % (perturbed["boundary"], perturbed["non_manifold"], perturbed["whole_boundary"],
            perturbed["whole_non_manifold"]))

finish(failures)
