// The OSMesa window on its own, run with DISPLAY unset and the library
// preloaded: the factory hands it out, it renders, resizes, reads pixels back,
// renders again after Finalize(), and two windows take turns.
#include "vtkOSMesaRenderWindow.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{

int failures = 0;

void Check(bool condition, const std::string& what)
{
  std::cout << (condition ? "ok:     " : "FAILED: ") << what << std::endl;
  if (!condition)
  {
    ++failures;
  }
}

// A red background and a blue unlit sphere in the middle.
vtkSmartPointer<vtkRenderer> MakeScene()
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(1, 0, 0);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0, 0, 1);
  actor->GetProperty()->LightingOff();
  renderer->AddActor(actor);
  renderer->ResetCamera();
  return renderer;
}

// Renders `window` and checks its image: size, red corner, blue centre.
void CheckImage(vtkRenderWindow* window, int width, int height, const std::string& what)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int dimensions[3];
  image->GetDimensions(dimensions);
  Check(dimensions[0] == width && dimensions[1] == height,
    what + ": image is " + std::to_string(dimensions[0]) + "x" + std::to_string(dimensions[1]));
  const auto* corner = static_cast<unsigned char*>(image->GetScalarPointer(1, 1, 0));
  const auto* centre =
    static_cast<unsigned char*>(image->GetScalarPointer(width / 2, height / 2, 0));
  Check(corner[0] == 255 && corner[1] == 0 && corner[2] == 0,
    what + ": background red (" + std::to_string(corner[0]) + ", " + std::to_string(corner[1]) +
      ", " + std::to_string(corner[2]) + ")");
  Check(centre[0] == 0 && centre[1] == 0 && centre[2] == 255,
    what + ": sphere blue (" + std::to_string(centre[0]) + ", " + std::to_string(centre[1]) + ", " +
      std::to_string(centre[2]) + ")");
}

} // namespace

int main()
{
  std::string where;
  const bool fromOSMesa = vtkOSMesaRenderWindow::CoreFunctionsComeFromOSMesa(&where);
  Check(fromOSMesa, "glClear comes from " + where);

  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  Check(vtkOSMesaRenderWindow::SafeDownCast(window) != nullptr,
    std::string("vtkRenderWindow::New() gives ") + window->GetClassName());
  vtkSmartPointer<vtkRenderWindowInteractor> interactor =
    vtkSmartPointer<vtkRenderWindowInteractor>::New();
  Check(std::string(interactor->GetClassName()) == "vtkGenericRenderWindowInteractor",
    std::string("vtkRenderWindowInteractor::New() gives ") + interactor->GetClassName());
  Check(window->SupportsOpenGL() == 1, "SupportsOpenGL");

  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(64, 48);
  window->AddRenderer(MakeScene());
  CheckImage(window, 64, 48, "first render");
  const std::string capabilities = window->ReportCapabilities();
  Check(capabilities.find("llvmpipe") != std::string::npos ||
      capabilities.find("softpipe") != std::string::npos,
    "renderer: " + capabilities.substr(0, capabilities.find("OpenGL extensions")));

  window->SetSize(100, 80);
  CheckImage(window, 100, 80, "after SetSize(100, 80)");

  window->Finalize();
  CheckImage(window, 100, 80, "after Finalize()");

  // A second window, and the two in turn.
  vtkNew<vtkOSMesaRenderWindow> second;
  second->SetMultiSamples(0);
  second->SetSize(40, 30);
  second->AddRenderer(MakeScene());
  CheckImage(second, 40, 30, "second window");
  CheckImage(window, 100, 80, "first window again");
  CheckImage(second, 40, 30, "second window again");

  // An interactor that plays events in the offscreen window.
  interactor->SetRenderWindow(second);
  interactor->Initialize();
  second->Render();
  Check(second->IsCurrent(), "the window is current after Render()");

  std::cout << (failures ? "FAILED" : "passed") << std::endl;
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
