#include "vtkSilhouetteSmoothingFilter.h"

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
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkSilhouetteSmoothingFilter);

vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, Tolerance, double, 1e-3, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, MinimumSamples, int, 2, 65536);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, MaximumSamples, int, 2, 65536);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, NewPointBudget, double, 1.0, 1e6);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, FeatureAngle, double, 0.0, 180.0);
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteSmoothingFilter, WeldTolerance, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkSilhouetteSmoothingFilter, FlatCreaseAngle, double, 0.0, 180.0);

namespace
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

// Input points (ids kept), copies of input points for extra smooth groups,
// then the added points; points lowered by the perturbation move in every
// copy. With `only`, just those output points (ascending ids), in order.
vtkSmartPointer<vtkPoints> BuildPoints(vtkPolyData* input, int pointType,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only = nullptr)
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
        points->GetData()->SetTuple(id, surface.outputSource(o), inPoints->GetData());
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

// Input point arrays are copied and extended with values interpolated for the
// added points (VTK's interpolation rules; the arrays those rules do not
// interpolate take the nearest source's value). The shading normals replace
// the input's normals (if any) as the active normals, keeping the input's
// array name. `OriginalPointId` gives every output point's input point (-1
// for added points), composed with an input array of that name. With
// `only`, just those output points (ascending ids), in order.
void BuildPointData(vtkPointData* in, vtkPointData* out, vtkIdType numPoints,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only = nullptr)
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
    const glm::dvec3& normal = o < base
      ? mesh.normals()[static_cast<std::size_t>(surface.outputPrepared(o))]
      : result.NewPoints[frame.Added[static_cast<std::size_t>(o - base)].NewPoint].Normal;
    *n++ = static_cast<float>(normal.x);
    *n++ = static_cast<float>(normal.y);
    *n++ = static_cast<float>(normal.z);
  }
  out->SetNormals(normals);
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

// Verts and lines pass through (PassVertsAndLines: `droppedCells` counts the
// ones left out); polygons and strips become the frame's triangles, written
// by the surface straight into the cell arrays. `OriginalCellId` is composed
// with an input array of that name.
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

// A frame's changes (WeldedSurface::assembleChanges) as a mesh of their own:
// the triangles over the output points they use (`used`, ascending output
// ids), each with its input cell's data, NewGeometry and OriginalCellId as
// the whole output gives them.
void BuildChangedCells(vtkPolyData* input, vtkPolyData* changes,
  const std::vector<vtkIdType>& triangleCell, const silsmooth::SurfaceFrame& frame,
  const std::vector<vtkIdType>& used)
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
      *ids++ = static_cast<vtkIdType>(
        std::lower_bound(used.begin(), used.end(), static_cast<vtkIdType>(v)) - used.begin());
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

// Output port 1: the silhouette polylines over their own compact point set.
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

} // namespace

namespace
{

// Feature edges marked by line cells (the core keeps those along triangle
// edges).
std::vector<silsmooth::FeatureEdge> MarkedFeatures(vtkPolyData* input, bool useLines)
{
  std::vector<silsmooth::FeatureEdge> marked;
  if (!useLines)
  {
    return marked;
  }
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    it->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 1 < npts; ++k)
    {
      marked.emplace_back(pts[k], pts[k + 1]);
    }
  }
  return marked;
}

// The input's cell arrays (which objects, and their times) and its point
// count: what must stay for a change to be one of the points only.
std::array<vtkMTimeType, 9> CellsOf(vtkPolyData* input)
{
  vtkCellArray* cells[4] = { input->GetVerts(), input->GetLines(), input->GetPolys(),
    input->GetStrips() };
  std::array<vtkMTimeType, 9> key{};
  for (int k = 0; k < 4; ++k)
  {
    key[2 * k] = static_cast<vtkMTimeType>(reinterpret_cast<std::uintptr_t>(cells[k]));
    key[2 * k + 1] = cells[k] ? cells[k]->GetMTime() : 0;
  }
  key[8] = static_cast<vtkMTimeType>(input->GetNumberOfPoints());
  return key;
}

} // namespace

