// The viewer's drivers (Viewer.h): the interactive window, the headless
// orbit, the playback of a recorded interaction, and `silhouette view`.
#include "Viewer.h"

#include "CliErrors.h"
#include "Figures.h"
#include "MeshIO.h"
#include "Rendering.h"
#include "RenderingBackend.h"
#include "Smoothing.h"
#include "TextFormat.h"
#include "VtkErrorLog.h"

#include "EvaluationModels.h"

#include <vtkCamera.h>
#include <vtkInteractorEventRecorder.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSilhouetteSmoothingFilter.h>
#include <vtkSilhouetteSmoothingMapper.h>
#include <vtkSliderWidget.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace cli
{

void Viewer::ReportStep(const std::string& action)
{
  char name[96];
  std::snprintf(name, sizeof(name), "step_%02d_%s.png", this->Step, action.c_str());
  const std::string screenshot = JoinPath(this->Options.ScreenshotDirectory, name);
  WriteWindowPng(this->Window, screenshot);
  const ViewerFigures figures = this->CurrentFigures();
  vtkCamera* camera = this->MainRenderer->GetActiveCamera();
  const bool parallel = camera->GetParallelProjection() != 0;
  double position[3];
  camera->GetPosition(position);
  const double tolerance = this->Filter->GetTolerance();
  const long long fineTriangles = this->Fine ? this->Fine->GetNumberOfPolys() : 0;
  if (this->Options.Json)
  {
    std::cout << "{\"step\": " << this->Step << ", \"action\": " << JsonString(action)
              << ", \"smoothing\": " << (this->Smoothing ? "true" : "false")
              << ", \"style\": " << JsonString(this->StyleName())
              << ", \"tolerance\": " << JsonNumber(tolerance)
              << ", \"parallel\": " << (parallel ? "true" : "false")
              << ", \"fine_reference\": " << (this->ShowFine ? "true" : "false")
              << ", \"fine_triangles\": " << fineTriangles
              << ", \"help\": " << (this->ShowHelp ? "true" : "false")
              << ", \"input_triangles\": " << figures.InputTriangles
              << ", \"output_triangles\": " << figures.OutputTriangles
              << ", \"silhouette_triangles\": " << figures.SilhouetteTriangles
              << ", \"new_triangles\": " << figures.NewTriangles << ", \"camera_position\": ["
              << JsonNumber(position[0]) << ", " << JsonNumber(position[1]) << ", "
              << JsonNumber(position[2]) << "], \"message\": " << JsonString(this->Message)
              << ", \"screenshot\": " << JsonString(screenshot) << "}" << std::endl;
  }
  else
  {
    std::cout << "step " << this->Step << " " << action << ": smoothing " << OnOff(this->Smoothing)
              << ", style " << this->StyleName() << ", tolerance " << tolerance << " px, "
              << (parallel ? "parallel" : "perspective") << ", fine reference "
              << OnOff(this->ShowFine) << " (" << fineTriangles << " triangles), help "
              << OnOff(this->ShowHelp) << "; triangles in " << figures.InputTriangles << ", out "
              << figures.OutputTriangles << ", silhouette " << figures.SilhouetteTriangles
              << ", new " << figures.NewTriangles << "; camera at " << position[0] << " "
              << position[1] << " " << position[2] << "; screenshot " << screenshot
              << (this->Message.empty() ? "" : "; " + this->Message) << std::endl;
  }
  ++this->Step;
}

void Viewer::Interact()
{
  this->BuildWindow(Mode::Interactive);
  if (this->Slider)
  {
    this->Slider->EnabledOn();
  }
  this->Interactor->Initialize();
  if (this->Options.FineReference)
  {
    this->Perform(ViewerAction::ToggleFineReference);
  }
  VtkErrorLog::Instance().Clear();
  this->Window->Render();
  VtkErrorLog::Instance().ThrowIfErrors("rendering failed");
  this->Interactor->Start();
}

void Viewer::RecordOrbit()
{
  const bool record = !this->Options.RecordDirectory.empty();
  if (record)
  {
    CreateDirectory(this->Options.RecordDirectory);
  }
  this->BuildWindow(Mode::Orbit);
  if (this->Options.FineReference)
  {
    this->Perform(ViewerAction::ToggleFineReference);
  }
  // Frame 0 smooths too (the caches stay), so every frame's time is one run:
  // the fine reference's render above has already smoothed this view.
  this->Filter->Modified();
  this->SmoothMapper->GetSmoothingFilter()->Modified();
  const int frames = this->Options.Frames;
  const double step = this->Options.OrbitDegrees / frames;
  vtkCamera* camera = this->MainRenderer->GetActiveCamera();
  VtkErrorLog& errors = VtkErrorLog::Instance();
  if (!this->Options.Json)
  {
    std::printf("%5s %9s %8s %8s %10s %8s %10s %10s%s\n", "frame", "azimuth", "input", "output",
      "silhouette", "new", "filter_ms", "render_ms", record ? "  image" : "");
  }
  for (int frame = 0; frame < frames; ++frame)
  {
    if (frame > 0)
    {
      camera->Azimuth(step);
    }
    errors.Clear();
    this->Window->Render();
    errors.ThrowIfErrors("rendering frame " + std::to_string(frame) + " failed");
    const ViewerFigures figures = this->CurrentFigures();
    // + 0.0: frame 0 of a negative step is -0 ("-0.00" printed).
    const double azimuth = frame * step + 0.0;
    std::string image;
    if (record)
    {
      char name[32];
      std::snprintf(name, sizeof(name), "frame_%04d.png", frame);
      image = JoinPath(this->Options.RecordDirectory, name);
      WriteWindowPng(this->Window, image);
    }
    if (this->Options.Json)
    {
      std::cout << "{\"frame\": " << frame << ", \"azimuth\": " << JsonNumber(azimuth)
                << ", \"input_triangles\": " << figures.InputTriangles
                << ", \"output_triangles\": " << figures.OutputTriangles
                << ", \"silhouette_triangles\": " << figures.SilhouetteTriangles
                << ", \"new_triangles\": " << figures.NewTriangles
                << ", \"filter_ms\": " << JsonNumber(figures.FilterMilliseconds)
                << ", \"render_ms\": " << JsonNumber(figures.RenderMilliseconds)
                << ", \"image\": " << (record ? JsonString(image) : "null") << "}\n";
    }
    else
    {
      std::printf("%5d %9.2f %8lld %8lld %10lld %8lld %10.3f %10.3f%s%s\n", frame, azimuth,
        static_cast<long long>(figures.InputTriangles),
        static_cast<long long>(figures.OutputTriangles),
        static_cast<long long>(figures.SilhouetteTriangles),
        static_cast<long long>(figures.NewTriangles), figures.FilterMilliseconds,
        figures.RenderMilliseconds, record ? "  " : "", image.c_str());
    }
    std::cout.flush();
  }
}

void Viewer::Play()
{
  const std::string& log = this->Options.PlayLog;
  if (!std::filesystem::is_regular_file(log))
  {
    throw RuntimeError("cannot read the event log '" + log + "'");
  }
  CreateDirectory(this->Options.ScreenshotDirectory);
  this->BuildWindow(Mode::Playback);
  if (this->Slider)
  {
    this->Slider->EnabledOn();
  }
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  this->Interactor->Initialize(); // renders the first frame
  if (this->Options.FineReference)
  {
    this->Perform(ViewerAction::ToggleFineReference);
  }
  this->Window->Render();
  errors.ThrowIfErrors("rendering failed");
  this->ReportStep("start");

  vtkNew<vtkInteractorEventRecorder> recorder;
  errors.Watch(recorder);
  recorder->KeyPressActivationOff();
  recorder->SetInteractor(this->Interactor);
  recorder->SetFileName(log.c_str());
  recorder->Play();
  recorder->Off();
  errors.ThrowIfErrors("playing '" + log + "' failed");
}

void RunView(const ViewOptions& options)
{
  Viewer viewer(options); // a bad file fails here, before any window
  const bool interactive = options.PlayLog.empty() && !options.Orbit;
  const char* display = std::getenv("DISPLAY");
  if ((interactive || ActiveRenderBackend() == RenderBackend::X) && (!display || !*display))
  {
    throw RuntimeError("view needs an X display and DISPLAY is not set; run it under "
                       "'xvfb-run -a' (offscreen with --orbit or --play)");
  }
  // VTK's X window crashes when the server named does not answer or refuses
  // the connection; the probe is the same (cached) one the back-end used.
  if ((interactive || ActiveRenderBackend() == RenderBackend::X) && !HaveXDisplay())
  {
    throw RuntimeError(std::string("view needs an X display, and DISPLAY ('") + display +
      "') does not answer or refuses the connection; run it under 'xvfb-run -a' (offscreen with "
      "--orbit or "
      "--play)");
  }
  if (!options.PlayLog.empty())
  {
    viewer.Play();
  }
  else if (options.Orbit)
  {
    viewer.RecordOrbit();
  }
  else
  {
    viewer.Interact();
  }
}

} // namespace cli
