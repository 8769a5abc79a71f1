#include "Figure.h"

#include "ArgumentList.h"
#include "CameraOptions.h"
#include "CliErrors.h"
#include "Compare.h"
#include "DataFolder.h"
#include "MeshIO.h"
#include "Rendering.h"
#include "RenderingBackend.h"
#include "Smoothing.h"
#include "VtkErrorLog.h"

#include "EvaluationModels.h"
#include "SilhouetteComparison.h"

#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSilhouetteSmoothingFilter.h>
#include <vtkTable.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <iostream>
#include <stdexcept>
#include <vector>

namespace cli
{
namespace
{

void AddLabel(vtkRenderer* renderer, const std::string& text)
{
  vtkNew<vtkTextActor> label;
  label->SetInput(text.c_str());
  label->GetTextProperty()->SetFontSize(18);
  label->GetTextProperty()->SetColor(0, 0, 0);
  label->GetTextProperty()->SetJustificationToCentered();
  label->GetTextProperty()->SetVerticalJustificationToTop();
  label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  label->SetPosition(0.5, 0.97);
  renderer->AddViewProp(label);
}

std::string Triangles(double count)
{
  return std::to_string(static_cast<long long>(count + 0.5)) + " triangles";
}

// Four panels in a row, one camera: shaded coarse, wireframe with the new
// geometry in red, shaded coarse + smoothing, shaded fine.
void RenderPanels(const silhouette_eval::ModelVersions& model, const FigureOptions& options)
{
  const int width = options.Camera.ViewportSize[0];
  const int height = options.Camera.ViewportSize[1];
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(4 * width, height);

  std::vector<vtkSmartPointer<vtkRenderer>> panels;
  for (int i = 0; i < 4; ++i)
  {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(0.25 * i, 0.0, 0.25 * (i + 1), 1.0);
    renderer->SetBackground(1, 1, 1);
    window->AddRenderer(renderer);
    panels.push_back(renderer);
  }
  SetUpCamera(panels[0], model.Original->GetBounds(), options.Camera);
  vtkCamera* camera = panels[0]->GetActiveCamera();
  for (int i = 1; i < 4; ++i)
  {
    panels[i]->SetActiveCamera(camera);
  }

  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  VtkErrorLog::Instance().Watch(smoother);
  smoother->SetInputData(model.Coarse);
  smoother->SetCamera(camera);
  smoother->SetViewportSize(width, height);
  ApplySmoothingOptions(smoother, options.Camera);
  smoother->Update();
  // The fine mesh's own limit normals, through a filter so the shaded style
  // is drawn exactly as for the others.
  vtkNew<vtkSilhouetteSmoothingFilter> fineNormals;
  fineNormals->SetInputData(model.Fine);
  fineNormals->SetCamera(camera);
  fineNormals->Update();

  AddStyleActors(panels[0], smoother, model.Coarse, RenderStyle::Shaded, false);
  AddStyleActors(panels[1], smoother, model.Coarse, RenderStyle::NewGeometry, true);
  AddStyleActors(panels[2], smoother, model.Coarse, RenderStyle::Shaded, true);
  AddStyleActors(panels[3], fineNormals, model.Fine, RenderStyle::Shaded, false);
  const double outTriangles =
    smoother->GetOutput()->GetFieldData()->GetArray("OutputTriangleCount")->GetTuple1(0);
  AddLabel(panels[0], "coarse, " + Triangles(model.Coarse->GetNumberOfPolys()));
  AddLabel(panels[1], "new geometry in red");
  AddLabel(panels[2], "coarse + smoothing, " + Triangles(outTriangles));
  AddLabel(panels[3],
    "fine (Loop " + std::to_string(options.FineLevel) + "), " +
      Triangles(model.Fine->GetNumberOfPolys()));
  for (auto& panel : panels)
  {
    panel->ResetCameraClippingRange();
  }
  window->Render();
  VtkErrorLog::Instance().ThrowIfErrors("rendering the figure failed");
  WriteWindowPng(window, options.Output);
  std::cout << "wrote " << options.Output << "\n";
}

void AddSeries(vtkChartXY* chart, const char* name, const std::vector<double>& x,
  const std::vector<double>& y, const unsigned char color[3])
{
  vtkNew<vtkTable> table;
  vtkNew<vtkDoubleArray> xs;
  xs->SetName("triangles");
  vtkNew<vtkDoubleArray> ys;
  ys->SetName(name);
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    xs->InsertNextValue(x[i]);
    ys->InsertNextValue(y[i]);
  }
  table->AddColumn(xs);
  table->AddColumn(ys);
  vtkPlot* line = chart->AddPlot(vtkChart::LINE);
  line->SetInputData(table, 0, 1);
  line->SetColor(color[0], color[1], color[2], 255);
  line->SetWidth(2.0);
  line->SetLabel(name);
  vtkPlot* points = chart->AddPlot(vtkChart::POINTS);
  points->SetInputData(table, 0, 1);
  points->SetColor(color[0], color[1], color[2], 255);
  points->SetLegendVisibility(false);
}

// Whole-frame time against rendered triangles: the coarse mesh at several
// decimations, with and without smoothing, and the fine reference at each
// Loop level up to FineLevel.
void RenderPlot(
  const silhouette_eval::ModelVersions& model, vtkPolyData* original, const FigureOptions& options)
{
  silhouette_eval::ComparisonOptions timing;
  timing.Width = options.Camera.ViewportSize[0];
  timing.Height = options.Camera.ViewportSize[1];
  timing.TimedFrames = options.Frames;
  timing.Tolerance = options.Camera.Tolerance;

  silhouette_eval::OrbitTimer timer(timing);
  const double base = static_cast<double>(model.Coarse->GetNumberOfPolys());
  std::vector<double> coarseX, coarseY, smoothX, smoothY, fineX, fineY;
  for (double factor : { 0.25, 0.5, 1.0, 2.0 })
  {
    const int target = static_cast<int>(base * factor);
    if (target < 40 || target > original->GetNumberOfPolys())
    {
      continue;
    }
    std::cerr << "figure: timing the coarse mesh at " << target << " triangles" << std::endl;
    vtkSmartPointer<vtkPolyData> coarse = silhouette_eval::Decimate(original, target);
    const auto plain = timer.Time(coarse, false);
    const auto smooth = timer.Time(coarse, true);
    coarseX.push_back(plain.Triangles);
    coarseY.push_back(plain.FrameMilliseconds);
    smoothX.push_back(smooth.Triangles);
    smoothY.push_back(smooth.FrameMilliseconds);
  }
  for (int level = 1; level <= options.FineLevel; ++level)
  {
    std::cerr << "figure: timing the fine reference at Loop level " << level << std::endl;
    vtkSmartPointer<vtkPolyData> fine = silhouette_eval::Refine(original, level);
    const auto plain = timer.Time(fine, false);
    fineX.push_back(plain.Triangles);
    fineY.push_back(plain.FrameMilliseconds);
  }

  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetMultiSamples(0);
  view->GetRenderWindow()->SetSize(900, 600);
  view->GetRenderer()->SetBackground(1, 1, 1);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle("Whole-frame time against triangles: " + model.Name + " (" +
    std::to_string(timing.Width) + "x" + std::to_string(timing.Height) + ", median of " +
    std::to_string(timing.TimedFrames) + " frames)");
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("triangles rendered");
  chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(true);
  chart->GetAxis(vtkAxis::LEFT)->SetTitle("milliseconds per frame");
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  const unsigned char grey[3] = { 110, 110, 110 };
  const unsigned char red[3] = { 210, 30, 30 };
  const unsigned char blue[3] = { 30, 70, 200 };
  AddSeries(chart, "coarse", coarseX, coarseY, grey);
  AddSeries(chart, "coarse + smoothing", smoothX, smoothY, red);
  AddSeries(chart, "fine (Loop refinement)", fineX, fineY, blue);
  // Twice: VTK 9.1's chart fits its axes to the data while it paints, after
  // painting the series with the axes it had, which puts them out of sight;
  // the image (read without rendering again) then had axes and no curves.
  view->GetRenderWindow()->Render();
  view->GetRenderWindow()->Render();
  VtkErrorLog::Instance().ThrowIfErrors("drawing the plot failed");
  WriteWindowPng(view->GetRenderWindow(), options.Plot);
  std::cout << "wrote " << options.Plot << "\n";
}

} // namespace

