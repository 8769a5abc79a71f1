// What `compare`, `figure` and the truth evaluation decimate and refine
// (silhouette_eval::WeldedTriangles): an asset file's triangle soup merged
// into one closed surface, wound outward.
// - The bunny as a soup (every triangle its own three points, as OBJ readers
//   give textured assets) comes back with the bunny's points (the soup's
//   other 18,000 or so are reported merged), closed and manifold.
// - With its first triangle reversed, the whole still comes back outward
//   (positive enclosed volume): winding each part as its first triangle had
//   turned the whole bunny inside out, and the truth evaluation swapped
//   outside and inside.
// - A mesh already consistent keeps its triangles as they were, corner for
//   corner (the points renumbered).
// - assimp's concave_polygon.obj (one face of 66 corners, a ring walked
//   through a slit) comes back as the 64 triangles the filters cut it into,
//   with the ring's area; vtkTriangleFilter, which this used before (the
//   wrong variant, counted here), cuts it into 17, and `figure` drew the
//   ring with pieces missing.
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include "EvaluationModels.h"
#include "SilhouetteTestSupport.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

namespace
{

// Every triangle its own three points; the first one reversed when asked.
vtkSmartPointer<vtkPolyData> SoupOf(vtkPolyData* mesh, bool reverseFirst)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    vtkIdType own[3];
    for (vtkIdType k = 0; k < 3; ++k)
    {
      own[k] = points->InsertNextPoint(mesh->GetPoint(ids[k]));
    }
    if (reverseFirst && cells->GetNumberOfCells() == 0)
    {
      std::swap(own[1], own[2]);
    }
    cells->InsertNextCell(3, own);
  }
  auto soup = vtkSmartPointer<vtkPolyData>::New();
  soup->SetPoints(points);
  soup->SetPolys(cells);
  return soup;
}

bool CheckSoup(vtkPolyData* bunny, bool reverseFirst)
{
  vtkSmartPointer<vtkPolyData> soup = SoupOf(bunny, reverseFirst);
  vtkIdType merged = 0;
  vtkSmartPointer<vtkPolyData> welded = silhouette_eval::WeldedTriangles(soup, &merged);
  const double volume = silhouette_eval::EnclosedVolume(welded);
  std::printf("bunny soup%s: %lld points merged, %lld points and %lld triangles left, volume %g "
              "(the bunny's %g)\n",
    reverseFirst ? ", first triangle reversed" : "", static_cast<long long>(merged),
    static_cast<long long>(welded->GetNumberOfPoints()),
    static_cast<long long>(welded->GetNumberOfPolys()), volume,
    silhouette_eval::EnclosedVolume(bunny));
  CHECK(merged == soup->GetNumberOfPoints() - bunny->GetNumberOfPoints(), "the merged count");
  CHECK(welded->GetNumberOfPoints() == bunny->GetNumberOfPoints(), "the bunny's points");
  CHECK(welded->GetNumberOfPolys() == bunny->GetNumberOfPolys(), "the bunny's triangles");
  CHECK(silhouette_eval::CountBoundaryOrNonManifoldEdges(welded) == 0, "closed and manifold");
  CHECK(volume > 0.0, "wound outward");
  return true;
}

} // namespace

// Half the length of the summed cross products: the area of triangles that
// tile a flat region facing one way.
double FlatArea(vtkPolyData* mesh)
{
  double sum[3] = { 0.0, 0.0, 0.0 };
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      double a[3];
      double b[3];
      mesh->GetPoint(ids[k], a);
      mesh->GetPoint(ids[(k + 1) % n], b);
      sum[0] += a[1] * b[2] - a[2] * b[1];
      sum[1] += a[2] * b[0] - a[0] * b[2];
      sum[2] += a[0] * b[1] - a[1] * b[0];
    }
  }
  return 0.5 * std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
}

bool CheckConcavePolygon()
{
  const std::string assets = silhouette_test::AssetModelsFolder();
  CHECK(!assets.empty(), "Debian's assimp-testmodels is installed (scripts/setup.sh installs it)");
  vtkSmartPointer<vtkPolyData> ring =
    silhouette_test::ReadMesh(assets + "/OBJ/concave_polygon.obj");
  CHECK(ring && ring->GetNumberOfPolys() == 1, "the file reads, one polygon");
  vtkSmartPointer<vtkPolyData> welded = silhouette_eval::WeldedTriangles(ring);
  vtkNew<vtkTriangleFilter> stock;
  stock->SetInputData(ring);
  stock->Update();
  const double area = FlatArea(ring);
  std::printf("concave_polygon.obj (area %.4f): %lld triangles of area %.4f (vtkTriangleFilter: "
              "%lld)\n",
    area, static_cast<long long>(welded->GetNumberOfPolys()), FlatArea(welded),
    static_cast<long long>(stock->GetOutput()->GetNumberOfPolys()));
  CHECK(welded->GetNumberOfPolys() == 64, "the ring's 64 triangles");
  CHECK(std::abs(FlatArea(welded) - area) < 1e-6 * area, "the ring's area");
  CHECK(stock->GetOutput()->GetNumberOfPolys() < 64, "vtkTriangleFilter drops part of it");
  return true;
}

int TestEvaluationWelding(int argc, char* argv[])
{
  const auto bunny = silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bunny.ply"));
  if (!bunny || !(silhouette_eval::EnclosedVolume(bunny) > 0.0))
  {
    std::printf("FAIL: the bunny reads, wound outward\n");
    return EXIT_FAILURE;
  }
  bool ok = CheckSoup(bunny, false);
  ok = CheckSoup(bunny, true) && ok;
  ok = CheckConcavePolygon() && ok;
  // A consistent mesh keeps its triangles.
  vtkSmartPointer<vtkPolyData> same = silhouette_eval::WeldedTriangles(bunny);
  bool identical = same->GetNumberOfPolys() == bunny->GetNumberOfPolys();
  for (vtkIdType c = 0; identical && c < same->GetNumberOfPolys(); ++c)
  {
    vtkIdType n = 0, m = 0;
    const vtkIdType* a = nullptr;
    const vtkIdType* b = nullptr;
    same->GetPolys()->GetCellAtId(c, n, a);
    bunny->GetPolys()->GetCellAtId(c, m, b);
    identical = n == 3 && m == 3;
    for (vtkIdType k = 0; identical && k < 3; ++k)
    {
      double p[3], q[3];
      same->GetPoint(a[k], p);
      bunny->GetPoint(b[k], q);
      identical = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    }
  }
  if (!identical)
  {
    std::printf("FAIL: the consistent bunny's triangles changed\n");
    ok = false;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
