// VisibilityMethod changes how the vertices facing the viewer are found, never
// the result: the filter's outputs (both ports) must be identical with
// PER_VERTEX and HIERARCHICAL, on the bunny and a sphere, from many
// perspective and parallel views, with vtkSMPTools splitting the work.
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include "SilhouetteTestSupport.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace
{

bool SameCells(vtkCellArray* a, vtkCellArray* b)
{
  if (a->GetNumberOfCells() != b->GetNumberOfCells() ||
    a->GetNumberOfConnectivityIds() != b->GetNumberOfConnectivityIds())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfConnectivityIds(); ++i)
  {
    if (a->GetConnectivityArray()->GetTuple1(i) != b->GetConnectivityArray()->GetTuple1(i))
    {
      return false;
    }
  }
  return true;
}

bool SamePoints(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3];
    double q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
    {
      return false;
    }
  }
  return true;
}

bool SameOutputs(vtkPolyData* mesh, const char* name)
{
  vtkNew<vtkSilhouetteSmoothingFilter> plain;
  vtkNew<vtkSilhouetteSmoothingFilter> tree;
  tree->SetVisibilityMethodToHierarchical();
  CHECK(plain->GetVisibilityMethod() == vtkSilhouetteSmoothingFilter::PER_VERTEX,
    "PER_VERTEX is the default");
  CHECK(tree->GetVisibilityMethod() == vtkSilhouetteSmoothingFilter::HIERARCHICAL,
    "SetVisibilityMethodToHierarchical");
  std::ostringstream printed;
  tree->Print(printed);
  CHECK(printed.str().find("VisibilityMethod: Hierarchical") != std::string::npos, "PrintSelf");
  // The other enumerations print by name too, and have their SetXTo...
  // forms (a user's trial read "NormalEstimation: 1").
  CHECK(printed.str().find("NormalEstimation: AreaWeighted") != std::string::npos &&
      printed.str().find("OutputPointsPrecision: Default") != std::string::npos,
    "PrintSelf names the normal estimation and the points' precision");
  vtkNew<vtkSilhouetteSmoothingFilter> quadric;
  quadric->SetNormalEstimationToQuadricFit();
  quadric->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  std::ostringstream printedQuadric;
  quadric->Print(printedQuadric);
  CHECK(quadric->GetNormalEstimation() == vtkSilhouetteSmoothingFilter::QUADRIC_FIT &&
      printedQuadric.str().find("NormalEstimation: QuadricFit") != std::string::npos &&
      printedQuadric.str().find("OutputPointsPrecision: Double") != std::string::npos,
    "SetNormalEstimationToQuadricFit, printed by name");

  int compared = 0;
  for (vtkSilhouetteSmoothingFilter* filter : { plain.GetPointer(), tree.GetPointer() })
  {
    filter->SetInputData(mesh);
    filter->SetViewportSize(800, 600);
  }
  for (const bool parallel : { false, true })
  {
    for (const auto& direction : silhouette_test::SphereDirections(30))
    {
      vtkSmartPointer<vtkCamera> camera =
        silhouette_test::CameraAroundMesh(mesh, direction, 3.0, parallel);
      plain->SetCamera(camera);
      tree->SetCamera(camera);
      plain->Update();
      tree->Update();
      vtkPolyData* a = plain->GetOutput();
      vtkPolyData* b = tree->GetOutput();
      CHECK(a->GetNumberOfPolys() > mesh->GetNumberOfPolys(), "the silhouette was smoothed");
      CHECK(SamePoints(a, b), "the same output points");
      CHECK(SameCells(a->GetPolys(), b->GetPolys()), "the same output triangles");
      CHECK(SamePoints(plain->GetSilhouetteOutput(), tree->GetSilhouetteOutput()),
        "the same silhouette points");
      CHECK(SameCells(
              plain->GetSilhouetteOutput()->GetLines(), tree->GetSilhouetteOutput()->GetLines()),
        "the same silhouette polylines");
      ++compared;
    }
  }
  std::printf("%s: %d views, identical outputs with both visibility methods\n", name, compared);
  return true;
}

} // namespace

int TestVisibilityMethod(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> bunny =
    silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bunny.ply"));
  if (!bunny)
  {
    std::printf("FAIL: cannot read bunny.ply\n");
    return EXIT_FAILURE;
  }
  bool ok = SameOutputs(bunny, "bunny");
  ok = SameOutputs(silhouette_test::Icosphere(5), "icosphere 5") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
