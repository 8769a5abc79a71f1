#include "Viewer.h"

#include "CliErrors.h"
#include "DataFolder.h"
#include "Figures.h"
#include "MeshIO.h"
#include "ModelInput.h"
#include "Rendering.h"
#include "RenderingBackend.h"
#include "Smoothing.h"
#include "TextFormat.h"
#include "VtkErrorLog.h"

#include "EvaluationModels.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSilhouetteSmoothingFilter.h>
#include <vtkSilhouetteSmoothingMapper.h>
#include <vtkSliderRepresentation2D.h>
#include <vtkSliderWidget.h>
#include <vtkTextActor.h>
#include <vtkViewDependentLevelOfDetail.h>

#include <algorithm>
#include <cctype>
#include <chrono>
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
namespace
{

// Frames per second are averaged over this many intervals between renders.
constexpr std::size_t MeasuredIntervals = 20;
// A longer pause between two renders is idling, not a slow frame.
constexpr double IdleGapSeconds = 1.0;

// The colours of the new-geometry style, as Rendering.cxx draws it.

struct KeyBinding
{
  const char* Keys;
  const char* Meaning;
};

// The one list the overlay and --help show; short, as the overlay must fit.
constexpr KeyBinding KeyBindings[] = {
  { "h", "this help on / off" },
  { "s", "smoothing on / off" },
  { "w", "wireframe on / off" },
  { "n", "new geometry in red on / off" },
  { "l", "silhouette lines only (pen and ink) on / off" },
  { "f", "side-by-side fine reference on / off" },
  { "+ -", "tolerance x2, /2 (also = _)" },
  { "p", "parallel / perspective" },
  { "r", "frame the mesh again (farther back with f on)" },
  { "c", "screenshot (PNG)" },
  { "q e", "quit" },
  { "drag", "rotate; with shift: pan; with ctrl: spin" },
  { "wheel", "zoom (also right drag)" },
};

// The trackball camera with only the viewer's keys: VTK's own (w/s
// wireframe/surface, 3 stereo, f fly-to, p pick, j/t joystick...) would
// change actors behind the viewer's back.
class ViewerInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static ViewerInteractorStyle* New();
  vtkTypeMacro(ViewerInteractorStyle, vtkInteractorStyleTrackballCamera);

  std::function<void(ViewerAction)> Act;

  void OnChar() override
  {
    vtkRenderWindowInteractor* interactor = this->Interactor;
    const char* keySym = interactor->GetKeySym();
    ViewerAction action;
    if (this->Act && ViewerActionOfKey(interactor->GetKeyCode(), keySym ? keySym : "", action))
    {
      this->Act(action);
    }
  }
};
vtkStandardNewMacro(ViewerInteractorStyle);

} // namespace

std::string ViewerKeysHelp()
{
  std::string text;
  for (const KeyBinding& binding : KeyBindings)
  {
    char line[32];
    std::snprintf(line, sizeof(line), "  %-6s ", binding.Keys);
    text += line;
    text += binding.Meaning;
    text += "\n";
  }
  return text;
}

bool ViewerActionOfKey(char keyCode, const std::string& keySym, ViewerAction& action)
{
  if (keySym == "KP_Add")
  {
    action = ViewerAction::ToleranceUp;
    return true;
  }
  if (keySym == "KP_Subtract")
  {
    action = ViewerAction::ToleranceDown;
    return true;
  }
  switch (std::tolower(static_cast<unsigned char>(keyCode)))
  {
    case 'h':
      action = ViewerAction::ToggleHelp;
      return true;
    case 's':
      action = ViewerAction::ToggleSmoothing;
      return true;
    case 'w':
      action = ViewerAction::ToggleWireframe;
      return true;
    case 'n':
      action = ViewerAction::ToggleNewGeometry;
      return true;
    case 'l':
      action = ViewerAction::ToggleLines;
      return true;
    case 'f':
      action = ViewerAction::ToggleFineReference;
      return true;
    case '+':
    case '=':
      action = ViewerAction::ToleranceUp;
      return true;
    case '-':
    case '_':
      action = ViewerAction::ToleranceDown;
      return true;
    case 'p':
      action = ViewerAction::ToggleProjection;
      return true;
    case 'r':
      action = ViewerAction::ResetCamera;
      return true;
    case 'c':
      action = ViewerAction::Screenshot;
      return true;
    case 'q':
    case 'e':
      action = ViewerAction::Quit;
      return true;
    default:
      return false;
  }
}

