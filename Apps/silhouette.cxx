// silhouette: the command-line front end of vtkSilhouetteSmoothingFilter.
// Run `silhouette --help` for what it does.
#include "CliErrors.h"
#include "CommandLine.h"
#include "PrintableText.h"
#include "RenderingBackend.h"
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
  const cli::Rendering rendering =
    commandLine.Selected ? commandLine.Selected->Renders(commandLine) : cli::Rendering::None;
  if (rendering != cli::Rendering::None)
  {
    cli::SelectRenderBackend(commandLine.Backend, rendering == cli::Rendering::Window, argv);
    cli::GuardRenderingAborts(argv);
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
    if (commandLine.Selected)
    {
      commandLine.Selected->Run(commandLine);
    }
    else
    {
      std::cout << commandLine.HelpText;
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
