// silhouette: the command-line front end of vtkSilhouetteSmoothingFilter.
// Run `silhouette --help` for what it does.
#include "CliErrors.h"
#include "CommandLine.h"
#include "Commands.h"
#include "Compare.h"
#include "Figure.h"
#include "Generate.h"
#include "PrintableText.h"
#include "RenderingBackend.h"
#include "Viewer.h"
#include "VtkErrorLog.h"

#include <csignal>
#include <exception>
#include <iostream>
#include <new>

namespace
{

int Fail(cli::ExitStatus status, const std::string& message)
{
  std::cerr << "silhouette: " << cli::PrintableText(message) << std::endl;
  return status;
}

// The commands that render pick their back-end before any VTK window exists
// (this may restart the program with the OSMesa library preloaded).
void SelectBackendFor(const cli::CommandLine& commandLine, char* argv[])
{
  using Action = cli::CommandLine::Action;
  switch (commandLine.What)
  {
    case Action::Render:
    case Action::Compare:
    case Action::Figure:
      cli::SelectRenderBackend(commandLine.Backend, false, argv);
      cli::GuardRenderingAborts(argv);
      break;
    case Action::Simplify:
      if (commandLine.Simplify.Measure)
      {
        cli::SelectRenderBackend(commandLine.Backend, false, argv);
        cli::GuardRenderingAborts(argv);
      }
      break;
    case Action::View:
    {
      const bool headless = commandLine.View.Orbit || !commandLine.View.PlayLog.empty();
      cli::SelectRenderBackend(commandLine.Backend, !headless, argv);
      cli::GuardRenderingAborts(argv);
      break;
    }
    default:
      break;
  }
}

} // namespace

int main(int argc, char* argv[])
{
  cli::RestoreEnvironmentAfterReexec();
  // Past a file-size limit, a write fails with EFBIG (and says so) instead of
  // killing the program.
  std::signal(SIGXFSZ, SIG_IGN);
  cli::VtkErrorLog::Instance().InstallMessageCapture();
  try
  {
    const cli::CommandLine commandLine = cli::ParseCommandLine(argc, argv);
    SelectBackendFor(commandLine, argv);
    switch (commandLine.What)
    {
      case cli::CommandLine::Action::ShowHelp:
        std::cout << commandLine.HelpText;
        break;
      case cli::CommandLine::Action::Smooth:
        cli::RunSmooth(commandLine.Smooth);
        break;
      case cli::CommandLine::Action::Render:
        cli::RunRender(commandLine.Render);
        break;
      case cli::CommandLine::Action::Generate:
        cli::RunGenerate(commandLine.Generate);
        break;
      case cli::CommandLine::Action::Compare:
        cli::RunCompare(commandLine.Compare);
        break;
      case cli::CommandLine::Action::Figure:
        cli::RunFigure(commandLine.Figure);
        break;
      case cli::CommandLine::Action::View:
        cli::RunView(commandLine.View);
        break;
      case cli::CommandLine::Action::Simplify:
        cli::RunSimplify(commandLine.Simplify);
        break;
    }
    return cli::ExitSuccess;
  }
  catch (const cli::UsageError& error)
  {
    return Fail(cli::ExitUsage, error.what());
  }
  catch (const cli::RuntimeError& error)
  {
    return Fail(cli::ExitFailure, error.what());
  }
  catch (const std::bad_alloc&)
  {
    return Fail(cli::ExitFailure, "out of memory");
  }
  catch (const std::exception& error)
  {
    return Fail(cli::ExitFailure, error.what());
  }
}