struct vtkSilhouetteSmoothingFilter::Internals
{
  // The view-independent cache, keyed on the input object, its MTime and the
  // settings that shape it.
  std::unique_ptr<silsmooth::WeldedSurface> Surface;
  std::vector<vtkIdType> TriangleCell; // input cell id of each triangle
  vtkIdType NonFinitePoints = 0;
  vtkIdType FirstNonFinitePoint = -1;
  vtkIdType TooSmallPolygons = 0;
  vtkPolyData* CachedInput = nullptr;
  vtkMTimeType CachedInputTime = 0;
  std::array<double, 10> CachedSettings{};
  bool HaveSettings = false;
  // The input's cells (the objects and their times) and point count when
  // the cache was built: when only the points change, the surface moves
  // them (WeldedSurface::movePoints) instead of being built anew.
  std::array<vtkMTimeType, 9> CachedCells{};
  // Counts the builds of the surface (not its moves), and the build the
  // base mesh BuildBaseMesh filled last was made for: while it is the same
  // build, the base mesh keeps its cell arrays and takes the new points.
  std::size_t Builds = 0;
  vtkPolyData* LastBase = nullptr;
  std::size_t LastBaseBuild = 0;
  // Per triangle: a ghost cell (duplicate or hidden), never re-meshed; empty
  // when the input has no ghost array. Read again whenever the input changed.
  std::vector<unsigned char> Frozen;
  vtkMTimeType FrozenTime = 0;

  // Returns an empty string, or the error to report.
  std::string Rebuild(vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options);
  // True when the points of the cached input's unchanged cells moved and
  // the surface took the move.
  bool MovePoints(vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options);

  // The cache for `input` and the filter's settings, rebuilt when either
  // changed (`rebuilt` says so); the warnings about the input are given once
  // per rebuild. False after reporting an error.
  bool Prepare(vtkSilhouetteSmoothingFilter* self, vtkPolyData* input, bool& rebuilt);
  // The frame for the view, with the filter's settings; warns when the new
  // point budget lowered the sampling.
  silsmooth::SmoothingResult Smooth(vtkSilhouetteSmoothingFilter* self, vtkPolyData* input,
    const silsmooth::ViewGeometry& view, bool boundaryMayBeSeam);
};

std::string vtkSilhouetteSmoothingFilter::Internals::Rebuild(
  vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options)
{
  vtkSilhouetteFilterSupport::Triangles mesh;
  const std::string error = vtkSilhouetteFilterSupport::ReadTriangles(input, mesh);
  this->Surface.reset();
  this->CachedInput = nullptr;
  if (!error.empty())
  {
    return error;
  }
  this->NonFinitePoints = mesh.NonFinitePoints;
  this->FirstNonFinitePoint = mesh.FirstNonFinitePoint;
  this->TooSmallPolygons = mesh.TooSmallPolygons;
  this->TriangleCell = std::move(mesh.CellIds);
  if (this->NonFinitePoints > 0)
  {
    return std::string(); // reported by the caller, on every request
  }
  this->Surface = std::make_unique<silsmooth::WeldedSurface>(std::move(mesh.Points),
    std::move(mesh.Cells), mesh.Normals, MarkedFeatures(input, useLines), options);
  this->CachedInput = input;
  this->CachedInputTime = input->GetMTime();
  this->CachedCells = CellsOf(input);
  ++this->Builds;
  return std::string();
}

bool vtkSilhouetteSmoothingFilter::Internals::MovePoints(
  vtkPolyData* input, bool useLines, const silsmooth::SurfaceOptions& options)
{
  if (!this->Surface || this->CachedInput != input || this->CachedCells != CellsOf(input))
  {
    return false;
  }
  vtkSilhouetteFilterSupport::Triangles mesh;
  if (!vtkSilhouetteFilterSupport::ReadTriangles(input, mesh).empty() || mesh.NonFinitePoints > 0 ||
    mesh.CellIds != this->TriangleCell)
  {
    return false;
  }
  if (!this->Surface->movePoints(
        std::move(mesh.Points), mesh.Normals, MarkedFeatures(input, useLines), options))
  {
    return false;
  }
  this->CachedInputTime = input->GetMTime();
  return true;
}

