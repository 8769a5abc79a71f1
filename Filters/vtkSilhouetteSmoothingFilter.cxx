#include "vtkSilhouetteSmoothingFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
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
#include "vtkUnsignedCharArray.h"

#include "vtkSilhouetteFilterSupport.h"

#include "ShadingNormals.h"
#include "SilhouetteSmoother.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkSilhouetteSmoothingFilter);

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

vtkSmartPointer<vtkPoints> BuildPoints(
  vtkPolyData* input, const silsmooth::PreparedMesh& mesh, const silsmooth::SmoothingResult& result)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  vtkPoints* inPoints = input->GetPoints();
  points->SetDataType(inPoints ? inPoints->GetDataType() : VTK_FLOAT);
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType prepared = static_cast<vtkIdType>(mesh.points().size());
  points->SetNumberOfPoints(prepared + static_cast<vtkIdType>(result.NewPoints.size()));
  if (numPoints > 0)
  {
    points->GetData()->InsertTuples(0, numPoints, 0, inPoints->GetData());
  }
  // Copies of feature points, one per extra smooth group.
  for (vtkIdType id = numPoints; id < prepared; ++id)
  {
    points->GetData()->SetTuple(id, mesh.sourcePoint(id), inPoints->GetData());
  }
  vtkIdType id = prepared;
  for (const silsmooth::NewPoint& p : result.NewPoints)
  {
    points->SetPoint(id++, p.Position.x, p.Position.y, p.Position.z);
  }
  // Vertices lowered below concave silhouette segments: in the output only.
  for (const auto& moved : result.MovedPoints)
  {
    points->SetPoint(moved.first, moved.second.x, moved.second.y, moved.second.z);
  }
  return points;
}

