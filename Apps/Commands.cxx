#include "Commands.h"

#include "CliErrors.h"
#include "Figures.h"
#include "MeshIO.h"
#include "PrintableText.h"
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

// The filter's warnings, one line each on stderr: the work goes on.
void PrintWarnings(const SmoothingRun& run)
{
  for (const std::string& warning : run.Warnings)
  {
    std::cerr << "silhouette: warning: " << PrintableText(warning) << "\n";
  }
}

// What a .ply could not keep, said once on stderr.
void ReportDropped(const std::vector<std::string>& dropped, const std::string& path)
{
  if (dropped.empty())
  {
    return;
  }
  std::string names;
  for (const std::string& name : dropped)
  {
    names += (names.empty() ? "" : ", ") + name;
  }
  std::cerr << "silhouette: note: PLY holds points, polygons, normals, texture coordinates and "
               "colours only: "
            << PrintableText(names) << " are not in '" << PrintableText(path)
            << "' (write .vtp to keep them)\n";
}

} // namespace

void RunSmooth(const SmoothOptions& options)
{
  if (options.Output)
  {
    CheckMeshOutputPath(*options.Output);
  }
  if (options.LinesOutput)
  {
    CheckLinesOutputPath(*options.LinesOutput);
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshWithTriangles(options.Input);
  const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
  SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);
  vtkCamera* camera = view.Renderer->GetActiveCamera();

  const SmoothingRun run = SmoothSilhouette(mesh, camera, options.Camera);
  PrintWarnings(run);
  if (options.Output)
  {
    ReportDropped(WriteMesh(run.Filter->GetOutput(), *options.Output), *options.Output);
  }
  if (options.LinesOutput)
  {
    WriteLines(run.Filter->GetSilhouetteOutput(), *options.LinesOutput);
  }
  PrintFigures(CollectFigures(options.Input, options.Output, run.Filter->GetOutput(),
                 run.PrepareMilliseconds, run.MedianMilliseconds, options.Camera, camera),
    options.Json);
}

void RunRender(const RenderOptions& options)
{
  CheckRenderOutputPath(options);
  if (options.LinesOutput)
  {
    CheckLinesOutputPath(*options.LinesOutput);
  }
  const bool svg = IsSvgPath(options.Output);
  if (!svg)
  {
    RequireDisplay(); // an SVG drawing is projected, not rendered
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshWithTriangles(options.Input);
  const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
  SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);
  vtkCamera* camera = view.Renderer->GetActiveCamera();

  const SmoothingRun run = SmoothSilhouette(mesh, camera, options.Camera);
  PrintWarnings(run);
  if (svg)
  {
    RenderToSvg(view, run.Filter, mesh, options);
  }
  else
  {
    RenderToPng(view, run.Filter, mesh, options);
  }
  if (options.LinesOutput)
  {
    WriteLines(run.Filter->GetSilhouetteOutput(), *options.LinesOutput);
  }
  PrintFigures(CollectFigures(options.Input, options.Output, run.Filter->GetOutput(),
                 run.PrepareMilliseconds, run.MedianMilliseconds, options.Camera, camera),
    options.Json);
}

} // namespace cli
