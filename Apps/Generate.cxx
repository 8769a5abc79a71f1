#include "Generate.h"

#include "CliErrors.h"
#include "MeshIO.h"
#include "VtkErrorLog.h"

#include <vtkIcosphereSource.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTorusSurfaceSource.h>

#include <iostream>

namespace cli
{

void RunGenerate(const GenerateOptions& options)
{
  CheckMeshOutputPath(options.Output);
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkNew<vtkPolyData> mesh;
  if (options.Shape == GeneratedShape::Sphere)
  {
    vtkNew<vtkIcosphereSource> sphere;
    sphere->SetSubdivisionLevel(options.Level);
    sphere->SetRadius(options.Radius);
    sphere->Update();
    mesh->ShallowCopy(sphere->GetOutput());
  }
  else
  {
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
