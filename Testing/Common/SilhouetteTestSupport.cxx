#include "SilhouetteTestSupport.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkIcosphereSource.h"
#include "vtkIdList.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSTLReader.h"
#include "vtkTestErrorObserver.h"
#include "vtkTorusSurfaceSource.h"
#include "vtkXMLPolyDataReader.h"
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace silhouette_test
{

std::string TopologyReport::summary() const
{
  std::ostringstream s;
  s << this->Triangles << " triangles, " << this->BoundaryEdges << " boundary edges, "
    << this->NonManifoldEdges << " non-manifold edges, " << this->OrientationConflicts
    << " orientation conflicts, " << this->DegenerateTriangles << " degenerate, "
    << this->FlippedTriangles << " flipped, " << this->OtherCells << " other cells, "
    << this->NonFinitePoints << " non-finite points";
  return s.str();
}

TopologyReport AnalyzeTopology(vtkPolyData* mesh)
{
  TopologyReport report;
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      ++report.NonFinitePoints;
    }
  }
  report.OtherCells = mesh->GetNumberOfStrips();
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n != 3)
    {
      ++report.OtherCells;
      continue;
    }
    ++report.Triangles;
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
      ++directed[{ ids[k], ids[(k + 1) % 3] }];
    }
    double u[3], v[3], face[3];
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, face);
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2] || vtkMath::Norm(face) == 0.0)
    {
      ++report.DegenerateTriangles;
      continue;
    }
    if (normals)
    {
      double sum[3] = { 0, 0, 0 };
      for (int k = 0; k < 3; ++k)
      {
        double n3[3];
        normals->GetTuple(ids[k], n3);
        vtkMath::Add(sum, n3, sum);
      }
      if (vtkMath::Dot(face, sum) < 0.0)
      {
        ++report.FlippedTriangles;
      }
    }
  }
  for (const auto& [edge, uses] : directed)
  {
    if (uses > 1)
    {
      ++report.OrientationConflicts;
    }
    const auto reverse = directed.find({ edge.second, edge.first });
    const int reverseUses = reverse == directed.end() ? 0 : reverse->second;
    // Count each undirected edge once, from its lower-id direction (or from
    // the only direction present).
    if (edge.first < edge.second || reverseUses == 0)
    {
      const int total = uses + reverseUses;
      report.BoundaryEdges += total == 1 ? 1 : 0;
      report.NonManifoldEdges += total > 2 ? 1 : 0;
    }
  }
  return report;
}

vtkSmartPointer<vtkPolyData> Soup(vtkPolyData* mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
  {
    mesh->GetPolys()->GetCellAtId(c, ids);
    vtkIdType own[3];
    for (vtkIdType k = 0; k < 3; ++k)
    {
      own[k] = points->InsertNextPoint(mesh->GetPoint(ids->GetId(k)));
    }
    polys->InsertNextCell(3, own);
  }
  auto soup = vtkSmartPointer<vtkPolyData>::New();
  soup->SetPoints(points);
  soup->SetPolys(polys);
  return soup;
}

vtkSmartPointer<vtkPolyData> Icosphere(int level)
{
  vtkNew<vtkIcosphereSource> source;
  source->SetSubdivisionLevel(level);
  source->Update();
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(source->GetOutput());
  return copy;
}

std::vector<std::array<double, 3>> SphereDirections(int count)
{
  std::vector<std::array<double, 3>> directions;
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double radius = std::sqrt(1.0 - z * z);
    const double angle = golden * i;
    directions.push_back({ radius * std::cos(angle), radius * std::sin(angle), z });
  }
  return directions;
}

vtkSmartPointer<vtkCamera> CameraLookingAtOrigin(
  const std::array<double, 3>& direction, double distance, double viewAngle)
{
  auto camera = vtkSmartPointer<vtkCamera>::New();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(direction[0] * distance, direction[1] * distance, direction[2] * distance);
  // Any up vector not along the view direction.
  if (std::abs(direction[1]) < 0.9)
  {
    camera->SetViewUp(0, 1, 0);
  }
  else
  {
    camera->SetViewUp(1, 0, 0);
  }
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(viewAngle);
  camera->SetClippingRange(0.01 * distance, 10.0 * distance);
  return camera;
}

vtkSmartPointer<vtkCamera> CameraAroundMesh(
  vtkPolyData* mesh, const std::array<double, 3>& direction, double distance, bool parallel)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  const double center[3] = { (bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
    (bounds[4] + bounds[5]) / 2 };
  const double radius = 0.5 *
    std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  auto camera = CameraLookingAtOrigin(direction, distance * radius);
  double position[3];
  camera->GetPosition(position);
  camera->SetFocalPoint(center);
  camera->SetPosition(position[0] + center[0], position[1] + center[1], position[2] + center[2]);
  camera->SetParallelProjection(parallel ? 1 : 0);
  camera->SetParallelScale(1.2 * radius);
  return camera;
}

bool IsUniformTessellationOf(vtkPolyData* input, vtkPolyData* out, int level)
{
  CHECK(out->GetNumberOfPolys() == input->GetNumberOfPolys() * (level + 1) * (level + 1),
    "triangle count = input x (k+1)^2");
  const TopologyReport report = AnalyzeTopology(out);
  CHECK(report.closedManifold(), report.summary().c_str());
  CHECK(report.FlippedTriangles == 0 && report.DegenerateTriangles == 0, report.summary().c_str());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double a[3];
    double b[3];
    input->GetPoint(i, a);
    out->GetPoint(i, b);
    CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2], "input points kept");
  }
  return true;
}

