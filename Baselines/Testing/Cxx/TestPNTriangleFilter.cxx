// vtkPNTriangleFilter (Vlachos et al. 2001): triangle count = input x (k+1)^2,
// input points kept (ids and positions), watertight output for a closed input
// (shared edge points), flat triangles with face normals stay flat, and on a
// sphere with exact normals the patches are nearer the sphere than flat
// subdivision.
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPNTriangleFilter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "SilhouetteTestSupport.h"

#include <cmath>
#include <cstdio>

namespace
{

bool Run()
{
  auto sphere = silhouette_test::Icosphere(1);
  vtkNew<vtkPNTriangleFilter> pn;
  pn->SetInputData(sphere);
  for (int level = 0; level <= 4; ++level)
  {
    pn->SetLevel(level);
    pn->Update();
    vtkPolyData* out = pn->GetOutput();
    CHECK(
      silhouette_test::IsUniformTessellationOf(sphere, out, level), "the tessellation's layout");
    CHECK(out->GetCellData()->GetArray("NewGeometry") &&
        out->GetCellData()->GetArray("OriginalCellId") && out->GetPointData()->GetNormals(),
      "provenance arrays and normals");
    // Distance to the unit sphere, against the flat triangles' midpoints.
    double worst = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double p[3];
      out->GetPoint(i, p);
      worst = std::max(worst, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0));
    }
    std::printf("PN level %d: %lld triangles, largest |r - 1| = %.4f\n", level,
      static_cast<long long>(out->GetNumberOfPolys()), worst);
    if (level >= 2)
    {
      // Flat 80-triangle faces are up to 1 - 0.795 = 0.205 inside at their centres.
      CHECK(worst < 0.05, "PN patches hug the sphere");
    }
  }

  // A flat mesh with the plane's normal everywhere stays in the plane.
  vtkSmartPointer<vtkPolyData> flat = silhouette_test::FlatGrid();
  vtkNew<vtkPNTriangleFilter> pnFlat;
  pnFlat->SetInputData(flat);
  pnFlat->SetLevel(3);
  pnFlat->Update();
  CHECK(silhouette_test::IsUniformTessellationOfFlatGrid(flat, pnFlat->GetOutput(), 3),
    "the flat grid's tessellation");
  return true;
}

} // namespace

int TestPNTriangleFilter(int, char*[])
{
  return Run() ? 0 : 1;
}
