#include "vtkSilhouetteViewAlgorithm.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"

#include "vtkSilhouetteFilterSupport.h"

#include <algorithm>
#include <string>

namespace support = vtkSilhouetteFilterSupport;

struct vtkSilhouetteViewAlgorithm::ViewInternals
{
  // The last view seen by GetMTime(), and when it last changed.
  support::ViewTracker Tracker;
};

vtkSilhouetteViewAlgorithm::vtkSilhouetteViewAlgorithm()
  : ViewInternal(new ViewInternals)
{
}

vtkSilhouetteViewAlgorithm::~vtkSilhouetteViewAlgorithm()
{
  this->SetCamera(nullptr);
  this->SetModelMatrix(nullptr);
}

vtkCxxSetObjectMacro(vtkSilhouetteViewAlgorithm, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkSilhouetteViewAlgorithm, ModelMatrix, vtkMatrix4x4);

void vtkSilhouetteViewAlgorithm::SetProp3D(vtkProp3D* prop)
{
  if (this->Prop3D != prop)
  {
    this->Prop3D = prop;
    this->Modified();
  }
}

vtkProp3D* vtkSilhouetteViewAlgorithm::GetProp3D()
{
  return this->Prop3D;
}

void vtkSilhouetteViewAlgorithm::SetRenderer(vtkRenderer* renderer)
{
  if (this->Renderer != renderer)
  {
    this->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkSilhouetteViewAlgorithm::GetRenderer()
{
  return this->Renderer;
}

namespace
{
// The viewport the view is computed for: a fixed one where it plays no part,
// so that window resizes do not re-run the filter.
std::array<int, 2> Viewport(bool dependent, vtkRenderer* renderer, const int fallback[2])
{
  return dependent ? support::ViewportOf(renderer, fallback) : std::array<int, 2>{ { 1, 1 } };
}
}

vtkMTimeType vtkSilhouetteViewAlgorithm::GetMTime()
{
  const vtkMTimeType mtime = this->Superclass::GetMTime();
  vtkCamera* camera = support::ActiveCamera(this->Camera, this->Renderer);
  if (!camera)
  {
    return mtime;
  }
  double model[16];
  support::ModelMatrixOf(this->Prop3D, this->ModelMatrix, model);
  return std::max(mtime,
    this->ViewInternal->Tracker.Update(
      camera, model, Viewport(this->ViewportDependent, this->Renderer, this->ViewportSize)));
}

int vtkSilhouetteViewAlgorithm::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Checked once here for every view filter, so that RequestViewData may
  // rely on it: polydata on the first input port and on every output.
  bool havePolyData = vtkPolyData::GetData(inputVector[0]) != nullptr;
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    havePolyData = havePolyData && vtkPolyData::GetData(outputVector, port) != nullptr;
  }
  if (!havePolyData)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }
  vtkSilhouetteFilterSupport::View view;
  switch (this->RequestView(view, this->WaitForRenderer))
  {
    case VIEW_READY:
      return this->RequestViewData(request, inputVector, outputVector, view);
    case VIEW_NO_CAMERA_YET:
      return this->RequestDataWithoutCamera(request, inputVector, outputVector);
    case VIEW_FAILED:
    default:
      return 0; // reported
  }
}

int vtkSilhouetteViewAlgorithm::RequestDataWithoutCamera(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Nothing to draw until the camera exists; the other outputs stay empty.
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (this->PassInputWithoutCamera && input && output)
  {
    output->ShallowCopy(input);
  }
  return 1;
}

vtkSilhouetteViewAlgorithm::ViewStatus vtkSilhouetteViewAlgorithm::RequestView(
  support::View& view, bool waitForRenderer)
{
  vtkCamera* camera = support::ActiveCamera(this->Camera, this->Renderer);
  if (!camera && this->Renderer && waitForRenderer)
  {
    return VIEW_NO_CAMERA_YET;
  }
  if (!camera)
  {
    vtkErrorMacro("No camera: call SetCamera() or SetRenderer() before updating.");
    return VIEW_FAILED;
  }
  double model[16];
  support::ModelMatrixOf(this->Prop3D, this->ModelMatrix, model);
  const std::string error = support::MakeViewGeometry(camera, model,
    Viewport(this->ViewportDependent, this->Renderer, this->ViewportSize), view.Geometry,
    &view.NormalToEye);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return VIEW_FAILED;
  }
  return VIEW_READY;
}

void vtkSilhouetteViewAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Prop3D: " << this->Prop3D.GetPointer() << "\n";
  os << indent << "ModelMatrix: " << this->ModelMatrix << "\n";
  os << indent << "Renderer: " << this->Renderer.GetPointer() << "\n";
  os << indent << "ViewportSize: " << this->ViewportSize[0] << " x " << this->ViewportSize[1]
     << (this->ViewportDependent ? "" : " (not used)") << "\n";
}