bool vtkSilhouetteSmoothingFilter::Internals::Prepare(
  vtkSilhouetteSmoothingFilter* self, vtkPolyData* input, bool& rebuilt)
{
  silsmooth::SurfaceOptions options;
  options.Weld = self->WeldCoincidentPoints;
  options.WeldTolerance = self->WeldTolerance;
  options.Orient = self->ConsistentOrientation;
  options.NormalSeams = self->NormalSeamFeatures;
  options.DetectFeatures = self->FeatureEdgeDetection;
  options.FeatureAngleDegrees = self->FeatureAngle;
  options.DetectFlatCreases = self->FlatCreaseDetection;
  options.FlatCreaseAngleDegrees = self->FlatCreaseAngle;
  options.Normals = static_cast<silsmooth::NormalWeighting>(self->NormalEstimation);
  const std::array<double, 10> settings{ { self->FeatureLines ? 1.0 : 0.0,
    options.DetectFeatures ? 1.0 : 0.0, options.FeatureAngleDegrees, options.Weld ? 1.0 : 0.0,
    options.WeldTolerance, options.Orient ? 1.0 : 0.0, options.NormalSeams ? 1.0 : 0.0,
    options.DetectFlatCreases ? 1.0 : 0.0, options.FlatCreaseAngleDegrees,
    static_cast<double>(self->NormalEstimation) } };
  rebuilt = !this->Surface || this->CachedInput != input ||
    this->CachedInputTime != input->GetMTime() || !this->HaveSettings ||
    this->CachedSettings != settings;
  if (rebuilt && this->HaveSettings && this->CachedSettings == settings &&
    this->MovePoints(input, self->FeatureLines, options))
  {
    rebuilt = false; // a deforming mesh: the same topology, the points moved
  }
  if (rebuilt)
  {
    this->HaveSettings = false;
    const std::string error = this->Rebuild(input, self->FeatureLines, options);
    if (!error.empty())
    {
      vtkErrorWithObjectMacro(self, << error);
      return false;
    }
    this->CachedSettings = settings;
    this->HaveSettings = this->Surface != nullptr;
  }
  if (this->FrozenTime != input->GetMTime() || rebuilt)
  {
    // Ghost cells (a piece's copies of its neighbours' cells) count for the
    // normals and the adjacency but are the other piece's to re-mesh.
    this->Frozen.clear();
    vtkUnsignedCharArray* ghosts = vtkArrayDownCast<vtkUnsignedCharArray>(
      input->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
    if (ghosts && ghosts->GetNumberOfValues() == input->GetNumberOfCells())
    {
      const unsigned char skip =
        vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
      this->Frozen.resize(this->TriangleCell.size());
      for (std::size_t t = 0; t < this->TriangleCell.size(); ++t)
      {
        this->Frozen[t] = (ghosts->GetValue(this->TriangleCell[t]) & skip) != 0 ? 1 : 0;
      }
    }
    this->FrozenTime = input->GetMTime();
  }
  if (this->NonFinitePoints > 0)
  {
    vtkErrorWithObjectMacro(self,
      "Input has " << this->NonFinitePoints
                   << " points with NaN or infinite coordinates (the first is point "
                   << this->FirstNonFinitePoint << ").");
    return false;
  }
  const silsmooth::SurfaceStatistics& statistics = this->Surface->statistics();
  if (rebuilt && statistics.FlatShadedNormals)
  {
    vtkWarningWithObjectMacro(self,
      "The input's point normals are its triangles' own normals (flat shading): "
      "they say nothing about the smooth surface, so they are not used; shading "
      "normals are computed, and creases come from FlatCreaseDetection and "
      "FeatureEdgeDetection.");
  }
  if (rebuilt && statistics.InconsistentEdgeCount > 0)
  {
    vtkWarningWithObjectMacro(
      self, << statistics.InconsistentEdgeCount
            << " edges join triangles that cannot be oriented consistently (a "
               "non-orientable surface, such as a Moebius strip): shading normals "
               "and visibility are unreliable next to them.");
  }
  return true;
}

silsmooth::SmoothingResult vtkSilhouetteSmoothingFilter::Internals::Smooth(
  vtkSilhouetteSmoothingFilter* self, vtkPolyData* input, const silsmooth::ViewGeometry& view,
  bool boundaryMayBeSeam)
{
  silsmooth::SmoothingParameters parameters;
  parameters.PerturbConcaveSilhouettes = self->PerturbVertices;
  parameters.PreventFolds = self->FoldPrevention;
  parameters.CullOutsideFrustum = self->FrustumCulling;
  parameters.FrozenTriangles = this->Frozen.empty() ? nullptr : &this->Frozen;
  parameters.BoundaryMayBeSeam = boundaryMayBeSeam;
  parameters.Visibility = self->VisibilityMethod == HIERARCHICAL
    ? silsmooth::VisibilityMethod::Hierarchical
    : silsmooth::VisibilityMethod::PerVertex;
  silsmooth::SamplingParameters& sampling = parameters.Sampling;
  sampling.TolerancePixels = self->Tolerance;
  sampling.MinimumSamples = self->MinimumSamples;
  sampling.MaximumSamples = self->MaximumSamples;
  parameters.MaximumSampledPoints = static_cast<std::size_t>(std::max(
    1e5, std::min(self->NewPointBudget * static_cast<double>(input->GetNumberOfPoints()), 1e15)));
  sampling.Rule = self->SamplingRule == WANG_EQUATION_8 ? silsmooth::SamplingRule::WangEquation8
                                                        : silsmooth::SamplingRule::SecondDifference;
  const silsmooth::ParallelFor smpFor =
    [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
      vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&body](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
    };
  silsmooth::SmoothingResult result =
    silsmooth::smoothSilhouettes(this->Surface->prepared(), view, parameters, smpFor);
  if (result.SampleBudgetMaximum > 0)
  {
    vtkWarningWithObjectMacro(self,
      "Sampled this frame's segments with at most "
        << result.SampleBudgetMaximum << " points each (MaximumSamples " << self->MaximumSamples
        << "), so that its " << result.SilhouetteTriangleCount
        << " silhouette triangles stay within NewPointBudget's " << parameters.MaximumSampledPoints
        << " new points.");
  }
  return result;
}

vtkSilhouetteSmoothingFilter::vtkSilhouetteSmoothingFilter()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
  // The renderer asks for the bounds before it creates its camera (to reset
  // it): give the input, and run for real once the camera exists.
  this->PassInputWithoutCamera = true;
}

