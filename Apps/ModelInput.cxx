#include "ModelInput.h"

#include "CliErrors.h"
#include "DataFolder.h"
#include "MeshIO.h"
#include "VtkErrorLog.h"

#include "EvaluationModels.h"

#include <filesystem>
#include <stdexcept>

namespace cli
{

void RequireModelOrFile(const std::string& input)
{
  std::error_code ignored;
  if (!silhouette_eval::IsModelName(input) && LowercaseExtension(input).empty() &&
    !std::filesystem::exists(input, ignored))
  {
    std::string models;
    for (const std::string& name : silhouette_eval::ModelNames())
    {
      models += (models.empty() ? "" : ", ") + name;
    }
    throw RuntimeError("'" + input + "' is neither a model (" + models +
      ") nor a mesh file (.ply, .obj, .stl, .vtp or .vtk)");
  }
}

vtkSmartPointer<vtkPolyData> CoarseModel(const std::string& name, const std::string& dataDirectory,
  int triangles, vtkSmartPointer<vtkPolyData>* original)
{
  const std::string folder = dataDirectory.empty() ? DefaultDataDirectory() : dataDirectory;
  VtkErrorLog::Instance().Clear();
  vtkSmartPointer<vtkPolyData> coarse;
  try
  {
    vtkSmartPointer<vtkPolyData> made = silhouette_eval::MakeOriginal(name, folder);
    coarse = silhouette_eval::Decimate(
      made, triangles > 0 ? triangles : silhouette_eval::DefaultCoarseTriangles(name));
    if (original)
    {
      *original = made;
    }
  }
  catch (const std::runtime_error& error)
  {
    throw RuntimeError(name + ": " + error.what());
  }
  VtkErrorLog::Instance().ThrowIfErrors("preparing " + name + " failed");
  return coarse;
}

vtkSmartPointer<vtkPolyData> ReadModelOrMesh(const std::string& input)
{
  if (silhouette_eval::IsModelName(input))
  {
    return CoarseModel(input);
  }
  RequireModelOrFile(input);
  return ReadMesh(input);
}

void RefuseOverwritingModelOrInput(
  const std::string& input, const std::string& output, const std::string& option)
{
  const std::string modelFile = silhouette_eval::IsModelName(input)
    ? silhouette_eval::ModelFile(input, DefaultDataDirectory())
    : std::string();
  RefuseOverwritingInput(modelFile.empty() ? input : modelFile, output, option);
}

} // namespace cli