void RunFigure(const FigureOptions& options)
{
  CheckImageOutputPath(options.Output);
  RefuseOverwritingInput(options.Input, options.Output, "-o");
  if (!options.Plot.empty())
  {
    CheckImageOutputPath(options.Plot);
    RefuseOverwritingInput(options.Input, options.Plot, "--plot");
  }
  RequireDisplay();
  const std::string dataDirectory =
    options.DataDirectory.empty() ? DefaultDataDirectory() : options.DataDirectory;
  try
  {
    int coarseTriangles = options.CoarseTriangles;
    vtkSmartPointer<vtkPolyData> original =
      OriginalOf(options.Input, dataDirectory, "figure", coarseTriangles);
    std::cerr << "figure: " << CoarseVersionText(original, coarseTriangles)
              << " and refining to Loop level " << options.FineLevel << std::endl;
    const silhouette_eval::ModelVersions model =
      silhouette_eval::MakeVersions(options.Input, original, coarseTriangles, options.FineLevel);
    // The plot's timing windows come first: after a 4096-pixel-wide panel
    // window (four 1024 px panels), Xvfb's default 1280x1024 screen refused
    // to create the next window (VTK aborts on that).
    if (!options.Plot.empty())
    {
      RenderPlot(model, original, options);
    }
    RenderPanels(model, options);
  }
  catch (const UsageError& error)
  {
    // Camera options that do not fit the mesh stay usage errors (exit 2).
    throw UsageError(options.Input + ": " + error.what());
  }
  catch (const std::runtime_error& error)
  {
    throw RuntimeError(options.Input + ": " + error.what());
  }
}

