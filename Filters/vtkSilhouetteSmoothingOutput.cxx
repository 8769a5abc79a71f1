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

#include "vtkSilhouetteAttributeSources.h"
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

std::vector<vtkSilhouetteFilterSupport::PointSource> PointSourcesOf(
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, vtkIdType first, vtkIdType end,
  const std::vector<vtkIdType>* only)
{
  using vtkSilhouetteFilterSupport::PointSource;
  const vtkIdType base = static_cast<vtkIdType>(surface.outputPointCount());
  std::vector<PointSource> sources;
  sources.reserve(static_cast<std::size_t>(end - first));
  for (vtkIdType i = first; i < end; ++i)
  {
    const vtkIdType o = only ? (*only)[static_cast<std::size_t>(i)] : i;
    if (o < base)
    {
      sources.push_back(PointSource::Copy(surface.outputSource(o)));
      continue;
    }
    const silsmooth::SurfaceFrame::AddedPoint& added =
      frame.Added[static_cast<std::size_t>(o - base)];
    PointSource source;
    for (std::size_t k = 0; k < 3; ++k)
    {
      source.Ids[k] = static_cast<vtkIdType>(added.Sources[k]);
    }
    source.Weights = result.NewPoints[added.NewPoint].Weights;
    sources.push_back(source);
  }
  return sources;
}

void BuildPointData(vtkPointData* in, vtkPointData* out, vtkIdType numPoints,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only)
{
  const vtkIdType base = static_cast<vtkIdType>(surface.outputPointCount());
  const vtkIdType total =
    only ? static_cast<vtkIdType>(only->size()) : base + static_cast<vtkIdType>(frame.Added.size());
  // Input points keep their ids in the whole output: copied as one block.
  const vtkIdType leading = only ? 0 : std::min(numPoints, total);
  vtkSilhouetteFilterSupport::FillPointData(
    in, out, leading, PointSourcesOf(surface, result, frame, leading, total, only));
  out->SetNormals(ShadingNormals(in, surface, result, frame, only));
}

vtkSmartPointer<vtkFloatArray> ShadingNormals(vtkPointData* in,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only)
{
  const vtkIdType base = static_cast<vtkIdType>(surface.outputPointCount());
  const vtkIdType total =
    only ? static_cast<vtkIdType>(only->size()) : base + static_cast<vtkIdType>(frame.Added.size());
  vtkDataArray* inNormals = in->GetNormals();
  const silsmooth::PreparedMesh& mesh = surface.prepared();
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName(inNormals && inNormals->GetName() ? inNormals->GetName() : "Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(total);
  float* n = normals->GetPointer(0);
  for (vtkIdType i = 0; i < total; ++i)
  {
    const vtkIdType o = only ? (*only)[static_cast<std::size_t>(i)] : i;
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
  return normals;
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

  vtkSilhouetteFilterSupport::FillCellData(
    input->GetCellData(), output->GetCellData(), origin, newGeometry);
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
  vtkSilhouetteFilterSupport::FillCellData(input->GetCellData(), output, origin, newGeometry);
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

std::vector<vtkIdType> BuildChangedCells(vtkPolyData* input, vtkPolyData* changes,
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
  vtkSilhouetteFilterSupport::FillCellData(
    input->GetCellData(), changes->GetCellData(), origin, newGeometry);
  return origin;
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
