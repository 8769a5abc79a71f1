// What an INPUT word names: a model of the evaluation's set (bunny, sphere,
// torus, ...; silhouette_eval::ModelNames) or a mesh file. Every command that
// takes a mesh resolves it the same way, model names first.
#ifndef ModelInput_h
#define ModelInput_h

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace cli
{

/// Throws RuntimeError("'INPUT' is neither a model (bunny, sphere, ...) nor a
/// mesh file (...)") for a name without an extension that is neither a model
/// of the set nor an existing file: the one error every command gives for it.
void RequireModelOrFile(const std::string& input);

/// A model's coarse version, the mesh `view MODEL` shows and `smooth MODEL`
/// and `render MODEL` smooth: its original (silhouette_eval::MakeOriginal;
/// the bunny from `dataDirectory`, empty: DefaultDataDirectory()) decimated
/// to `triangles` (0: the model's default, DefaultCoarseTriangles). The
/// original goes to `original` when it is given. Throws RuntimeError.
vtkSmartPointer<vtkPolyData> CoarseModel(const std::string& name,
  const std::string& dataDirectory = "", int triangles = 0,
  vtkSmartPointer<vtkPolyData>* original = nullptr);

/// A model's coarse version (CoarseModel) for a model name, else the mesh
/// file `input` (ReadMesh), after RequireModelOrFile.
vtkSmartPointer<vtkPolyData> ReadModelOrMesh(const std::string& input);

/// RefuseOverwritingInput (MeshIO.h) for an INPUT word: for a model name,
/// the file the model is read from (the bunny's PLY in the data folder) is
/// the input that `output` must not overwrite.
void RefuseOverwritingModelOrInput(
  const std::string& input, const std::string& output, const std::string& option);

} // namespace cli

#endif