// Input point arrays are copied and extended with values interpolated for the
// added points; the shading normals replace the input's normals (if any) as
// the active normals, keeping the input's array name.
void BuildPointData(vtkPointData* in, vtkPointData* out, vtkIdType numPoints,
  const silsmooth::PreparedMesh& mesh, const silsmooth::SmoothingResult& result)
{
  const vtkIdType prepared = static_cast<vtkIdType>(mesh.points().size());
  const vtkIdType total = prepared + static_cast<vtkIdType>(result.NewPoints.size());
  vtkDataArray* inNormals = in->GetNormals();
  // VTK's attribute rules decide what is copied and interpolated (global and
  // pedigree ids are not interpolated); the normals are replaced below.
  out->CopyAllOn();
  out->CopyNormalsOff();
  out->InterpolateAllocate(in, total);
  if (numPoints > 0)
  {
    out->CopyData(in, 0, numPoints, 0);
  }
  for (vtkIdType id = numPoints; id < prepared; ++id)
  {
    out->CopyData(in, mesh.sourcePoint(id), id);
  }
  vtkNew<vtkIdList> sources;
  sources->SetNumberOfIds(3);
  vtkIdType id = prepared;
  for (const silsmooth::NewPoint& p : result.NewPoints)
  {
    for (int k = 0; k < 3; ++k)
    {
      sources->SetId(k, mesh.sourcePoint(p.Sources[k]));
    }
    double weights[3] = { p.Weights[0], p.Weights[1], p.Weights[2] };
    out->InterpolatePoint(in, id++, sources, weights);
  }
  if (inNormals && inNormals->GetName() && out->GetArray(inNormals->GetName()))
  {
    out->RemoveArray(inNormals->GetName());
  }

  vtkNew<vtkFloatArray> normals;
  normals->SetName(inNormals && inNormals->GetName() ? inNormals->GetName() : "Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(total);
  float* n = normals->GetPointer(0);
  for (const glm::dvec3& normal : mesh.normals())
  {
    *n++ = static_cast<float>(normal.x);
    *n++ = static_cast<float>(normal.y);
    *n++ = static_cast<float>(normal.z);
  }
  for (const silsmooth::NewPoint& p : result.NewPoints)
  {
    *n++ = static_cast<float>(p.Normal.x);
    *n++ = static_cast<float>(p.Normal.y);
    *n++ = static_cast<float>(p.Normal.z);
  }
  out->SetNormals(normals);
}

// Verts and lines pass through; polygons and strips become the triangles of
// the prepared mesh, with the silhouette triangles replaced in place.
void BuildCells(vtkPolyData* input, vtkPolyData* output, const std::vector<vtkIdType>& triangleCell,
  const silsmooth::PreparedMesh& mesh, const silsmooth::SmoothingResult& result)
{
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  const vtkIdType passThrough = input->GetNumberOfVerts() + input->GetNumberOfLines();

  const std::vector<silsmooth::Triangle>& triangles = mesh.triangles();
  const std::size_t outTriangles =
    triangles.size() - result.RemeshedTriangles.size() + result.Replacements.size();
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(outTriangles + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(outTriangles * 3));
  const vtkIdType outCells = passThrough + static_cast<vtkIdType>(outTriangles);
  vtkNew<vtkIdTypeArray> originalCellId;
  originalCellId->SetName("OriginalCellId");
  originalCellId->SetNumberOfValues(outCells);
  vtkNew<vtkUnsignedCharArray> newGeometry;
  newGeometry->SetName("NewGeometry");
  newGeometry->SetNumberOfValues(outCells);
  vtkIdType* origin = originalCellId->GetPointer(0);
  unsigned char* kinds = newGeometry->GetPointer(0);
  std::iota(origin, origin + passThrough, vtkIdType{ 0 });
  std::fill(kinds, kinds + passThrough, static_cast<unsigned char>(0));

  vtkIdType* conn = connectivity->GetPointer(0);
  vtkIdType* offs = offsets->GetPointer(0);
  vtkIdType cell = passThrough;
  std::size_t written = 0;
  auto emit = [&](const silsmooth::Triangle& t, vtkIdType from, unsigned char kind) {
    offs[written] = static_cast<vtkIdType>(written * 3);
    std::copy(t.begin(), t.end(), conn + written * 3);
    ++written;
    origin[cell] = from;
    kinds[cell] = kind;
    ++cell;
  };
  std::size_t next = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (next < result.RemeshedTriangles.size() &&
      result.RemeshedTriangles[next] == static_cast<silsmooth::Id>(t))
    {
      const auto kind = static_cast<unsigned char>(result.RemeshKinds[next]);
      for (std::size_t r = result.ReplacementOffsets[next]; r < result.ReplacementOffsets[next + 1];
           ++r)
      {
        emit(result.Replacements[r], triangleCell[t], kind);
      }
      ++next;
    }
    else
    {
      emit(triangles[t], triangleCell[t], 0);
    }
  }
  offs[written] = static_cast<vtkIdType>(written * 3);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);

  vtkCellData* in = input->GetCellData();
  vtkCellData* out = output->GetCellData();
  // Each output cell takes its original cell's data, under VTK's attribute
  // rules (global ids are not duplicated onto the replacement cells).
  if (in->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> source;
    source->SetNumberOfIds(outCells);
    std::copy(origin, origin + outCells, source->begin());
    vtkNew<vtkIdList> destination;
    destination->SetNumberOfIds(outCells);
    std::iota(destination->begin(), destination->end(), vtkIdType{ 0 });
    out->CopyAllOn();
    out->CopyAllocate(in, outCells);
    out->CopyData(in, source, destination);
  }
  out->AddArray(newGeometry);
  out->AddArray(originalCellId);
}

// Output port 1: the silhouette polylines over their own compact point set.
void BuildSilhouetteLines(
  vtkPolyData* mesh, const silsmooth::SmoothingResult& result, vtkPolyData* lines)
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
  for (const std::vector<silsmooth::Id>& chain : result.Polylines)
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
}

} // namespace

struct vtkSilhouetteSmoothingFilter::Internals
{
  // The view-independent cache, keyed on the input object and its MTime.
  std::unique_ptr<silsmooth::PreparedMesh> Mesh;
  std::vector<vtkIdType> TriangleCell; // input cell id of each triangle
  vtkIdType NonFinitePoints = 0;
  vtkIdType FirstNonFinitePoint = -1;
  vtkIdType TooSmallPolygons = 0;
  vtkPolyData* CachedInput = nullptr;
  vtkMTimeType CachedInputTime = 0;
  // The feature settings the cache was built with.
  std::array<double, 3> CachedFeatureSettings{ { -1.0, -1.0, -1.0 } };

  bool Rebuild(vtkPolyData* input, bool useLines, bool detect, double featureAngle);
};