bool IsUniformTessellationOfFlatGrid(vtkPolyData* flat, vtkPolyData* out, int level)
{
  CHECK(
    out->GetNumberOfPolys() == flat->GetNumberOfPolys() * (level + 1) * (level + 1), "flat count");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    CHECK(std::abs(p[2]) < 1e-7, "flat stays flat");
    double n[3];
    out->GetPointData()->GetNormals()->GetTuple(i, n);
    CHECK(std::abs(n[2] - 1.0) < 1e-6, "flat normals stay the plane's");
  }
  const TopologyReport report = AnalyzeTopology(out);
  CHECK(report.NonManifoldEdges == 0 && report.OrientationConflicts == 0 &&
      report.BoundaryEdges == 2 * (4 + 3) * (level + 1),
    report.summary().c_str());
  return true;
}

std::string AssetModelsFolder()
{
  const std::string folder = "/usr/share/assimp/models";
  return vtksys::SystemTools::FileExists(folder + "/OBJ/spider.obj", true) ? folder : std::string();
}

std::string DataFile(int argc, char* argv[], const std::string& name)
{
  for (int i = 0; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-D")
    {
      return std::string(argv[i + 1]) + "/" + name;
    }
  }
  return name;
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (extension == ".ply")
  {
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(path.c_str());
    reader = ply;
  }
  else if (extension == ".vtp")
  {
    auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    vtp->SetFileName(path.c_str());
    reader = vtp;
  }
  else if (extension == ".obj")
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(path.c_str());
    reader = obj;
  }
  else if (extension == ".stl")
  {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(path.c_str());
    reader = stl;
  }
  else
  {
    return nullptr;
  }
  reader->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutputDataObject(0));
  return mesh->GetNumberOfPoints() > 0 ? mesh : nullptr;
}

SphereTorusBunny MakeSphereTorusBunny(int argc, char* argv[])
{
  SphereTorusBunny meshes;
  vtkNew<vtkIcosphereSource> sphere;
  sphere->Update();
  meshes.Sphere = sphere->GetOutput();
  vtkNew<vtkTorusSurfaceSource> torus;
  torus->Update();
  meshes.Torus = torus->GetOutput();
  meshes.Bunny = ReadMesh(DataFile(argc, argv, "bunny_coarse.ply"));
  if (!meshes.Bunny)
  {
    std::printf("FAIL: cannot read bunny_coarse.ply\n");
  }
  return meshes;
}

vtkSmartPointer<vtkPolyData> FlatGrid()
{
  const int columns = 4;
  const int rows = 3;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int j = 0; j <= rows; ++j)
  {
    for (int i = 0; i <= columns; ++i)
    {
      points->InsertNextPoint(-1.0 + 2.0 * i / columns, -1.0 + 2.5 * j / rows, 0.0);
      normals->InsertNextTuple3(0.0, 0.0, 1.0);
    }
  }
  vtkNew<vtkCellArray> polys;
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i < columns; ++i)
    {
      const vtkIdType a = j * (columns + 1) + i;
      const vtkIdType b = a + 1;
      const vtkIdType c = a + columns + 1;
      const vtkIdType lower[3] = { a, b, c + 1 };
      const vtkIdType upper[3] = { a, c + 1, c };
      polys->InsertNextCell(3, lower);
      polys->InsertNextCell(3, upper);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetNormals(normals);
  return mesh;
}

vtkSmartPointer<vtkPolyData> MeshNamingAMissingPoint()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = { 0, 1, 7 };
  polys->InsertNextCell(3, ids);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

int UpdateReportingError(vtkAlgorithm* filter, std::string& message)
{
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkTest::ErrorObserver> executiveErrors;
  const unsigned long onFilter = filter->AddObserver(vtkCommand::ErrorEvent, errors);
  const unsigned long onExecutive =
    filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  const int result = filter->GetExecutive()->Update();
  message = errors->GetError() ? errors->GetErrorMessage() : "";
  filter->RemoveObserver(onFilter);
  filter->GetExecutive()->RemoveObserver(onExecutive);
  return result;
}

void StyleImageActor(vtkPolyDataMapper* mapper, vtkActor* actor, int newGeometryKinds)
{
  if (newGeometryKinds <= 0)
  {
    mapper->ScalarVisibilityOff();
    actor->GetProperty()->SetColor(0.75, 0.78, 0.85);
    actor->GetProperty()->SetSpecular(0.3);
    actor->GetProperty()->SetSpecularPower(30);
    return;
  }
  const double rgb[3][3] = { { 0.25, 0.25, 0.25 }, { 0.9, 0.0, 0.0 }, { 0.0, 0.3, 0.9 } };
  const int values = std::min(newGeometryKinds, 2) + 1;
  vtkNew<vtkLookupTable> colors;
  colors->SetNumberOfTableValues(values);
  for (int k = 0; k < values; ++k)
  {
    colors->SetTableValue(k, rgb[k][0], rgb[k][1], rgb[k][2]);
  }
  colors->SetTableRange(0, values - 1);
  colors->Build();
  mapper->SetScalarModeToUseCellFieldData();
  mapper->SetColorModeToMapScalars(); // unsigned char would be read as colours
  mapper->SelectColorArray("NewGeometry");
  mapper->SetLookupTable(colors);
  mapper->SetScalarRange(0, values - 1);
  mapper->ScalarVisibilityOn();
  actor->GetProperty()->SetRepresentationToWireframe();
  actor->GetProperty()->LightingOff();
}

} // namespace silhouette_test
