#include "Generate.h"

#include "ArgumentList.h"
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

namespace
{

// The options of one shape only, and the shapes they apply to.
struct ShapeOption
{
  const char* Name;
  bool Sphere;
  bool Torus;
};
const ShapeOption ShapeOptions[] = {
  { "--level", true, false },
  { "--radius", true, true },
  { "--ring-resolution", false, true },
  { "--tube-resolution", false, true },
  { "--tube-radius", false, true },
};

// Refuses an option given for a shape it does not shape (it was ignored).
void CheckShapeOptions(GeneratedShape shape, const std::vector<std::string>& given)
{
  for (const std::string& name : given)
  {
    for (const ShapeOption& option : ShapeOptions)
    {
      if (name != option.Name)
      {
        continue;
      }
      const bool applies = shape == GeneratedShape::Sphere ? option.Sphere : option.Torus;
      if (!applies)
      {
        throw UsageError("option '" + name + "' applies to a " +
          (option.Sphere ? "sphere" : "torus") + ", not a " +
          (shape == GeneratedShape::Sphere ? "sphere" : "torus"));
      }
    }
  }
}

} // namespace

GenerateOptions ParseGenerate(ArgumentList& arguments)
{
  GenerateOptions options;
  bool haveShape = false;
  std::vector<std::string> given; // the options of one shape that were given
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!LooksLikeOption(word))
    {
      if (haveShape)
      {
        throw UsageError("unexpected argument '" + word + "' (the shape is already given)");
      }
      if (word != "sphere" && word != "torus")
      {
        throw UsageError("'generate' makes a sphere or a torus, not '" + word + "'");
      }
      options.Shape = word == "sphere" ? GeneratedShape::Sphere : GeneratedShape::Torus;
      haveShape = true;
      continue;
    }
    const Option option = SplitOption(word);
    given.push_back(option.Name);
    if (option.Name == "-o" || option.Name == "--output")
    {
      options.Output = arguments.TakeValue(option);
    }
    else if (option.Name == "--level")
    {
      options.Level = ParseCount(option, arguments.TakeValue(option), 0, 8);
    }
    else if (option.Name == "--ring-resolution")
    {
      options.RingResolution = ParseCount(option, arguments.TakeValue(option), 3, 100000);
    }
    else if (option.Name == "--tube-resolution")
    {
      options.TubeResolution = ParseCount(option, arguments.TakeValue(option), 3, 100000);
    }
    else if (option.Name == "--radius" || option.Name == "--tube-radius")
    {
      const std::string text = arguments.TakeValue(option);
      const double value = ParseNumber(option.Name, text);
      if (!(value > 0.0))
      {
        throw UsageError("option '" + option.Name + "' needs a number above 0, got '" + text + "'");
      }
      (option.Name == "--radius" ? options.Radius : options.TubeRadius) = value;
    }
    else
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'generate'; run 'silhouette generate --help'");
    }
  }
  if (!haveShape)
  {
    throw UsageError("'generate' needs a shape: sphere or torus");
  }
  CheckShapeOptions(options.Shape, given);
  if (options.Output.empty())
  {
    throw UsageError("'generate' needs '-o OUTPUT'");
  }
  return options;
}

} // namespace cli