bool vtkSilhouetteSmoothingFilter::Internals::Rebuild(
  vtkPolyData* input, bool useLines, bool detect, double featureAngle)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<glm::dvec3> points(static_cast<std::size_t>(numPoints));
  this->NonFinitePoints = 0;
  this->FirstNonFinitePoint = -1;
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      if (this->NonFinitePoints++ == 0)
      {
        this->FirstNonFinitePoint = i;
      }
    }
    points[static_cast<std::size_t>(i)] = glm::dvec3(p[0], p[1], p[2]);
  }

  // Triangulate: polygons as fans, strips with alternating orientation, so
  // every triangle keeps its cell's orientation.
  std::vector<silsmooth::Triangle> triangles;
  this->TriangleCell.clear();
  this->TooSmallPolygons = 0;
  const vtkIdType cellOffset = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkIdType cellId = cellOffset;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cellId)
  {
    polys->GetCurrentCell(npts, pts);
    this->TooSmallPolygons += npts < 3 ? 1 : 0;
    for (vtkIdType k = 1; k + 1 < npts; ++k)
    {
      triangles.push_back({ pts[0], pts[k], pts[k + 1] });
      this->TriangleCell.push_back(cellId);
    }
  }
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cellId)
  {
    strips->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      if (k % 2 == 0)
      {
        triangles.push_back({ pts[k], pts[k + 1], pts[k + 2] });
      }
      else
      {
        triangles.push_back({ pts[k + 1], pts[k], pts[k + 2] });
      }
      this->TriangleCell.push_back(cellId);
    }
  }
  for (const silsmooth::Triangle& t : triangles)
  {
    for (const silsmooth::Id id : t)
    {
      if (id < 0 || id >= numPoints)
      {
        return false;
      }
    }
  }
  // Verts and lines pass through, so their ids must be valid too.
  for (vtkCellArray* cells : { input->GetVerts(), input->GetLines() })
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(npts, pts);
      for (vtkIdType k = 0; k < npts; ++k)
      {
        if (pts[k] < 0 || pts[k] >= numPoints)
        {
          return false;
        }
      }
    }
  }

  std::vector<glm::dvec3> normals;
  if (vtkDataArray* given = input->GetPointData()->GetNormals())
  {
    if (given->GetNumberOfComponents() == 3 && given->GetNumberOfTuples() == numPoints)
    {
      normals.resize(static_cast<std::size_t>(numPoints));
      for (vtkIdType i = 0; i < numPoints; ++i)
      {
        double n[3];
        given->GetTuple(i, n);
        normals[static_cast<std::size_t>(i)] = glm::dvec3(n[0], n[1], n[2]);
      }
    }
  }
  // Feature edges: the segments of line cells (marked), and edges sharper
  // than the feature angle (detected).
  std::vector<silsmooth::FeatureEdge> features;
  if (useLines)
  {
    auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(npts, pts);
      for (vtkIdType k = 0; k + 1 < npts; ++k)
      {
        features.emplace_back(pts[k], pts[k + 1]);
      }
    }
  }
  if (detect)
  {
    const std::vector<silsmooth::FeatureEdge> sharp =
      silsmooth::featureEdgesByAngle(points, triangles, featureAngle);
    features.insert(features.end(), sharp.begin(), sharp.end());
  }
  this->Mesh = std::make_unique<silsmooth::PreparedMesh>(
    std::move(points), std::move(triangles), normals, std::move(features));
  this->CachedInput = input;
  this->CachedInputTime = input->GetMTime();
  this->CachedFeatureSettings = { { useLines ? 1.0 : 0.0, detect ? 1.0 : 0.0, featureAngle } };
  return true;
}

vtkSilhouetteSmoothingFilter::vtkSilhouetteSmoothingFilter()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
}

vtkSilhouetteSmoothingFilter::~vtkSilhouetteSmoothingFilter() = default;

