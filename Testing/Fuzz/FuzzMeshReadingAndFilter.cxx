// libFuzzer target for mesh reading plus the VTK filter (issue 6, item 4).
//
// Input layout: byte 0 picks the format (.ply .obj .stl .vtp .vtk), the next
// ParameterBytes bytes pick the camera and the filter's settings, and the rest
// is the file. The file goes through cli::ReadMesh, the code path of the
// `silhouette` program (its PLY, OBJ, STL and legacy VTK pre-checks included);
// whatever reads is smoothed by vtkSilhouetteSmoothingFilter for a camera
// made from the parameter bytes: around the mesh or anywhere (eye inside or
// outside, on the focal point, any view-up), parallel or perspective, any
// viewport, then again for a second camera. The run must not crash or hang;
// when a request succeeds its outputs must hold only finite points and
// normals and in-range ids, and no valid input triangle may be lost.
//
// Seeds: scripts/fuzz.sh prefixes small meshes with a format byte and
// ParameterBytes bytes of 0x80 (a camera around the mesh).
#include "CliErrors.h"
#include "MeshIO.h"
#include "VtkErrorLog.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{

constexpr std::size_t ParameterBytes = 48; // two cameras and the settings, with room
const char* const Extensions[] = { ".ply", ".obj", ".stl", ".vtp", ".vtk" };
constexpr std::size_t FormatCount = sizeof(Extensions) / sizeof(Extensions[0]);

// Reads parameter bytes as small values; zeros when exhausted.
class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  std::uint8_t byte() { return this->At < this->Size ? this->Data[this->At++] : 0; }
  double unit() // in [-1, 1]
  {
    const int value = (this->byte() << 8) | this->byte();
    return value / 32767.5 - 1.0;
  }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t At = 0;
};

void require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "FuzzMeshReadingAndFilter: broken invariant: %s\n", what);
    std::abort();
  }
}

bool Finite(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void RequireValid(vtkPolyData* mesh)
{
  const vtkIdType points = mesh->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    require(Finite(p), "finite output points");
  }
  if (vtkDataArray* normals = mesh->GetPointData()->GetNormals())
  {
    require(normals->GetNumberOfTuples() == points, "one normal per point");
    for (vtkIdType i = 0; i < points; ++i)
    {
      double n[3];
      normals->GetTuple(i, n);
      require(Finite(n), "finite output normals");
    }
  }
  for (vtkCellArray* cells :
    { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    auto cell = vtk::TakeSmartPointer(cells->NewIterator());
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      cell->GetCurrentCell(size, ids);
      for (vtkIdType k = 0; k < size; ++k)
      {
        require(ids[k] >= 0 && ids[k] < points, "output ids in range");
      }
    }
  }
}

// Triangles with three distinct ids, counting polygons fanned and strips split.
vtkIdType ValidTriangles(vtkPolyData* mesh)
{
  vtkIdType count = 0;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(size, ids);
    if (size == 3 && ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2])
    {
      ++count;
    }
  }
  return count;
}

