"""The Python package (issue 7): every class of the module imports beside
Debian's vtkmodules and works in a pipeline with VTK's own classes; errors
reach Python as VTK errors; the README's example runs and draws the bunny;
the render-time mapper draws what the filter draws.

    PYTHONPATH=<build>/lib/python3.11/dist-packages python3 TestSilhouetteSmoothing.py DATA_DIR
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkRenderingCore import vtkCamera

import silhouette_smoothing
from silhouette_smoothing import (vtkIcosphereSource, vtkOpenSubdivRefiner,
                                  vtkSilhouetteSmoothingFilter, vtkTorusSurfaceSource)

DATA = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..",
                                                                 "..", "Data")
EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Examples",
                       "Python", "smooth_and_render.py")


def field(mesh, name):
    return mesh.GetFieldData().GetArray(name).GetValue(0)


class SilhouetteSmoothingTest(unittest.TestCase):
    def test_package(self):
        self.assertEqual(silhouette_smoothing.__version__.count("."), 2)
        for cls in (vtkIcosphereSource, vtkOpenSubdivRefiner, vtkSilhouetteSmoothingFilter,
                    vtkTorusSurfaceSource):
            self.assertTrue(cls().IsA("vtkAlgorithm"), cls.__name__)

    def test_view_filters_share_the_view_superclass(self):
        # The abstract superclass is wrapped, and the view methods of the
        # four view-dependent filters come from it.
        self.assertTrue(hasattr(silhouette_smoothing, "vtkSilhouetteViewAlgorithm"))
        camera = vtkCamera()
        for name in ("vtkSilhouetteSmoothingFilter", "vtkBoundaryCurveSmoothingFilter",
                     "vtkFaceSilhouetteLines", "vtkSilhouetteProximity"):
            view_filter = getattr(silhouette_smoothing, name)()
            self.assertTrue(view_filter.IsA("vtkSilhouetteViewAlgorithm"), name)
            view_filter.SetCamera(camera)
            view_filter.SetViewportSize(640, 480)
            self.assertIs(view_filter.GetCamera(), camera)
            self.assertEqual(view_filter.GetViewportSize(), (640, 480))

    def test_level_of_detail_feeds_the_smoothing(self):
        # vtkViewDependentLevelOfDetail (issue 18): a fine sphere is drawn
        # with a fraction of its triangles, the same for a second update of
        # an unchanged view, and the smoothing filter takes its output.
        sphere = vtkIcosphereSource()
        sphere.SetSubdivisionLevel(5)
        sphere.Update()
        camera = vtkCamera()
        camera.SetPosition(0.3, 0.5, 5.0)
        lod = silhouette_smoothing.vtkViewDependentLevelOfDetail()
        self.assertTrue(lod.IsA("vtkSilhouetteViewAlgorithm"))
        lod.SetInputConnection(sphere.GetOutputPort())
        lod.SetCamera(camera)
        lod.SetViewportSize(640, 480)
        lod.Update()
        drawn = lod.GetOutput().GetNumberOfPolys()
        full = sphere.GetOutput().GetNumberOfPolys()
        self.assertLess(drawn, full // 2)
        self.assertGreater(drawn, 100)
        self.assertIsNotNone(lod.GetOutput().GetPointData().GetArray("OriginalPointId"))
        smoothing = vtkSilhouetteSmoothingFilter()
        smoothing.SetInputConnection(lod.GetOutputPort())
        smoothing.SetCamera(camera)
        smoothing.SetViewportSize(640, 480)
        smoothing.Update()
        self.assertGreater(field(smoothing.GetOutput(), "SilhouetteTriangleCount"), 0)
        lod.Modified()
        lod.Update()
        self.assertEqual(lod.GetOutput().GetNumberOfPolys(), drawn)

    def test_triangle_soup_is_welded(self):
        # Every corner its own point, as VTK's OBJ reader makes of textured
        # assets: smoothed as the welded sphere, unless welding is off (issue 12).
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
        sphere = vtkIcosphereSource()
        sphere.SetSubdivisionLevel(1)
        sphere.Update()
        mesh = sphere.GetOutput()
        points, cells = vtkPoints(), vtkCellArray()
        for c in range(mesh.GetNumberOfCells()):
            ids = mesh.GetCell(c).GetPointIds()
            cells.InsertNextCell(3)
            for k in range(3):
                cells.InsertCellPoint(points.InsertNextPoint(mesh.GetPoint(ids.GetId(k))))
        soup = vtkPolyData()
        soup.SetPoints(points)
        soup.SetPolys(cells)
        bare = vtkPolyData()  # the sphere without its normals, as the soup
        bare.SetPoints(mesh.GetPoints())
        bare.SetPolys(mesh.GetPolys())
        mesh = bare
        camera = vtkCamera()
        camera.SetPosition(0.3, 0.4, 5.0)
        counts = {}
        for source, weld in ((mesh, True), (soup, True), (soup, False)):
            smoother = vtkSilhouetteSmoothingFilter()
            smoother.SetInputData(source)
            smoother.SetCamera(camera)
            smoother.SetWeldCoincidentPoints(weld)
            smoother.Update()
            counts[(source is soup, weld)] = field(smoother.GetOutput(), "SilhouetteTriangleCount")
        self.assertGreater(counts[(False, True)], 0)
        self.assertEqual(counts[(True, True)], counts[(False, True)])
        self.assertEqual(counts[(True, False)], 0)

    def test_sphere_silhouette_is_the_exact_circle(self):
        # 80 triangles on the unit sphere with exact normals, eye at distance
        # about 5: the exact contour is seen at the angle asin(1 / d) from the
        # line of sight to the centre; 1e-3 rad is 1.4 px at 1024 x 768.
        sphere = vtkIcosphereSource()
        sphere.SetSubdivisionLevel(1)
        camera = vtkCamera()
        camera.SetPosition(0.3, 0.4, 5.0)
        camera.SetFocalPoint(0.0, 0.0, 0.0)
        eye = camera.GetPosition()
        distance = math.sqrt(sum(c * c for c in eye))
        exact = math.asin(1.0 / distance)
        smoother = vtkSilhouetteSmoothingFilter()
        smoother.SetInputConnection(sphere.GetOutputPort())
        smoother.SetCamera(camera)
        smoother.Update()
        out = smoother.GetOutput()
        self.assertEqual(field(out, "InputTriangleCount"), 80)
        self.assertGreater(field(out, "SilhouetteTriangleCount"), 0)
        self.assertEqual(out.GetNumberOfPolys(), field(out, "OutputTriangleCount"))
        kinds = out.GetCellData().GetArray("NewGeometry")
        self.assertEqual(set(int(kinds.GetValue(i)) for i in range(kinds.GetNumberOfTuples())),
                         {0, 1})
        lines = smoother.GetSilhouetteOutput()
        self.assertGreater(lines.GetNumberOfPoints(), 20)

        def angle_from_axis(x):
            ray = [a - b for a, b in zip(x, eye)]
            cosine = -sum(a * b for a, b in zip(ray, eye)) / (
                math.sqrt(sum(a * a for a in ray)) * distance)
            return math.acos(max(-1.0, min(1.0, cosine)))

        worst = max(abs(angle_from_axis(lines.GetPoint(i)) - exact)
                    for i in range(lines.GetNumberOfPoints()))
        print("sphere silhouette: %d points, at most %.2e rad from the exact contour"
              % (lines.GetNumberOfPoints(), worst))
        self.assertLess(worst, 1e-3)

    def test_refiner_and_torus(self):
        torus = vtkTorusSurfaceSource()
        refiner = vtkOpenSubdivRefiner()
        refiner.SetInputConnection(torus.GetOutputPort())
        refiner.SetLevel(1)
        refiner.Update()
        torus.Update()
        self.assertEqual(refiner.GetOutput().GetNumberOfPolys(),
                         4 * torus.GetOutput().GetNumberOfPolys())

    def test_missing_camera_is_a_vtk_error(self):
        errors = []
        sphere = vtkIcosphereSource()  # kept: a port does not keep its producer alive
        smoother = vtkSilhouetteSmoothingFilter()
        smoother.SetInputConnection(sphere.GetOutputPort())
        smoother.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
        self.assertEqual(smoother.GetExecutive().Update(), 0)
        self.assertTrue(errors)
        self.assertEqual(smoother.GetOutput().GetNumberOfPoints(), 0)

    def test_mapper_draws_what_the_filter_draws(self):
        # vtkSilhouetteSmoothingMapper, with no wiring, against the filter
        # wired to the renderer: the same pixels; with smoothing off (the
        # chord outline) thousands differ, so the comparison can fail.
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL back-end)
        from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                                 vtkRenderWindow, vtkWindowToImageFilter)
        from silhouette_smoothing import vtkSilhouetteSmoothingMapper
        sphere = vtkIcosphereSource()
        sphere.SetSubdivisionLevel(2)
        # One window open throughout: each image's window closes, and an X
        # server whose last client leaves resets, refusing the next one.
        keeper = vtkRenderWindow()
        keeper.SetOffScreenRendering(1)
        keeper.SetSize(8, 8)
        keeper.Render()

        def pixels(kind):
            renderer = vtkRenderer()
            window = vtkRenderWindow()
            window.SetOffScreenRendering(1)
            window.SetMultiSamples(0)
            window.SetSize(300, 300)
            window.AddRenderer(renderer)
            actor = vtkActor()
            if kind == "filter":
                smoother = vtkSilhouetteSmoothingFilter()
                smoother.SetInputConnection(sphere.GetOutputPort())
                smoother.SetRenderer(renderer)
                smoother.SetProp3D(actor)
                mapper = vtkPolyDataMapper()
                mapper.SetInputConnection(smoother.GetOutputPort())
            else:
                mapper = vtkSilhouetteSmoothingMapper()
                mapper.SetInputConnection(sphere.GetOutputPort())
                mapper.SetSmoothing(kind == "mapper")
            actor.SetMapper(mapper)
            renderer.AddActor(actor)
            renderer.ResetCamera()
            renderer.GetActiveCamera().Azimuth(25)
            renderer.GetActiveCamera().Elevation(15)
            window.Render()
            grab = vtkWindowToImageFilter()
            grab.SetInput(window)
            grab.Update()
            scalars = grab.GetOutput().GetPointData().GetScalars()
            return [scalars.GetTuple(i) for i in range(scalars.GetNumberOfTuples())]

        expected = pixels("filter")
        differing = sum(a != b for a, b in zip(pixels("mapper"), expected))
        unsmoothed = sum(a != b for a, b in zip(pixels("unsmoothed"), expected))
        print("mapper: %d pixels differ from the filter's image, %d with smoothing off"
              % (differing, unsmoothed))
        self.assertLessEqual(differing, 10)
        self.assertGreater(unsmoothed, 10)
        keeper.Finalize()

    def test_readme_example_draws_the_bunny(self):
        with tempfile.TemporaryDirectory() as folder:
            image = os.path.join(folder, "bunny.png")
            result = subprocess.run([sys.executable, EXAMPLE,
                                     os.path.join(DATA, "bunny_coarse.ply"), image],
                                    capture_output=True, text=True, check=False)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("silhouette triangles:", result.stdout)
            reader = vtkPNGReader()
            reader.SetFileName(image)
            reader.Update()
            pixels = reader.GetOutput().GetPointData().GetScalars()
            covered = sum(1 for i in range(pixels.GetNumberOfTuples())
                          if pixels.GetTuple(i)[:3] != (255.0, 255.0, 255.0))
            fraction = covered / pixels.GetNumberOfTuples()
            print("example image: %.1f%% of the pixels show the bunny" % (100.0 * fraction))
            self.assertGreater(fraction, 0.1)
            self.assertLess(fraction, 0.6)


if __name__ == "__main__":
    unittest.main(verbosity=2)
