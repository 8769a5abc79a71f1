#include "Commands.h"

#include "CliErrors.h"
#include "Figures.h"
#include "MeshIO.h"
#include "Rendering.h"
#include "Smoothing.h"

#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSilhouetteSmoothingFilter.h>

#include <iostream>

namespace cli
{
namespace
{

// Reads the mesh and refuses one the filter could do nothing with.
vtkSmartPointer<vtkPolyData> ReadMeshWithTriangles(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh = ReadMesh(path);
  if (CountTriangles(mesh) == 0)
  {
    throw RuntimeError(path + " has no triangles");
  }
  return mesh;
}

void PrintFigures(const Figures& figures, bool json)
{
  if (json)
  {
    PrintFiguresAsJson(std::cout, figures);
  }
  else
  {
    PrintFiguresAsText(std::cout, figures);
  }
  std::cout.flush();
}

} // namespace

void RunSmooth(const SmoothOptions& options)
{
  if (options.Output)
  {
    CheckMeshOutputPath(*options.Output);
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshWithTriangles(options.Input);
  const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
  SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);
  vtkCamera* camera = view.Renderer->GetActiveCamera();

  const SmoothingRun run = SmoothSilhouette(mesh, camera, options.Camera);
  if (options.Output)
  {
    WriteMesh(run.Filter->GetOutput(), *options.Output);
  }
  PrintFigures(CollectFigures(options.Input, options.Output, run.Filter->GetOutput(),
                 run.PrepareMilliseconds, run.MedianMilliseconds, options.Camera, camera),
    options.Json);
}

void RunRender(const RenderOptions& options)
{
  CheckImageOutputPath(options.Output);
  RequireDisplay();
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshWithTriangles(options.Input);
  const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
  SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);
  vtkCamera* camera = view.Renderer->GetActiveCamera();

  const SmoothingRun run = SmoothSilhouette(mesh, camera, options.Camera);
  RenderToPng(view, run.Filter, mesh, options);
  PrintFigures(CollectFigures(options.Input, options.Output, run.Filter->GetOutput(),
                 run.PrepareMilliseconds, run.MedianMilliseconds, options.Camera, camera),
    options.Json);
}

} // namespace cli