Viewer::Viewer(const ViewOptions& options)
  : Options(options)
  , CurrentStyle(options.Style)
  , Smoothing(!options.NoSmoothing)
  , ShowHelp(options.HelpOverlay)
{
  this->LoadMesh();
}

Viewer::~Viewer()
{
  if (this->Slider)
  {
    this->Slider->EnabledOff();
  }
}

void Viewer::LoadMesh()
{
  const std::string dataDirectory =
    this->Options.DataDirectory.empty() ? DefaultDataDirectory() : this->Options.DataDirectory;
  const std::string& input = this->Options.Input;
  if (input.empty() || !silhouette_eval::IsModelName(input))
  {
    const std::string path = input.empty() ? JoinPath(dataDirectory, "bunny_coarse.ply") : input;
    RequireModelOrFile(path);
    this->Mesh = ReadMesh(path);
    this->Original = this->Mesh;
    this->MeshName = std::filesystem::path(path).filename().string();
    if (CountTriangles(this->Mesh) == 0)
    {
      throw RuntimeError(path + " has no triangles");
    }
  }
  else
  {
    this->Mesh = CoarseModel(input, dataDirectory, this->Options.CoarseTriangles, &this->Original);
    this->MeshName = input + " (coarse)";
  }
  this->InputTriangles = CountTriangles(this->Mesh);
  this->Loaded = this->Mesh;
  if (this->Options.Lod)
  {
    this->Lod = vtkSmartPointer<vtkViewDependentLevelOfDetail>::New();
    VtkErrorLog::Instance().Watch(this->Lod);
    this->Lod->SetInputData(this->Loaded);
    const auto& size = this->Options.Camera.ViewportSize;
    this->Lod->SetViewportSize(size[0], size[1]);
    this->Mesh = this->Lod->GetOutput(); // filled before the first render (BuildWindow)
  }
}

