#ifndef CommandLine_h
#define CommandLine_h

#include "CameraOptions.h"
#include "Compare.h"
#include "Figure.h"
#include "Generate.h"

#include <optional>
#include <string>

namespace cli
{

enum class RenderStyle
{
  Shaded,
  Wireframe,
  NewGeometry,
  Lines
};
const char* NameOf(RenderStyle style);

struct SmoothOptions
{
  std::string Input;
  std::optional<std::string> Output;
  bool Json = false;
  CameraOptions Camera;
};

struct RenderOptions
{
  std::string Input;
  std::string Output;
  RenderStyle Style = RenderStyle::Shaded;
  bool NoSmoothing = false;
  bool Json = false;
  CameraOptions Camera;
};

/// What the command line asks for.
struct CommandLine
{
  enum class Action
  {
    ShowHelp, ///< print HelpText and exit 0
    Smooth,
    Render,
    Generate,
    Compare,
    Figure
  };
  Action What = Action::ShowHelp;
  std::string HelpText;
  SmoothOptions Smooth;
  RenderOptions Render;
  GenerateOptions Generate;
  CompareOptions Compare;
  FigureOptions Figure;
};

/// Parses argv; throws UsageError for anything it cannot make sense of.
CommandLine ParseCommandLine(int argc, char* argv[]);

} // namespace cli

#endif
