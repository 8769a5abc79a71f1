#include "MeshIO.h"

#include "CliErrors.h"
#include "LegacyCheck.h"
#include "ObjCheck.h"
#include "PlyCheck.h"
#include "StlCheck.h"
#include "VtpCheck.h"
#include "VtkErrorLog.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace cli
{
namespace
{

std::string Quoted(const std::string& path)
{
  return "'" + path + "'";
}

// VTK's readers say little about a file they cannot open; the C library says why.
void RequireReadableFile(const std::string& path)
{
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
  {
    throw RuntimeError("cannot read " + Quoted(path) + ": it is a directory");
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(
    std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file)
  {
    throw RuntimeError("cannot read " + Quoted(path) + ": " + std::strerror(errno));
  }
}

// The legacy reader happily reads nothing from a file of another dataset type.
void RequireLegacyPolyData(vtkPolyDataReader* reader, const std::string& path)
{
  if (reader->IsFilePolyData())
  {
    return;
  }
  const char* otherType = reader->IsFileUnstructuredGrid() ? "UNSTRUCTURED_GRID"
    : reader->IsFileStructuredGrid()                       ? "STRUCTURED_GRID"
    : reader->IsFileRectilinearGrid()                      ? "RECTILINEAR_GRID"
    : reader->IsFileStructuredPoints()                     ? "STRUCTURED_POINTS"
                                                           : nullptr;
  if (otherType)
  {
    throw RuntimeError(Quoted(path) + " is a legacy VTK " + otherType +
      " file, not POLYDATA; only polygonal meshes can be smoothed");
  }
  throw RuntimeError(Quoted(path) + " is not a readable legacy VTK POLYDATA file");
}

vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& path, const std::string& extension)
{
  if (extension == ".ply")
  {
    CheckPlyFile(path); // vtkPLYReader crashes on some malformed files
    auto reader = vtkSmartPointer<vtkPLYReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (extension == ".obj")
  {
    CheckObjFile(path); // vtkOBJReader silently misreads "nan"
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (extension == ".stl")
  {
    CheckStlFile(path); // vtkSTLReader allocates for any triangle count a binary header declares
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (extension == ".vtp")
  {
    CheckVtpFile(path); // vtkXMLPolyDataReader allocates what a binary array's header declares
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (extension == ".vtk")
  {
    auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    RequireLegacyPolyData(reader, path);
    CheckLegacyVtkFile(path); // vtkPolyDataReader crashes on short or unparsable cell sections
    return reader;
  }
  throw RuntimeError(Quoted(path) + ": unknown mesh format '" + extension +
    "'; expected .ply, .obj, .stl, .vtp or .vtk");
}

} // namespace

std::string LowercaseExtension(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  const std::string extension = LowercaseExtension(path);
  if (extension.empty())
  {
    throw RuntimeError(Quoted(path) + " has no extension; expected .ply, .obj, .stl, .vtp or .vtk");
  }
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  RequireReadableFile(path);
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(path, extension);

  errors.Clear();
  errors.Watch(reader);
  reader->Update();
  errors.ThrowIfErrors("cannot read " + Quoted(path));
  vtkPolyData* read = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!read)
  {
    throw RuntimeError("cannot read " + Quoted(path) + ": the reader gave no polygonal mesh");
  }
  // A copy of our own, so the reader's pipeline can go.
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(read);
  return mesh;
}

vtkIdType CountTriangles(vtkPolyData* mesh)
{
  vtkIdType triangles = 0;
  for (vtkCellArray* cells : { mesh->GetPolys(), mesh->GetStrips() })
  {
    auto cell = vtk::TakeSmartPointer(cells->NewIterator());
    vtkIdType size = 0;
    const vtkIdType* points = nullptr;
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      cell->GetCurrentCell(size, points);
      triangles += std::max<vtkIdType>(size - 2, 0);
    }
  }
  return triangles;
}

void RequireOutputDirectory(const std::string& path)
{
  std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (directory.empty())
  {
    directory = ".";
  }
  std::error_code ignored;
  if (!std::filesystem::is_directory(directory, ignored))
  {
    throw RuntimeError(
      "cannot write " + Quoted(path) + ": there is no directory " + Quoted(directory.string()));
  }
  if (std::filesystem::is_directory(path, ignored))
  {
    throw RuntimeError("cannot write " + Quoted(path) + ": it is a directory");
  }
}

void CheckMeshOutputPath(const std::string& path)
{
  const std::string extension = LowercaseExtension(path);
  if (extension != ".vtp" && extension != ".ply")
  {
    throw RuntimeError("cannot write " + Quoted(path) + ": unknown output format '" + extension +
      "'; expected .vtp or .ply");
  }
  RequireOutputDirectory(path);
}

void WriteMesh(vtkPolyData* mesh, const std::string& path)
{
  CheckMeshOutputPath(path);
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  int written = 0;
  if (LowercaseExtension(path) == ".vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    errors.Watch(writer);
    writer->SetInputData(mesh);
    writer->SetFileName(path.c_str());
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToZLib();
    written = writer->Write();
  }
  else
  {
    // vtkPLYWriter appends ".ply" to a name that does not end in lower-case
    // ".ply" (and its WriteToOutputString gives nothing in 9.1): write under
    // such a name next to the target, then rename.
    const bool nameKept = std::filesystem::path(path).extension() == ".ply";
    const std::string writtenPath = nameKept ? path : path + ".partial.ply";
    vtkNew<vtkPLYWriter> writer;
    errors.Watch(writer);
    writer->SetInputData(mesh);
    writer->SetFileName(writtenPath.c_str());
    writer->SetFileTypeToBinary();
    written = writer->Write();
    if (!nameKept && written && !errors.HasErrors())
    {
      std::error_code renameError;
      std::filesystem::rename(writtenPath, path, renameError);
      if (renameError)
      {
        std::filesystem::remove(writtenPath, renameError);
        throw RuntimeError("cannot write " + Quoted(path) + ": " + renameError.message());
      }
    }
  }
  errors.ThrowIfErrors("cannot write " + Quoted(path));
  if (!written)
  {
    throw RuntimeError("cannot write " + Quoted(path));
  }
}

} // namespace cli
