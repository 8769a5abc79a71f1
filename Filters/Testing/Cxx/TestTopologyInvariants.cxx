// Topology invariants (the crack-free rule, issue 2): over 120 camera positions each on
// the sphere, a torus and the coarse bunny, perspective and parallel, at near
// and far distances: closed manifold in, closed manifold out, consistent
// orientation, no degenerate triangle, finite points, closed silhouette loops;
// flipped triangles counted, and zero on the sphere and torus. Then an open
// mesh keeps its boundary, and a view without silhouette returns the input.
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIcosphereSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include "SilhouetteTestSupport.h"

#include <cstdio>
#include <map>
#include <set>
#include <utility>

namespace
{

bool CheckMeshOverViews(const char* name, vtkPolyData* mesh, bool expectNoFlips)
{
  const auto input = silhouette_test::AnalyzeTopology(mesh);
  if (!input.closedManifold())
  {
    std::printf("FAIL: %s input is not a closed manifold: %s\n", name, input.summary().c_str());
    return false;
  }
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(mesh);
  smoother->SetViewportSize(1024, 768);
  const auto directions = silhouette_test::SphereDirections(120);
  const double distances[3] = { 2.0, 4.0, 12.0 };
  long flipped = 0;
  long newTriangles = 0;
  long silhouetteTriangles = 0;
  bool ok = true;
  for (std::size_t v = 0; v < directions.size(); ++v)
  {
    const bool parallel = v % 4 == 3;
    smoother->SetCamera(
      silhouette_test::CameraAroundMesh(mesh, directions[v], distances[v % 3], parallel));
    smoother->Update();
    vtkPolyData* out = smoother->GetOutput();
    const auto report = silhouette_test::AnalyzeTopology(out);
    if (!report.closedManifold() || report.DegenerateTriangles > 0 || report.NonFinitePoints > 0)
    {
      std::printf("FAIL: %s view %zu: %s\n", name, v, report.summary().c_str());
      ok = false;
    }
    vtkPolyData* lines = smoother->GetSilhouetteOutput();
    auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      if (n < 3 || ids[0] != ids[n - 1])
      {
        std::printf("FAIL: %s view %zu: a silhouette polyline of %lld points is not closed\n", name,
          v, static_cast<long long>(n));
        ok = false;
        break;
      }
    }
    if (lines->GetNumberOfLines() == 0)
    {
      std::printf("FAIL: %s view %zu: no silhouette\n", name, v);
      ok = false;
    }
    flipped += report.FlippedTriangles;
    newTriangles += static_cast<long>(report.Triangles - input.Triangles);
    silhouetteTriangles += static_cast<long>(
      smoother->GetOutput()->GetFieldData()->GetArray("SilhouetteTriangleCount")->GetTuple1(0));
  }
  std::printf(
    "%-8s %6ld input triangles; over %zu views: %ld silhouette triangles, %ld triangles added, "
    "%ld flipped\n",
    name, input.Triangles, directions.size(), silhouetteTriangles, newTriangles, flipped);
  if (expectNoFlips && flipped != 0)
  {
    std::printf("FAIL: %s has flipped triangles\n", name);
    ok = false;
  }
  return ok;
}

