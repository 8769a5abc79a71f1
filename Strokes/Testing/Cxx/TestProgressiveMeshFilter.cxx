// vtkProgressiveMeshFilter (Kim and Choe 3.1): on the bunnies, every level is
// a manifold mesh with consistent orientation, the triangle count asked for
// is met by the lowest level that has it, and the full level gives back the
// input exactly (points bit for bit, triangles in order). A triangle soup of
// the icosphere (each triangle with points of its own, as VTK reads a
// textured OBJ) coarsens as the welded sphere does, each level a closed
// manifold once its copies are merged, and comes back as the soup exactly,
// each point with its own data; with WeldCoincidentPoints off it cannot
// coarsen into a surface (the wrong variant). assimp's concave_polygon.obj
// (one face of 66 corners, a ring walked through a slit) behind a vertex
// cell is read as the module's filters read it: 64 triangles at the full
// level, each with the polygon's cell id and data.
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProgressiveMeshFilter.h"

#include "SilhouetteTestSupport.h"

#include <cstdio>
#include <string>

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

// Every triangle with three points of its own, each with a value of its own
// in the point array "Corner".
vtkSmartPointer<vtkPolyData> Soup(vtkPolyData* mesh)
{
  vtkSmartPointer<vtkPolyData> soup = silhouette_test::Soup(mesh);
  vtkNew<vtkFloatArray> corner;
  corner->SetName("Corner");
  corner->SetNumberOfValues(soup->GetNumberOfPoints());
  for (vtkIdType p = 0; p < soup->GetNumberOfPoints(); ++p)
  {
    corner->SetValue(p, static_cast<float>(p));
  }
  soup->GetPointData()->AddArray(corner);
  return soup;
}

bool RunOnSoup(const std::string& path)
{
  auto welded = silhouette_test::ReadMesh(path);
  CHECK(welded && welded->GetNumberOfPolys() > 0, "mesh read");
  vtkSmartPointer<vtkPolyData> soup = Soup(welded);
  const vtkIdType full = soup->GetNumberOfPolys();
  vtkNew<vtkProgressiveMeshFilter> pm;
  pm->SetInputData(soup);
  pm->SetTriangleCount(0);
  pm->Update();
  const vtkIdType base = Field(pm->GetOutput(), "BaseTriangleCount");
  std::printf("%s as a soup: %lld triangles, base mesh %lld triangles\n", path.c_str(),
    static_cast<long long>(full), static_cast<long long>(base));
  CHECK(base > 0 && base < full / 10, "the soup coarsens far");
  for (vtkIdType count : { base, full / 4, full / 2 })
  {
    pm->SetTriangleCount(count);
    pm->Update();
    vtkNew<vtkCleanPolyData> merged; // the copies at one position as one point
    merged->SetInputData(pm->GetOutput());
    merged->PointMergingOn();
    merged->SetTolerance(0.0);
    merged->Update();
    const auto report = silhouette_test::AnalyzeTopology(merged->GetOutput());
    CHECK(report.closedManifold() && report.OrientationConflicts == 0 &&
        report.DegenerateTriangles == 0,
      report.summary().c_str());
  }
  pm->SetTriangleCount(full);
  pm->Update();
  vtkPolyData* out = pm->GetOutput();
  CHECK(SameAsInput(soup, out), "the full level is the soup exactly");
  auto* pointIds = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("OriginalPointId"));
  vtkDataArray* corner = out->GetPointData()->GetArray("Corner");
  CHECK(corner && out->GetNumberOfPoints() == soup->GetNumberOfPoints(), "every copy kept");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    CHECK(corner->GetTuple1(i) == static_cast<double>(pointIds->GetValue(i)),
      "each copy with its own point data");
  }
  // Unwelded, every triangle is a part of its own with borders all round:
  // half of the soup's triangles are no closed surface.
  pm->WeldCoincidentPointsOff();
  pm->SetTriangleCount(full / 2);
  pm->Update();
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputData(pm->GetOutput());
  merged->PointMergingOn();
  merged->SetTolerance(0.0);
  merged->Update();
  const auto unwelded = silhouette_test::AnalyzeTopology(merged->GetOutput());
  std::printf("unwelded, half the soup: %s\n", unwelded.summary().c_str());
  CHECK(!unwelded.closedManifold(), "unwelded, the soup falls apart (the wrong variant)");
  return true;
}

bool RunOnPolygon()
{
  const std::string assets = silhouette_test::AssetModelsFolder();
  CHECK(!assets.empty(), "Debian's assimp-testmodels is installed (scripts/setup.sh installs it)");
  vtkSmartPointer<vtkPolyData> ring =
    silhouette_test::ReadMesh(assets + "/OBJ/concave_polygon.obj");
  CHECK(ring && ring->GetNumberOfPolys() == 1 && ring->GetNumberOfVerts() == 0, "one polygon");
  vtkNew<vtkCellArray> verts;
  const vtkIdType first = 0;
  verts->InsertNextCell(1, &first);
  ring->SetVerts(verts);
  ring->GetCellData()->Initialize(); // the reader's arrays have one tuple, for the polygon
  vtkNew<vtkIdTypeArray> label;      // the vertex cell's, then the polygon's
  label->SetName("Label");
  label->InsertNextValue(7);
  label->InsertNextValue(42);
  ring->GetCellData()->AddArray(label);
  vtkNew<vtkProgressiveMeshFilter> pm;
  pm->SetInputData(ring);
  pm->Update();
  vtkPolyData* out = pm->GetOutput();
  std::printf("concave_polygon.obj: %lld triangles at the full level, base mesh %lld\n",
    static_cast<long long>(out->GetNumberOfPolys()),
    static_cast<long long>(Field(out, "BaseTriangleCount")));
  CHECK(out->GetNumberOfPolys() == 64 && Field(out, "FullTriangleCount") == 64,
    "the ring's 64 triangles");
  auto* cells = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("OriginalCellId"));
  auto* labels = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("Label"));
  CHECK(cells && labels, "OriginalCellId and the cell data");
  for (vtkIdType t = 0; t < out->GetNumberOfPolys(); ++t)
  {
    CHECK(cells->GetValue(t) == 1 && labels->GetValue(t) == 42, "each triangle the polygon's");
  }
  return true;
}

} // namespace

int TestProgressiveMeshFilter(int argc, char* argv[])
{
  const bool ok = RunOn(silhouette_test::DataFile(argc, argv, "bunny_coarse.ply")) &&
    RunOn(silhouette_test::DataFile(argc, argv, "bunny.ply")) &&
    RunOn(silhouette_test::DataFile(argc, argv, "sphere_ico80.vtp")) &&
    RunOnSoup(silhouette_test::DataFile(argc, argv, "bunny_coarse.ply")) && RunOnPolygon();
  return ok ? 0 : 1;
}
