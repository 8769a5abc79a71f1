#include "vtkOpenSubdivRefiner.h"

#include "vtkOpenSubdivBaseMesh.h"
#include "vtkSilhouetteFilterSupport.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOpenSubdivRefiner);

vtkSilhouetteCheckedSetterMacro(vtkOpenSubdivRefiner, FeatureAngle, double, 0.0, 180.0);

namespace
{

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// OpenSubdiv's primvar interface over an interleaved buffer of doubles: one
// vertex is `Size` values (x, y, z, then every carried point-array component).
struct VertexRef
{
  double* Data;
  int Size;

  void Clear() { std::fill(this->Data, this->Data + this->Size, 0.0); }
  void AddWithWeight(const VertexRef& source, double weight)
  {
    for (int i = 0; i < this->Size; ++i)
    {
      this->Data[i] += weight * source.Data[i];
    }
  }
};

struct VertexBuffer
{
  double* Data;
  int Stride;

  VertexRef operator[](int index) const
  {
    return { this->Data + static_cast<std::size_t>(index) * this->Stride, this->Stride };
  }
};

// Destination of a limit tangent: only the x, y, z of the source vertices.
struct TangentRef
{
  double* Data;

  void Clear() { this->Data[0] = this->Data[1] = this->Data[2] = 0.0; }
  void AddWithWeight(const VertexRef& source, double weight)
  {
    this->Data[0] += weight * source.Data[0];
    this->Data[1] += weight * source.Data[1];
    this->Data[2] += weight * source.Data[2];
  }
};

struct TangentBuffer
{
  double* Data;

  TangentRef operator[](int index) const
  {
    return { this->Data + 3 * static_cast<std::size_t>(index) };
  }
};

// A point array carried through the refinement.
struct CarriedArray
{
  vtkDataArray* Input;
  int Offset;    // first component in the interleaved vertex
  int Attribute; // vtkDataSetAttributes::AttributeTypes, or -1
};

bool IsIntegerType(int dataType)
{
  return dataType != VTK_FLOAT && dataType != VTK_DOUBLE;
}

} // namespace

