#include "vtkSilhouetteSmoothingOutput.h"

#include "vtkAlgorithm.h"
#include "vtkNew.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include "vtkSilhouetteFilterSupport.h"

#include "ShadingNormals.h"
#include "SilhouetteSmoother.h"
#include "WeldedSurface.h"

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

namespace
{

// The source with the largest weight: the value an added point takes of an
// array that cannot be interpolated (ids, labels, strings).
vtkIdType NearestSource(
  const silsmooth::SurfaceFrame::AddedPoint& added, const silsmooth::SmoothingResult& result)
{
  const std::array<double, 3>& w = result.NewPoints[added.NewPoint].Weights;
  const std::size_t k = w[0] >= w[1] && w[0] >= w[2] ? 0 : (w[1] >= w[2] ? 1 : 2);
  return static_cast<vtkIdType>(added.Sources[k]);
}

// Copies of every input array that VTK's attribute rules left out (vtkIdType
// and string arrays, global and pedigree ids): from[i] is the input tuple of
// output tuple i. They come out as plain arrays under their own names: ids
// repeated on copies are no longer unique.
void AddUncopiedArrays(vtkDataSetAttributes* in, vtkDataSetAttributes* out,
  const std::vector<vtkIdType>& from, const char* skip)
{
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = in->GetAbstractArray(a);
    if (!array->GetName() || out->GetAbstractArray(array->GetName()) ||
      (skip && std::strcmp(array->GetName(), skip) == 0))
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> copy = vtk::TakeSmartPointer(array->NewInstance());
    copy->SetName(array->GetName());
    copy->SetNumberOfComponents(array->GetNumberOfComponents());
    copy->SetNumberOfTuples(static_cast<vtkIdType>(from.size()));
    for (std::size_t i = 0; i < from.size(); ++i)
    {
      copy->SetTuple(static_cast<vtkIdType>(i), from[i], array);
    }
    out->AddArray(copy);
  }
}

// Output cell c takes the data of input cell origin[c] (the arrays VTK's
// rules leave out as plain copies), with NewGeometry and `OriginalCellId`
// (origin composed with an input array of that name).
void CellDataFrom(vtkCellData* in, vtkCellData* out, const std::vector<vtkIdType>& origin,
  vtkUnsignedCharArray* newGeometry)
{
  const vtkIdType count = static_cast<vtkIdType>(origin.size());
  if (in->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> source;
    source->SetNumberOfIds(count);
    std::copy(origin.begin(), origin.end(), source->begin());
    vtkNew<vtkIdList> destination;
    destination->SetNumberOfIds(count);
    std::iota(destination->begin(), destination->end(), vtkIdType{ 0 });
    out->CopyAllOn();
    out->CopyAllocate(in, count);
    out->CopyData(in, source, destination);
    AddUncopiedArrays(in, out, origin, "OriginalCellId");
  }
  vtkDataArray* inOriginal = in->GetArray("OriginalCellId");
  vtkNew<vtkIdTypeArray> originalCellId;
  originalCellId->SetName("OriginalCellId");
  originalCellId->SetNumberOfValues(count);
  vtkIdType* originalIds = originalCellId->GetPointer(0);
  for (vtkIdType c = 0; c < count; ++c)
  {
    const vtkIdType from = origin[static_cast<std::size_t>(c)];
    originalIds[c] = inOriginal ? static_cast<vtkIdType>(inOriginal->GetTuple1(from)) : from;
  }
  if (out->GetAbstractArray("OriginalCellId"))
  {
    out->RemoveArray("OriginalCellId");
  }
  out->AddArray(newGeometry);
  out->AddArray(originalCellId);
}

// The number of zero bits below the lowest set bit of bits (not 0).
std::size_t countTrailingZeros(std::uint64_t bits)
{
  return std::bitset<64>((bits & (~bits + 1)) - 1).count();
}

} // namespace

namespace vtkSilhouetteSmoothingOutput
{

void AddCount(vtkFieldData* fd, const char* name, vtkIdType value)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->SetNumberOfTuples(1);
  array->SetValue(0, value);
  fd->AddArray(array);
}

int OutputPointType(vtkPolyData* input, int precision)
{
  if (precision == vtkAlgorithm::SINGLE_PRECISION)
  {
    return VTK_FLOAT;
  }
  if (precision == vtkAlgorithm::DOUBLE_PRECISION)
  {
    return VTK_DOUBLE;
  }
  vtkPoints* inPoints = input->GetPoints();
  return inPoints ? inPoints->GetDataType() : VTK_FLOAT;
}

