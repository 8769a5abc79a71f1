// vtkProgressiveMeshFilter (Kim and Choe 3.1): on the bunnies, every level is
// a manifold mesh with consistent orientation, the triangle count asked for
// is met by the lowest level that has it, and the full level gives back the
// input exactly (points bit for bit, triangles in order).
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProgressiveMeshFilter.h"

#include "SilhouetteTestSupport.h"

#include <cstdio>

namespace
{

vtkIdType Field(vtkPolyData* output, const char* name)
{
  auto* array = vtkIdTypeArray::SafeDownCast(output->GetFieldData()->GetArray(name));
  return array ? array->GetValue(0) : -1;
}

bool SameAsInput(vtkPolyData* input, vtkPolyData* output)
{
  auto* pointIds =
    vtkIdTypeArray::SafeDownCast(output->GetPointData()->GetArray("OriginalPointId"));
  CHECK(pointIds, "OriginalPointId");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double a[3];
    double b[3];
    output->GetPoint(i, a);
    input->GetPoint(pointIds->GetValue(i), b);
    CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2], "points bit for bit");
  }
  CHECK(output->GetNumberOfPolys() == input->GetNumberOfPolys(), "all triangles");
  vtkIdType n = 0;
  const vtkIdType* in = nullptr;
  vtkIdType m = 0;
  const vtkIdType* out = nullptr;
  for (vtkIdType c = 0; c < input->GetNumberOfPolys(); ++c)
  {
    input->GetPolys()->GetCellAtId(c, n, in);
    output->GetPolys()->GetCellAtId(c, m, out);
    CHECK(n == 3 && m == 3, "triangles");
    for (int k = 0; k < 3; ++k)
    {
      CHECK(pointIds->GetValue(out[k]) == in[k], "same triangle, same corner order");
    }
  }
  return true;
}

bool RunOn(const std::string& path)
{
  auto input = silhouette_test::ReadMesh(path);
  CHECK(input && input->GetNumberOfPolys() > 0, "mesh read");
  const vtkIdType full = input->GetNumberOfPolys();
  const auto inputReport = silhouette_test::AnalyzeTopology(input);
  vtkNew<vtkProgressiveMeshFilter> pm;
  pm->SetInputData(input);
  pm->Update();
  CHECK(SameAsInput(input, pm->GetOutput()), "full level is the input");
  const vtkIdType base = Field(pm->GetOutput(), "BaseTriangleCount");
  std::printf("%s: %lld triangles, base mesh %lld triangles, %lld vertex splits\n", path.c_str(),
    static_cast<long long>(full), static_cast<long long>(base),
    static_cast<long long>(Field(pm->GetOutput(), "SplitCount")));
  CHECK(base > 0 && base < full / 10, "coarsens far");
  // Down, up and back: each level manifold, oriented, no degenerate triangles.
  for (vtkIdType count : { full / 2, base, full / 10, full / 4, full - 7, full / 3 })
  {
    pm->SetTriangleCount(count);
    pm->Update();
    vtkPolyData* out = pm->GetOutput();
    const vtkIdType got = out->GetNumberOfPolys();
    CHECK(got >= count && got <= count + 1, "lowest level with at least the count");
    const auto report = silhouette_test::AnalyzeTopology(out);
    CHECK(report.NonManifoldEdges == 0 && report.OrientationConflicts == 0 &&
        report.DegenerateTriangles == 0,
      report.summary().c_str());
    if (inputReport.closedManifold())
    {
      CHECK(report.closedManifold(), report.summary().c_str());
    }
    CHECK(out->GetCellData()->GetArray("OriginalCellId"), "OriginalCellId");
  }
  pm->SetTriangleCount(-1);
  pm->SetFraction(1.0);
  pm->Update();
  CHECK(SameAsInput(input, pm->GetOutput()), "refined back to the input exactly");
  return true;
}

} // namespace

int TestProgressiveMeshFilter(int argc, char* argv[])
{
  const bool ok = RunOn(silhouette_test::DataFile(argc, argv, "bunny_coarse.ply")) &&
    RunOn(silhouette_test::DataFile(argc, argv, "bunny.ply")) &&
    RunOn(silhouette_test::DataFile(argc, argv, "sphere_ico80.vtp"));
  return ok ? 0 : 1;
}