namespace
{

using namespace vtkOpenSubdivBaseMesh;

// Step 7: the primvars, positions and the carried point arrays interleaved
// (Stride doubles per vertex), at the base vertices; then refined.
struct Primvars
{
  std::vector<CarriedArray> Carried;
  int Stride = 3;
  std::vector<double> Values;
  std::vector<double> Tangents; ///< the limit's two tangents per vertex, after Refine
};

Primvars BasePrimvars(vtkPointData* inPD, const BaseMesh& base)
{
  Primvars primvars;
  vtkDataArray* inNormals = inPD->GetNormals();
  for (int i = 0; i < inPD->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = inPD->GetArray(i);
    if (!array || array == inNormals ||
      (array->GetName() && std::string(array->GetName()) == "Normals"))
    {
      continue; // normals are made anew, from the limit
    }
    primvars.Carried.push_back({ array, primvars.Stride, inPD->IsArrayAnAttribute(i) });
    primvars.Stride += array->GetNumberOfComponents();
  }
  const int stride = primvars.Stride;
  primvars.Values.resize(static_cast<std::size_t>(base.numBase()) * stride);
  for (int v = 0; v < base.numBase(); ++v)
  {
    double* vertex = &primvars.Values[static_cast<std::size_t>(v) * stride];
    std::copy_n(&base.Positions[3 * v], 3, vertex);
    for (const CarriedArray& c : primvars.Carried)
    {
      c.Input->GetTuple(base.BasePoint[static_cast<std::size_t>(v)], vertex + c.Offset);
    }
  }
  return primvars;
}

// Interpolates the primvars level by level, then (with `limit`) projects
// them and takes the limit tangents. `proceed(level)` reports progress and
// returns false to stop (an abort); so does this function then.
bool RefinePrimvars(const Far::TopologyRefiner& refiner, int level, bool limit, Primvars& primvars,
  const std::function<bool(int)>& proceed)
{
  Far::PrimvarRefinerReal<double> primvarRefiner(refiner);
  const int stride = primvars.Stride;
  std::vector<double> next;
  for (int l = 1; l <= level; ++l)
  {
    if (!proceed(l - 1))
    {
      return false;
    }
    next.assign(static_cast<std::size_t>(refiner.GetLevel(l).GetNumVertices()) * stride, 0.0);
    const VertexBuffer source{ primvars.Values.data(), stride };
    VertexBuffer destination{ next.data(), stride };
    primvarRefiner.Interpolate(l, source, destination);
    primvars.Values.swap(next);
  }
  proceed(level);
  if (limit)
  {
    const int numVertices = refiner.GetLevel(level).GetNumVertices();
    next.assign(primvars.Values.size(), 0.0);
    primvars.Tangents.assign(6 * static_cast<std::size_t>(numVertices), 0.0);
    const VertexBuffer source{ primvars.Values.data(), stride };
    VertexBuffer destination{ next.data(), stride };
    TangentBuffer tangent1{ primvars.Tangents.data() };
    TangentBuffer tangent2{ primvars.Tangents.data() + 3 * static_cast<std::size_t>(numVertices) };
    primvarRefiner.Limit(source, destination, tangent1, tangent2);
    primvars.Values.swap(next);
  }
  return true;
}

// Step 8: the last level's triangles, and per triangle the input cell of its
// base face (`OriginalCellId`). Empty string, or the error.
std::string WriteTriangles(const Far::TopologyRefiner& refiner, int level,
  const std::vector<vtkIdType>& triangleCell, vtkPolyData* output, vtkIdTypeArray* originalCellIds)
{
  const Far::TopologyLevel& last = refiner.GetLevel(level);
  const int numFaces = last.GetNumFaces();
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numFaces + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(numFaces));
  originalCellIds->SetName("OriginalCellId");
  originalCellIds->SetNumberOfValues(numFaces);
  for (int f = 0; f < numFaces; ++f)
  {
    const Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    if (vertices.size() != 3)
    {
      return "OpenSubdiv returned a refined face with " + std::to_string(vertices.size()) +
        " vertices.";
    }
    offsets->SetValue(f, 3 * static_cast<vtkIdType>(f));
    for (int k = 0; k < 3; ++k)
    {
      connectivity->SetValue(3 * static_cast<vtkIdType>(f) + k, vertices[k]);
    }
    int parent = f;
    for (int l = level; l > 0; --l)
    {
      parent = refiner.GetLevel(l).GetFaceParentFace(parent);
    }
    originalCellIds->SetValue(f, triangleCell[static_cast<std::size_t>(parent)]);
  }
  offsets->SetValue(numFaces, 3 * static_cast<vtkIdType>(numFaces));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);
  return "";
}

// Step 9: the points, of `pointsType`.
void WritePoints(const Primvars& primvars, int numVertices, int pointsType, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(pointsType);
  points->SetNumberOfPoints(numVertices);
  for (int v = 0; v < numVertices; ++v)
  {
    points->SetPoint(v, &primvars.Values[static_cast<std::size_t>(v) * primvars.Stride]);
  }
  output->SetPoints(points);
}