vtkSilhouetteSmoothingFilter::~vtkSilhouetteSmoothingFilter() = default;

vtkPolyData* vtkSilhouetteSmoothingFilter::GetSilhouetteOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkSilhouetteSmoothingFilter::RequestViewData(vtkInformation*,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector,
  const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* lines = vtkPolyData::GetData(outputVector, 1);
  if (!input || !output || !lines)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }

  if (this->MinimumSamples > this->MaximumSamples)
  {
    vtkErrorMacro("MinimumSamples (" << this->MinimumSamples << ") is more than MaximumSamples ("
                                     << this->MaximumSamples << ").");
    return 0;
  }
  // (Arrays of the wrong length were refused before: GuardRequest.)

  Internals& internal = *this->Internal;
  bool rebuilt = false;
  if (!internal.Prepare(this, input, rebuilt))
  {
    return 0; // reported
  }
  this->UpdateProgress(0.2);

  // A piece of a distributed mesh: its boundary may be a seam with another
  // piece, whose silhouette points there must stay the same as ours.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const bool boundaryMayBeSeam =
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) > 1;
  const silsmooth::SmoothingResult result =
    internal.Smooth(this, input, view.Geometry, boundaryMayBeSeam);
  const silsmooth::PreparedMesh& mesh = internal.Surface->prepared();
  const silsmooth::SurfaceStatistics& statistics = internal.Surface->statistics();
  this->UpdateProgress(0.6);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkIdType droppedCells = 0;
  const silsmooth::SurfaceFrame frame =
    BuildCells(input, output, internal.TriangleCell, *internal.Surface, result, droppedCells);
  this->UpdateProgress(0.7);
  output->SetPoints(BuildPoints(
    input, OutputPointType(input, this->OutputPointsPrecision), *internal.Surface, result, frame));
  BuildPointData(
    input->GetPointData(), output->GetPointData(), numPoints, *internal.Surface, result, frame);
  if (internal.TooSmallPolygons > 0)
  {
    vtkWarningMacro(<< internal.TooSmallPolygons
                    << " polygons with fewer than 3 points make no triangle and were dropped.");
  }
  if (rebuilt && droppedCells > 0) // said once per input, not every frame
  {
    vtkWarningMacro(<< droppedCells
                    << " vertex cells without points or lines with one point draw nothing and "
                       "were dropped.");
  }

  vtkFieldData* fd = output->GetFieldData();
  fd->PassData(input->GetFieldData());
  const vtkIdType inputTriangles = static_cast<vtkIdType>(mesh.triangles().size());
  const vtkIdType remeshedTriangles = static_cast<vtkIdType>(result.RemeshedTriangles.size());
  const vtkIdType newTriangles = static_cast<vtkIdType>(result.newTriangleCount());
  AddCount(fd, "SilhouetteTriangleCount", static_cast<vtkIdType>(result.SilhouetteTriangleCount));
  AddCount(fd, "FeatureTriangleCount", static_cast<vtkIdType>(mesh.featureTriangles().size()));
  AddCount(fd, "FeatureEdgeCount", static_cast<vtkIdType>(mesh.features().edges().size()));
  AddCount(fd, "SplitPointCount",
    static_cast<vtkIdType>(
      internal.Surface->outputPointCount() - internal.Surface->inputPointCount()));
  AddCount(fd, "WeldedPointCount", static_cast<vtkIdType>(statistics.WeldedPointCount));
  AddCount(fd, "ReversedTriangleCount", static_cast<vtkIdType>(statistics.ReversedTriangleCount));
  AddCount(fd, "NormalSeamEdgeCount", static_cast<vtkIdType>(statistics.NormalSeamEdgeCount));
  AddCount(fd, "FlatCreaseEdgeCount", static_cast<vtkIdType>(statistics.FlatCreaseEdgeCount));
  AddCount(fd, "NewTriangleCount", newTriangles);
  AddCount(fd, "NewPointCount", static_cast<vtkIdType>(frame.Added.size()));
  AddCount(fd, "ConcaveSegmentCount", static_cast<vtkIdType>(result.ConcaveSegmentCount));
  AddCount(fd, "PerturbedPointCount", static_cast<vtkIdType>(result.MovedPoints.size()));
  AddCount(fd, "ChordFallbackCount", static_cast<vtkIdType>(result.ChordFallbackTriangles));
  AddCount(
    fd, "StraightSilhouettePointCount", static_cast<vtkIdType>(result.StraightSilhouettePoints));
  AddCount(
    fd, "StraightFeatureSegmentCount", static_cast<vtkIdType>(result.StraightFeatureSegments));
  AddCount(fd, "PinnedPointCount", static_cast<vtkIdType>(result.PinnedPoints));
  AddCount(fd, "UnresolvedFoldCount", static_cast<vtkIdType>(result.UnresolvedFolds));
  AddCount(fd, "FoldGuardRoundCount", static_cast<vtkIdType>(result.FoldGuardRounds));
  AddCount(fd, "SampleBudgetMaximum", static_cast<vtkIdType>(result.SampleBudgetMaximum));
  AddCount(fd, "CulledTriangleCount", static_cast<vtkIdType>(result.CulledTriangles));
  AddCount(fd, "InputTriangleCount", inputTriangles);
  AddCount(fd, "OutputTriangleCount", inputTriangles - remeshedTriangles + newTriangles);

  BuildSilhouetteLines(output, frame, lines);
  this->UpdateProgress(1.0);
  return 1;
}

