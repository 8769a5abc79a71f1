#include "MeshIO.h"

#include "AtomicFile.h"
#include "CliErrors.h"
#include "LegacyCheck.h"
#include "MeshValidation.h"
#include "ObjCheck.h"
#include "PlyCheck.h"
#include "PrintableText.h"
#include "SandboxedReading.h"
#include "StlCheck.h"
#include "VtkErrorLog.h"
#include "VtpCheck.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <sys/stat.h>

namespace cli
{
namespace
{

std::string Quoted(const std::string& path)
{
  return "'" + path + "'";
}

const char* KindOfFile(mode_t mode)
{
  return S_ISDIR(mode) ? "a directory"
    : S_ISCHR(mode)    ? "a character device"
    : S_ISBLK(mode)    ? "a block device"
    : S_ISFIFO(mode)   ? "a pipe"
    : S_ISSOCK(mode)   ? "a socket"
                       : "not a regular file";
}

// VTK's readers say little about a file they cannot open; the C library says
// why. Devices and pipes are refused before anything opens them: /dev/zero
// reads forever, and opening a pipe waits for a writer. Returns the size.
std::uint64_t RequireReadableFile(const std::string& path)
{
  struct stat status
  {
  };
  if (::stat(path.c_str(), &status) != 0)
  {
    throw RuntimeError("cannot read " + Quoted(path) + ": " + std::strerror(errno));
  }
  if (!S_ISREG(status.st_mode))
  {
    throw RuntimeError("cannot read " + Quoted(path) + ": it is " + KindOfFile(status.st_mode) +
      ", not a regular file");
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(
    std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file)
  {
    throw RuntimeError("cannot read " + Quoted(path) + ": " + std::strerror(errno));
  }
  return static_cast<std::uint64_t>(status.st_size);
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

// What the pre-checks learnt of the file that reading it needs.
struct FileFacts
{
  StlFacts Stl;
  PlyFacts Ply;
  FileGeometry Obj;
  FileGeometry Legacy;
  VtpFacts Vtp;
};

// The pre-check for the format, then VTK's reader.
vtkSmartPointer<vtkAlgorithm> MakeReader(
  const std::string& path, const std::string& extension, FileFacts& facts)
{
  if (extension == ".ply")
  {
    // Refuses what is not PLY, and reads the geometry to hold the reader to.
    facts.Ply = CheckPlyFile(path);
  }
  else if (extension == ".obj")
  {
    // Refuses what is not OBJ, and reads the geometry to hold the reader to.
    facts.Obj = CheckObjFile(path);
  }
  else if (extension == ".stl")
  {
    // Refuses what the reader would allocate for or misread, and reads the
    // facets to hold the reader to.
    facts.Stl = CheckStlFile(path);
  }
  else if (extension == ".vtp")
  {
    // Refuses what the reader would allocate or fill from its buffer, and
    // reads the geometry to hold the reader to.
    facts.Vtp = CheckVtpFile(path);
  }
  vtkSmartPointer<vtkAlgorithm> reader = NewVtkReader(path);
  if (!reader)
  {
    throw RuntimeError(Quoted(path) + ": unknown mesh format '" + extension +
      "'; expected .ply, .obj, .stl, .vtp or .vtk");
  }
  if (facts.Ply.FaceTextureCoordinates)
  {
    // Its splitting of points can give a face another face's point.
    vtkPLYReader::SafeDownCast(reader)->SetDuplicatePointsForFaceTexture(false);
  }
  if (extension == ".vtk")
  {
    RequireLegacyPolyData(vtkPolyDataReader::SafeDownCast(reader), path);
    // Refuses what is not legacy VTK, and reads the geometry to hold the reader to.
    facts.Legacy = CheckLegacyVtkFile(path);
  }
  return reader;
}

// What the reading process runs: the pre-check, VTK's reader, and the
// checks that make the result safe to pass back.
vtkSmartPointer<vtkPolyData> ReadWithVtk(const std::string& path, const std::string& extension)
{
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  FileFacts facts;
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(path, extension, facts);
  errors.Clear();
  errors.Watch(reader);
  reader->Update();
  if (extension == ".vtp" && !facts.Vtp.Read)
  {
    // What the format's rules could not read names the problem where the
    // reader failed too (it often only finds an array too short), and where
    // it did not, its mesh cannot be checked.
    throw RuntimeError("cannot read " + Quoted(path) + ": VTK XML: " + facts.Vtp.Unreadable +
      (errors.HasErrors() ? "" : ", so what vtkXMLPolyDataReader read of it cannot be checked"));
  }
  if (extension == ".vtp" && errors.HasErrors())
  {
    if (facts.Vtp.Pieces > 0 && facts.Vtp.FirstPiecePoints == 0)
    {
      const std::int64_t points = facts.Vtp.Geometry.VertexCount();
      if (points == 0)
      {
        throw RuntimeError(Quoted(path) + " holds no points");
      }
      throw RuntimeError("cannot read " + Quoted(path) +
        ": its first piece has no points, which vtkXMLPolyDataReader 9.1 cannot read (its other "
        "pieces hold " +
        std::to_string(points) + "); write the pieces as one");
    }
  }
  errors.ThrowIfErrors("cannot read " + Quoted(path));
  if (facts.Ply.UnreadVertexTextureCoordinates)
  {
    errors.Record(VtkErrorLog::Kind::Warning, true,
      (Quoted(path) +
        ": its vertices' texture coordinates ('s' and 't') are left out: vtkPLYReader 9.1 "
        "reads 'u' and 'v' (or 'texture_u' and 'texture_v') only")
        .c_str());
  }
  if (facts.Ply.FaceTextureCoordinates)
  {
    errors.Record(VtkErrorLog::Kind::Warning, true,
      (Quoted(path) +
        ": its faces give texture coordinates per corner, which vtkPLYReader 9.1 "
        "can attach to the wrong points; they are read one per point, so texture "
        "seams are lost")
        .c_str());
  }
  vtkPolyData* read = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!read)
  {
    throw RuntimeError("cannot read " + Quoted(path) + ": the reader gave no polygonal mesh");
  }
  // Whatever the reader got wrong, it is not the file's mesh.
  if (extension == ".ply")
  {
    RequireReadAsWritten(facts.Ply.Geometry, read, path, "vtkPLYReader");
  }
  if (extension == ".vtk")
  {
    RequireReadAsWritten(facts.Legacy, read, path, "vtkPolyDataReader");
  }
  if (extension == ".vtp")
  {
    RequireReadAsWritten(facts.Vtp.Geometry, read, path, "vtkXMLPolyDataReader");
  }
  if (extension == ".obj")
  {
    JoinTextureCoordinateArrays(read);
    const std::string invented = DropUnnamedCornerData(facts.Obj, read);
    if (!invented.empty())
    {
      errors.Record(VtkErrorLog::Kind::Warning, true,
        (Quoted(path) + ": its " + invented +
          " are named by no face, so they are left out (vtkOBJReader would give vertex i the "
          "i-th)")
          .c_str());
    }
    RequireReadAsWritten(facts.Obj, read, path, "vtkOBJReader");
    const std::string lost = CellsLeftOut(facts.Obj, read);
    if (!lost.empty())
    {
      errors.Record(VtkErrorLog::Kind::Warning, true,
        (Quoted(path) + ": vtkOBJReader left out " + lost).c_str());
    }
  }
  // vtkSTLReader merges equal points and drops a facet left with two corners
  // at one point, without a word.
  if (extension == ".stl")
  {
    RequireReadAsWritten(facts.Stl.Geometry, read, path, "vtkSTLReader");
    const std::uint64_t dropped = facts.Stl.Needles;
    if (dropped > 0)
    {
      errors.Record(VtkErrorLog::Kind::Warning, true,
        (Quoted(path) + ": left out " + std::to_string(dropped) +
          (dropped == 1 ? " facet" : " facets") +
          " with two corners at one point (vtkSTLReader merges them away)")
          .c_str());
    }
  }
  // A copy of our own, so the reader's pipeline can go.
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(read);
  const std::string unmatched = RemoveMismatchedArrays(mesh);
  if (!unmatched.empty())
  {
    errors.Record(VtkErrorLog::Kind::Warning, true,
      (Quoted(path) + ": left out " + unmatched + ", which the reader gave the wrong length")
        .c_str());
  }
  RequireConsistentMesh(mesh, Quoted(path));
  const std::string removed = RemoveCellsWithTooFewPoints(mesh);
  if (!removed.empty())
  {
    errors.Record(VtkErrorLog::Kind::Warning, true,
      (Quoted(path) + ": left out " + removed + " (they draw nothing)").c_str());
  }
  return mesh;
}

} // namespace

std::string LowercaseExtension(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

vtkSmartPointer<vtkAlgorithm> NewVtkReader(const std::string& path)
{
  const std::string extension = LowercaseExtension(path);
  const auto make = [&path](auto reader) -> vtkSmartPointer<vtkAlgorithm> {
    reader->SetFileName(path.c_str());
    return reader;
  };
  if (extension == ".ply")
  {
    return make(vtkSmartPointer<vtkPLYReader>::New());
  }
  if (extension == ".obj")
  {
    return make(vtkSmartPointer<vtkOBJReader>::New());
  }
  if (extension == ".stl")
  {
    return make(vtkSmartPointer<vtkSTLReader>::New());
  }
  if (extension == ".vtp")
  {
    return make(vtkSmartPointer<vtkXMLPolyDataReader>::New());
  }
  if (extension == ".vtk")
  {
    return make(vtkSmartPointer<vtkPolyDataReader>::New());
  }
  return nullptr;
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  const std::string extension = LowercaseExtension(path);
  if (extension.empty())
  {
    throw RuntimeError(Quoted(path) + " has no extension; expected .ply, .obj, .stl, .vtp or .vtk");
  }
  const std::uint64_t bytes = RequireReadableFile(path);
  VtkErrorLog::Instance().Clear();
  vtkSmartPointer<vtkPolyData> mesh =
    ReadInSandbox(Quoted(path), path, ReadLimits::ForFileOfSize(bytes));
  // Again on this side: the child ran a reader on hostile bytes, and what it
  // sent is trusted no more than the file.
  RequireConsistentMesh(mesh, Quoted(path));
  // The reader's warnings now, so that they are not mistaken for later ones.
  for (const std::string& warning : VtkErrorLog::Instance().Warnings())
  {
    std::cerr << "silhouette: warning: " << PrintableText(warning) << "\n";
  }
  VtkErrorLog::Instance().Clear();
  return mesh;
}

vtkSmartPointer<vtkPolyData> ReadMeshInThisProcess(const std::string& path)
{
  return ReadWithVtk(path, LowercaseExtension(path));
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

void RefuseOverwritingInput(
  const std::string& input, const std::string& output, const std::string& option)
{
  std::error_code error;
  if (std::filesystem::exists(input, error) && std::filesystem::exists(output, error) &&
    std::filesystem::equivalent(input, output, error) && !error)
  {
    throw UsageError("option '" + option + "' names the input file " + Quoted(output) +
      ", which would be overwritten; write to another file");
  }
}

void CheckMeshOutputPath(const std::string& path)
{
  const std::string extension = LowercaseExtension(path);
  if (extension != ".vtp" && extension != ".ply")
  {
    throw UsageError("cannot write " + Quoted(path) + ": unknown output format '" + extension +
      "'; expected .vtp or .ply");
  }
  RequireOutputDirectory(path);
}

namespace
{

template<typename T>
void Put(std::ostream& out, T value)
{
  // PLY binary_little_endian, written as the machine stores it.
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "a little-endian machine");
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

void WriteOrAdd(const std::string& path, const std::string& bytes, FileBatch* batch)
{
  if (batch)
  {
    batch->Add(path, bytes);
  }
  else
  {
    WriteFileAtomically(path, bytes);
  }
}

// Our own PLY writer: vtkPLYWriter (VTK 9.1) cannot write normals, and the
// shading normals are what makes the smoothed mesh look smooth.
std::vector<std::string> WritePly(vtkPolyData* mesh, const std::string& path, FileBatch* batch)
{
  static_assert(sizeof(float) == 4 && sizeof(double) == 8, "IEEE floats");
  vtkPointData* pd = mesh->GetPointData();
  vtkDataArray* normals = pd->GetNormals();
  vtkDataArray* tcoords = pd->GetTCoords();
  if (tcoords && tcoords->GetNumberOfComponents() != 2)
  {
    tcoords = nullptr;
  }
  vtkUnsignedCharArray* colors = vtkUnsignedCharArray::SafeDownCast(pd->GetScalars());
  if (colors && colors->GetNumberOfComponents() != 3 && colors->GetNumberOfComponents() != 4)
  {
    colors = nullptr;
  }
  const bool doubles = mesh->GetPoints() && mesh->GetPoints()->GetDataType() == VTK_DOUBLE;
  std::vector<std::string> dropped;
  for (vtkFieldData* fd :
    { static_cast<vtkFieldData*>(pd), static_cast<vtkFieldData*>(mesh->GetCellData()) })
  {
    for (int a = 0; a < fd->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = fd->GetAbstractArray(a);
      if (array != normals && array != tcoords && array != colors)
      {
        dropped.push_back(array->GetName() ? array->GetName() : "(an unnamed array)");
      }
    }
  }
  if (mesh->GetNumberOfLines() > 0)
  {
    dropped.emplace_back("line cells");
  }
  if (mesh->GetNumberOfVerts() > 0)
  {
    dropped.emplace_back("vertex cells");
  }

  std::ostringstream out(std::ios::binary);
  const vtkIdType n = mesh->GetNumberOfPoints();
  out << "ply\nformat binary_little_endian 1.0\ncomment written by silhouette\n";
  out << "element vertex " << n << "\n";
  for (const char* axis : { "x", "y", "z" })
  {
    out << "property " << (doubles ? "double " : "float ") << axis << "\n";
  }
  if (normals)
  {
    out << "property float nx\nproperty float ny\nproperty float nz\n";
  }
  if (tcoords)
  {
    out << "property float u\nproperty float v\n";
  }
  if (colors)
  {
    out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (colors->GetNumberOfComponents() == 4)
    {
      out << "property uchar alpha\n";
    }
  }
  vtkCellArray* polys = mesh->GetPolys();
  out << "element face " << polys->GetNumberOfCells() << "\n";
  out << "property list uchar int vertex_indices\nend_header\n";
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (const double x : p)
    {
      if (doubles)
      {
        Put(out, x);
      }
      else
      {
        Put(out, static_cast<float>(x));
      }
    }
    if (normals)
    {
      double v[3];
      normals->GetTuple(i, v);
      for (const double x : v)
      {
        Put(out, static_cast<float>(x));
      }
    }
    if (tcoords)
    {
      Put(out, static_cast<float>(tcoords->GetComponent(i, 0)));
      Put(out, static_cast<float>(tcoords->GetComponent(i, 1)));
    }
    if (colors)
    {
      for (int k = 0; k < colors->GetNumberOfComponents(); ++k)
      {
        Put(out, colors->GetTypedComponent(i, k));
      }
    }
  }
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(count, ids);
    if (count > 255 || n > 2147483647)
    {
      throw RuntimeError("cannot write " + Quoted(path) +
        ": a polygon has more than 255 points or the mesh more than 2^31 points (write .vtp)");
    }
    Put(out, static_cast<unsigned char>(count));
    for (vtkIdType k = 0; k < count; ++k)
    {
      Put(out, static_cast<std::int32_t>(ids[k]));
    }
  }
  WriteOrAdd(path, std::move(out).str(), batch);
  return dropped;
}

} // namespace

std::vector<std::string> WriteMesh(vtkPolyData* mesh, const std::string& path, FileBatch* batch)
{
  CheckMeshOutputPath(path);
  if (LowercaseExtension(path) == ".ply")
  {
    return WritePly(mesh, path, batch);
  }
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkNew<vtkXMLPolyDataWriter> writer;
  errors.Watch(writer);
  writer->SetInputData(mesh);
  writer->WriteToOutputStringOn();
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToZLib();
  const int written = writer->Write();
  errors.ThrowIfErrors("cannot write " + Quoted(path));
  if (!written)
  {
    throw RuntimeError("cannot write " + Quoted(path) + ": VTK's XML writer failed");
  }
  WriteOrAdd(path, writer->GetOutputString(), batch);
  return {};
}

void CheckLinesOutputPath(const std::string& path)
{
  if (LowercaseExtension(path) != ".vtp")
  {
    throw UsageError("cannot write " + Quoted(path) + ": unknown format for polylines '" +
      LowercaseExtension(path) + "'; expected .vtp");
  }
  RequireOutputDirectory(path);
}

void WriteLines(vtkPolyData* lines, const std::string& path, FileBatch* batch)
{
  CheckLinesOutputPath(path);
  WriteMesh(lines, path, batch);
}

} // namespace cli