// The limit normals (the cross product of the limit tangents), oriented like
// the refined triangles around each vertex, whose area-weighted normal
// stands in where the tangents are parallel. Returns the counts of flipped
// normals and of such stand-ins.
std::pair<vtkIdType, vtkIdType> WriteLimitNormals(
  const Far::TopologyLevel& last, const Primvars& primvars, int pointsType, vtkPointData* outPD)
{
  const int numVertices = last.GetNumVertices();
  const int stride = primvars.Stride;
  std::vector<Vector> meshNormals(static_cast<std::size_t>(numVertices), Vector{ 0, 0, 0 });
  for (int f = 0; f < last.GetNumFaces(); ++f)
  {
    const Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    const double* p0 = &primvars.Values[static_cast<std::size_t>(vertices[0]) * stride];
    const double* p1 = &primvars.Values[static_cast<std::size_t>(vertices[1]) * stride];
    const double* p2 = &primvars.Values[static_cast<std::size_t>(vertices[2]) * stride];
    const Vector n = Cross(Sub(p1, p0), Sub(p2, p0));
    for (int k = 0; k < 3; ++k)
    {
      Vector& m = meshNormals[static_cast<std::size_t>(vertices[k])];
      m = { m[0] + n[0], m[1] + n[1], m[2] + n[2] };
    }
  }
  auto normals = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(pointsType));
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(numVertices);
  vtkIdType flipped = 0;
  vtkIdType fallbacks = 0;
  for (int v = 0; v < numVertices; ++v)
  {
    const double* t1 = &primvars.Tangents[3 * static_cast<std::size_t>(v)];
    const double* t2 = &primvars.Tangents[3 * (static_cast<std::size_t>(numVertices) + v)];
    const Vector tangent1{ t1[0], t1[1], t1[2] };
    const Vector tangent2{ t2[0], t2[1], t2[2] };
    const Vector& meshNormal = meshNormals[static_cast<std::size_t>(v)];
    Vector n = Cross(tangent1, tangent2);
    double length = Norm(n);
    if (!(length > 1e-12 * Norm(tangent1) * Norm(tangent2)))
    {
      n = meshNormal;
      length = Norm(n);
      ++fallbacks;
    }
    else if (Dot(n, meshNormal) < 0.0)
    {
      n = { -n[0], -n[1], -n[2] };
      ++flipped;
    }
    if (length > 0.0)
    {
      n = { n[0] / length, n[1] / length, n[2] / length };
    }
    normals->SetTuple(v, n.data());
  }
  outPD->SetNormals(normals);
  return { flipped, fallbacks };
}

// Step 10: the carried point arrays, back in their own types (integers
// rounded and clamped to their type's range), attributes kept.
void WriteCarriedArrays(const Primvars& primvars, int numVertices, vtkPointData* outPD)
{
  std::vector<double> tuple;
  for (const CarriedArray& c : primvars.Carried)
  {
    const int components = c.Input->GetNumberOfComponents();
    auto array = vtk::TakeSmartPointer(c.Input->NewInstance());
    array->SetName(c.Input->GetName());
    array->SetNumberOfComponents(components);
    array->CopyComponentNames(c.Input);
    array->SetNumberOfTuples(numVertices);
    const bool integer = IsIntegerType(c.Input->GetDataType());
    const double lowest = c.Input->GetDataTypeMin();
    const double highest = c.Input->GetDataTypeMax();
    tuple.resize(static_cast<std::size_t>(components));
    for (int v = 0; v < numVertices; ++v)
    {
      const double* values =
        &primvars.Values[static_cast<std::size_t>(v) * primvars.Stride + c.Offset];
      if (integer)
      {
        for (int k = 0; k < components; ++k)
        {
          tuple[k] = std::min(highest, std::max(lowest, std::round(values[k])));
        }
        array->SetTuple(v, tuple.data());
      }
      else
      {
        array->SetTuple(v, values);
      }
    }
    const int index = outPD->AddArray(array);
    if (c.Attribute >= 0)
    {
      outPD->SetActiveAttribute(index, c.Attribute);
    }
  }
}

// Step 11: the cell data, each refined triangle with its input cell's
// values, and `OriginalCellId`.
void WriteCellData(vtkCellData* inCD, vtkIdTypeArray* originalCellIds, vtkCellData* outCD)
{
  const vtkIdType numFaces = originalCellIds->GetNumberOfValues();
  outCD->CopyNormalsOff();
  outCD->CopyFieldOff("OriginalCellId");
  outCD->CopyAllocate(inCD, numFaces);
  if (inCD->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> fromIds;
    fromIds->SetNumberOfIds(numFaces);
    vtkNew<vtkIdList> toIds;
    toIds->SetNumberOfIds(numFaces);
    for (vtkIdType f = 0; f < numFaces; ++f)
    {
      fromIds->SetId(f, originalCellIds->GetValue(f));
      toIds->SetId(f, f);
    }
    outCD->CopyData(inCD, fromIds, toIds);
  }
  outCD->AddArray(originalCellIds);
}

} // namespace

