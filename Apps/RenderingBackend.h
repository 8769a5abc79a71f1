#ifndef RenderingBackend_h
#define RenderingBackend_h

#include <string>

namespace cli
{

/**
 * How the program renders. Debian's VTK renders only into X windows; the
 * OSMesa back-end (Rendering/OSMesa, libsilhouette_osmesa.so) makes it
 * render with no X server. That library must be preloaded to work (its
 * README says why), so the program does not link it: when OSMesa is wanted
 * it re-executes itself with LD_PRELOAD naming the library, and when X is
 * wanted the library is simply not there. Where VTK itself was built with
 * OSMesa or EGL, its own offscreen windows need no X and no library.
 */
enum class RenderBackend
{
  Auto,   ///< X when there is a usable X display, OSMesa otherwise
  OSMesa, ///< offscreen through OSMesa (or VTK's own offscreen window)
  X       ///< VTK's X window (DISPLAY must be set)
};

/// "osmesa" or "x" for --backend; UsageError naming `option` otherwise.
RenderBackend ParseRenderBackend(const std::string& option, const std::string& value);

/// The --backend lines of the commands' help, the description from `column`.
std::string RenderBackendHelp(int column);

/// First thing in main(): if this process is the re-execution
/// SelectRenderBackend() made, puts LD_PRELOAD back as it was, so programs
/// this one starts do not inherit the library.
void RestoreEnvironmentAfterReexec();

/**
 * Makes this process render through `requested`, before any rendering:
 * returns when it already does, re-executes the program (/proc/self/exe,
 * same arguments) with LD_PRELOAD changed when it does not, and throws
 * RuntimeError when it cannot (--backend x with no display; no OSMesa
 * library) or UsageError (--backend osmesa for an on-screen window).
 * `interactive`: the command opens a window on screen, which needs X.
 */
void SelectRenderBackend(RenderBackend requested, bool interactive, char* argv[]);

/// The back-end this process renders with (X before SelectRenderBackend).
RenderBackend ActiveRenderBackend();

/// True when DISPLAY is set and names an X server that answers (tried for up
/// to a second: a busy Xvfb has been seen to refuse a connection for a moment).
bool HaveXDisplay();

/**
 * For the rest of the process: when VTK aborts while rendering (it does when
 * it cannot open its X display or make a GL context), re-execute the program
 * once with the same arguments, since such failures have been transient under
 * Xvfb; if that was already the retry, end with one line on stderr instead of
 * VTK's abort. Call after SelectRenderBackend(), for commands that render.
 */
void GuardRenderingAborts(char* argv[]);

} // namespace cli

#endif
