#ifndef CommandLine_h
#define CommandLine_h

#include "CameraOptions.h"
#include "Compare.h"
#include "Figure.h"
#include "Generate.h"
#include "RenderingBackend.h"
#include "Simplify.h"

#include <optional>
#include <string>

namespace cli
{

enum class RenderStyle
{
  Shaded,
  Wireframe,
  NewGeometry,
  Lines,
  // Stylized strokes of the silhouette (Kim and Choe's brush functions).
  Charcoal,
  Lazy,
  Hand,
  Rough
};

const char* NameOf(RenderStyle style);

struct SmoothOptions
{
  std::string Input;
  std::optional<std::string> Output;
  std::optional<std::string> LinesOutput; ///< the silhouette polylines (.vtp)
  bool Json = false;
  CameraOptions Camera;
};

struct RenderOptions
{
  std::string Input;
  std::string Output;
  std::optional<std::string> LinesOutput; ///< the silhouette polylines (.vtp)
  RenderStyle Style = RenderStyle::Shaded;
  bool NoSmoothing = false;
  bool HiddenLines = false;  ///< --hidden dashed: the hidden parts too (grey; dashed in drawings)
  bool WidthByDepth = false; ///< SVG or PDF: lines thinner away from the eye
  bool JoinLines = false;    ///< SVG or PDF: lines that meet end to end joined into one path
  bool Lod = false;          ///< refine the input for the view first (LevelOfDetail.h)
  /// --progressive N: N drawings along the progressive mesh into the folder
  /// Output (0: one drawing), as PNG images, or with --svg or --pdf as
  /// those drawings ("png", "svg" or "pdf").
  int ProgressiveLevels = 0;
  std::string ProgressiveFormat = "png";
  bool Json = false;
  CameraOptions Camera;
  /// The command line as given ("silhouette render ...", words quoted as a
  /// shell would need): a drawing's title.
  std::string CommandText;
};

/// `silhouette view`: the interactive viewer, its headless orbit and its
/// recorded-interaction playback (see ViewHelp in CommandLine.cxx).
struct ViewOptions
{
  std::string Input; ///< a model of the set or a mesh file; empty: the bundled coarse bunny
  RenderStyle Style = RenderStyle::Shaded;
  bool NoSmoothing = false;
  bool FineReference = false; ///< start with the side-by-side fine reference
  bool HelpOverlay = false;   ///< start with the key help shown
  bool NoOverlay = false;     ///< no text overlays and no slider
  bool NoTimes = false;       ///< leave the times out of the overlay (repeatable images)
  bool Lod = false;           ///< refine the mesh for every view first (LevelOfDetail.h)
  int FineLevel = 3;
  int CoarseTriangles = 0;   ///< 0: the model's default
  std::string DataDirectory; ///< where bunny.ply is; empty: the built-in default
  std::string ScreenshotDirectory = ".";
  bool Orbit = false; ///< headless: render an orbit offscreen and print per-frame figures
  double OrbitDegrees = 360.0;
  int Frames = 36;
  std::string RecordDirectory; ///< where the orbit's frames go; empty: none written
  std::string PlayLog;         ///< a vtkInteractorEventRecorder log to play offscreen
  bool Json = false;
  CameraOptions Camera;
};

class ArgumentList;
struct CommandLine;

/// Whether a command renders: it picks its back-end before any VTK window
/// exists, an on-screen one for an interactive window.
enum class Rendering
{
  None,
  Offscreen,
  Window
};

/// One command of the program. The table in CommandLine.cxx lists them all;
/// nothing else names them.
struct Command
{
  const char* Name;
  std::string (*Help)();
  /// Parses the command's arguments into its options in `into`; throws
  /// UsageError.
  void (*Parse)(const std::string& name, ArgumentList& arguments, CommandLine& into);
  void (*Run)(const CommandLine& commandLine);
  Rendering (*Renders)(const CommandLine& commandLine);
};

/// What the command line asks for.
struct CommandLine
{
  const Command* Selected = nullptr; ///< null: print HelpText and exit 0
  std::string HelpText;
  SmoothOptions Smooth;
  RenderOptions Render;
  GenerateOptions Generate;
  CompareOptions Compare;
  FigureOptions Figure;
  ViewOptions View;
  SimplifyOptions Simplify;
  /// --backend of the commands that render (render, compare, figure, view).
  RenderBackend Backend = RenderBackend::Auto;
};

/// Parses argv; throws UsageError for anything it cannot make sense of.
CommandLine ParseCommandLine(int argc, char* argv[]);

} // namespace cli

#endif