int vtkOpenSubdivRefiner::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  if (!input)
  {
    return 1;
  }

  TriangleCells read = ReadTriangleCells(input);
  if (!read.Error.empty())
  {
    vtkErrorMacro(<< read.Error);
    return 0;
  }
  if (read.Dropped > 0)
  {
    vtkWarningMacro("Dropped " << read.Dropped
                               << " degenerate triangle(s) or polygon(s) (repeated point ids or "
                                  "fewer than 3 points).");
  }
  if (read.Triangles.empty())
  {
    return 1; // empty in, empty out
  }
  // 2. OpenSubdiv indexes with int: the refined mesh must fit.
  const double lastLevelFaceVertices =
    3.0 * static_cast<double>(read.Triangles.size()) * std::pow(4.0, this->Level);
  if (lastLevelFaceVertices >= static_cast<double>(std::numeric_limits<int>::max()))
  {
    vtkErrorMacro("The refined mesh (" << read.Triangles.size() << " triangles times 4^"
                                       << this->Level
                                       << ") is too large for OpenSubdiv's 32-bit indices.");
    return 0;
  }

  BaseMesh base;
  EdgeList edges;
  std::string error = MakeBaseMesh(input, read.Triangles, base);
  if (error.empty())
  {
    error = CollectEdges(base, read.Cells, edges);
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  const CreaseEdges creases = FindCreases(input, base, edges, this->FeatureAngle);
  if (creases.Ignored > 0)
  {
    vtkWarningMacro("Ignored " << creases.Ignored
                               << " crease segment(s) of the input lines that are not edges of "
                                  "the triangle mesh.");
  }
  vtkDebugMacro(<< creases.count() << " crease edges.");

  const int level = this->Level;
  const std::unique_ptr<Far::TopologyRefiner> refiner =
    MakeRefiner(base, creases, level, this->ProjectToLimit);
  if (!refiner)
  {
    vtkErrorMacro("OpenSubdiv could not build the topology of the input mesh.");
    return 0;
  }
  this->UpdateProgress(0.1);

  Primvars primvars = BasePrimvars(input->GetPointData(), base);
  const bool finished = RefinePrimvars(*refiner, level, this->ProjectToLimit, primvars, [&](int l) {
    if (l > 0)
    {
      this->UpdateProgress(0.1 + 0.7 * l / level);
    }
    return !this->GetAbortExecute();
  });
  if (!finished)
  {
    return 1; // aborted: the output stays empty
  }

  vtkNew<vtkIdTypeArray> originalCellIds;
  error = WriteTriangles(*refiner, level, read.Cells, output, originalCellIds);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    output->Initialize();
    return 0;
  }
  int pointsType = VTK_DOUBLE;
  if (this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION ||
    (this->OutputPointsPrecision == vtkAlgorithm::DEFAULT_PRECISION &&
      input->GetPoints()->GetDataType() == VTK_FLOAT))
  {
    pointsType = VTK_FLOAT;
  }
  const Far::TopologyLevel& last = refiner->GetLevel(level);
  WritePoints(primvars, last.GetNumVertices(), pointsType, output);
  if (this->ProjectToLimit)
  {
    const auto [flipped, fallbacks] =
      WriteLimitNormals(last, primvars, pointsType, output->GetPointData());
    vtkDebugMacro(<< flipped << " limit normals flipped to the triangles' side, " << fallbacks
                  << " taken from the triangles.");
  }
  WriteCarriedArrays(primvars, last.GetNumVertices(), output->GetPointData());
  WriteCellData(input->GetCellData(), originalCellIds, output->GetCellData());
  this->UpdateProgress(1.0);
  return 1;
}

void vtkOpenSubdivRefiner::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "ProjectToLimit: " << (this->ProjectToLimit ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