// Every input boundary edge must survive as a boundary edge, or as two
// boundary edges through the silhouette point that split it.
bool CheckOpenMesh()
{
  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(2);
  sphere->Update();
  vtkNew<vtkPolyData> open;
  open->SetPoints(sphere->GetOutput()->GetPoints());
  open->GetPointData()->ShallowCopy(sphere->GetOutput()->GetPointData());
  vtkNew<vtkCellArray> polys;
  auto it = vtk::TakeSmartPointer(sphere->GetOutput()->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    double z = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      z += sphere->GetOutput()->GetPoint(ids[k])[2] / 3.0;
    }
    if (z < 0.5) // cut a cap off: one boundary loop
    {
      polys->InsertNextCell(n, ids);
    }
  }
  open->SetPolys(polys);

  auto boundaryEdges = [](vtkPolyData* mesh) {
    std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
    auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
    for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      cells->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k < n; ++k)
      {
        ++directed[{ ids[k], ids[(k + 1) % n] }];
      }
    }
    std::set<std::pair<vtkIdType, vtkIdType>> boundary;
    for (const auto& entry : directed)
    {
      if (!directed.count({ entry.first.second, entry.first.first }))
      {
        boundary.insert(entry.first);
      }
    }
    return boundary;
  };
  const auto before = boundaryEdges(open);
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(open);
  long splitEdges = 0;
  for (const auto& direction : silhouette_test::SphereDirections(40))
  {
    smoother->SetCamera(silhouette_test::CameraLookingAtOrigin(direction, 4.0));
    smoother->Update();
    const auto report = silhouette_test::AnalyzeTopology(smoother->GetOutput());
    if (report.NonManifoldEdges || report.OrientationConflicts || report.DegenerateTriangles)
    {
      std::printf("FAIL: open mesh: %s\n", report.summary().c_str());
      return false;
    }
    auto after = boundaryEdges(smoother->GetOutput());
    std::size_t expected = before.size();
    for (const auto& edge : before)
    {
      if (after.count(edge))
      {
        continue;
      }
      // Look for edge.first -> P -> edge.second along the new boundary.
      bool split = false;
      for (const auto& candidate : after)
      {
        if (candidate.first == edge.first && after.count({ candidate.second, edge.second }))
        {
          split = true;
          break;
        }
      }
      if (!split)
      {
        std::printf("FAIL: open mesh: boundary edge %lld-%lld is gone\n",
          static_cast<long long>(edge.first), static_cast<long long>(edge.second));
        return false;
      }
      ++expected;
      ++splitEdges;
    }
    if (after.size() != expected)
    {
      std::printf("FAIL: open mesh: %zu boundary edges, expected %zu\n", after.size(), expected);
      return false;
    }
  }
  std::printf(
    "open mesh: %zu boundary edges kept over 40 views (%ld splits at silhouette points)\n",
    before.size(), splitEdges);
  return splitEdges > 0; // the views must actually exercise the split case
}

bool CheckNoSilhouetteIsIdentity()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(6, 5);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  vtkPolyData* input = triangles->GetOutput();
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(input);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.1, 0.2, 3.0);
  camera->SetFocalPoint(0, 0, 0);
  smoother->SetCamera(camera);
  smoother->Update();
  vtkPolyData* out = smoother->GetOutput();
  if (out->GetNumberOfPoints() != input->GetNumberOfPoints() ||
    out->GetNumberOfPolys() != input->GetNumberOfPolys())
  {
    std::printf("FAIL: a view without silhouette changed the mesh\n");
    return false;
  }
  for (vtkIdType c = 0; c < input->GetNumberOfPolys(); ++c)
  {
    vtkIdType n1 = 0, n2 = 0;
    const vtkIdType *a = nullptr, *b = nullptr;
    input->GetCellPoints(c, n1, a);
    out->GetCellPoints(c, n2, b);
    if (n1 != n2 || !std::equal(a, a + n1, b) ||
      out->GetCellData()->GetArray("NewGeometry")->GetTuple1(c) != 0)
    {
      std::printf("FAIL: cell %lld changed without a silhouette\n", static_cast<long long>(c));
      return false;
    }
  }
  std::printf("no-silhouette view: input returned unchanged (%lld triangles)\n",
    static_cast<long long>(out->GetNumberOfPolys()));
  return true;
}

} // namespace

int TestTopologyInvariants(int argc, char* argv[])
{
  const silhouette_test::SphereTorusBunny meshes =
    silhouette_test::MakeSphereTorusBunny(argc, argv);
  if (!meshes.Bunny)
  {
    return EXIT_FAILURE;
  }
  bool ok = true;
  ok = CheckMeshOverViews("sphere", meshes.Sphere, true) && ok;
  ok = CheckMeshOverViews("torus", meshes.Torus, true) && ok;
  ok = CheckMeshOverViews("bunny", meshes.Bunny, false) && ok;
  ok = CheckOpenMesh() && ok;
  ok = CheckNoSilhouetteIsIdentity() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
