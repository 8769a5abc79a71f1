#include "CommandLine.h"

#include "EvaluationModels.h"

#include "ArgumentList.h"
#include "CliErrors.h"
#include "CommandHelp.h"
#include "Commands.h"
#include "Compare.h"
#include "Figure.h"
#include "Generate.h"
#include "MeshIO.h"
#include "Simplify.h"
#include "Smoothing.h"
#include "Viewer.h"

#include <cmath>
#include <vector>

namespace cli
{
namespace
{

bool IsHelpWord(const std::string& word)
{
  return word == "--help" || word == "-h";
}

std::optional<RenderStyle> ParseRenderStyle(const std::string& name)
{
  for (RenderStyle style :
    { RenderStyle::Shaded, RenderStyle::Wireframe, RenderStyle::NewGeometry, RenderStyle::Lines,
      RenderStyle::Charcoal, RenderStyle::Lazy, RenderStyle::Hand, RenderStyle::Rough })
  {
    if (name == NameOf(style))
    {
      return style;
    }
  }
  return std::nullopt;
}

// The value of --style; a usage error names the styles.
RenderStyle TakeRenderStyle(const Option& option, ArgumentList& arguments)
{
  const std::string name = arguments.TakeValue(option);
  const std::optional<RenderStyle> style = ParseRenderStyle(name);
  if (!style)
  {
    throw UsageError("option '--style' needs shaded, wireframe, new-geometry, lines, charcoal, "
                     "lazy, hand or rough, got '" +
      name + "'");
  }
  return *style;
}

ViewOptions ParseView(ArgumentList& arguments, RenderBackend& backend)
{
  ViewOptions options;
  bool onlyOperands = false; // after "--"
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!onlyOperands && word == "--")
    {
      onlyOperands = true;
      continue;
    }
    if (onlyOperands || !LooksLikeOption(word))
    {
      if (!options.Input.empty())
      {
        throw UsageError(
          "unexpected argument '" + word + "' (the mesh is already '" + options.Input + "')");
      }
      options.Input = word;
      continue;
    }
    const Option option = SplitOption(word);
    const auto flag = [&option](bool& value) {
      RejectInlineValue(option);
      value = true;
    };
    if (option.Name == "--style")
    {
      options.Style = TakeRenderStyle(option, arguments);
    }
    else if (option.Name == "--no-smoothing")
    {
      flag(options.NoSmoothing);
    }
    else if (option.Name == "--fine-reference")
    {
      flag(options.FineReference);
    }
    else if (option.Name == "--fine-level")
    {
      options.FineLevel = ParseCount(option, arguments.TakeValue(option), 1, 5);
    }
    else if (option.Name == "--coarse-triangles")
    {
      options.CoarseTriangles = ParseCount(option, arguments.TakeValue(option), 4, 10000000);
    }
    else if (option.Name == "--data")
    {
      options.DataDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--help-overlay")
    {
      flag(options.HelpOverlay);
    }
    else if (option.Name == "--no-overlay")
    {
      flag(options.NoOverlay);
    }
    else if (option.Name == "--no-times")
    {
      flag(options.NoTimes);
    }
    else if (option.Name == "--lod")
    {
      flag(options.Lod);
    }
    else if (option.Name == "--screenshot-dir")
    {
      options.ScreenshotDirectory = arguments.TakeValue(option);
    }
    else if (option.Name == "--orbit")
    {
      const std::string degrees = arguments.TakeValue(option);
      options.OrbitDegrees = ParseNumber(option.Name, degrees);
      if (std::abs(options.OrbitDegrees) > 36000.0)
      {
        // A hundred turns is orbit enough; a 1e308-degree one printed its
        // azimuths with 300 digits.
        throw UsageError(
          "option '--orbit' needs degrees from -36000 to 36000, got '" + degrees + "'");
      }
      options.Orbit = true;
    }
    else if (option.Name == "--frames")
    {
      options.Frames = ParseCount(option, arguments.TakeValue(option), 1, 100000);
      options.Orbit = true;
    }
    else if (option.Name == "--record")
    {
      options.RecordDirectory = arguments.TakeValue(option);
      options.Orbit = true;
    }
    else if (option.Name == "--play")
    {
      options.PlayLog = arguments.TakeValue(option);
    }
    else if (option.Name == "--json")
    {
      flag(options.Json);
    }
    else if (option.Name == "--backend")
    {
      backend = ParseRenderBackend(option.Name, arguments.TakeValue(option));
    }
    else if (!ParseCameraOption(option, arguments, options.Camera))
    {
      throw UsageError(
        "unknown option '" + option.Name + "' for 'view'; run 'silhouette view --help'");
    }
  }
  if (options.Orbit && !options.PlayLog.empty())
  {
    throw UsageError("'--play' cannot be combined with '--orbit', '--frames' or '--record'");
  }
  CheckCameraOptions(options.Camera);
  return options;
}

// The parts both commands share: INPUT, --json and the camera options.
// `parseOwnOption` handles the command's other options and says whether it knew it.
template<typename Options, typename OwnOptionParser>
void ParseCommand(const std::string& command, ArgumentList& arguments, Options& options,
  OwnOptionParser parseOwnOption)
{
  bool onlyOperands = false; // after "--"
  while (!arguments.AtEnd())
  {
    const std::string word = arguments.Take();
    if (!onlyOperands && word == "--")
    {
      onlyOperands = true;
    }
    else if (!onlyOperands && LooksLikeOption(word))
    {
      const Option option = SplitOption(word);
      if (option.Name == "--json")
      {
        RejectInlineValue(option);
        options.Json = true;
      }
      else if (!ParseCameraOption(option, arguments, options.Camera) &&
        !parseOwnOption(option, arguments))
      {
        throw UsageError("unknown option '" + option.Name + "' for '" + command +
          "'; run 'silhouette " + command + " --help'");
      }
    }
    else if (options.Input.empty())
    {
      options.Input = word;
    }
    else
    {
      throw UsageError(
        "unexpected argument '" + word + "' (INPUT is already '" + options.Input + "')");
    }
  }
  if (options.Input.empty())
  {
    throw UsageError(
      "'" + command + "' needs an INPUT mesh; run 'silhouette " + command + " --help'");
  }
  CheckCameraOptions(options.Camera);
}

bool IsOutputOption(const Option& option)
{
  return option.Name == "-o" || option.Name == "--output";
}

SmoothOptions ParseSmooth(const std::string& command, ArgumentList& arguments)
{
  SmoothOptions options;
  SmoothOptions& smooth = options;
  ParseCommand(command, arguments, smooth, [&smooth](const Option& option, ArgumentList& args) {
    if (option.Name == "--lines-output")
    {
      smooth.LinesOutput = args.TakeValue(option);
      return true;
    }
    if (!IsOutputOption(option))
    {
      return false;
    }
    smooth.Output = args.TakeValue(option);
    return true;
  });
  return options;
}

RenderOptions ParseRender(
  const std::string& command, ArgumentList& arguments, RenderBackend& backend)
{
  RenderOptions options;
  RenderOptions& render = options;
  ParseCommand(command, arguments, render, [&](const Option& option, ArgumentList& args) {
    if (IsOutputOption(option))
    {
      render.Output = args.TakeValue(option);
    }
    else if (option.Name == "--lines-output")
    {
      render.LinesOutput = args.TakeValue(option);
    }
    else if (option.Name == "--backend")
    {
      backend = ParseRenderBackend(option.Name, args.TakeValue(option));
    }
    else if (option.Name == "--style")
    {
      render.Style = TakeRenderStyle(option, args);
    }
    else if (option.Name == "--no-smoothing")
    {
      RejectInlineValue(option);
      render.NoSmoothing = true;
    }
    else if (option.Name == "--hidden")
    {
      const std::string value = args.TakeValue(option);
      if (value != "none" && value != "dashed")
      {
        throw UsageError("option '--hidden' needs none or dashed, got '" + value + "'");
      }
      render.HiddenLines = value == "dashed";
    }
    else if (option.Name == "--width-by-depth")
    {
      RejectInlineValue(option);
      render.WidthByDepth = true;
    }
    else if (option.Name == "--join-lines")
    {
      RejectInlineValue(option);
      render.JoinLines = true;
    }
    else if (option.Name == "--lod")
    {
      RejectInlineValue(option);
      render.Lod = true;
    }
    else if (option.Name == "--progressive")
    {
      render.ProgressiveLevels = ParseCount(option, args.TakeValue(option), 2, 64);
    }
    else if (option.Name == "--svg" || option.Name == "--pdf")
    {
      RejectInlineValue(option);
      const std::string format = option.Name.substr(2);
      if (render.ProgressiveFormat != "png" && render.ProgressiveFormat != format)
      {
        throw UsageError("options '--svg' and '--pdf' do not go together: the sketch's "
                         "drawings are of one kind");
      }
      render.ProgressiveFormat = format;
    }
    else
    {
      return false;
    }
    return true;
  });
  if (render.Output.empty())
  {
    throw UsageError(render.ProgressiveLevels > 0
        ? "'render --progressive' needs '-o DIR'"
        : "'render' needs '-o IMAGE.png', '-o DRAWING.svg' or '-o DRAWING.pdf'");
  }
  // -o of --progressive is a folder; one named like an image became a folder
  // called x.png.
  const std::string outputExtension = LowercaseExtension(render.Output);
  if (render.ProgressiveLevels > 0 &&
    (outputExtension == ".png" || outputExtension == ".svg" || outputExtension == ".pdf"))
  {
    throw UsageError("with '--progressive', -o names a folder for the drawings (sketch-01." +
      render.ProgressiveFormat + ", ...), not an image: '" + render.Output + "'");
  }
  if (render.Lod && render.ProgressiveLevels > 0)
  {
    throw UsageError("option '--lod' does not go with '--progressive' (each drawing is one "
                     "level of the progressive mesh already)");
  }
  if (render.ProgressiveFormat != "png" && render.ProgressiveLevels == 0)
  {
    throw UsageError("option '--" + render.ProgressiveFormat +
      "' goes with '--progressive'; for one drawing write '-o DRAWING." + render.ProgressiveFormat +
      "'");
  }
  return options;
}

Rendering NoRendering(const CommandLine&)
{
  return Rendering::None;
}

Rendering OffscreenRendering(const CommandLine&)
{
  return Rendering::Offscreen;
}

// The program's commands: name, help, parsing, running, rendering.
const Command Commands[] = {
  { "smooth", SmoothHelp,
    [](const std::string& name, ArgumentList& arguments, CommandLine& into) {
      into.Smooth = ParseSmooth(name, arguments);
    },
    [](const CommandLine& commandLine) { RunSmooth(commandLine.Smooth); }, NoRendering },
  { "render", RenderHelp,
    [](const std::string& name, ArgumentList& arguments, CommandLine& into) {
      into.Render = ParseRender(name, arguments, into.Backend);
    },
    [](const CommandLine& commandLine) { RunRender(commandLine.Render); }, OffscreenRendering },
  { "generate", GenerateHelp,
    [](const std::string&, ArgumentList& arguments, CommandLine& into) {
      into.Generate = ParseGenerate(arguments);
    },
    [](const CommandLine& commandLine) { RunGenerate(commandLine.Generate); }, NoRendering },
  { "compare", CompareHelp,
    [](const std::string&, ArgumentList& arguments, CommandLine& into) {
      into.Compare = ParseCompare(arguments, into.Backend);
    },
    [](const CommandLine& commandLine) { RunCompare(commandLine.Compare); }, OffscreenRendering },
  { "figure", FigureHelp,
    [](const std::string&, ArgumentList& arguments, CommandLine& into) {
      into.Figure = ParseFigure(arguments, into.Backend);
    },
    [](const CommandLine& commandLine) { RunFigure(commandLine.Figure); }, OffscreenRendering },
  { "view", ViewHelp,
    [](const std::string&, ArgumentList& arguments, CommandLine& into) {
      into.View = ParseView(arguments, into.Backend);
    },
    [](const CommandLine& commandLine) { RunView(commandLine.View); },
    [](const CommandLine& commandLine) {
      // An orbit or a played log renders offscreen; otherwise a window.
      const ViewOptions& view = commandLine.View;
      return view.Orbit || !view.PlayLog.empty() ? Rendering::Offscreen : Rendering::Window;
    } },
  { "simplify", SimplifyHelp,
    [](const std::string& name, ArgumentList& arguments, CommandLine& into) {
      SimplifyOptions& simplify = into.Simplify;
      ParseCommand(
        name, arguments, simplify, [&simplify](const Option& option, ArgumentList& args) {
          return ParseSimplifyOption(option, args, simplify);
        });
      CheckSimplifyOptions(simplify);
    },
    [](const CommandLine& commandLine) { RunSimplify(commandLine.Simplify); },
    [](const CommandLine& commandLine) {
      return commandLine.Simplify.Measure ? Rendering::Offscreen : Rendering::None;
    } },
};

// `words` as one line a shell would split back into them: "silhouette",
// then each word, in single quotes where it holds anything but letters,
// digits and _ - + . , / : = @ %.
std::string QuotedCommandLine(const std::vector<std::string>& words)
{
  std::string line = "silhouette";
  for (const std::string& word : words)
  {
    const bool plain = !word.empty() &&
      word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                             "_-+.,/:=@%") == std::string::npos;
    line += ' ';
    if (plain)
    {
      line += word;
      continue;
    }
    line += '\'';
    for (const char c : word)
    {
      line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    line += '\'';
  }
  return line;
}

// The command named `name`, or UsageError if there is none.
const Command& FindCommand(const std::string& name)
{
  for (const Command& command : Commands)
  {
    if (name == command.Name)
    {
      return command;
    }
  }
  throw UsageError("unknown command '" + name + "'; run 'silhouette --help'");
}

// The help of `command` ("help" is the program's), or UsageError.
std::string HelpOf(const std::string& command)
{
  if (command == "version")
  {
    return "Usage: silhouette version  (or --version)\n\nPrints the program's version.\n";
  }
  return command == "help" ? MainHelp() : FindCommand(command).Help();
}

} // namespace