vtkSmartPointer<vtkPoints> BuildPoints(vtkPolyData* input, int pointType,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(pointType);
  vtkPoints* inPoints = input->GetPoints();
  if (only)
  {
    const vtkIdType base = static_cast<vtkIdType>(surface.outputPointCount());
    points->SetNumberOfPoints(static_cast<vtkIdType>(only->size()));
    auto moved = frame.Moved.begin();
    for (std::size_t i = 0; i < only->size(); ++i)
    {
      const vtkIdType o = (*only)[i];
      const vtkIdType id = static_cast<vtkIdType>(i);
      while (moved != frame.Moved.end() && moved->first < o)
      {
        ++moved;
      }
      if (moved != frame.Moved.end() && moved->first == o)
      {
        points->SetPoint(id, moved->second.x, moved->second.y, moved->second.z);
      }
      else if (o < base)
      {
        // By value: SetTuple from another array type (the output's
        // precision need not be the input's) would fail.
        double x[3];
        inPoints->GetPoint(surface.outputSource(o), x);
        points->SetPoint(id, x);
      }
      else
      {
        const glm::dvec3& p =
          result.NewPoints[frame.Added[static_cast<std::size_t>(o - base)].NewPoint].Position;
        points->SetPoint(id, p.x, p.y, p.z);
      }
    }
    return points;
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType base = static_cast<vtkIdType>(surface.outputPointCount());
  points->SetNumberOfPoints(base + static_cast<vtkIdType>(frame.Added.size()));
  if (numPoints > 0)
  {
    points->GetData()->InsertTuples(0, numPoints, 0, inPoints->GetData());
  }
  for (vtkIdType id = numPoints; id < base; ++id)
  {
    points->GetData()->SetTuple(id, surface.outputSource(id), inPoints->GetData());
  }
  vtkIdType id = base;
  for (const silsmooth::SurfaceFrame::AddedPoint& added : frame.Added)
  {
    const glm::dvec3& p = result.NewPoints[added.NewPoint].Position;
    points->SetPoint(id++, p.x, p.y, p.z);
  }
  for (const auto& moved : frame.Moved)
  {
    points->SetPoint(moved.first, moved.second.x, moved.second.y, moved.second.z);
  }
  return points;
}

void BuildPointData(vtkPointData* in, vtkPointData* out, vtkIdType numPoints,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only)
{
  const vtkIdType base = static_cast<vtkIdType>(surface.outputPointCount());
  const vtkIdType total =
    only ? static_cast<vtkIdType>(only->size()) : base + static_cast<vtkIdType>(frame.Added.size());
  auto outputOf = [only](vtkIdType i) {
    return only ? (*only)[static_cast<std::size_t>(i)] : i;
  };
  vtkDataArray* inNormals = in->GetNormals();
  vtkDataArray* inOriginal = in->GetArray("OriginalPointId");
  out->CopyAllOn();
  out->CopyNormalsOff();
  out->InterpolateAllocate(in, total);
  vtkNew<vtkIdList> sources;
  sources->SetNumberOfIds(3);
  auto interpolate = [&](const silsmooth::SurfaceFrame::AddedPoint& added, vtkIdType id) {
    for (int k = 0; k < 3; ++k)
    {
      sources->SetId(k, added.Sources[static_cast<std::size_t>(k)]);
    }
    const std::array<double, 3>& w = result.NewPoints[added.NewPoint].Weights;
    double weights[3] = { w[0], w[1], w[2] };
    out->InterpolatePoint(in, id, sources, weights);
  };
  if (only)
  {
    for (vtkIdType i = 0; i < total; ++i)
    {
      const vtkIdType o = outputOf(i);
      if (o < base)
      {
        out->CopyData(in, surface.outputSource(o), i);
      }
      else
      {
        interpolate(frame.Added[static_cast<std::size_t>(o - base)], i);
      }
    }
  }
  else
  {
    if (numPoints > 0)
    {
      out->CopyData(in, 0, numPoints, 0);
    }
    for (vtkIdType id = numPoints; id < base; ++id)
    {
      out->CopyData(in, surface.outputSource(id), id);
    }
    vtkIdType id = base;
    for (const silsmooth::SurfaceFrame::AddedPoint& added : frame.Added)
    {
      interpolate(added, id++);
    }
  }
  if (inNormals && inNormals->GetName() && out->GetArray(inNormals->GetName()))
  {
    out->RemoveArray(inNormals->GetName());
  }

  std::vector<vtkIdType> from(static_cast<std::size_t>(total));
  for (vtkIdType i = 0; i < total; ++i)
  {
    const vtkIdType o = outputOf(i);
    from[static_cast<std::size_t>(i)] = o < base
      ? surface.outputSource(o)
      : NearestSource(frame.Added[static_cast<std::size_t>(o - base)], result);
  }
  AddUncopiedArrays(in, out, from, inNormals ? inNormals->GetName() : nullptr);

  vtkNew<vtkIdTypeArray> original;
  original->SetName("OriginalPointId");
  original->SetNumberOfValues(total);
  for (vtkIdType i = 0; i < total; ++i)
  {
    const vtkIdType o = outputOf(i);
    const vtkIdType source = o < base ? surface.outputSource(o) : -1;
    original->SetValue(i,
      source >= 0 && inOriginal ? static_cast<vtkIdType>(inOriginal->GetTuple1(source)) : source);
  }
  if (out->GetAbstractArray("OriginalPointId"))
  {
    out->RemoveArray("OriginalPointId");
  }
  out->AddArray(original);

  const silsmooth::PreparedMesh& mesh = surface.prepared();
  vtkNew<vtkFloatArray> normals;
  normals->SetName(inNormals && inNormals->GetName() ? inNormals->GetName() : "Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(total);
  float* n = normals->GetPointer(0);
  for (vtkIdType i = 0; i < total; ++i)
  {
    const vtkIdType o = outputOf(i);
    const glm::dvec3& oriented = o < base
      ? mesh.normals()[static_cast<std::size_t>(surface.outputPrepared(o))]
      : result.NewPoints[frame.Added[static_cast<std::size_t>(o - base)].NewPoint].Normal;
    // As the input's own winding, which the output keeps, faces.
    const bool reversed = surface.outputNormalReversed(
      o < base ? o : frame.Added[static_cast<std::size_t>(o - base)].Sources[0]);
    const glm::dvec3 normal = reversed ? -oriented : oriented;
    *n++ = static_cast<float>(normal.x);
    *n++ = static_cast<float>(normal.y);
    *n++ = static_cast<float>(normal.z);
  }
  out->SetNormals(normals);
}

silsmooth::SurfaceFrame BuildCells(vtkPolyData* input, vtkPolyData* output,
  const std::vector<vtkIdType>& triangleCell, const silsmooth::WeldedSurface& surface,
  const silsmooth::SmoothingResult& result, vtkIdType& droppedCells)
{
  const vtkSilhouetteFilterSupport::PassedCells passed =
    vtkSilhouetteFilterSupport::PassVertsAndLines(input);
  droppedCells = passed.Dropped;
  output->SetVerts(passed.Verts);
  output->SetLines(passed.Lines);
  const vtkIdType passThrough = static_cast<vtkIdType>(passed.CellIds.size());

  const std::size_t outTriangles = surface.outputTriangleCount(result);
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(outTriangles + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(outTriangles * 3));
  const vtkIdType outCells = passThrough + static_cast<vtkIdType>(outTriangles);
  vtkNew<vtkUnsignedCharArray> newGeometry;
  newGeometry->SetName("NewGeometry");
  newGeometry->SetNumberOfValues(outCells);
  std::vector<vtkIdType> origin(static_cast<std::size_t>(outCells));
  unsigned char* kinds = newGeometry->GetPointer(0);
  std::copy(passed.CellIds.begin(), passed.CellIds.end(), origin.begin());
  std::fill(kinds, kinds + passThrough, static_cast<unsigned char>(0));
  silsmooth::SurfaceFrame frame = surface.assemble(
    result, connectivity->GetPointer(0), origin.data() + passThrough, kinds + passThrough);
  for (vtkIdType c = passThrough; c < outCells; ++c)
  {
    origin[static_cast<std::size_t>(c)] =
      triangleCell[static_cast<std::size_t>(origin[static_cast<std::size_t>(c)])];
  }
  vtkIdType* offs = offsets->GetPointer(0);
  for (std::size_t t = 0; t <= outTriangles; ++t)
  {
    offs[t] = static_cast<vtkIdType>(t * 3);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);

  CellDataFrom(input->GetCellData(), output->GetCellData(), origin, newGeometry);
  return frame;
}

void BuildBaseCellData(
  vtkPolyData* input, vtkCellData* output, const std::vector<vtkIdType>& triangleCell)
{
  std::vector<vtkIdType> origin = vtkSilhouetteFilterSupport::PassVertsAndLines(input).CellIds;
  origin.insert(origin.end(), triangleCell.begin(), triangleCell.end());
  vtkNew<vtkUnsignedCharArray> newGeometry;
  newGeometry->SetName("NewGeometry");
  newGeometry->SetNumberOfValues(static_cast<vtkIdType>(origin.size()));
  newGeometry->FillValue(0);
  CellDataFrom(input->GetCellData(), output, origin, newGeometry);
}

UsedPoints::UsedPoints(const std::vector<silsmooth::Triangle>& triangles, std::size_t pointCount)
  : Bits((pointCount + 63) / 64, 0)
  , Before(this->Bits.size(), 0)
{
  for (const silsmooth::Triangle& t : triangles)
  {
    for (const silsmooth::Id v : t)
    {
      const std::size_t i = static_cast<std::size_t>(v);
      this->Bits[i / 64] |= std::uint64_t{ 1 } << (i % 64);
    }
  }
  vtkIdType count = 0;
  for (std::size_t w = 0; w < this->Bits.size(); ++w)
  {
    this->Before[w] = count;
    for (std::uint64_t bits = this->Bits[w]; bits != 0; bits &= bits - 1)
    {
      this->Ids.push_back(static_cast<vtkIdType>(w * 64 + countTrailingZeros(bits)));
      ++count;
    }
  }
}

vtkIdType UsedPoints::indexOf(silsmooth::Id id) const
{
  const std::size_t i = static_cast<std::size_t>(id);
  const std::uint64_t below = this->Bits[i / 64] & ((std::uint64_t{ 1 } << (i % 64)) - 1);
  return this->Before[i / 64] + static_cast<vtkIdType>(std::bitset<64>(below).count());
}

void BuildChangedCells(vtkPolyData* input, vtkPolyData* changes,
  const std::vector<vtkIdType>& triangleCell, const silsmooth::SurfaceFrame& frame,
  const UsedPoints& used)
{
  const vtkIdType count = static_cast<vtkIdType>(frame.Triangles.size());
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(count * 3);
  vtkIdType* ids = connectivity->GetPointer(0);
  for (const silsmooth::Triangle& t : frame.Triangles)
  {
    for (const silsmooth::Id v : t)
    {
      *ids++ = used.indexOf(v);
    }
  }
  for (vtkIdType t = 0; t <= count; ++t)
  {
    offsets->SetValue(t, t * 3);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  changes->SetPolys(polys);

  std::vector<vtkIdType> origin(static_cast<std::size_t>(count));
  vtkNew<vtkUnsignedCharArray> newGeometry;
  newGeometry->SetName("NewGeometry");
  newGeometry->SetNumberOfValues(count);
  for (vtkIdType c = 0; c < count; ++c)
  {
    origin[static_cast<std::size_t>(c)] =
      triangleCell[static_cast<std::size_t>(frame.SourceTriangle[static_cast<std::size_t>(c)])];
    newGeometry->SetValue(c, frame.Kind[static_cast<std::size_t>(c)]);
  }
  CellDataFrom(input->GetCellData(), changes->GetCellData(), origin, newGeometry);
}

void BuildSilhouetteLines(
  vtkPolyData* mesh, const silsmooth::SurfaceFrame& frame, vtkPolyData* lines)
{
  vtkPoints* meshPoints = mesh->GetPoints();
  vtkDataArray* meshNormals = mesh->GetPointData()->GetNormals();
  vtkNew<vtkPoints> points;
  points->SetDataType(meshPoints->GetDataType());
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> cells;
  std::unordered_map<silsmooth::Id, vtkIdType> compact;
  for (const std::vector<silsmooth::Id>& chain : frame.Polylines)
  {
    cells->InsertNextCell(static_cast<int>(chain.size())); // VTK takes the size as int here
    for (const silsmooth::Id id : chain)
    {
      auto inserted = compact.emplace(id, points->GetNumberOfPoints());
      if (inserted.second)
      {
        points->InsertNextPoint(meshPoints->GetPoint(id));
        normals->InsertNextTuple(meshNormals->GetTuple(id));
      }
      cells->InsertCellPoint(inserted.first->second);
    }
  }
  lines->SetPoints(points);
  lines->SetLines(cells);
  lines->GetPointData()->SetNormals(normals);
  lines->GetCellData()->AddArray(vtkSilhouetteFilterSupport::LineKindArray(
    cells->GetNumberOfCells(), vtkSilhouetteFilterSupport::SilhouetteLine));
}

} // namespace vtkSilhouetteSmoothingOutput
