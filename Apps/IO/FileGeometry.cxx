#include "FileGeometry.h"

#include "CliErrors.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <sstream>

namespace cli
{
namespace
{

bool SameAsStored(double inFile, double asRead)
{
  const auto file = static_cast<float>(inFile);
  const auto read = static_cast<float>(asRead);
  return file == read || (std::isnan(file) && std::isnan(read));
}

bool SameTriple(const double* inFile, const double* asRead)
{
  return SameAsStored(inFile[0], asRead[0]) && SameAsStored(inFile[1], asRead[1]) &&
    SameAsStored(inFile[2], asRead[2]);
}

std::string Triple(const double* v)
{
  std::ostringstream text;
  text.precision(9);
  text << "(" << static_cast<float>(v[0]) << ", " << static_cast<float>(v[1]) << ", "
       << static_cast<float>(v[2]) << ")";
  return text.str();
}

class Comparison
{
public:
  Comparison(const FileGeometry& file, vtkPolyData* read, const std::string& path,
    const std::string& readerName)
    : File(file)
    , Read(read)
    , Prefix("cannot read '" + path + "': " + readerName + " read ")
  {
  }

  void Run() const
  {
    this->CompareVertices();
    this->CompareFaces();
  }

private:
  [[noreturn]] void Differ(const std::string& what) const
  {
    throw RuntimeError(this->Prefix + what + "; the file is not read as written");
  }

  void CompareVertices() const
  {
    if (!this->File.VertexOrderKept)
    {
      return;
    }
    const std::int64_t count = this->File.VertexCount();
    const std::int64_t read = this->Read->GetNumberOfPoints();
    if (read < count)
    {
      this->Differ(std::to_string(read) + " of the file's " + std::to_string(count) + " vertices");
    }
    vtkDataArray* normals = this->Read->GetPointData()->GetNormals();
    const bool compareNormals = !this->File.Normals.empty() && normals &&
      normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() >= count;
    for (std::int64_t i = 0; i < count; ++i)
    {
      double asRead[3];
      this->Read->GetPoint(i, asRead);
      const double* inFile = &this->File.Positions[3 * i];
      if (!SameTriple(inFile, asRead))
      {
        this->Differ("vertex " + std::to_string(i) + " at " + Triple(asRead) +
          " where the file puts it at " + Triple(inFile));
      }
      if (compareNormals)
      {
        normals->GetTuple(i, asRead);
        if (!SameTriple(&this->File.Normals[3 * i], asRead))
        {
          this->Differ("vertex " + std::to_string(i) + "'s normal as " + Triple(asRead) +
            " where the file gives " + Triple(&this->File.Normals[3 * i]));
        }
      }
    }
  }

  void CompareFaces() const
  {
    vtkCellArray* polys = this->Read->GetPolys();
    const std::int64_t count = this->File.FaceCount();
    const std::int64_t read = polys ? polys->GetNumberOfCells() : 0;
    if (read != count)
    {
      this->Differ(std::to_string(read) + (read == 1 ? " face" : " faces") +
        " where the file holds " + std::to_string(count));
    }
    if (count == 0)
    {
      return;
    }
    auto cells = vtk::TakeSmartPointer(polys->NewIterator());
    std::int64_t face = 0;
    for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++face)
    {
      vtkIdType size = 0;
      const vtkIdType* ids = nullptr;
      cells->GetCurrentCell(size, ids);
      const std::int64_t start = this->File.FaceStarts[face];
      const std::int64_t corners = this->File.FaceStarts[face + 1] - start;
      if (size != corners)
      {
        this->Differ("face " + std::to_string(face) + " with " + std::to_string(size) +
          " corners where the file gives it " + std::to_string(corners));
      }
      for (std::int64_t k = 0; k < corners; ++k)
      {
        this->CompareCorner(face, k, ids[k], this->File.FaceCorners[start + k]);
      }
    }
  }

  void CompareCorner(
    std::int64_t face, std::int64_t corner, vtkIdType readId, std::int64_t fileVertex) const
  {
    const double* inFile = &this->File.Positions[3 * fileVertex];
    double asRead[3] = { 0.0, 0.0, 0.0 };
    const bool exists = readId >= 0 && readId < this->Read->GetNumberOfPoints();
    if (exists)
    {
      this->Read->GetPoint(readId, asRead);
    }
    if (!exists || !SameTriple(inFile, asRead))
    {
      this->Differ("corner " + std::to_string(corner) + " of face " + std::to_string(face) +
        (exists ? " at " + Triple(asRead)
                : " as point " + std::to_string(readId) + ", which it does not have,") +
        " where the file puts it at vertex " + std::to_string(fileVertex) + " " + Triple(inFile));
    }
  }

  const FileGeometry& File;
  vtkPolyData* Read;
  std::string Prefix;
};

} // namespace

void RequireReadAsWritten(const FileGeometry& file, vtkPolyData* read, const std::string& path,
  const std::string& readerName)
{
  Comparison(file, read, path, readerName).Run();
}

} // namespace cli
