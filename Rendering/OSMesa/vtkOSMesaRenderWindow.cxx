#include "vtkOSMesaRenderWindow.h"

#include "OSMesaApi.h"

#include <vtkObjectFactory.h>

#include <dlfcn.h>

vtkStandardNewMacro(vtkOSMesaRenderWindow);

namespace
{

// Core profile, 3.2 or newer (VTK 9.1's OpenGL2 back-end needs 3.2), RGBA and
// a 24-bit depth buffer on the default framebuffer. VTK draws into its own
// framebuffer objects, so the default framebuffer is only the place Frame()
// copies the image to.
OSMesaContext CreateCoreContext()
{
  const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS,
    0, OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
    OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  return OSMesaCreateContextAttribs(attributes, nullptr);
}

// The file name of the shared object that holds `address`.
std::string LibraryOf(const void* address)
{
  Dl_info info;
  if (address && dladdr(address, &info) && info.dli_fname)
  {
    return info.dli_fname;
  }
  return "(not found)";
}

} // namespace

vtkOSMesaRenderWindow::vtkOSMesaRenderWindow()
{
  // Offscreen only: OSMesa's buffer is never shown, and it is single-buffered.
  this->ShowWindow = false;
  this->UseOffScreenBuffers = true;
  this->DoubleBuffer = 0;
  // The context is ours, made and made current by this class rather than by
  // the observers vtkGenericOpenGLRenderWindow otherwise relies on.
  this->OwnContext = 1;
  this->ReadyForRendering = true;
  this->SetWindowName("VTK OSMesa offscreen window");
  // What VTK's own OSMesa window reports as the "screen".
  this->ScreenSize[0] = 1280;
  this->ScreenSize[1] = 1024;
}

vtkOSMesaRenderWindow::~vtkOSMesaRenderWindow()
{
  // The base destructor's Finalize() would not reach this class's.
  this->Finalize();
}

void vtkOSMesaRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << this->Context << "\n";
  os << indent << "BufferSize: " << this->BufferSize[0] << " x " << this->BufferSize[1] << "\n";
}

bool vtkOSMesaRenderWindow::CoreFunctionsComeFromOSMesa(std::string* where)
{
  // VTK's libraries bind glClear & co. through the process's global scope, as
  // dlsym(RTLD_DEFAULT) does; OSMesa exports its own copies.
  const void* clear = dlsym(RTLD_DEFAULT, "glClear");
  const std::string clearLibrary = LibraryOf(clear);
  const std::string osmesaLibrary =
    LibraryOf(reinterpret_cast<const void*>(&OSMesaCreateContextAttribs));
  if (where)
  {
    *where = clearLibrary;
  }
  return clear && clearLibrary == osmesaLibrary;
}

bool vtkOSMesaRenderWindow::CreateContext()
{
  if (this->Context)
  {
    return true;
  }
  if (this->ContextFailed || this->Finalizing)
  {
    return false;
  }
  std::string where;
  if (!CoreFunctionsComeFromOSMesa(&where))
  {
    this->ContextFailed = true;
    vtkErrorMacro("OpenGL functions such as glClear come from "
      << where
      << ", not from OSMesa: preload libsilhouette_osmesa.so (LD_PRELOAD) rather than linking it, "
         "or link OSMesa before VTK");
    return false;
  }
  this->Context = CreateCoreContext();
  if (!this->Context)
  {
    this->ContextFailed = true;
    vtkErrorMacro("OSMesaCreateContextAttribs could not make an OpenGL 3.2 core context");
    return false;
  }
  return this->BindBuffer();
}

