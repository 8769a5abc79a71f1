#include "LevelOfDetail.h"

#include "CameraOptions.h"
#include "VtkErrorLog.h"

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkViewDependentLevelOfDetail.h>

#include <chrono>
#include <sstream>

namespace cli
{

std::string LevelOfDetailRun::summary() const
{
  std::ostringstream text;
  text << "level of detail: " << this->Triangles << " of " << this->InputTriangles
       << " triangles for this view (hierarchy built and cut in "
       << static_cast<long long>(this->BuildMilliseconds + 0.5) << " ms)";
  return text.str();
}

LevelOfDetailRun ExtractForView(vtkPolyData* mesh, vtkCamera* camera, const CameraOptions& options)
{
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkNew<vtkViewDependentLevelOfDetail> lod;
  errors.Watch(lod);
  lod->SetInputData(mesh);
  lod->SetCamera(camera);
  lod->SetViewportSize(options.ViewportSize[0], options.ViewportSize[1]);
  LevelOfDetailRun run;
  const auto start = std::chrono::steady_clock::now();
  lod->Update();
  run.BuildMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  errors.ThrowIfErrors("the level of detail failed");
  run.Mesh = vtkSmartPointer<vtkPolyData>::New();
  run.Mesh->ShallowCopy(lod->GetOutput());
  run.Triangles = static_cast<long long>(run.Mesh->GetNumberOfPolys());
  vtkDataArray* input = run.Mesh->GetFieldData()->GetArray("LevelOfDetailInputTriangles");
  run.InputTriangles = input ? static_cast<long long>(input->GetTuple1(0)) : 0;
  return run;
}

} // namespace cli