std::string FigureHelp()
{
  return R"(Usage: silhouette figure MODEL|MESH -o FIGURE.png [--plot PLOT.png] [options]
                        [camera options]

Draws the four panels of Figs. 1 and 7 of R. Xing's "Adaptive Local Remeshing
for Smooth Silhouette on 3D Triangle Meshes" side by side, labelled, from
one camera: the coarse mesh shaded, its wireframe after smoothing with the
new triangles in red, the coarse mesh with smoothing shaded, and the fine
reference (OpenSubdiv Loop refinement of the original) shaded. MODEL is one
of bunny, sphere, torus, ellipsoid, supertoroid, knot; any other MESH is a
file, decimated and refined like a model. With --plot it also times orbits
(whole frames: camera move, filter, render) of the coarse mesh at 1/4, 1/2,
1 and 2 times its triangles (those of at least 40 and at most the
original's), with and without smoothing, and of the fine
reference at each Loop level, and plots milliseconds against triangles
with VTK's charts. Where there is no X display it renders through OSMesa
(--backend).

Options:
  -o, --output FILE     the figure (.png); required
  --plot FILE           also write the time plot (.png)
  --coarse-triangles N  triangles of the coarse version (default: the
                        model's own; 1000 for a mesh file)
  --fine-level L        Loop level of the fine reference, 1 to 5 (default 3)
  --frames N            timed orbit frames per point of the plot (default 30)
  --data DIR            the folder that holds bunny.ply (default: the one
                        installed with the program, share/SilhouetteSmoothing/
                        Data beside its bin folder)
)" + RenderBackendHelp(24) +
    R"(  -h, --help            show this help and exit

Camera options as for 'smooth' (--size is the size of ONE panel, default
1024x768; the framing camera frames the original mesh).
)";
}

FigureOptions ParseFigure(ArgumentList& arguments, RenderBackend& backend)
{
  FigureOptions options;
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!LooksLikeOption(word))
    {
      if (!options.Input.empty())
      {
        throw UsageError(
          "unexpected argument '" + word + "' (INPUT is already '" + options.Input + "')");
      }
      options.Input = word;
      continue;
    }
    const Option option = SplitOption(word);
    if (option.Name == "-o" || option.Name == "--output")
    {
      options.Output = arguments.TakeValue(option);
    }
    else if (option.Name == "--plot")
    {
      options.Plot = arguments.TakeValue(option);
    }
    else if (option.Name == "--coarse-triangles")
    {
      options.CoarseTriangles = ParseCount(option, arguments.TakeValue(option), 4, 10000000);
    }
    else if (option.Name == "--fine-level")
    {
      options.FineLevel = ParseCount(option, arguments.TakeValue(option), 1, 5);
    }
    else if (option.Name == "--frames")
    {
      options.Frames = ParseCount(option, arguments.TakeValue(option), 1, 100000);
    }
    else if (option.Name == "--data")
    {
      options.DataDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--backend")
    {
      backend = ParseRenderBackend(option.Name, arguments.TakeValue(option));
    }
    else if (!ParseCameraOption(option, arguments, options.Camera))
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'figure'; run 'silhouette figure --help'");
    }
  }
  if (options.Input.empty())
  {
    throw UsageError("'figure' needs a model name or a mesh file");
  }
  if (options.Output.empty())
  {
    throw UsageError("'figure' needs '-o FIGURE.png'");
  }
  CheckCameraOptions(options.Camera);
  return options;
}

} // namespace cli
