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
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "EvaluationModels.h"
#include "SilhouetteTestSupport.h"

#include <cstdio>
#include <cstdlib>
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
