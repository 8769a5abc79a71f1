#include "Commands.h"

#include "AtomicFile.h"
#include "CliErrors.h"
#include "Figures.h"
#include "LevelOfDetail.h"
#include "MeshIO.h"
#include "ModelInput.h"
#include "PrintableText.h"
#include "Rendering.h"
#include "Smoothing.h"
#include "TextFormat.h"
#include "VectorDrawing.h"
#include "VtkErrorLog.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProgressiveMeshFilter.h>
#include <vtkRenderer.h>
#include <vtkSilhouetteSmoothingFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace cli
{
namespace
{

// Whether a triangle of the mesh (polygons fanned, strips split) has an
// area: one without any has no outline, whatever the view.
bool HasTriangleWithArea(vtkPolyData* mesh)
{
  vtkPoints* points = mesh->GetPoints();
  if (!points)
  {
    return false;
  }
  for (vtkCellArray* cells : { mesh->GetPolys(), mesh->GetStrips() })
  {
    const bool strips = cells == mesh->GetStrips();
    auto cell = vtk::TakeSmartPointer(cells->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      vtkIdType size = 0;
      const vtkIdType* ids = nullptr;
      cell->GetCurrentCell(size, ids);
      for (vtkIdType k = 1; k + 1 < size; ++k)
      {
        double a[3], b[3], c[3], ab[3], ac[3], normal[3];
        points->GetPoint(ids[strips ? k - 1 : 0], a);
        points->GetPoint(ids[k], b);
        points->GetPoint(ids[k + 1], c);
        for (int i = 0; i < 3; ++i)
        {
          ab[i] = b[i] - a[i];
          ac[i] = c[i] - a[i];
        }
        vtkMath::Cross(ab, ac, normal);
        if (vtkMath::Norm(normal) > 0.0)
        {
          return true;
        }
      }
    }
  }
  return false;
}

// A drawing of nothing, of a mesh that has an outline from some view, says
// why (a flat mesh seen from its side drew a blank image with no word).
void WarnIfBlank(bool blank, const std::string& path, vtkPolyData* mesh, bool lines)
{
  if (!blank || !HasTriangleWithArea(mesh))
  {
    return;
  }
  // A drawing is blank too when the mesh fills the view and none of its
  // lines crosses it (zoomed in on the surface): a user read "shows nothing
  // of the mesh" of such a drawing as the mesh being out of view.
  std::cerr
    << "silhouette: warning: '" << PrintableText(path)
    << (lines ? "' has no visible line in it: no outline, crease or border of the mesh crosses "
                "the view (the mesh's image may cover the whole view, or the mesh is "
                "outside the view, smaller than a pixel, or seen edge-on); try another "
                "--azimuth, --elevation or --zoom\n"
              : "' shows nothing of the mesh: it is outside the view, smaller than a "
                "pixel, or seen edge-on (a flat mesh from its side); try another "
                "--azimuth, --elevation or --zoom\n");
}

// Reads the mesh and refuses one the filter could do nothing with. One whose
// triangles all lack an area (all its points at one place, or on one line)
// goes on, as the filter's input without a proper triangle does, but says
// why nothing comes of it: the run gave a blank image and no word.
vtkSmartPointer<vtkPolyData> ReadMeshWithTriangles(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh = ReadModelOrMesh(path); // a model name: its coarse version
  if (CountTriangles(mesh) == 0)
  {
    throw RuntimeError(path + " has no triangles");
  }
  if (!HasTriangleWithArea(mesh))
  {
    std::cerr << "silhouette: warning: '" << PrintableText(path)
              << "': none of its triangles has an area (its points are all at one place or on "
                 "one line): there is no outline to smooth or draw\n";
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
    PrintFilterWarning(warning);
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
    RefuseOverwritingModelOrInput(options.Input, *options.Output, "-o");
  }
  if (options.LinesOutput)
  {
    CheckLinesOutputPath(*options.LinesOutput);
    RefuseOverwritingModelOrInput(options.Input, *options.LinesOutput, "--lines-output");
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshWithTriangles(options.Input);
  const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
  SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);
  vtkCamera* camera = view.Renderer->GetActiveCamera();

  const SmoothingRun run = SmoothSilhouette(mesh, camera, options.Camera);
  PrintWarnings(run);
  // Both files or neither: one that cannot be written leaves the other as it was.
  FileBatch outputs;
  std::vector<std::string> dropped;
  if (options.Output)
  {
    dropped = WriteMesh(run.Filter->GetOutput(), *options.Output, &outputs);
  }
  if (options.LinesOutput)
  {
    WriteLines(run.Filter->GetSilhouetteOutput(), *options.LinesOutput, &outputs);
  }
  outputs.Commit();
  if (options.Output)
  {
    ReportDropped(dropped, *options.Output);
  }
  PrintFigures(CollectFigures(options.Input, options.Output, run.Filter->GetOutput(),
                 run.PrepareMilliseconds, run.MedianMilliseconds, options.Camera, camera),
    options.Json);
}

// The folder of a progressive sketch: made when missing (not its parents).
// The name of the sketch's drawing `number` (from 1): sketch-01.svg, ...
std::string SketchName(int number, const std::string& extension)
{
  char name[32];
  std::snprintf(name, sizeof name, "sketch-%02d.%s", number, extension.c_str());
  return name;
}

void PrepareSketchFolder(const std::string& folder, int levels, const std::string& extension)
{
  std::error_code error;
  const std::filesystem::path path(folder);
  if (!std::filesystem::exists(path, error))
  {
    if (!std::filesystem::create_directory(path, error))
    {
      throw RuntimeError("cannot make the sketch's directory '" + folder + "': " + error.message());
    }
    return;
  }
  if (!std::filesystem::is_directory(path, error))
  {
    throw RuntimeError("cannot write the sketch into '" + folder + "': it is not a directory");
  }
  // Drawings of an earlier, longer run stay (nothing of the user's is
  // deleted), but would pass for this run's: a user's animation mixed two
  // runs (2026-12-05). Say which.
  std::vector<int> stale;
  for (const auto& entry : std::filesystem::directory_iterator(path, error))
  {
    const std::string name = entry.path().filename().string();
    int number = 0;
    if (std::sscanf(name.c_str(), "sketch-%d", &number) == 1 && number > levels &&
      name == SketchName(number, extension))
    {
      stale.push_back(number);
    }
  }
  if (!stale.empty())
  {
    std::sort(stale.begin(), stale.end());
    std::cerr << "silhouette: warning: '" << PrintableText(folder) << "' also holds "
              << (stale.size() == 1 ? SketchName(stale.front(), extension)
                                    : SketchName(stale.front(), extension) + " to " +
                       SketchName(stale.back(), extension) + " (" + std::to_string(stale.size()) +
                       " drawings)")
              << " of an earlier run, not of this one\n";
  }
}

// Kim and Choe's progressive sketch (Fig. 3): the drawing of the progressive
// mesh at `levels` triangle counts from its base mesh to the input,
// spaced geometrically, all from the camera that frames the input.
void RunProgressiveSketch(const RenderOptions& options)
{
  if (!IsLineStyle(options.Style))
  {
    throw UsageError(std::string("--progressive draws a line style (lines, charcoal, lazy, "
                                 "hand or rough), not '") +
      NameOf(options.Style) + "'");
  }
  // The single drawing's checks (CheckRenderOutputPath), for a folder of
  // PNG drawings or of SVG or PDF ones (--svg, --pdf).
  const bool vector = options.ProgressiveFormat != "png";
  if (options.ProgressiveFormat == "pdf")
  {
    CheckPdfPageSize(options.Camera.ViewportSize);
  }
  if (!vector && options.WidthByDepth)
  {
    throw UsageError("--width-by-depth needs SVG or PDF drawings; add --svg or --pdf to "
                     "--progressive");
  }
  if (!vector && options.JoinLines)
  {
    throw UsageError("--join-lines needs SVG or PDF drawings; add --svg or --pdf to --progressive");
  }
  if (!vector && options.HiddenLines && options.Style != RenderStyle::Lines)
  {
    throw UsageError("--hidden dashed draws the hidden lines of '--style lines' in PNG drawings "
                     "(of any line style with --svg or --pdf), not of '" +
      std::string(NameOf(options.Style)) + "'");
  }
  if (options.LinesOutput)
  {
    throw UsageError("option '--lines-output' does not go with '--progressive' (its drawings "
                     "are of many meshes)");
  }
  if (!vector)
  {
    RequireDisplay();
  }
  const std::string& extension = options.ProgressiveFormat;
  PrepareSketchFolder(options.Output, options.ProgressiveLevels, extension);
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshWithTriangles(options.Input);
  vtkNew<vtkProgressiveMeshFilter> progressive;
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  errors.Watch(progressive);
  progressive->SetInputData(mesh);
  progressive->SetTriangleCount(0); // the base mesh
  progressive->Update();
  errors.ThrowIfErrors("the progressive mesh failed");
  auto field = [&](const char* name) {
    vtkDataArray* array = progressive->GetOutput()->GetFieldData()->GetArray(name);
    return array ? static_cast<double>(array->GetTuple1(0)) : 0.0;
  };
  const double base = std::max(1.0, field("BaseTriangleCount"));
  const double full = std::max(base, field("FullTriangleCount"));

  std::string json = "[";
  for (int level = 0; level < options.ProgressiveLevels; ++level)
  {
    const double fraction =
      static_cast<double>(level) / static_cast<double>(options.ProgressiveLevels - 1);
    const auto count = static_cast<vtkIdType>(std::llround(base * std::pow(full / base, fraction)));
    progressive->SetTriangleCount(count);
    progressive->Update();
    errors.ThrowIfErrors("the progressive mesh failed");
    auto levelMesh = vtkSmartPointer<vtkPolyData>::New();
    levelMesh->DeepCopy(progressive->GetOutput());

    RenderOptions levelOptions = options;
    levelOptions.Output =
      (std::filesystem::path(options.Output) / SketchName(level + 1, extension)).string();
    levelOptions.Input = options.Input;
    // Every level from the camera that frames the input (the finest level).
    const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
    SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);
    vtkCamera* camera = view.Renderer->GetActiveCamera();
    const SmoothingRun run = SmoothSilhouette(levelMesh, camera, options.Camera);
    // The smoothing's warnings about the file (near copies to weld, normals
    // it ignores) are those of the input's own level; the coarser levels'
    // points are the progressive mesh's, which the user cannot change.
    if (level + 1 == options.ProgressiveLevels)
    {
      PrintWarnings(run);
    }
    if (vector)
    {
      WarnIfBlank(RenderToDrawing(view, run.Filter, levelMesh, levelOptions), levelOptions.Output,
        levelMesh, true);
    }
    else
    {
      WarnIfBlank(RenderToPng(view, run.Filter, levelMesh, levelOptions), levelOptions.Output,
        levelMesh, true);
    }
    const Figures figures =
      CollectFigures(options.Input, levelOptions.Output, run.Filter->GetOutput(),
        run.PrepareMilliseconds, run.MedianMilliseconds, options.Camera, camera);
    if (options.Json)
    {
      std::ostringstream object;
      PrintFiguresAsJson(object, figures);
      std::string text = object.str();
      while (!text.empty() && text.back() == '\n')
      {
        text.pop_back();
      }
      json += (level > 0 ? ",\n" : "") + text;
    }
    else
    {
      std::cout << levelOptions.Output << ": " << figures.InputTriangles << " triangles"
                << (level == 0 ? " (the base mesh)" : "")
                << (level + 1 == options.ProgressiveLevels ? " (the input)" : "") << ", "
                << figures.SilhouetteTriangles << " silhouette triangles smoothed\n";
    }
  }
  if (options.Json)
  {
    std::cout << json << "]\n";
  }
}

void RunRender(const RenderOptions& options)
{
  if (options.ProgressiveLevels > 0)
  {
    RunProgressiveSketch(options);
    return;
  }
  CheckRenderOutputPath(options);
  RefuseOverwritingModelOrInput(options.Input, options.Output, "-o");
  if (options.LinesOutput)
  {
    CheckLinesOutputPath(*options.LinesOutput);
    RefuseOverwritingModelOrInput(options.Input, *options.LinesOutput, "--lines-output");
  }
  const bool drawing = IsVectorDrawingPath(options.Output);
  if (!drawing)
  {
    RequireDisplay(); // a drawing is projected, not rendered
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadMeshWithTriangles(options.Input);
  if (!drawing)
  {
    WarnIfTooSmallOrLargeToDraw(mesh->GetBounds());
  }
  const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
  SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  std::optional<Figures::LevelOfDetail> lodFigures;
  if (options.Lod)
  {
    std::cerr << "render: building the level-of-detail hierarchy of "
              << Grouped(mesh->GetNumberOfPolys()) << " triangles..." << std::endl;
    const LevelOfDetailRun lod = ExtractForView(mesh, camera, options.Camera);
    (options.Json ? std::cerr : std::cout) << lod.summary() << "\n";
    mesh = lod.Mesh;
    lodFigures = Figures::LevelOfDetail{ lod.InputTriangles, lod.BuildMilliseconds };
  }

  const SmoothingRun run = SmoothSilhouette(mesh, camera, options.Camera);
  PrintWarnings(run);
  // Both files or neither: one that cannot be written leaves the other as it was.
  FileBatch outputs;
  if (drawing)
  {
    WarnIfBlank(
      RenderToDrawing(view, run.Filter, mesh, options, &outputs), options.Output, mesh, true);
  }
  else
  {
    WarnIfBlank(RenderToPng(view, run.Filter, mesh, options, &outputs), options.Output, mesh,
      IsLineStyle(options.Style));
  }
  if (options.LinesOutput)
  {
    WriteLines(run.Filter->GetSilhouetteOutput(), *options.LinesOutput, &outputs);
  }
  outputs.Commit();
  Figures figures = CollectFigures(options.Input, options.Output, run.Filter->GetOutput(),
    run.PrepareMilliseconds, run.MedianMilliseconds, options.Camera, camera);
  figures.Lod = lodFigures;
  PrintFigures(figures, options.Json);
}

} // namespace cli