void Viewer::BuildWindow(Mode mode)
{
  this->RunMode = mode;
  const auto& size = this->Options.Camera.ViewportSize;
  this->Window = vtkSmartPointer<vtkRenderWindow>::New();
  this->Window->SetSize(size[0], size[1]);
  this->Window->SetMultiSamples(0); // repeatable images, and quick on software OpenGL
  this->Window->SetOffScreenRendering(mode == Mode::Interactive ? 0 : 1);
  this->Window->SetWindowName(("silhouette view: " + this->MeshName).c_str());
  this->Window->SetNumberOfLayers(2);

  this->MainRenderer = vtkSmartPointer<vtkRenderer>::New();
  this->MainRenderer->SetBackground(White[0], White[1], White[2]);
  this->Window->AddRenderer(this->MainRenderer);
  this->FineRenderer = vtkSmartPointer<vtkRenderer>::New();
  this->FineRenderer->SetBackground(White[0], White[1], White[2]);
  this->FineRenderer->SetActiveCamera(this->MainRenderer->GetActiveCamera());
  this->OverlayRenderer = vtkSmartPointer<vtkRenderer>::New();
  this->OverlayRenderer->SetLayer(1);
  this->OverlayRenderer->InteractiveOff(); // the camera style acts on the views under it
  this->Window->AddRenderer(this->OverlayRenderer);

  // Clip on what is drawn (the smoothed outline bulges past the input), in
  // each view, as the camera is shared.
  this->MainRenderer->AddObserver(vtkCommand::StartEvent, this, &Viewer::OnViewRenderStart);
  this->FineRenderer->AddObserver(vtkCommand::StartEvent, this, &Viewer::OnViewRenderStart);
  this->MainRenderer->AddObserver(vtkCommand::EndEvent, this, &Viewer::OnMainRenderEnd);
  this->OverlayRenderer->AddObserver(vtkCommand::StartEvent, this, &Viewer::OnOverlayRenderStart);

  this->Filter = vtkSmartPointer<vtkSilhouetteSmoothingFilter>::New();
  VtkErrorLog::Instance().Watch(this->Filter);
  this->Filter->SetInputData(this->Mesh);
  this->Filter->SetRenderer(this->MainRenderer);
  ApplySmoothingOptions(this->Filter, this->Options.Camera);
  this->Filter->AddObserver(vtkCommand::StartEvent, this, &Viewer::OnFilterStart);
  this->Filter->AddObserver(vtkCommand::EndEvent, this, &Viewer::OnFilterEnd);
  this->SmoothMapper = vtkSmartPointer<vtkSilhouetteSmoothingMapper>::New();
  this->SmoothMapper->SetInputData(this->Mesh);
  this->SmoothMapper->ScalarVisibilityOff();
  ApplySmoothingOptions(this->SmoothMapper->GetSmoothingFilter(), this->Options.Camera);
  VtkErrorLog::Instance().Watch(this->SmoothMapper->GetSmoothingFilter());

  this->ShowFine = false;
  this->ApplyLayout();
  this->SetUpTheCamera();
  // The unsmoothed styles take the filter's shading normals, and a mesh the
  // filter refuses (NaN points) should fail before any window opens.
  VtkErrorLog::Instance().Clear();
  if (this->Lod)
  {
    // The hierarchy takes a while on a large mesh (about 30 s at 940k
    // triangles), before any window shows: say so, and what it took.
    std::cerr << "view: building the level-of-detail hierarchy of "
              << Grouped(CountTriangles(this->Loaded)) << " triangles..." << std::endl;
    const auto started = std::chrono::steady_clock::now();
    this->Lod->SetRenderer(this->MainRenderer);
    this->Lod->Update();
    VtkErrorLog::Instance().ThrowIfErrors("the level of detail failed");
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - started;
    std::cerr << "view: level of detail: " << Grouped(CountTriangles(this->Lod->GetOutput()))
              << " triangles for this view (" << static_cast<long long>(took.count() * 1000.0 + 0.5)
              << " ms)" << std::endl;
  }
  this->Filter->Update();
  VtkErrorLog::Instance().ThrowIfErrors("smoothing failed");
  for (const std::string& warning : VtkErrorLog::Instance().Warnings())
  {
    PrintFilterWarning(warning); // about the input: once, as smooth and render say them
  }
  this->FilterRunsAtLastFrame = this->FilterRuns; // that run belongs to no frame

  if (mode == Mode::Interactive || mode == Mode::Playback)
  {
    if (mode == Mode::Interactive)
    {
      this->Interactor = vtkSmartPointer<vtkRenderWindowInteractor>::New();
    }
    else
    {
      // Events come from the log only; nothing waits on the X server.
      this->Interactor = vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
    }
    this->Interactor->SetRenderWindow(this->Window);
    auto style = vtkSmartPointer<ViewerInteractorStyle>::New();
    style->Act = [this](ViewerAction action) {
      this->Perform(action);
    };
    this->Style = style;
    this->Interactor->SetInteractorStyle(style);
  }
  if (!this->Options.NoOverlay)
  {
    this->BuildOverlay(this->Interactor != nullptr);
  }
  this->RebuildActors();
}

void Viewer::SetUpTheCamera()
{
  CameraOptions camera = this->Options.Camera;
  if (this->CameraSetUp)
  {
    camera.Parallel = this->MainRenderer->GetActiveCamera()->GetParallelProjection() != 0;
  }
  if (!this->CameraSetUp)
  {
    WarnIfTooSmallOrLargeToDraw(this->Loaded->GetBounds());
  }
  SetUpCamera(this->MainRenderer, this->Loaded->GetBounds(), camera);
  this->CameraSetUp = true;
}

void Viewer::ApplyLayout()
{
  if (this->ShowFine)
  {
    this->MainRenderer->SetViewport(0.0, 0.0, 0.5, 1.0);
    this->FineRenderer->SetViewport(0.5, 0.0, 1.0, 1.0);
    if (!this->Window->HasRenderer(this->FineRenderer))
    {
      this->Window->AddRenderer(this->FineRenderer);
    }
  }
  else
  {
    this->MainRenderer->SetViewport(0.0, 0.0, 1.0, 1.0);
    this->Window->RemoveRenderer(this->FineRenderer);
  }
}