// A camera from the parameter bytes: around the mesh's bounding sphere, or
// at any place and scale (which may be degenerate on purpose).
void MakeCamera(Bytes& bytes, vtkPolyData* mesh, vtkCamera* camera)
{
  const std::uint8_t mode = bytes.byte();
  double bounds[6];
  mesh->GetBounds(bounds);
  double center[3], radius = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    center[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    radius = std::max(radius, 0.5 * (bounds[2 * a + 1] - bounds[2 * a]));
  }
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    radius = 1.0;
  }
  if (!Finite(center))
  {
    center[0] = center[1] = center[2] = 0.0;
  }
  double position[3], focal[3];
  if ((mode & 2) == 0)
  {
    // Around the mesh: a direction, a distance from 0.1 to 100 radii (the eye
    // may be inside), and a focal point near the centre.
    const double azimuth = 3.14159265358979 * bytes.unit();
    const double elevation = 1.5707963267949 * bytes.unit();
    const double distance = radius * std::pow(10.0, 3.0 * (bytes.byte() / 255.0) - 1.0);
    const double direction[3] = { std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
      std::cos(elevation) * std::sin(azimuth) };
    for (int a = 0; a < 3; ++a)
    {
      focal[a] = center[a] + 0.2 * radius * bytes.unit();
      position[a] = focal[a] + distance * direction[a];
    }
  }
  else
  {
    // Anywhere, at scales from 1e-30 to 1e30; the eye may sit on the focal point.
    const double scale = std::pow(10.0, static_cast<int>(bytes.byte() % 61) - 30);
    for (int a = 0; a < 3; ++a)
    {
      position[a] = scale * bytes.unit();
    }
    for (int a = 0; a < 3; ++a)
    {
      focal[a] = (mode & 4) ? position[a] : scale * bytes.unit();
    }
  }
  camera->SetPosition(position);
  camera->SetFocalPoint(focal);
  // Any view-up, possibly zero or along the view direction.
  const double up[3] = { bytes.unit(), bytes.unit(), bytes.unit() };
  camera->SetViewUp(up[0], up[1], up[2]);
  camera->SetViewAngle(1.0 + bytes.byte() % 179);
  camera->SetParallelProjection(mode & 1);
  camera->SetParallelScale(radius * std::pow(10.0, 2.0 * (bytes.byte() / 255.0) - 1.0));
}

// The file: one per process, in the temporary directory.
std::string InputPath(std::size_t format)
{
  static const std::string stem = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp && *tmp ? tmp : "/tmp") + "/silhouette-fuzz-" +
      std::to_string(static_cast<long>(getpid()));
  }();
  return stem + Extensions[format];
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // VTK's messages go to the program's log instead of the terminal.
  cli::VtkErrorLog::Instance().InstallMessageCapture();
  vtkSMPTools::Initialize(1); // one thread: the fuzzer runs many inputs, not big ones
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1 + ParameterBytes)
  {
    return 0;
  }
  const std::size_t format = data[0] % FormatCount;
  Bytes parameters(data + 1, ParameterBytes);
  const std::string path = InputPath(format);
  {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(data + 1 + ParameterBytes),
      static_cast<std::streamsize>(size - 1 - ParameterBytes));
    require(static_cast<bool>(file), "the input file is written");
  }

  vtkSmartPointer<vtkPolyData> mesh;
  try
  {
    mesh = cli::ReadMesh(path);
  }
  catch (const cli::RuntimeError&)
  {
    std::remove(path.c_str());
    return 0; // a clear error: what the program does with a bad file
  }
  std::remove(path.c_str());
  require(mesh != nullptr, "ReadMesh gives a mesh or throws");

  vtkNew<vtkCamera> camera;
  MakeCamera(parameters, mesh, camera);
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  cli::VtkErrorLog& errors = cli::VtkErrorLog::Instance();
  errors.Clear();
  errors.Watch(filter);
  filter->SetInputData(mesh);
  filter->SetCamera(camera);
  filter->SetViewportSize(parameters.byte() * 8, parameters.byte() * 8);
  filter->SetTolerance(0.05 + parameters.byte() / 50.0);
  filter->SetPerturbVertices(parameters.byte() % 2 == 0);
  filter->SetSamplingRule(parameters.byte() % 2);
  filter->Update();
  if (errors.HasErrors())
  {
    return 0; // the request failed with an error, as documented for bad input
  }
  RequireValid(filter->GetOutput());
  RequireValid(filter->GetSilhouetteOutput());
  require(
    ValidTriangles(filter->GetOutput()) >= ValidTriangles(mesh), "no valid input triangle is lost");

  // Move the camera and run again: the prepared cache must serve any view.
  MakeCamera(parameters, mesh, camera);
  errors.Clear();
  filter->Update();
  if (!errors.HasErrors())
  {
    RequireValid(filter->GetOutput());
    RequireValid(filter->GetSilhouetteOutput());
  }
  return 0;
}
