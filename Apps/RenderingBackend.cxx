#include "RenderingBackend.h"

#include "CliErrors.h"
#include "DataFolder.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>
#include <thread>
#include <vector>

#if SILHOUETTE_VTK_HAS_X
#include <X11/Xlib.h>
#endif

// Set by Apps/CMakeLists.txt from Rendering/OSMesa's configure checks.
#ifndef SILHOUETTE_VTK_NATIVE_OFFSCREEN
#define SILHOUETTE_VTK_NATIVE_OFFSCREEN 0
#endif
#ifndef SILHOUETTE_OSMESA_SHIM
#define SILHOUETTE_OSMESA_SHIM 0
#endif

namespace cli
{
namespace
{

// Set in the environment of the re-executed program: LD_PRELOAD as it was
// before ("unset", or "set:" and the value).
constexpr const char* ReexecVariable = "SILHOUETTE_REEXEC_LD_PRELOAD";

bool Reexecuted = false;
RenderBackend Active = RenderBackend::X;

std::string Environment(const char* name)
{
  const char* value = std::getenv(name);
  return value ? value : "";
}

bool HaveDisplayVariable()
{
  return !Environment("DISPLAY").empty();
}

#if SILHOUETTE_OSMESA_SHIM
// The library's marker function is in the process when it was preloaded.
bool OSMesaLibraryLoaded()
{
  return dlsym(RTLD_DEFAULT, "silhouette_osmesa_loaded") != nullptr;
}

// bin/../lib/libsilhouette_osmesa.so.N (the build tree and an installed tree
// alike, wherever the tree was moved).
std::optional<std::string> FindOSMesaLibrary()
{
  namespace fs = std::filesystem;
  const std::optional<fs::path> folder = ProgramFolder();
  if (!folder)
  {
    return std::nullopt;
  }
  const fs::path candidate =
    *folder / SILHOUETTE_OSMESA_LIBRARY_RELATIVE_DIR / SILHOUETTE_OSMESA_LIBRARY_NAME;
  std::error_code error;
  if (!fs::is_regular_file(candidate, error))
  {
    return std::nullopt;
  }
  return fs::weakly_canonical(candidate, error).string();
}

// LD_PRELOAD's entries (separated by ':' or spaces) without `name`'s file.
std::string WithoutLibrary(const std::string& preload, const std::string& name)
{
  std::string result;
  std::string entry;
  std::istringstream entries(preload);
  while (std::getline(entries, entry, ':'))
  {
    std::istringstream words(entry);
    std::string word;
    while (words >> word)
    {
      if (std::filesystem::path(word).filename().string().rfind(name, 0) == 0)
      {
        continue;
      }
      result += (result.empty() ? "" : ":") + word;
    }
  }
  return result;
}

[[noreturn]] void Reexecute(bool withOSMesa, char* argv[])
{
  const char* before = std::getenv("LD_PRELOAD");
  const std::string previous = before ? before : "";
  std::string preload;
  if (withOSMesa)
  {
    const std::optional<std::string> library = FindOSMesaLibrary();
    if (!library)
    {
      throw RuntimeError(std::string("there is no X display, and the OSMesa back-end library ") +
        SILHOUETTE_OSMESA_LIBRARY_NAME +
        " is missing (looked in the lib folder beside the "
        "program's); run under 'xvfb-run -a'");
    }
    preload = *library + (previous.empty() ? "" : ":" + previous);
  }
  else
  {
    preload = WithoutLibrary(previous, "libsilhouette_osmesa.so");
  }
  setenv(ReexecVariable, before ? ("set:" + previous).c_str() : "unset", 1);
  setenv("LD_PRELOAD", preload.c_str(), 1);
  execv("/proc/self/exe", argv);
  const int failure = errno;
  unsetenv(ReexecVariable);
  throw RuntimeError(std::string("cannot restart the program to switch its rendering back-end: ") +
    std::strerror(failure));
}
#endif

} // namespace

RenderBackend ParseRenderBackend(const std::string& option, const std::string& value)
{
  if (value == "osmesa")
  {
    return RenderBackend::OSMesa;
  }
  if (value == "x")
  {
    return RenderBackend::X;
  }
  throw UsageError("option '" + option + "' needs osmesa or x, got '" + value + "'");
}

std::string RenderBackendHelp(int column)
{
  const std::string name = "  --backend NAME";
  const std::string text =
    "how to render: osmesa (Mesa's OSMesa, offscreen, no X server needed) or x (a VTK X "
    "window; needs an X display) (default: x when DISPLAY names an X server that answers, "
    "osmesa otherwise)";
  // Wrapped at 78 columns, the description starting at `column`.
  std::string help =
    name + std::string(column > static_cast<int>(name.size()) ? column - name.size() : 1, ' ');
  std::size_t lineLength = help.size();
  std::istringstream words(text);
  std::string word;
  bool first = true;
  while (words >> word)
  {
    if (!first && lineLength + 1 + word.size() > 78)
    {
      help += "\n" + std::string(column, ' ');
      lineLength = column;
      first = true;
    }
    help += (first ? "" : " ") + word;
    lineLength += (first ? 0 : 1) + word.size();
    first = false;
  }
  return help + "\n";
}

void RestoreEnvironmentAfterReexec()
{
  const char* saved = std::getenv(ReexecVariable);
  if (!saved)
  {
    return;
  }
  Reexecuted = true;
  const std::string value = saved;
  if (value.rfind("set:", 0) == 0)
  {
    setenv("LD_PRELOAD", value.substr(4).c_str(), 1);
  }
  else
  {
    unsetenv("LD_PRELOAD");
  }
  unsetenv(ReexecVariable);
}

bool HaveXDisplay()
{
  static const bool answer = [] {
    if (!HaveDisplayVariable())
    {
      return false;
    }
#if SILHOUETTE_VTK_HAS_X
    // A busy Xvfb has been seen to refuse a connection for a moment, so a
    // refusal is retried for up to a second before it counts. Xlib prints a
    // server's refusal itself ("Authorization required, ...", two lines) at
    // every attempt, 40 lines in all where X refuses us and OSMesa then
    // renders fine: the probe runs with stderr on /dev/null, and a command
    // that needs X says in its own line that the display does not answer.
    std::fflush(stderr);
    const int savedStderr = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0);
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    const bool silenced = savedStderr >= 0 && null >= 0 && dup2(null, STDERR_FILENO) >= 0;
    if (null >= 0)
    {
      close(null);
    }
    bool answered = false;
    for (int attempt = 0; attempt < 20 && !answered; ++attempt)
    {
      if (Display* display = XOpenDisplay(nullptr))
      {
        XCloseDisplay(display);
        answered = true;
      }
      else
      {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
    }
    std::fflush(stderr);
    if (silenced)
    {
      dup2(savedStderr, STDERR_FILENO);
    }
    if (savedStderr >= 0)
    {
      close(savedStderr);
    }
    return answered;
#else
    return true;
#endif
  }();
  return answer;
}

RenderBackend ActiveRenderBackend()
{
  return Active;
}

void SelectRenderBackend(RenderBackend requested, bool interactive, char* argv[])
{
  if (requested == RenderBackend::OSMesa && interactive)
  {
    throw UsageError("the interactive viewer needs an X display; '--backend osmesa' renders "
                     "offscreen only (use --orbit or --play)");
  }
#if SILHOUETTE_VTK_NATIVE_OFFSCREEN && !SILHOUETTE_VTK_HAS_X
  if (requested == RenderBackend::X || interactive)
  {
    throw RuntimeError("this VTK was built without X windows: it renders offscreen only (no "
                       "'--backend x', no interactive viewer)");
  }
#endif
  if (requested == RenderBackend::X && !HaveXDisplay())
  {
    throw RuntimeError(std::string("'--backend x' needs an X display, and ") +
      (HaveDisplayVariable()
          ? "DISPLAY ('" + Environment("DISPLAY") + "') does not answer or refuses the connection"
          : "DISPLAY is not set") +
      "; run it under 'xvfb-run -a', or leave '--backend' out to render through OSMesa");
  }
#if SILHOUETTE_VTK_NATIVE_OFFSCREEN
  // VTK's own windows render offscreen without X (VTK_OPENGL_HAS_OSMESA or
  // _EGL; the commands ask for offscreen rendering), so there is nothing to
  // switch: "OSMesa" here means VTK's own offscreen window.
  (void)argv;
  Active =
    (requested == RenderBackend::X || interactive) ? RenderBackend::X : RenderBackend::OSMesa;
#elif SILHOUETTE_OSMESA_SHIM
  bool wantOSMesa = requested == RenderBackend::OSMesa;
  if (requested == RenderBackend::Auto)
  {
    // The on-screen viewer stays on X, and fails later with its own message
    // when there is no display. A re-executed process keeps the choice its
    // parent made, rather than probing the display a second time.
    wantOSMesa = Reexecuted ? OSMesaLibraryLoaded() : !interactive && !HaveXDisplay();
  }
  if (wantOSMesa != OSMesaLibraryLoaded())
  {
    if (Reexecuted)
    {
      throw RuntimeError(std::string("cannot switch the rendering back-end to ") +
        (wantOSMesa ? "OSMesa" : "X") + ": LD_PRELOAD did not take effect");
    }
    Reexecute(wantOSMesa, argv);
  }
  Active = wantOSMesa ? RenderBackend::OSMesa : RenderBackend::X;
#else
  // Built without the OSMesa back-end: X only.
  (void)argv;
  if (requested == RenderBackend::OSMesa)
  {
    throw RuntimeError("this build has no OSMesa back-end (GL/osmesa.h or libOSMesa was missing "
                       "when it was configured); run under 'xvfb-run -a' instead");
  }
  Active = RenderBackend::X;
#endif
}

namespace
{

// Prepared before any rendering, because the abort handler may only use
// async-signal-safe calls (write, execve, _exit).
char** RetryArguments = nullptr;
std::vector<std::string> RetryEnvironmentStrings;
std::vector<char*> RetryEnvironment;
constexpr const char* RetryVariable = "SILHOUETTE_RENDER_RETRY";

void RetryOrReportAbort(int)
{
  if (RetryArguments && !RetryEnvironment.empty())
  {
    static const char retrying[] =
      "silhouette: VTK could not open its window (X display or GL context); retrying once\n";
    const ssize_t ignored = write(STDERR_FILENO, retrying, sizeof(retrying) - 1);
    (void)ignored;
    execve("/proc/self/exe", RetryArguments, RetryEnvironment.data());
  }
  static const char message[] = "silhouette: rendering aborted: VTK could not use the X display "
                                "(is DISPLAY right? try 'xvfb-run -a')\n";
  const ssize_t ignored = write(STDERR_FILENO, message, sizeof(message) - 1);
  (void)ignored;
  _exit(ExitFailure);
}

} // namespace

void GuardRenderingAborts(char* argv[])
{
  RetryArguments = argv;
  RetryEnvironmentStrings.clear();
  RetryEnvironment.clear();
  if (!std::getenv(RetryVariable))
  {
    for (char** variable = environ; *variable; ++variable)
    {
      RetryEnvironmentStrings.emplace_back(*variable);
    }
    RetryEnvironmentStrings.emplace_back(std::string(RetryVariable) + "=1");
    for (std::string& variable : RetryEnvironmentStrings)
    {
      RetryEnvironment.push_back(variable.data());
    }
    RetryEnvironment.push_back(nullptr);
  }
  std::signal(SIGABRT, RetryOrReportAbort);
}

} // namespace cli