void Viewer::RebuildActors()
{
  this->MainRenderer->RemoveAllViewProps();
  this->AddMainActors();
  this->FineRenderer->RemoveAllViewProps();
  if (this->ShowFine && this->Fine)
  {
    // The fine mesh drawn as the reference for the style: its outline for
    // the lines, shaded otherwise (its edges would be a black mass).
    const RenderStyle fineStyle =
      this->CurrentStyle == RenderStyle::Lines ? RenderStyle::Lines : RenderStyle::Shaded;
    AddStyleActors(this->FineRenderer, this->FineNormals, this->Fine, fineStyle, false);
  }
  if (this->FineLabel)
  {
    this->OverlayRenderer->RemoveViewProp(this->FineLabel);
    if (this->ShowFine && this->Fine)
    {
      const std::string label = std::string("fine reference\n") +
        (this->CurrentStyle == RenderStyle::Lines ? "face-based silhouette of " : "") +
        "Loop level " + std::to_string(this->Options.FineLevel) + ", " +
        Grouped(this->Fine->GetNumberOfPolys()) + " triangles";
      this->FineLabel->SetInput(label.c_str());
      this->OverlayRenderer->AddViewProp(this->FineLabel);
    }
  }
}

bool Viewer::UsesMapper() const
{
  return this->Smoothing && this->CurrentStyle == RenderStyle::Shaded;
}

void Viewer::AddMainActors()
{
  // Smoothed, the shaded style draws through the render-time mapper (the
  // mesh is uploaded once, a frame costs the silhouette), and the other
  // styles are fed by the filter's ports: the pipeline re-runs it when the
  // view changes. Unsmoothed, they show the input.
  AddStyleActors(this->MainRenderer, this->Filter, this->Mesh, this->CurrentStyle, this->Smoothing,
    false, this->UsesMapper() ? this->SmoothMapper.Get() : nullptr);
}

bool Viewer::MakeFineReference()
{
  if (this->Fine)
  {
    return true;
  }
  this->Message = "computing the fine reference (Loop level " +
    std::to_string(this->Options.FineLevel) + " of " + Grouped(CountTriangles(this->Original)) +
    " triangles), a moment...";
  this->Window->Render(); // show the message before the wait
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  try
  {
    // Merged first, as compare and figure do: Loop refinement joins
    // triangles by point ids, and a file's seams and hard edges would leave
    // each piece refined apart, faceted (the Wuson OBJ's reference was).
    this->Fine = silhouette_eval::Refine(
      silhouette_eval::WeldedTriangles(this->Original), this->Options.FineLevel);
    errors.ThrowIfErrors("Loop refinement failed");
  }
  catch (const std::exception& error)
  {
    this->Fine = nullptr;
    this->Message = std::string("no fine reference: ") + error.what();
    return false;
  }
  this->FineNormals = vtkSmartPointer<vtkSilhouetteSmoothingFilter>::New();
  this->FineNormals->SetInputData(this->Fine);
  this->FineNormals->SetCamera(this->MainRenderer->GetActiveCamera());
  this->FineNormals->Update();
  this->Message.clear();
  return true;
}

void Viewer::SetTolerance(double tolerance)
{
  this->Filter->SetTolerance(tolerance);
  this->SmoothMapper->GetSmoothingFilter()->SetTolerance(tolerance);
  if (this->SliderRepresentation)
  {
    this->SliderRepresentation->SetValue(tolerance);
  }
}

void Viewer::ToggleProjection()
{
  vtkCamera* camera = this->MainRenderer->GetActiveCamera();
  if (!camera->GetParallelProjection())
  {
    // Keep the size of what is at the focal point.
    camera->SetParallelScale(
      camera->GetDistance() * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle() / 2.0)));
  }
  camera->SetParallelProjection(!camera->GetParallelProjection());
}

