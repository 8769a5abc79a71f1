#include "FileGeometry.h"

#include "CliErrors.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
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

bool SameValues(const double* inFile, const double* asRead, int count = 3)
{
  for (int c = 0; c < count; ++c)
  {
    if (!SameAsStored(inFile[c], asRead[c]))
    {
      return false;
    }
  }
  return true;
}

std::string Values(const double* v, int count = 3)
{
  std::ostringstream text;
  text.precision(9);
  text << "(";
  for (int c = 0; c < count; ++c)
  {
    text << (c ? ", " : "") << static_cast<float>(v[c]);
  }
  text << ")";
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
    this->CompareVertices(this->File.VertexOrderKept);
    const bool fileNumbering = this->CompareFaces();
    this->CompareCells(this->File.Strips, this->Read->GetStrips(), "triangle strip");
    this->CompareCells(this->File.Lines, this->Read->GetLines(), "line");
    this->CompareCells(this->File.Vertices, this->Read->GetVerts(), "vertex cell");
    // A reader whose faces use the file's vertex numbers kept the file's
    // vertices as its points: the ones no face uses are compared too (they
    // frame the view).
    if (!this->File.VertexOrderKept && fileNumbering &&
      this->Read->GetNumberOfPoints() == this->File.VertexCount())
    {
      this->CompareVertices(true);
    }
  }