const char* NameOf(RenderStyle style)
{
  switch (style)
  {
    case RenderStyle::Wireframe:
      return "wireframe";
    case RenderStyle::NewGeometry:
      return "new-geometry";
    case RenderStyle::Lines:
      return "lines";
    case RenderStyle::Charcoal:
      return "charcoal";
    case RenderStyle::Lazy:
      return "lazy";
    case RenderStyle::Hand:
      return "hand";
    case RenderStyle::Rough:
      return "rough";
    case RenderStyle::Shaded:
    default:
      return "shaded";
  }
}

CommandLine ParseCommandLine(int argc, char* argv[])
{
  std::vector<std::string> words(argv + 1, argv + argc);
  CommandLine result;
  if (words.empty())
  {
    throw UsageError("no command given; run 'silhouette --help'");
  }
  const std::string command = words.front();
  if (command == "--version" || command == "version")
  {
    if (words.size() == 2 && IsHelpWord(words[1]))
    {
      result.HelpText = HelpOf("version"); // as for every other command
      return result;
    }
    if (words.size() > 1)
    {
      throw UsageError("'" + command + "' takes no arguments");
    }
    // The project's version (CMake's project(VERSION), Apps/CMakeLists.txt).
    result.HelpText = "silhouette " SILHOUETTE_VERSION "\n";
    return result;
  }
  if (IsHelpWord(command) || command == "help")
  {
    if (command == "help" && words.size() > 2)
    {
      throw UsageError("'help' takes at most one COMMAND");
    }
    result.HelpText = words.size() == 2 ? HelpOf(words[1]) : MainHelp();
    return result;
  }
  const Command& selected = FindCommand(command); // rejects unknown commands
  // "--help" anywhere before "--" wins over mistakes elsewhere on the line.
  for (std::size_t i = 1; i < words.size() && words[i] != "--"; ++i)
  {
    if (IsHelpWord(words[i]))
    {
      result.HelpText = selected.Help();
      return result;
    }
  }

  ArgumentList arguments({ words.begin() + 1, words.end() });
  result.Selected = &selected;
  selected.Parse(command, arguments, result);
  result.Render.CommandText = QuotedCommandLine(words);
  return result;
}

} // namespace cli