vtkPolyData* vtkSilhouetteSmoothingFilter::GetSilhouetteOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkSilhouetteSmoothingFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* lines = vtkPolyData::GetData(outputVector, 1);
  if (!input || !output || !lines)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }

  vtkSilhouetteFilterSupport::View view;
  const ViewStatus viewStatus = this->RequestView(view);
  if (viewStatus == VIEW_NO_CAMERA_YET)
  {
    // The renderer asks for the bounds before it creates its camera (to reset
    // it): give the input, and run for real once the camera exists.
    output->ShallowCopy(input);
    lines->Initialize();
    return 1;
  }
  if (viewStatus != VIEW_READY)
  {
    return 0; // reported
  }

  Internals& internal = *this->Internal;
  const std::array<double, 3> featureSettings{ { this->FeatureLines ? 1.0 : 0.0,
    this->FeatureEdgeDetection ? 1.0 : 0.0, this->FeatureAngle } };
  if (!internal.Mesh || internal.CachedInput != input ||
    internal.CachedInputTime != input->GetMTime() ||
    internal.CachedFeatureSettings != featureSettings)
  {
    if (!internal.Rebuild(
          input, this->FeatureLines, this->FeatureEdgeDetection, this->FeatureAngle))
    {
      internal.Mesh.reset();
      vtkErrorMacro("Input cells refer to points that do not exist.");
      return 0;
    }
  }
  if (internal.NonFinitePoints > 0)
  {
    vtkErrorMacro("Input has " << internal.NonFinitePoints
                               << " points with NaN or infinite coordinates (the first is point "
                               << internal.FirstNonFinitePoint << ").");
    return 0;
  }
  this->UpdateProgress(0.2);

  silsmooth::SmoothingParameters parameters;
  parameters.PerturbConcaveSilhouettes = this->PerturbVertices;
  parameters.Visibility = this->VisibilityMethod == HIERARCHICAL
    ? silsmooth::VisibilityMethod::Hierarchical
    : silsmooth::VisibilityMethod::PerVertex;
  silsmooth::SamplingParameters& sampling = parameters.Sampling;
  sampling.TolerancePixels = this->Tolerance;
  sampling.MinimumSamples = this->MinimumSamples;
  sampling.MaximumSamples = std::max(this->MinimumSamples, this->MaximumSamples);
  sampling.Rule = this->SamplingRule == WANG_EQUATION_8 ? silsmooth::SamplingRule::WangEquation8
                                                        : silsmooth::SamplingRule::SecondDifference;
  const silsmooth::ParallelFor smpFor =
    [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
      vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&body](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
    };
  const silsmooth::SmoothingResult result =
    silsmooth::smoothSilhouettes(*internal.Mesh, view.Geometry, parameters, smpFor);
  this->UpdateProgress(0.6);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  const vtkIdType numPoints = input->GetNumberOfPoints();
  output->SetPoints(BuildPoints(input, *internal.Mesh, result));
  BuildPointData(input->GetPointData(), output->GetPointData(), numPoints, *internal.Mesh, result);
  this->UpdateProgress(0.8);
  BuildCells(input, output, internal.TriangleCell, *internal.Mesh, result);
  if (internal.TooSmallPolygons > 0)
  {
    vtkWarningMacro(<< internal.TooSmallPolygons
                    << " polygons with fewer than 3 points make no triangle and were dropped.");
  }

  vtkFieldData* fd = output->GetFieldData();
  fd->PassData(input->GetFieldData());
  const vtkIdType inputTriangles = static_cast<vtkIdType>(internal.Mesh->triangles().size());
  const vtkIdType remeshedTriangles = static_cast<vtkIdType>(result.RemeshedTriangles.size());
  const vtkIdType newTriangles = static_cast<vtkIdType>(result.newTriangleCount());
  AddCount(fd, "SilhouetteTriangleCount", static_cast<vtkIdType>(result.SilhouetteTriangleCount));
  AddCount(
    fd, "FeatureTriangleCount", static_cast<vtkIdType>(internal.Mesh->featureTriangles().size()));
  AddCount(
    fd, "FeatureEdgeCount", static_cast<vtkIdType>(internal.Mesh->features().edges().size()));
  AddCount(fd, "SplitPointCount",
    static_cast<vtkIdType>(internal.Mesh->points().size() - internal.Mesh->inputPointCount()));
  AddCount(fd, "NewTriangleCount", newTriangles);
  AddCount(fd, "NewPointCount", static_cast<vtkIdType>(result.NewPoints.size()));
  AddCount(fd, "ConcaveSegmentCount", static_cast<vtkIdType>(result.ConcaveSegmentCount));
  AddCount(fd, "PerturbedPointCount", static_cast<vtkIdType>(result.MovedPoints.size()));
  AddCount(fd, "InputTriangleCount", inputTriangles);
  AddCount(fd, "OutputTriangleCount", inputTriangles - remeshedTriangles + newTriangles);

  BuildSilhouetteLines(output, result, lines);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkSilhouetteSmoothingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSamples: " << this->MinimumSamples << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "PerturbVertices: " << (this->PerturbVertices ? "On" : "Off") << "\n";
  os << indent << "FeatureLines: " << (this->FeatureLines ? "On" : "Off") << "\n";
  os << indent << "FeatureEdgeDetection: " << (this->FeatureEdgeDetection ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "SamplingRule: "
     << (this->SamplingRule == SECOND_DIFFERENCE ? "SecondDifference" : "WangEquation8") << "\n";
  os << indent << "VisibilityMethod: "
     << (this->VisibilityMethod == HIERARCHICAL ? "Hierarchical" : "PerVertex") << "\n";
}
