#include "Generate.h"

#include "CliErrors.h"
#include "MeshIO.h"
#include "VtkErrorLog.h"

#include <vtkIcosphereSource.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTorusSurfaceSource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>

namespace cli
{
namespace
{

// A number read from a file, or 0 when there is none ("max", say).
double NumberIn(const char* path)
{
  std::ifstream file(path);
  double value = 0.0;
  return file >> value ? value : 0.0;
}

// The memory the program can have now, in bytes: the system's MemAvailable,
// less where a control group (a container's, cgroup v2 or v1) limits it to
// less; 0 when nothing says.
double AvailableMemory()
{
  double available = 0.0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0.0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
  {
    if (key == "MemAvailable:")
    {
      available = kilobytes * 1024.0;
      break;
    }
  }
  const std::pair<const char*, const char*> groups[] = {
    { "/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current" },
    { "/sys/fs/cgroup/memory/memory.limit_in_bytes", "/sys/fs/cgroup/memory/memory.usage_in_bytes" }
  };
  for (const auto& [limitFile, usageFile] : groups)
  {
    const double limit = NumberIn(limitFile);
    // v1 says "no limit" with a number near 2^63.
    if (limit > 0.0 && limit < 1e18)
    {
      const double left = std::max(0.0, limit - NumberIn(usageFile));
      available = available > 0.0 ? std::min(available, left) : left;
    }
  }
  return available;
}

// Refuses a mesh that would not fit in memory, before making it: past what
// the system has, the kernel kills the program instead of letting an
// allocation fail (a 20,000 x 20,000 torus grew to 23 GB and was killed).
// About 250 bytes per point (measured: 1.0 GB at its peak for 4M points): its coordinates and
// normal, two triangles' cells, and the copies the writer makes.
void RequireMemoryFor(double points, const std::string& what)
{
  const double needed = 250.0 * points;
  const double available = AvailableMemory();
  if (available > 0.0 && needed > available)
  {
    std::ostringstream message;
    message.setf(std::ios::fixed);
    message.precision(1);
    message << what << " needs about " << needed / 1e9 << " GB of memory; this machine has "
            << available / 1e9 << " GB available";
    throw RuntimeError(message.str());
  }
}

} // namespace

void RunGenerate(const GenerateOptions& options)
{
  CheckMeshOutputPath(options.Output);
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkNew<vtkPolyData> mesh;
  if (options.Shape == GeneratedShape::Sphere)
  {
    RequireMemoryFor(10.0 * std::pow(4.0, options.Level) + 2.0,
      "a sphere of level " + std::to_string(options.Level));
    vtkNew<vtkIcosphereSource> sphere;
    sphere->SetSubdivisionLevel(options.Level);
    sphere->SetRadius(options.Radius);
    sphere->Update();
    mesh->ShallowCopy(sphere->GetOutput());
  }
  else
  {
    RequireMemoryFor(static_cast<double>(options.RingResolution) * options.TubeResolution,
      "a torus of " + std::to_string(options.RingResolution) + " x " +
        std::to_string(options.TubeResolution));
    if (options.TubeRadius >= options.Radius)
    {
      std::cerr << "silhouette: warning: the tube radius (" << options.TubeRadius
                << ") is not less than the ring radius (" << options.Radius
                << "): the torus passes through itself\n";
    }
    vtkNew<vtkTorusSurfaceSource> torus;
    torus->SetRingResolution(options.RingResolution);
    torus->SetTubeResolution(options.TubeResolution);
    torus->SetRingRadius(options.Radius);
    torus->SetTubeRadius(options.TubeRadius);
    torus->Update();
    mesh->ShallowCopy(torus->GetOutput());
  }
  errors.ThrowIfErrors("generating the mesh failed");
  WriteMesh(mesh, options.Output);
  std::cout << "wrote " << options.Output << ": " << mesh->GetNumberOfPoints() << " points, "
            << mesh->GetNumberOfPolys() << " triangles, exact point normals\n";
}

} // namespace cli