private:
  [[noreturn]] void Differ(const std::string& what) const
  {
    throw RuntimeError(this->Prefix + what + "; the file is not read as written");
  }

  void CompareVertices(bool inOrder) const
  {
    if (!inOrder)
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
      if (!SameValues(inFile, asRead))
      {
        this->Differ("vertex " + std::to_string(i + this->File.FirstIndex) + " at " +
          Values(asRead) + " where the file puts it at " + Values(inFile));
      }
      if (compareNormals)
      {
        normals->GetTuple(i, asRead);
        if (!SameValues(&this->File.Normals[3 * i], asRead))
        {
          this->Differ("vertex " + std::to_string(i + this->File.FirstIndex) + "'s normal as " +
            Values(asRead) + " where the file gives " + Values(&this->File.Normals[3 * i]));
        }
      }
    }
  }

  // The point data a corner of the file is compared against: the reader's
  // normals and texture coordinates.
  struct CornerAttribute
  {
    const char* Name;
    const std::vector<std::int64_t>& Corners;
    const std::vector<double>& Table;
    int Width;
    vtkDataArray* Read;
  };

  std::vector<CornerAttribute> CornerAttributes() const
  {
    std::vector<CornerAttribute> attributes;
    vtkPointData* data = this->Read->GetPointData();
    vtkDataArray* normals = data->GetNormals();
    if (!this->File.CornerNormals.empty() && normals && normals->GetNumberOfComponents() == 3 &&
      normals->GetNumberOfTuples() > 0)
    {
      attributes.push_back(
        { "normal", this->File.CornerNormals, this->File.NormalTable, 3, normals });
    }
    vtkDataArray* textures = data->GetTCoords();
    if (!this->File.CornerTextures.empty() && textures && textures->GetNumberOfComponents() == 2 &&
      textures->GetNumberOfTuples() > 0)
    {
      attributes.push_back(
        { "texture coordinate", this->File.CornerTextures, this->File.TextureTable, 2, textures });
    }
    return attributes;
  }

  void CompareCornerAttributes(const std::vector<CornerAttribute>& attributes, std::int64_t face,
    std::int64_t corner, vtkIdType readId, std::int64_t fileCorner) const
  {
    for (const CornerAttribute& attribute : attributes)
    {
      const std::int64_t entry = attribute.Corners[fileCorner];
      if (entry < 0)
      {
        continue;
      }
      const double* inFile = &attribute.Table[attribute.Width * entry];
      double asRead[3] = { 0.0, 0.0, 0.0 };
      // An array shorter than the points shows its last value.
      const vtkIdType tuples = attribute.Read->GetNumberOfTuples();
      attribute.Read->GetTuple(std::min<vtkIdType>(readId, tuples - 1), asRead);
      if (readId >= tuples || !SameValues(inFile, asRead, attribute.Width))
      {
        this->Differ(this->CornerName(face, corner) + " with the " + attribute.Name + " " +
          Values(asRead, attribute.Width) + " where the file gives it " + attribute.Name + " " +
          std::to_string(entry + this->File.FirstIndex) + " " + Values(inFile, attribute.Width));
      }
    }
  }

  std::string FaceName(std::int64_t face) const
  {
    std::string name = "face " + std::to_string(face + this->File.FirstIndex);
    if (!this->File.FaceLines.empty())
    {
      name += " (line " + std::to_string(this->File.FaceLines[face]) + ")";
    }
    return name;
  }

  std::string CornerName(std::int64_t face, std::int64_t corner) const
  {
    return "corner " + std::to_string(corner + this->File.FirstIndex) + " of " +
      this->FaceName(face);
  }

  // Returns whether every corner the reader gave uses the file's number for
  // its vertex.
  bool CompareFaces() const
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
      return true;
    }
    bool fileNumbering = true;
    const std::vector<CornerAttribute> attributes = this->CornerAttributes();
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
        this->Differ(this->FaceName(face) + " with " + std::to_string(size) +
          " corners where the file gives it " + std::to_string(corners));
      }
      for (std::int64_t k = 0; k < corners; ++k)
      {
        this->CompareCorner(face, k, ids[k], this->File.FaceCorners[start + k]);
        this->CompareCornerAttributes(attributes, face, k, ids[k], start + k);
        fileNumbering = fileNumbering && ids[k] == this->File.FaceCorners[start + k];
      }
    }
    return fileNumbering;
  }

  // Cells of another kind than faces, by position only.
  void CompareCells(const FileCells& file, vtkCellArray* cells, const std::string& kind) const
  {
    if (!file.Given)
    {
      return;
    }
    const std::int64_t count = file.Count();
    const std::int64_t read = cells ? cells->GetNumberOfCells() : 0;
    if (read != count)
    {
      this->Differ(std::to_string(read) + " " + kind + (read == 1 ? "" : "s") +
        " where the file holds " + std::to_string(count));
    }
    if (count == 0)
    {
      return;
    }
    auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
    std::int64_t cell = 0;
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal();
         iterator->GoToNextCell(), ++cell)
    {
      vtkIdType size = 0;
      const vtkIdType* ids = nullptr;
      iterator->GetCurrentCell(size, ids);
      const std::int64_t start = file.Starts[cell];
      const std::int64_t corners = file.Starts[cell + 1] - start;
      const std::string name = kind + " " + std::to_string(cell + this->File.FirstIndex);
      if (size != corners)
      {
        this->Differ(name + " with " + std::to_string(size) + " points where the file gives it " +
          std::to_string(corners));
      }
      for (std::int64_t k = 0; k < corners; ++k)
      {
        const std::int64_t fileVertex = file.Corners[start + k];
        const bool inFile = fileVertex >= 0 && fileVertex < this->File.VertexCount();
        double asRead[3] = { 0.0, 0.0, 0.0 };
        const bool exists = ids[k] >= 0 && ids[k] < this->Read->GetNumberOfPoints();
        if (exists)
        {
          this->Read->GetPoint(ids[k], asRead);
        }
        if (inFile && (!exists || !SameValues(&this->File.Positions[3 * fileVertex], asRead)))
        {
          this->Differ("point " + std::to_string(k + this->File.FirstIndex) + " of " + name +
            (exists ? " at " + Values(asRead) : " as a point it does not have") +
            " where the file puts it at vertex " +
            std::to_string(fileVertex + this->File.FirstIndex) + " " +
            Values(&this->File.Positions[3 * fileVertex]));
        }
      }
    }
  }

  void CompareCorner(
    std::int64_t face, std::int64_t corner, vtkIdType readId, std::int64_t fileVertex) const
  {
    if (fileVertex < 0 || fileVertex >= this->File.VertexCount())
    {
      return; // no vertex of the file: validation refuses the id, with its own message
    }
    const double* inFile = &this->File.Positions[3 * fileVertex];
    double asRead[3] = { 0.0, 0.0, 0.0 };
    const bool exists = readId >= 0 && readId < this->Read->GetNumberOfPoints();
    if (exists)
    {
      this->Read->GetPoint(readId, asRead);
    }
    if (!exists || !SameValues(inFile, asRead))
    {
      this->Differ(this->CornerName(face, corner) +
        (exists ? " at " + Values(asRead)
                : " as point " + std::to_string(readId) + ", which it does not have,") +
        " where the file puts it at vertex " + std::to_string(fileVertex + this->File.FirstIndex) +
        " " + Values(inFile));
    }
  }

  const FileGeometry& File;
  vtkPolyData* Read;
  std::string Prefix;
};

} // namespace