int vtkSilhouetteSmoothingFilter::BuildBaseMesh(vtkPolyData* input, vtkPolyData* base)
{
  if (!input || !base)
  {
    vtkErrorMacro("BuildBaseMesh needs an input and a mesh to fill.");
    return 0;
  }
  bool rebuilt = false;
  if (!this->Internal->Prepare(this, input, rebuilt))
  {
    return 0;
  }
  Internals& internal = *this->Internal;
  const silsmooth::SmoothingResult nothing;
  vtkNew<vtkPolyData> fresh;
  vtkIdType droppedCells = 0;
  const silsmooth::SurfaceFrame frame =
    BuildCells(input, fresh, internal.TriangleCell, *internal.Surface, nothing, droppedCells);
  fresh->SetPoints(BuildPoints(
    input, OutputPointType(input, this->OutputPointsPrecision), *internal.Surface, nothing, frame));
  BuildPointData(input->GetPointData(), fresh->GetPointData(), input->GetNumberOfPoints(),
    *internal.Surface, nothing, frame);
  fresh->GetFieldData()->PassData(input->GetFieldData());
  if (base == internal.LastBase && internal.LastBaseBuild == internal.Builds &&
    base->GetNumberOfPoints() == fresh->GetNumberOfPoints())
  {
    // The same build of the surface (only points moved since): the same
    // cells, so `base` keeps its cell arrays, and a renderer its index
    // buffers; the points and every attribute are new.
    base->SetPoints(fresh->GetPoints());
    base->GetPointData()->ShallowCopy(fresh->GetPointData());
    base->GetCellData()->ShallowCopy(fresh->GetCellData());
    base->GetFieldData()->ShallowCopy(fresh->GetFieldData());
    return 1;
  }
  base->ShallowCopy(fresh);
  internal.LastBase = base;
  internal.LastBaseBuild = internal.Builds;
  return 1;
}

