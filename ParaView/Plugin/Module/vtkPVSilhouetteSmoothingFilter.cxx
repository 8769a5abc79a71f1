#include "vtkPVSilhouetteSmoothingFilter.h"

#include "vtkCamera.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkPVSilhouetteSmoothingFilter);

vtkPVSilhouetteSmoothingFilter::vtkPVSilhouetteSmoothingFilter()
{
  // The superclass holds a reference; its GetMTime() compares the camera by
  // value, so a changed property re-runs the filter and an unchanged one
  // (ParaView pushes every property on Apply) does not.
  this->SetCamera(this->ViewCamera);
}

vtkPVSilhouetteSmoothingFilter::~vtkPVSilhouetteSmoothingFilter() = default;

void vtkPVSilhouetteSmoothingFilter::SetCameraPosition(double x, double y, double z)
{
  this->ViewCamera->SetPosition(x, y, z);
}

void vtkPVSilhouetteSmoothingFilter::SetCameraFocalPoint(double x, double y, double z)
{
  this->ViewCamera->SetFocalPoint(x, y, z);
}

void vtkPVSilhouetteSmoothingFilter::SetCameraViewUp(double x, double y, double z)
{
  this->ViewCamera->SetViewUp(x, y, z);
}

void vtkPVSilhouetteSmoothingFilter::SetCameraViewAngle(double degrees)
{
  this->ViewCamera->SetViewAngle(degrees);
}

void vtkPVSilhouetteSmoothingFilter::SetCameraParallelProjection(int parallel)
{
  this->ViewCamera->SetParallelProjection(parallel != 0);
}

void vtkPVSilhouetteSmoothingFilter::SetCameraParallelScale(double scale)
{
  this->ViewCamera->SetParallelScale(scale);
}

void vtkPVSilhouetteSmoothingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