std::string JoinTextureCoordinateArrays(vtkPolyData* read)
{
  vtkPointData* data = read->GetPointData();
  std::vector<vtkDataArray*> arrays;
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetArray(a);
    if (array && array->GetNumberOfComponents() == 2 && array != data->GetNormals())
    {
      arrays.push_back(array);
    }
  }
  if (arrays.size() < 2)
  {
    return "";
  }
  vtkNew<vtkFloatArray> joined;
  joined->SetName("TCoords");
  joined->SetNumberOfComponents(2);
  joined->SetNumberOfTuples(read->GetNumberOfPoints());
  std::string names;
  for (vtkIdType p = 0; p < read->GetNumberOfPoints(); ++p)
  {
    double uv[2] = { -1.0, -1.0 };
    for (vtkDataArray* array : arrays)
    {
      double value[2];
      array->GetTuple(p, value);
      if (value[0] != -1.0 || value[1] != -1.0)
      {
        uv[0] = value[0];
        uv[1] = value[1];
        break;
      }
    }
    joined->SetTuple(p, uv);
  }
  for (vtkDataArray* array : arrays)
  {
    names +=
      (names.empty() ? "'" : ", '") + std::string(array->GetName() ? array->GetName() : "") + "'";
    data->RemoveArray(array->GetName());
  }
  data->SetTCoords(joined);
  return names;
}

std::string DropUnnamedCornerData(const FileGeometry& file, vtkPolyData* read)
{
  const auto unnamed = [](const std::vector<double>& table,
                         const std::vector<std::int64_t>& corners) {
    return !table.empty() &&
      std::all_of(corners.begin(), corners.end(), [](std::int64_t e) { return e < 0; });
  };
  std::string dropped;
  vtkPointData* data = read->GetPointData();
  if (unnamed(file.NormalTable, file.CornerNormals) && data->GetNormals())
  {
    data->SetNormals(nullptr);
    dropped = "normals ('vn')";
  }
  if (unnamed(file.TextureTable, file.CornerTextures) && data->GetTCoords())
  {
    data->SetTCoords(nullptr);
    dropped += (dropped.empty() ? "" : " and ") + std::string("texture coordinates ('vt')");
  }
  return dropped;
}

std::string CellsLeftOut(const FileGeometry& file, vtkPolyData* read)
{
  std::string lost;
  const auto count = [&lost](std::int64_t inFile, std::int64_t asRead, const char* kind) {
    if (inFile > asRead)
    {
      lost += (lost.empty() ? "" : " and ") + std::to_string(inFile - asRead) + " of its " +
        std::to_string(inFile) + " " + kind;
    }
  };
  if (file.LineCells >= 0)
  {
    count(file.LineCells, read->GetNumberOfLines(), "lines ('l')");
  }
  if (file.VertexCells >= 0)
  {
    count(file.VertexCells, read->GetNumberOfVerts(), "point cells ('p')");
  }
  return lost;
}

void RequireReadAsWritten(const FileGeometry& file, vtkPolyData* read, const std::string& path,
  const std::string& readerName)
{
  Comparison(file, read, path, readerName).Run();
}

} // namespace cli