int vtkSilhouetteSmoothingFilter::BuildChanges(vtkPolyData* input, vtkCamera* camera,
  const double modelMatrix[16], int width, int height, vtkPolyData* changes,
  vtkIdTypeArray* replacedTriangles)
{
  if (!input || !camera || !changes || !replacedTriangles)
  {
    vtkErrorMacro("BuildChanges needs an input, a camera, a mesh and an array to fill.");
    return 0;
  }
  if (this->MinimumSamples > this->MaximumSamples)
  {
    vtkErrorMacro("MinimumSamples (" << this->MinimumSamples << ") is more than MaximumSamples ("
                                     << this->MaximumSamples << ").");
    return 0;
  }
  silsmooth::ViewGeometry view;
  const std::string viewError =
    vtkSilhouetteFilterSupport::MakeViewGeometry(camera, modelMatrix, { { width, height } }, view);
  if (!viewError.empty())
  {
    vtkErrorMacro(<< viewError);
    return 0;
  }
  bool rebuilt = false;
  if (!this->Internal->Prepare(this, input, rebuilt))
  {
    return 0;
  }
  Internals& internal = *this->Internal;
  const silsmooth::SmoothingResult result = internal.Smooth(this, input, view, false);
  const silsmooth::SurfaceFrame frame = internal.Surface->assembleChanges(result);
  std::vector<vtkIdType> used;
  used.reserve(frame.Triangles.size() * 3);
  for (const silsmooth::Triangle& t : frame.Triangles)
  {
    used.insert(used.end(), t.begin(), t.end());
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  changes->Initialize();
  BuildChangedCells(input, changes, internal.TriangleCell, frame, used);
  changes->SetPoints(BuildPoints(input, OutputPointType(input, this->OutputPointsPrecision),
    *internal.Surface, result, frame, &used));
  BuildPointData(input->GetPointData(), changes->GetPointData(), input->GetNumberOfPoints(),
    *internal.Surface, result, frame, &used);
  replacedTriangles->SetNumberOfComponents(1);
  replacedTriangles->SetNumberOfValues(static_cast<vtkIdType>(frame.ReplacedTriangles.size()));
  std::copy(frame.ReplacedTriangles.begin(), frame.ReplacedTriangles.end(),
    replacedTriangles->GetPointer(0));
  vtkFieldData* fd = changes->GetFieldData();
  AddCount(fd, "SilhouetteTriangleCount", static_cast<vtkIdType>(result.SilhouetteTriangleCount));
  AddCount(fd, "ChordFallbackCount", static_cast<vtkIdType>(result.ChordFallbackTriangles));
  AddCount(fd, "UnresolvedFoldCount", static_cast<vtkIdType>(result.UnresolvedFolds));
  AddCount(fd, "CulledTriangleCount", static_cast<vtkIdType>(result.CulledTriangles));
  return 1;
}

void vtkSilhouetteSmoothingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSamples: " << this->MinimumSamples << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "NewPointBudget: " << this->NewPointBudget << "\n";
  os << indent << "PerturbVertices: " << (this->PerturbVertices ? "On" : "Off") << "\n";
  os << indent << "FoldPrevention: " << (this->FoldPrevention ? "On" : "Off") << "\n";
  os << indent << "FrustumCulling: " << (this->FrustumCulling ? "On" : "Off") << "\n";
  os << indent << "FeatureLines: " << (this->FeatureLines ? "On" : "Off") << "\n";
  os << indent << "FeatureEdgeDetection: " << (this->FeatureEdgeDetection ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "SamplingRule: "
     << (this->SamplingRule == SECOND_DIFFERENCE ? "SecondDifference" : "WangEquation8") << "\n";
  os << indent << "WeldCoincidentPoints: " << (this->WeldCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "WeldTolerance: " << this->WeldTolerance << "\n";
  os << indent << "ConsistentOrientation: " << (this->ConsistentOrientation ? "On" : "Off") << "\n";
  os << indent << "NormalSeamFeatures: " << (this->NormalSeamFeatures ? "On" : "Off") << "\n";
  os << indent << "FlatCreaseDetection: " << (this->FlatCreaseDetection ? "On" : "Off") << "\n";
  os << indent << "FlatCreaseAngle: " << this->FlatCreaseAngle << "\n";
  os << indent << "NormalEstimation: " << this->NormalEstimation << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "VisibilityMethod: "
     << (this->VisibilityMethod == HIERARCHICAL ? "Hierarchical" : "PerVertex") << "\n";
}
