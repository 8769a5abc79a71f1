// GLX and GLEW interposition: how VTK 9.1 built for X11 (Debian's) gets its
// OpenGL functions from OSMesa.
//
// Debian's VTK loads OpenGL through GLEW, and GLEW built for X11 does two
// things that fail without an X server:
//  1. it asks glXGetProcAddressARB for every function address; and
//  2. glewInit(), after loading the OpenGL functions, goes on to load GLX's
//     and fails for want of a GLX display (GLEW_ERROR_GLX_VERSION_11_ONLY or
//     GLEW_ERROR_NO_GLX_DISPLAY), which VTK reports as "GLEW could not be
//     initialized" and stops.
// This library defines both symbols. Preloaded (LD_PRELOAD), it comes before
// libGLX and libGLEW in the process's global scope, so GLEW and VTK call these:
//  - glXGetProcAddressARB / glXGetProcAddress answer OpenGL names with
//    OSMesaGetProcAddress while an OSMesa context is current, and pass
//    everything else (GLX names, or no OSMesa context) to the real GLX;
//  - glewInit calls the real one (dlsym RTLD_NEXT) and, while an OSMesa
//    context is current, reports success when the only failure was GLX's:
//    the OpenGL part (GLEW's function pointers and version flags) is loaded
//    by then.
// With no OSMesa context current both pass straight through, so an X window
// in the same process would behave as usual.
//
// Core OpenGL 1.x functions (glClear, glReadPixels...) are not loaded
// through GLEW: VTK's libraries import them directly, and they bind to the
// first library of the global scope that exports them. OSMesa exports them;
// it must come before libGL/libOpenGL, which it does when this library is
// preloaded (OSMesa is its first dependency) or when a program links OSMesa
// before VTK. vtkOSMesaRenderWindow checks it before making a context.
#include "OSMesaApi.h"

#include <dlfcn.h>

#include <cstring>

namespace
{

using ProcAddress = void (*)();
using GetProcAddressFunction = ProcAddress (*)(const GLubyte*);
using GlewInitFunction = GLenum (*)();

template<typename Function>
Function Next(const char* name)
{
  return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
}

bool OSMesaIsCurrent()
{
  return OSMesaGetCurrentContext() != nullptr;
}

bool IsGlxName(const GLubyte* name)
{
  return std::strncmp(reinterpret_cast<const char*>(name), "glX", 3) == 0;
}

ProcAddress Lookup(const GLubyte* name, GetProcAddressFunction glx)
{
  if (!name)
  {
    return nullptr;
  }
  if (OSMesaIsCurrent() && !IsGlxName(name))
  {
    return reinterpret_cast<ProcAddress>(OSMesaGetProcAddress(reinterpret_cast<const char*>(name)));
  }
  return glx ? glx(name) : nullptr;
}

} // namespace

extern "C"
{

  __attribute__((visibility("default"))) ProcAddress glXGetProcAddressARB(const GLubyte* name)
  {
    static const auto glx = Next<GetProcAddressFunction>("glXGetProcAddressARB");
    return Lookup(name, glx);
  }

  __attribute__((visibility("default"))) ProcAddress glXGetProcAddress(const GLubyte* name)
  {
    static const auto glx = Next<GetProcAddressFunction>("glXGetProcAddress");
    return Lookup(name, glx);
  }

  __attribute__((visibility("default"))) GLenum GLEWAPIENTRY glewInit(void)
  {
    static const auto glew = Next<GlewInitFunction>("glewInit");
    if (!glew)
    {
      return GLEW_ERROR_NO_GL_VERSION;
    }
    const GLenum result = glew();
    if (OSMesaIsCurrent() &&
      (result == GLEW_ERROR_GLX_VERSION_11_ONLY || result == GLEW_ERROR_NO_GLX_DISPLAY))
    {
      return GLEW_OK;
    }
    return result;
  }

  /// Present only when this library is loaded: how the silhouette program
  /// tells whether its OSMesa back-end is active.
  __attribute__((visibility("default"))) int silhouette_osmesa_loaded(void)
  {
    return 1;
  }

} // extern "C"