void Viewer::Perform(ViewerAction action)
{
  std::string name;
  const auto toggleStyle = [this](RenderStyle style) {
    this->CurrentStyle = this->CurrentStyle == style ? RenderStyle::Shaded : style;
    this->RebuildActors();
    return std::string(this->StyleName());
  };
  this->Message.clear();
  try
  {
    switch (action)
    {
      case ViewerAction::ToggleHelp:
        this->ShowHelp = !this->ShowHelp;
        if (this->Help)
        {
          this->Help->SetVisibility(this->ShowHelp);
        }
        name = std::string("help-") + OnOff(this->ShowHelp);
        break;
      case ViewerAction::ToggleSmoothing:
        this->Smoothing = !this->Smoothing;
        this->RebuildActors();
        name = std::string("smoothing-") + OnOff(this->Smoothing);
        break;
      case ViewerAction::ToggleWireframe:
        name = toggleStyle(RenderStyle::Wireframe);
        break;
      case ViewerAction::ToggleNewGeometry:
        name = toggleStyle(RenderStyle::NewGeometry);
        break;
      case ViewerAction::ToggleLines:
        name = toggleStyle(RenderStyle::Lines);
        break;
      case ViewerAction::ToggleFineReference:
        if (this->ShowFine || this->MakeFineReference())
        {
          this->ShowFine = !this->ShowFine;
          this->ApplyLayout();
          this->RebuildActors();
        }
        name = std::string("fine-reference-") + OnOff(this->ShowFine);
        break;
      case ViewerAction::ToleranceUp:
      case ViewerAction::ToleranceDown:
      {
        const double factor = action == ViewerAction::ToleranceUp ? 2.0 : 0.5;
        this->SetTolerance(std::clamp(
          this->Filter->GetTolerance() * factor, MinimumSliderTolerance, MaximumSliderTolerance));
        name = action == ViewerAction::ToleranceUp ? "tolerance-up" : "tolerance-down";
        break;
      }
      case ViewerAction::ToggleProjection:
        this->ToggleProjection();
        name = this->MainRenderer->GetActiveCamera()->GetParallelProjection() ? "parallel"
                                                                              : "perspective";
        break;
      case ViewerAction::ResetCamera:
        this->SetUpTheCamera();
        name = "reset-camera";
        break;
      case ViewerAction::Screenshot:
      {
        const std::string path = this->NextScreenshotPath();
        this->Window->Render();
        this->Message = "screenshot written: " + this->WriteScreenshot(path);
        std::cout << "wrote " << path << std::endl;
        name = "screenshot";
        break;
      }
      case ViewerAction::Quit:
        if (this->Interactor)
        {
          this->Interactor->ExitCallback();
        }
        return;
    }
  }
  catch (const std::exception& error)
  {
    this->Message = error.what();
    name = "failed";
  }
  this->Window->Render();
  if (this->RunMode == Mode::Playback)
  {
    this->ReportStep(name);
  }
}

std::string Viewer::WriteScreenshot(const std::string& path)
{
  CreateDirectory(this->Options.ScreenshotDirectory);
  WriteWindowPng(this->Window, path);
  return path;
}

std::string Viewer::NextScreenshotPath() const
{
  for (int number = 1;; ++number)
  {
    char name[64];
    std::snprintf(name, sizeof(name), "silhouette_view_%04d.png", number);
    const std::string path = JoinPath(this->Options.ScreenshotDirectory, name);
    if (!std::filesystem::exists(path))
    {
      return path;
    }
  }
}

void Viewer::OnViewRenderStart(vtkObject* renderer, unsigned long, void*)
{
  if (this->Lod && renderer == this->MainRenderer.GetPointer())
  {
    this->Lod->Update(); // the mesh for this view, before anything draws it
  }
  static_cast<vtkRenderer*>(renderer)->ResetCameraClippingRange();
}

void Viewer::OnMainRenderEnd()
{
  const Clock::time_point now = Clock::now();
  if (!this->FrameEnds.empty() &&
    std::chrono::duration<double>(now - this->FrameEnds.back()).count() > IdleGapSeconds)
  {
    this->FrameEnds.clear();
  }
  this->FrameEnds.push_back(now);
  while (this->FrameEnds.size() > MeasuredIntervals + 1)
  {
    this->FrameEnds.pop_front();
  }
  this->FilterRanInLastFrame = this->FilterRuns != this->FilterRunsAtLastFrame;
  this->FilterRunsAtLastFrame = this->FilterRuns;
}

void Viewer::OnFilterStart()
{
  this->FilterStarted = Clock::now();
}

void Viewer::OnFilterEnd()
{
  this->LastFilterMilliseconds =
    std::chrono::duration<double, std::milli>(Clock::now() - this->FilterStarted).count();
  ++this->FilterRuns;
}

} // namespace cli
