"""Helpers shared by the pvbatch tests of the SilhouetteSmoothing plugin."""
import os
import sys

from paraview import simple


def setting(name):
    """A test setting, passed by ctest in the environment."""
    value = os.environ.get(name)
    if not value:
        sys.exit("test setting %s is not set (run the test through ctest)" % name)
    return value


def load_plugin():
    """Loads the plugin on every rank (remote=True: the server side, which in
    pvbatch is all the MPI ranks) and returns the filter's constructor, as
    paraview.simple makes it from the server-manager XML."""
    names = {"__name__": __name__}  # not empty: LoadPlugin takes an empty one for "none given"
    simple.LoadPlugin(setting("SILHOUETTE_PLUGIN"), remote=True, ns=names)
    if "SilhouetteSmoothing" not in names:
        sys.exit("the plugin loaded but did not define SilhouetteSmoothing")
    return names["SilhouetteSmoothing"]


def show_bunny_view(view):
    """The look every image test shares: no orientation axes, white, and the
    camera on the coarse bunny (three-quarter view from above)."""
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.CameraPosition = [16.0, 11.0, 22.0]
    view.CameraFocalPoint = [0.0, 4.8, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30.0
    view.CameraParallelProjection = 0


def plain_render_view(size):
    """A new render view of `size` pixels, white, without orientation axes,
    whose first render keeps the camera it is given."""
    simple._DisableFirstRenderCameraReset()
    view = simple.CreateView("RenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    return view


def bunny_render_view(size):
    """A new render view of `size` pixels with the image tests' look and
    camera (show_bunny_view), which its first render keeps."""
    simple._DisableFirstRenderCameraReset()
    view = simple.CreateView("RenderView")
    view.ViewSize = size
    show_bunny_view(view)
    return view


def copy_camera(view, smoother):
    """Copies the render view's camera and size into the filter's properties:
    ParaView does not hand the view's vtkCamera to a filter."""
    smoother.CameraPosition = list(view.CameraPosition)
    smoother.CameraFocalPoint = list(view.CameraFocalPoint)
    smoother.CameraViewUp = list(view.CameraViewUp)
    smoother.CameraViewAngle = view.CameraViewAngle
    smoother.CameraParallelProjection = view.CameraParallelProjection
    smoother.CameraParallelScale = view.CameraParallelScale
    smoother.ViewportSize = list(view.ViewSize)


def load_representation_plugin():
    """Loads the plugin on every rank for its representation (Smooth
    Silhouette Surface): nothing to return, the representation is a value of
    a display's Representation property."""
    names = {"__name__": __name__}
    simple.LoadPlugin(setting("SILHOUETTE_PLUGIN"), remote=True, ns=names)


def image_error(image, baseline):
    """vtkImageDifference's thresholded error between two PNG files:
    per-pixel threshold 16 (its default, 105, forgives too much here),
    one-pixel shifts and averaging allowed, as the plugin's image tests
    compare."""
    from vtkmodules.vtkImagingCore import vtkImageDifference
    from vtkmodules.vtkIOImage import vtkPNGReader

    readers = []
    for name in (image, baseline):
        png = vtkPNGReader()
        png.SetFileName(name)
        png.Update()
        readers.append(png)
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[0].GetOutputPort())
    difference.SetImageConnection(readers[1].GetOutputPort())
    difference.SetThreshold(16)
    difference.AllowShiftOn()
    difference.AveragingOn()
    difference.Update()
    return difference.GetThresholdedError()


def two_ranks():
    """The number of MPI ranks, which must be two (the tests split the mesh
    in two); exits otherwise."""
    from vtkmodules.vtkParallelCore import vtkMultiProcessController

    ranks = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()
    print("ranks: %d" % ranks)
    if ranks != 2:
        sys.exit("FAILED: run with mpirun -np 2 (got %d ranks)" % ranks)
    return ranks


def read_with_point_normals(ply_file):
    """A PLY mesh with point normals computed on the whole mesh (no
    splitting, no reorientation), before any partitioning, so that both sides
    of a seam carry the same normals at the same points."""
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkIOPLY import vtkPLYReader

    ply = vtkPLYReader()
    ply.SetFileName(ply_file)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(ply.GetOutputPort())
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.ComputeCellNormalsOff()
    normals.Update()
    return normals.GetOutput()


def cell_point_ids(mesh):
    """Each cell's point ids, in cell order."""
    from vtkmodules.vtkCommonCore import vtkIdList

    ids = vtkIdList()
    cell_points = []
    for cell in range(mesh.GetNumberOfCells()):
        mesh.GetCellPoints(cell, ids)
        cell_points.append([ids.GetId(i) for i in range(ids.GetNumberOfIds())])
    return cell_points


def halves_at_median_x(mesh, cell_points):
    """The two halves of `mesh` as lists of cell ids (in cell order): the
    cells whose centroid lies left of the median x, then the others."""
    centroids = [sum(mesh.GetPoint(p)[0] for p in points) / len(points) for points in cell_points]
    median = sorted(centroids)[len(centroids) // 2]
    return [[cell for cell in range(len(centroids)) if (centroids[cell] >= median) == (half == 1)]
            for half in range(2)]


def write_pieces(mesh, pieces, output_dir, name, ghosts=False):
    """Writes each piece of `mesh` (a list of (cell id, ghost flag) pairs, in
    the order the piece keeps them) as a .vtp of the points it uses, the whole
    mesh as NAME_whole.vtp, and NAME_pieces.pvtp listing the pieces (rank i
    reads piece i); returns the .pvtp's and the whole file's paths. With
    `ghosts` the pieces carry the flags as vtkGhostType and the .pvtp says
    GhostLevel 1. The data are inline, not appended: the expat of Debian
    bookworm (2.5.0 with the reparse-deferral security fix) breaks how
    ParaView 5.11's VTK reads appended data (and so RedistributeDataSet,
    which sends pieces as appended XML, fails the same way)."""
    from vtkmodules.vtkCommonCore import vtkIdList, vtkUnsignedCharArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataSetAttributes, vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkCleanPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    def write(file_name, data=None, port=None):
        writer = vtkXMLPolyDataWriter()
        writer.SetDataModeToBinary()
        if port is not None:
            writer.SetInputConnection(port)
        else:
            writer.SetInputData(data)
        writer.SetFileName(os.path.join(output_dir, file_name))
        writer.Write()

    os.makedirs(output_dir, exist_ok=True)
    ids = vtkIdList()
    piece_files = []
    for index, cells in enumerate(pieces):
        polys = vtkCellArray()
        ghost_type = vtkUnsignedCharArray()
        ghost_type.SetName(vtkDataSetAttributes.GhostArrayName())
        for cell, flag in cells:
            mesh.GetCellPoints(cell, ids)
            polys.InsertNextCell(ids)
            ghost_type.InsertNextValue(flag)
        piece = vtkPolyData()
        piece.SetPoints(mesh.GetPoints())
        piece.GetPointData().ShallowCopy(mesh.GetPointData())
        piece.SetPolys(polys)
        if ghosts:
            piece.GetCellData().AddArray(ghost_type)
        compact = vtkCleanPolyData()  # drops the unused points, merges none
        compact.SetInputData(piece)
        compact.PointMergingOff()
        piece_files.append("%s_piece%d.vtp" % (name, index))
        write(piece_files[-1], port=compact.GetOutputPort())
    whole_file = os.path.join(output_dir, "%s_whole.vtp" % name)
    write(os.path.basename(whole_file), data=mesh)
    xml_types = {"float": "Float32", "double": "Float64"}
    cell_data = ""
    if ghosts:
        cell_data = ("    <PCellData>\n"
                     "      <PDataArray type=\"UInt8\" Name=\"%s\" NumberOfComponents=\"1\"/>\n"
                     "    </PCellData>\n" % vtkDataSetAttributes.GhostArrayName())
    normals = mesh.GetPointData().GetNormals()
    point_data = ""
    if normals is not None:
        point_data = ("    <PPointData Normals=\"Normals\">\n"
                      "      <PDataArray type=\"%s\" Name=\"Normals\" NumberOfComponents=\"3\"/>\n"
                      "    </PPointData>\n" % xml_types[normals.GetDataTypeAsString()])
    parallel_file = os.path.join(output_dir, "%s_pieces.pvtp" % name)
    with open(parallel_file, "w") as pvtp:
        pvtp.write(
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"PPolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <PPolyData GhostLevel=\"%d\">\n"
            "%s"
            "%s"
            "    <PPoints>\n"
            "      <PDataArray type=\"%s\" NumberOfComponents=\"3\"/>\n"
            "    </PPoints>\n"
            "%s"
            "  </PPolyData>\n"
            "</VTKFile>\n"
            % (1 if ghosts else 0, point_data, cell_data,
               xml_types[mesh.GetPoints().GetData().GetDataTypeAsString()],
               "".join("    <Piece Source=\"%s\"/>\n" % file for file in piece_files)))
    return parallel_file, whole_file


def field_value(polydata, name):
    array = polydata.GetFieldData().GetArray(name)
    return int(array.GetTuple1(0)) if array is not None else None


def triangle_count(polydata):
    cells = polydata.GetPolys()
    return cells.GetNumberOfCells() if cells is not None else 0


def finish(failures):
    """Prints the verdict; on failures, raises: pvbatch 5.11 then exits with
    code 1, where sys.exit with a non-zero code after rendering crashes it
    (SIGSEGV) and os._exit loses the captured output."""
    for failure in failures:
        print("FAILED: " + failure)
    if failures:
        raise RuntimeError("%d check(s) failed" % len(failures))
    print("passed")
