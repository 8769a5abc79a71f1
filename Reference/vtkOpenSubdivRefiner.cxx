#include "vtkOpenSubdivRefiner.h"

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
#include <limits>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOpenSubdivRefiner);

vtkSilhouetteCheckedSetterMacro(vtkOpenSubdivRefiner, FeatureAngle, double, 0.0, 180.0);

vtkTypeBool vtkOpenSubdivRefiner::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  return vtkSilhouetteFilterSupport::GuardRequest(this, request, inputs, outputs,
    [&] { return static_cast<int>(this->Superclass::ProcessRequest(request, inputs, outputs)); });
}

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

using Triangle = std::array<vtkIdType, 3>;
using Vector = std::array<double, 3>;

Vector Sub(const double* a, const double* b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

Vector Cross(const Vector& a, const Vector& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double Norm(const Vector& a)
{
  return std::sqrt(Dot(a, a));
}

std::uint64_t EdgeKey(int a, int b)
{
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

// One use of an undirected edge by a triangle, for sorting.
struct EdgeUse
{
  std::uint64_t Key;
  int Triangle;
  bool Forward; // the triangle runs from the lower to the higher base index
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
  const vtkIdType numPoints = input->GetNumberOfPoints();

  // 1. Triangles, with the input cell each came from.
  std::vector<Triangle> triangles;
  std::vector<vtkIdType> triangleCell;
  vtkIdType droppedCells = 0;
  vtkIdType badCell = -1;
  vtkIdType badPoint = -1;
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType cellId) {
    if (a == b || b == c || c == a)
    {
      ++droppedCells;
      return;
    }
    triangles.push_back({ a, b, c });
    triangleCell.push_back(cellId);
  };
  auto validIds = [&](vtkIdType npts, const vtkIdType* pts, vtkIdType cellId) {
    for (vtkIdType i = 0; i < npts; ++i)
    {
      if (pts[i] < 0 || pts[i] >= numPoints)
      {
        badCell = cellId;
        badPoint = pts[i];
        return false;
      }
    }
    return true;
  };
  const vtkIdType numVerts = input->GetNumberOfVerts();
  const vtkIdType numLines = input->GetNumberOfLines();
  const vtkIdType numPolys = input->GetNumberOfPolys();
  {
    vtkIdType cellId = numVerts + numLines;
    auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
    for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cellId)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      polys->GetCurrentCell(npts, pts);
      if (!validIds(npts, pts, cellId))
      {
        break;
      }
      if (npts < 3)
      {
        ++droppedCells;
      }
      for (vtkIdType i = 1; i + 1 < npts; ++i)
      {
        addTriangle(pts[0], pts[i], pts[i + 1], cellId);
      }
    }
  }
  if (badCell < 0)
  {
    vtkIdType cellId = numVerts + numLines + numPolys;
    auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
    for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cellId)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      strips->GetCurrentCell(npts, pts);
      if (!validIds(npts, pts, cellId))
      {
        break;
      }
      if (npts < 3)
      {
        ++droppedCells;
      }
      for (vtkIdType i = 0; i + 2 < npts; ++i)
      {
        if (i % 2 == 0)
        {
          addTriangle(pts[i], pts[i + 1], pts[i + 2], cellId);
        }
        else
        {
          addTriangle(pts[i + 1], pts[i], pts[i + 2], cellId);
        }
      }
    }
  }
  if (badCell < 0)
  {
    vtkIdType cellId = numVerts;
    auto lines = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
    for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell(), ++cellId)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      lines->GetCurrentCell(npts, pts);
      if (!validIds(npts, pts, cellId))
      {
        break;
      }
    }
  }
  if (badCell >= 0)
  {
    vtkErrorMacro("Cell " << badCell << " refers to point " << badPoint << ", but the input has "
                          << numPoints << " points.");
    return 0;
  }
  if (droppedCells > 0)
  {
    vtkWarningMacro("Dropped " << droppedCells
                               << " degenerate triangle(s) or polygon(s) (repeated point ids or "
                                  "fewer than 3 points).");
  }
  if (triangles.empty())
  {
    return 1; // empty in, empty out
  }

  // 2. OpenSubdiv indexes with int: the refined mesh must fit.
  const double lastLevelFaceVertices =
    3.0 * static_cast<double>(triangles.size()) * std::pow(4.0, this->Level);
  if (lastLevelFaceVertices >= static_cast<double>(std::numeric_limits<int>::max()))
  {
    vtkErrorMacro("The refined mesh (" << triangles.size() << " triangles times 4^" << this->Level
                                       << ") is too large for OpenSubdiv's 32-bit indices.");
    return 0;
  }

  // 3. The points used by triangles become OpenSubdiv's base vertices, in order
  // of first use; their coordinates must be finite.
  vtkPoints* inPoints = input->GetPoints();
  std::vector<int> baseIndex(static_cast<std::size_t>(numPoints), -1);
  std::vector<vtkIdType> basePoint;
  std::vector<int> faceVertices;
  faceVertices.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
  {
    for (vtkIdType id : t)
    {
      int& index = baseIndex[static_cast<std::size_t>(id)];
      if (index < 0)
      {
        double p[3];
        inPoints->GetPoint(id, p);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        {
          vtkErrorMacro("Point " << id << " has a NaN or infinite coordinate.");
          return 0;
        }
        index = static_cast<int>(basePoint.size());
        basePoint.push_back(id);
      }
      faceVertices.push_back(index);
    }
  }
  const int numBase = static_cast<int>(basePoint.size());
  const int numTriangles = static_cast<int>(triangles.size());
  std::vector<double> basePositions(3 * static_cast<std::size_t>(numBase));
  for (int v = 0; v < numBase; ++v)
  {
    inPoints->GetPoint(basePoint[static_cast<std::size_t>(v)], &basePositions[3 * v]);
  }

  // 4. Edges: each in one or two triangles, used in opposite directions.
  std::vector<EdgeUse> uses;
  uses.reserve(faceVertices.size());
  for (int t = 0; t < numTriangles; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = faceVertices[3 * t + k];
      const int b = faceVertices[3 * t + (k + 1) % 3];
      uses.push_back({ EdgeKey(a, b), t, a < b });
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.Key < y.Key || (x.Key == y.Key && x.Triangle < y.Triangle);
  });
  std::vector<std::uint64_t> edgeKeys;
  std::vector<std::array<int, 2>> edgeTriangles;
  for (std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].Key == uses[i].Key)
    {
      ++j;
    }
    const vtkIdType pointA = basePoint[static_cast<std::size_t>(uses[i].Key >> 32)];
    const vtkIdType pointB = basePoint[static_cast<std::size_t>(uses[i].Key & 0xffffffffu)];
    if (j - i > 2)
    {
      vtkErrorMacro("Non-manifold input: the edge between points "
        << pointA << " and " << pointB << " is shared by " << (j - i) << " triangles.");
      return 0;
    }
    if (j - i == 2 && uses[i].Forward == uses[i + 1].Forward)
    {
      vtkErrorMacro("Inconsistent orientation: cells "
        << triangleCell[static_cast<std::size_t>(uses[i].Triangle)] << " and "
        << triangleCell[static_cast<std::size_t>(uses[i + 1].Triangle)]
        << " run through the edge between points " << pointA << " and " << pointB
        << " in the same direction.");
      return 0;
    }
    edgeKeys.push_back(uses[i].Key);
    edgeTriangles.push_back({ uses[i].Triangle, j - i == 2 ? uses[i + 1].Triangle : -1 });
    i = j;
  }
  uses = std::vector<EdgeUse>();

  // 5. Creases: edges marked by the input lines, and edges sharper than FeatureAngle.
  std::vector<char> isCrease(edgeKeys.size(), 0);
  if (this->FeatureAngle > 0.0)
  {
    std::vector<Vector> normals(static_cast<std::size_t>(numTriangles));
    for (int t = 0; t < numTriangles; ++t)
    {
      const double* p0 = &basePositions[3 * faceVertices[3 * t]];
      const double* p1 = &basePositions[3 * faceVertices[3 * t + 1]];
      const double* p2 = &basePositions[3 * faceVertices[3 * t + 2]];
      Vector n = Cross(Sub(p1, p0), Sub(p2, p0));
      const double length = Norm(n);
      normals[t] = length > 0.0 ? Vector{ n[0] / length, n[1] / length, n[2] / length }
                                : Vector{ 0.0, 0.0, 0.0 };
    }
    const double cosLimit = std::cos(vtkMath::RadiansFromDegrees(this->FeatureAngle));
    for (std::size_t e = 0; e < edgeKeys.size(); ++e)
    {
      const std::array<int, 2>& pair = edgeTriangles[e];
      if (pair[1] < 0)
      {
        continue;
      }
      const Vector& n0 = normals[static_cast<std::size_t>(pair[0])];
      const Vector& n1 = normals[static_cast<std::size_t>(pair[1])];
      if (Dot(n0, n0) > 0.0 && Dot(n1, n1) > 0.0 && Dot(n0, n1) < cosLimit)
      {
        isCrease[e] = 1;
      }
    }
  }
  vtkIdType ignoredSegments = 0;
  {
    auto lines = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
    for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      lines->GetCurrentCell(npts, pts);
      for (vtkIdType i = 0; i + 1 < npts; ++i)
      {
        if (pts[i] == pts[i + 1])
        {
          continue;
        }
        const int a = baseIndex[static_cast<std::size_t>(pts[i])];
        const int b = baseIndex[static_cast<std::size_t>(pts[i + 1])];
        const std::uint64_t key = a >= 0 && b >= 0 ? EdgeKey(a, b) : 0;
        const auto found = std::lower_bound(edgeKeys.begin(), edgeKeys.end(), key);
        if (a < 0 || b < 0 || found == edgeKeys.end() || *found != key)
        {
          ++ignoredSegments;
          continue;
        }
        isCrease[static_cast<std::size_t>(found - edgeKeys.begin())] = 1;
      }
    }
  }
  if (ignoredSegments > 0)
  {
    vtkWarningMacro("Ignored " << ignoredSegments
                               << " crease segment(s) of the input lines that are not edges of "
                                  "the triangle mesh.");
  }
  std::vector<int> creasePairs;
  for (std::size_t e = 0; e < edgeKeys.size(); ++e)
  {
    if (isCrease[e])
    {
      creasePairs.push_back(static_cast<int>(edgeKeys[e] >> 32));
      creasePairs.push_back(static_cast<int>(edgeKeys[e] & 0xffffffffu));
    }
  }
  const int numCreases = static_cast<int>(creasePairs.size() / 2);
  const std::vector<float> creaseWeights(
    static_cast<std::size_t>(numCreases), Sdc::Crease::SHARPNESS_INFINITE);
  edgeTriangles = std::vector<std::array<int, 2>>();
  vtkDebugMacro(<< numCreases << " crease edges.");

  // 6. OpenSubdiv's topology, refined uniformly.
  std::vector<int> vertsPerFace(static_cast<std::size_t>(numTriangles), 3);
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = numBase;
  descriptor.numFaces = numTriangles;
  descriptor.numVertsPerFace = vertsPerFace.data();
  descriptor.vertIndicesPerFace = faceVertices.data();
  descriptor.numCreases = numCreases;
  descriptor.creaseVertexIndexPairs = creasePairs.data();
  descriptor.creaseWeights = creaseWeights.data();

  Sdc::Options schemeOptions;
  schemeOptions.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_LOOP, schemeOptions)));
  if (!refiner)
  {
    vtkErrorMacro("OpenSubdiv could not build the topology of the input mesh.");
    return 0;
  }
  const int level = this->Level;
  if (level > 0)
  {
    Far::TopologyRefiner::UniformOptions uniform(level);
    uniform.fullTopologyInLastLevel = this->ProjectToLimit;
    refiner->RefineUniform(uniform);
  }
  this->UpdateProgress(0.1);

  // 7. The primvars: positions and the carried point arrays, interleaved.
  vtkPointData* inPD = input->GetPointData();
  vtkDataArray* inNormals = inPD->GetNormals();
  std::vector<CarriedArray> carried;
  int stride = 3;
  for (int i = 0; i < inPD->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = inPD->GetArray(i);
    if (!array || array == inNormals ||
      (array->GetName() && std::string(array->GetName()) == "Normals"))
    {
      continue;
    }
    carried.push_back({ array, stride, inPD->IsArrayAnAttribute(i) });
    stride += array->GetNumberOfComponents();
  }
  std::vector<double> current(static_cast<std::size_t>(numBase) * stride);
  for (int v = 0; v < numBase; ++v)
  {
    double* vertex = &current[static_cast<std::size_t>(v) * stride];
    std::copy_n(&basePositions[3 * v], 3, vertex);
    for (const CarriedArray& c : carried)
    {
      c.Input->GetTuple(basePoint[static_cast<std::size_t>(v)], vertex + c.Offset);
    }
  }
  basePositions = std::vector<double>();

  Far::PrimvarRefinerReal<double> primvarRefiner(*refiner);
  std::vector<double> next;
  for (int l = 1; l <= level; ++l)
  {
    if (this->GetAbortExecute())
    {
      return 1;
    }
    next.assign(static_cast<std::size_t>(refiner->GetLevel(l).GetNumVertices()) * stride, 0.0);
    const VertexBuffer source{ current.data(), stride };
    VertexBuffer destination{ next.data(), stride };
    primvarRefiner.Interpolate(l, source, destination);
    current.swap(next);
    this->UpdateProgress(0.1 + 0.7 * l / level);
  }

  const Far::TopologyLevel& last = refiner->GetLevel(level);
  const int numVertices = last.GetNumVertices();
  std::vector<double> tangents;
  if (this->ProjectToLimit)
  {
    next.assign(current.size(), 0.0);
    tangents.assign(6 * static_cast<std::size_t>(numVertices), 0.0);
    const VertexBuffer source{ current.data(), stride };
    VertexBuffer destination{ next.data(), stride };
    TangentBuffer tangent1{ tangents.data() };
    TangentBuffer tangent2{ tangents.data() + 3 * static_cast<std::size_t>(numVertices) };
    primvarRefiner.Limit(source, destination, tangent1, tangent2);
    current.swap(next);
  }
  next = std::vector<double>();

  // 8. The triangles of the last level, each with its base face.
  const int numFaces = last.GetNumFaces();
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numFaces + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(numFaces));
  vtkNew<vtkIdTypeArray> originalCellIds;
  originalCellIds->SetName("OriginalCellId");
  originalCellIds->SetNumberOfValues(numFaces);
  for (int f = 0; f < numFaces; ++f)
  {
    const Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    if (vertices.size() != 3)
    {
      vtkErrorMacro("OpenSubdiv returned a refined face with " << vertices.size() << " vertices.");
      return 0;
    }
    offsets->SetValue(f, 3 * static_cast<vtkIdType>(f));
    for (int k = 0; k < 3; ++k)
    {
      connectivity->SetValue(3 * static_cast<vtkIdType>(f) + k, vertices[k]);
    }
    int parent = f;
    for (int l = level; l > 0; --l)
    {
      parent = refiner->GetLevel(l).GetFaceParentFace(parent);
    }
    originalCellIds->SetValue(f, triangleCell[static_cast<std::size_t>(parent)]);
  }
  offsets->SetValue(numFaces, 3 * static_cast<vtkIdType>(numFaces));

  // 9. Points, and the limit normals oriented like the refined triangles.
  int pointsType = VTK_DOUBLE;
  if (this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION ||
    (this->OutputPointsPrecision == vtkAlgorithm::DEFAULT_PRECISION &&
      inPoints->GetDataType() == VTK_FLOAT))
  {
    pointsType = VTK_FLOAT;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(pointsType);
  points->SetNumberOfPoints(numVertices);
  for (int v = 0; v < numVertices; ++v)
  {
    points->SetPoint(v, &current[static_cast<std::size_t>(v) * stride]);
  }

  vtkPointData* outPD = output->GetPointData();
  if (this->ProjectToLimit)
  {
    std::vector<Vector> meshNormals(static_cast<std::size_t>(numVertices), Vector{ 0, 0, 0 });
    for (int f = 0; f < numFaces; ++f)
    {
      const Far::ConstIndexArray vertices = last.GetFaceVertices(f);
      const double* p0 = &current[static_cast<std::size_t>(vertices[0]) * stride];
      const double* p1 = &current[static_cast<std::size_t>(vertices[1]) * stride];
      const double* p2 = &current[static_cast<std::size_t>(vertices[2]) * stride];
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
      const double* t1 = &tangents[3 * static_cast<std::size_t>(v)];
      const double* t2 = &tangents[3 * (static_cast<std::size_t>(numVertices) + v)];
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
    vtkDebugMacro(<< flipped << " limit normals flipped to the triangles' side, " << fallbacks
                  << " taken from the triangles.");
    outPD->SetNormals(normals);
  }

  // 10. The carried point arrays, back in their own types.
  std::vector<double> tuple;
  for (const CarriedArray& c : carried)
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
      const double* values = &current[static_cast<std::size_t>(v) * stride + c.Offset];
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

  // 11. Cell data: the original cell id, and the input's cell arrays.
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyNormalsOff();
  outCD->CopyFieldOff("OriginalCellId");
  outCD->CopyAllocate(inCD, numFaces);
  if (inCD->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> fromIds;
    fromIds->SetNumberOfIds(numFaces);
    vtkNew<vtkIdList> toIds;
    toIds->SetNumberOfIds(numFaces);
    for (int f = 0; f < numFaces; ++f)
    {
      fromIds->SetId(f, originalCellIds->GetValue(f));
      toIds->SetId(f, f);
    }
    outCD->CopyData(inCD, fromIds, toIds);
  }
  outCD->AddArray(originalCellIds);

  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
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
