/**
 * @class vtkOSMesaRenderWindow
 * @brief An offscreen render window drawn by Mesa's OSMesa: VTK rendering
 * with no X server, for a VTK built for X11 only (Debian's VTK 9.1).
 *
 * A vtkGenericOpenGLRenderWindow that owns its context: an OSMesa context
 * (core profile, OpenGL 3.2 or newer, 24-bit depth) drawing into a pixel
 * buffer of the window's size. The context is made the first time the
 * window needs it (Start, Render, MakeCurrent), the buffer follows SetSize,
 * and Finalize() or the destructor release both. Everything else is VTK's
 * own OpenGL code: VTK renders into its framebuffer objects as usual, and
 * reading pixels back (vtkWindowToImageFilter, GetPixelData) works as with
 * any render window. The window is offscreen only: nothing is ever shown,
 * and there is no event loop (use vtkGenericRenderWindowInteractor).
 *
 * It works only together with the rest of libsilhouette_osmesa (see
 * README.md in this folder): Debian's VTK loads OpenGL through GLEW, which
 * asks GLX for function addresses, and VTK's direct gl* calls must reach
 * OSMesa rather than libGL. The library is meant to be preloaded
 * (LD_PRELOAD); CoreFunctionsComeFromOSMesa() tells whether it was, and
 * the window refuses to make a context (one VTK error) when it was not.
 *
 * Where VTK itself was built with OSMesa or EGL (VTK_OPENGL_HAS_OSMESA,
 * VTK_OPENGL_HAS_EGL), use VTK's own offscreen window instead: the project
 * does not build this class then.
 */
#ifndef vtkOSMesaRenderWindow_h
#define vtkOSMesaRenderWindow_h

#include <vtkGenericOpenGLRenderWindow.h>

#include <string>
#include <vector>

struct osmesa_context;

class vtkOSMesaRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkOSMesaRenderWindow* New();
  vtkTypeMacro(vtkOSMesaRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Makes the OSMesa context and its buffer (if not made yet), makes them
  /// current and initialises VTK's OpenGL state (GLEW included).
  void Initialize() override;
  /// Releases VTK's graphics resources, then the context and the buffer.
  /// The window can render again afterwards (with a new context).
  void Finalize() override;

  void Start() override;
  void OpenGLInit() override;
  /// Renders as VTK's own windows do, keeping VTK's OpenGL state between
  /// frames (vtkGenericOpenGLRenderWindow would restore a host's state).
  void Render() override;
  void MakeCurrent() override;
  bool IsCurrent() override;
  /// 1 if an OSMesa core context of OpenGL 3.2 or newer can be made here.
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override { return 0; }

  /// Resizes the pixel buffer with the window (VTK's framebuffers follow by themselves).
  void SetSize(int width, int height) override;
  using vtkGenericOpenGLRenderWindow::SetSize;

  /// The OSMesa context (OSMesaContext), or nullptr before the first render.
  void* GetGenericContext() override;
  /// The pixel buffer OSMesa draws the default framebuffer into (RGBA, 8 bits each).
  void* GetGenericDrawable() override;

  /// True when the process's gl* functions (glClear, glReadPixels...) are
  /// OSMesa's, as they must be: libsilhouette_osmesa was preloaded, or the
  /// program links OSMesa before VTK. `where` gets the library that provides
  /// glClear.
  static bool CoreFunctionsComeFromOSMesa(std::string* where = nullptr);

protected:
  vtkOSMesaRenderWindow();
  ~vtkOSMesaRenderWindow() override;

  /// Makes the context; false (with one VTK error) when that is impossible.
  bool CreateContext();
  void DestroyContext();
  /// Binds the context to a buffer of the window's current size.
  bool BindBuffer();

  osmesa_context* Context = nullptr;
  std::vector<unsigned char> Buffer;
  int BufferSize[2] = { 0, 0 };
  bool ContextFailed = false; // report a failed context once, not every frame
  bool Finalizing = false;    // no new context while the old one is released

private:
  vtkOSMesaRenderWindow(const vtkOSMesaRenderWindow&) = delete;
  void operator=(const vtkOSMesaRenderWindow&) = delete;
};

#endif
