// `silhouette view`: the interactive viewer of vtkSilhouetteSmoothingFilter,
// its headless orbit (numbered PNGs and per-frame figures) and the playback
// of recorded interaction (vtkInteractorEventRecorder) used by its test.
#ifndef Viewer_h
#define Viewer_h

#include "CommandLine.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <chrono>
#include <deque>
#include <string>

class vtkCamera;
class vtkInteractorStyle;
class vtkObject;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderWindowInteractor;
class vtkRenderer;
class vtkSilhouetteSmoothingFilter;
class vtkSilhouetteSmoothingMapper;
class vtkSliderRepresentation2D;
class vtkSliderWidget;
class vtkTextActor;
class vtkViewDependentLevelOfDetail;

namespace cli
{

/// What the viewer's keys do.
enum class ViewerAction
{
  ToggleHelp,
  ToggleSmoothing,
  ToggleWireframe,
  ToggleNewGeometry,
  ToggleLines,
  ToggleFineReference,
  ToleranceUp,
  ToleranceDown,
  ToggleProjection,
  ResetCamera,
  Screenshot,
  Quit
};

/// The keys and the mouse, one per line, as the help overlay and
/// 'silhouette view --help' show them.
std::string ViewerKeysHelp();

/// The action of a key (the interactor's key code and key symbol), if any.
bool ViewerActionOfKey(char keyCode, const std::string& keySym, ViewerAction& action);

/// What one rendered frame shows and cost.
struct ViewerFigures
{
  vtkIdType InputTriangles = 0;
  vtkIdType OutputTriangles = 0;     ///< the input's with smoothing off
  vtkIdType SilhouetteTriangles = 0; ///< 0 with smoothing off (the filter does not run)
  vtkIdType NewTriangles = 0;        ///< 0 with smoothing off
  /// Silhouette triangles the mapper left as they are, their smoothing below
  /// the tolerance (not in SilhouetteTriangles; 0 in the filter's styles).
  vtkIdType SubpixelTriangles = 0;
  /// Crease segments the mapper drew by their chords, below the tolerance.
  vtkIdType SubpixelFeatureSegments = 0;
  /// The filter's run for this frame (0 if it did not run); in the shaded
  /// style, the mapper's smoothing before it drew the frame.
  double FilterMilliseconds = 0.0;
  double RenderMilliseconds = 0.0; ///< vtkRenderer::GetLastRenderTimeInSeconds of the main view
};

/**
 * The viewer: the mesh, the filter fed by the main renderer (so the pipeline
 * re-runs it whenever the view changes), the actors of the current style, an
 * optional second viewport with the fine reference sharing the camera, and
 * an overlay layer with the status text, the key help and the tolerance
 * slider. Toggles rebuild the actors once; camera moves rebuild nothing.
 */
class Viewer
{
public:
  /// Reads or makes the mesh and runs the filter once; throws RuntimeError
  /// with one line for a bad file or a mesh the filter refuses. Opens nothing.
  explicit Viewer(const ViewOptions& options);
  ~Viewer();

  /// Opens the window and runs the event loop until q or e.
  void Interact();
  /// Renders the --orbit offscreen, writing frames and printing figures.
  void RecordOrbit();
  /// Plays the --play event log offscreen, a screenshot and figures after each step.
  void Play();

private:
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // The slider's range; the keys double and halve the tolerance within it.
  static constexpr double MinimumSliderTolerance = 0.1;
  static constexpr double MaximumSliderTolerance = 5.0;

  enum class Mode
  {
    Interactive,
    Orbit,
    Playback
  };

  void LoadMesh();
  void BuildWindow(Mode mode);
  void BuildOverlay(bool withWidget);
  void SetUpTheCamera();
  void ApplyLayout();
  void RebuildActors();
  void AddMainActors();
  bool MakeFineReference();
  void Perform(ViewerAction action);
  void SetTolerance(double tolerance);
  void ToggleProjection();
  std::string WriteScreenshot(const std::string& path);
  std::string NextScreenshotPath() const;
  void ReportStep(const std::string& action);

  // Observers.
  void OnViewRenderStart(vtkObject* renderer, unsigned long, void*);
  void OnMainRenderEnd();
  void OnOverlayRenderStart();
  void OnFilterStart();
  void OnFilterEnd();
  void OnSliderMoved();
  void OnSliderReleased();

  ViewerFigures CurrentFigures() const;
  std::string StatusText() const;
  std::string StyleName() const;
  double FramesPerSecond() const;

  ViewOptions Options;
  Mode RunMode = Mode::Interactive;
  std::string MeshName;
  vtkSmartPointer<vtkPolyData> Mesh; ///< what is shown and smoothed
  /// --lod: refines the loaded mesh for the main view before every render;
  /// Mesh is then its output (one object, updated in place).
  vtkSmartPointer<vtkViewDependentLevelOfDetail> Lod;
  vtkSmartPointer<vtkPolyData> Loaded;   ///< the mesh as loaded (the LOD's input)
  vtkSmartPointer<vtkPolyData> Original; ///< what the fine reference refines
  vtkSmartPointer<vtkPolyData> Fine;     ///< made the first time it is shown
  vtkIdType InputTriangles = 0;

  vtkSmartPointer<vtkSilhouetteSmoothingFilter> Filter;
  /// The shaded style smoothed draws through the render-time mapper (the
  /// other styles need the filter's geometry: the new triangles, the lines).
  vtkSmartPointer<vtkSilhouetteSmoothingMapper> SmoothMapper;
  bool UsesMapper() const;
  vtkSmartPointer<vtkSilhouetteSmoothingFilter> FineNormals; ///< the fine mesh's shading normals
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> MainRenderer;
  vtkSmartPointer<vtkRenderer> FineRenderer;
  vtkSmartPointer<vtkRenderer> OverlayRenderer;
  vtkSmartPointer<vtkRenderWindowInteractor> Interactor;
  vtkSmartPointer<vtkInteractorStyle> Style;
  vtkSmartPointer<vtkSliderRepresentation2D> SliderRepresentation;
  vtkSmartPointer<vtkSliderWidget> Slider;
  vtkSmartPointer<vtkTextActor> Status;
  vtkSmartPointer<vtkTextActor> Help;
  vtkSmartPointer<vtkTextActor> FineLabel;

  RenderStyle CurrentStyle = RenderStyle::Shaded;
  bool Smoothing = true;
  bool ShowFine = false;
  bool ShowHelp = false;
  bool CameraSetUp = false; ///< later resets keep the projection the user chose
  std::string Message;      ///< one transient line: a screenshot written, a failure

  using Clock = std::chrono::steady_clock;
  std::deque<Clock::time_point> FrameEnds; ///< ends of the last renders of the main view
  Clock::time_point FilterStarted;
  double LastFilterMilliseconds = 0.0;
  long FilterRuns = 0;
  long FilterRunsAtLastFrame = 0;
  bool FilterRanInLastFrame = false;
  int Step = 0; ///< playback steps reported so far
};

/// `silhouette view`: the viewer, its headless orbit or its playback.
void RunView(const ViewOptions& options);

} // namespace cli

#endif