bool vtkOSMesaRenderWindow::BindBuffer()
{
  // VTK leaves Size at 0 x 0 until someone sets it; its own windows use 300 x 300 then.
  const int width = this->Size[0] > 0 ? this->Size[0] : 300;
  const int height = this->Size[1] > 0 ? this->Size[1] : 300;
  if (width != this->BufferSize[0] || height != this->BufferSize[1])
  {
    // Bind the new buffer before the old one is freed: OSMesa keeps a pointer to it.
    std::vector<unsigned char> buffer(static_cast<size_t>(width) * height * 4);
    if (!OSMesaMakeCurrent(this->Context, buffer.data(), GL_UNSIGNED_BYTE, width, height))
    {
      vtkErrorMacro("OSMesaMakeCurrent failed for a " << width << " x " << height << " buffer");
      return false;
    }
    this->Buffer.swap(buffer);
    this->BufferSize[0] = width;
    this->BufferSize[1] = height;
    return true;
  }
  if (OSMesaGetCurrentContext() != this->Context)
  {
    if (!OSMesaMakeCurrent(this->Context, this->Buffer.data(), GL_UNSIGNED_BYTE,
          this->BufferSize[0], this->BufferSize[1]))
    {
      vtkErrorMacro("OSMesaMakeCurrent failed");
      return false;
    }
  }
  return true;
}

void vtkOSMesaRenderWindow::DestroyContext()
{
  if (!this->Context)
  {
    return;
  }
  if (OSMesaGetCurrentContext() == this->Context)
  {
    // Unbind, so nothing draws into the buffer once it is freed.
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }
  OSMesaDestroyContext(this->Context);
  this->Context = nullptr;
  std::vector<unsigned char>().swap(this->Buffer);
  this->BufferSize[0] = 0;
  this->BufferSize[1] = 0;
}

void vtkOSMesaRenderWindow::MakeCurrent()
{
  if (this->CreateContext())
  {
    this->BindBuffer();
  }
}

bool vtkOSMesaRenderWindow::IsCurrent()
{
  return this->Context && OSMesaGetCurrentContext() == this->Context;
}

void vtkOSMesaRenderWindow::Initialize()
{
  if (this->Initialized)
  {
    this->MakeCurrent();
    return;
  }
  this->OpenGLInit();
}

// vtkGenericOpenGLRenderWindow shares its context with a host application:
// it saves the OpenGL state before OpenGLInit() and Render() and restores it
// after, so VTK's initial state (depth test GL_LEQUAL, blending...) does not
// survive into the next frame. This window owns its context, as VTK's X and
// OSMesa windows do, and renders as they do (vtkOpenGLRenderWindow's own
// OpenGLInit() and Render()); otherwise coincident lines and overlapping 2D
// props resolve differently from the X window (GL_LESS instead of GL_LEQUAL).
void vtkOSMesaRenderWindow::OpenGLInit()
{
  // GLEW needs the context current first.
  this->MakeCurrent();
  if (!this->IsCurrent())
  {
    return;
  }
  this->vtkOpenGLRenderWindow::OpenGLInit();
}

void vtkOSMesaRenderWindow::Render()
{
  if (!this->Initialized)
  {
    this->OpenGLInit();
  }
  this->MakeCurrent();
  if (!this->IsCurrent())
  {
    return; // CreateContext() said why
  }
  this->vtkOpenGLRenderWindow::Render();
}

void vtkOSMesaRenderWindow::Start()
{
  if (!this->Initialized)
  {
    this->OpenGLInit();
  }
  this->Superclass::Start();
}

void vtkOSMesaRenderWindow::Finalize()
{
  if (!this->Context)
  {
    return;
  }
  this->Finalizing = true;
  this->MakeCurrent();
  // VTK's framebuffers, shaders and buffers, in this context.
  this->ReleaseGraphicsResources(this);
  this->DestroyContext();
  this->Finalizing = false;
}

int vtkOSMesaRenderWindow::SupportsOpenGL()
{
  if (this->Context)
  {
    return 1;
  }
  if (!CoreFunctionsComeFromOSMesa())
  {
    return 0;
  }
  OSMesaContext probe = CreateCoreContext();
  if (!probe)
  {
    return 0;
  }
  OSMesaDestroyContext(probe);
  return 1;
}

void vtkOSMesaRenderWindow::SetSize(int width, int height)
{
  if (this->Size[0] == width && this->Size[1] == height)
  {
    return;
  }
  this->Superclass::SetSize(width, height);
  if (this->Context && !this->Finalizing)
  {
    // A new buffer of the new size at once: the old one must not stay bound.
    this->BindBuffer();
  }
}

void* vtkOSMesaRenderWindow::GetGenericContext()
{
  return this->Context;
}

void* vtkOSMesaRenderWindow::GetGenericDrawable()
{
  return this->Buffer.empty() ? nullptr : this->Buffer.data();
}
