#include "vtkSilhouetteSmoothingFilter.h"

#include "vtkCamera.h"
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
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include "ShadingNormals.h"
#include "SilhouetteSmoother.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkSilhouetteSmoothingFilter);

namespace
{

// Everything about the view that changes the result. The camera's own MTime
// is not enough: renderers reset its clipping range every frame, which would
// re-run the filter for nothing, while a prop's matrix or a window's size can
// change without touching the camera at all.
struct ViewSignature
{
  std::array<double, 19> Camera{};
  std::array<double, 16> Model{};
  std::array<int, 2> Viewport{};

  bool operator==(const ViewSignature& o) const
  {
    return this->Camera == o.Camera && this->Model == o.Model && this->Viewport == o.Viewport;
  }
  bool operator!=(const ViewSignature& o) const { return !(*this == o); }
};

void AddCount(vtkFieldData* fd, const char* name, vtkIdType value)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->SetNumberOfTuples(1);
  array->SetValue(0, value);
  fd->AddArray(array);
}

vtkSmartPointer<vtkPoints> BuildPoints(vtkPolyData* input, const silsmooth::SmoothingResult& result)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  vtkPoints* inPoints = input->GetPoints();
  points->SetDataType(inPoints ? inPoints->GetDataType() : VTK_FLOAT);
  const vtkIdType numPoints = input->GetNumberOfPoints();
  points->SetNumberOfPoints(numPoints + static_cast<vtkIdType>(result.NewPoints.size()));
  if (numPoints > 0)
  {
    points->GetData()->InsertTuples(0, numPoints, 0, inPoints->GetData());
  }
  vtkIdType id = numPoints;
  for (const silsmooth::NewPoint& p : result.NewPoints)
  {
    points->SetPoint(id++, p.Position.x, p.Position.y, p.Position.z);
  }
  return points;
}

// Input point arrays are copied and extended with values interpolated for the
// added points; the shading normals replace the input's normals (if any) as
// the active normals, keeping the input's array name.
void BuildPointData(vtkPointData* in, vtkPointData* out, vtkIdType numPoints,
  const silsmooth::PreparedMesh& mesh, const silsmooth::SmoothingResult& result)
{
  const vtkIdType total = numPoints + static_cast<vtkIdType>(result.NewPoints.size());
  vtkDataArray* inNormals = in->GetNormals();
  vtkNew<vtkIdList> sources;
  sources->SetNumberOfIds(3);
  for (int i = 0; i < in->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* source = in->GetAbstractArray(i);
    if (!source || source == inNormals)
    {
      continue;
    }
    // A fresh array: SetNumberOfTuples() on a copy would reallocate without
    // keeping the copied values.
    auto array = vtk::TakeSmartPointer(source->NewInstance());
    array->SetName(source->GetName());
    array->SetNumberOfComponents(source->GetNumberOfComponents());
    array->CopyComponentNames(source);
    array->SetNumberOfTuples(total);
    if (numPoints > 0)
    {
      array->InsertTuples(0, numPoints, 0, source);
    }
    vtkIdType id = numPoints;
    for (const silsmooth::NewPoint& p : result.NewPoints)
    {
      for (int k = 0; k < 3; ++k)
      {
        sources->SetId(k, p.Sources[k]);
      }
      double weights[3] = { p.Weights[0], p.Weights[1], p.Weights[2] };
      array->InterpolateTuple(id++, sources, source, weights);
    }
    out->AddArray(array);
    const int attribute = in->IsArrayAnAttribute(i);
    if (attribute >= 0 && source->GetName())
    {
      out->SetActiveAttribute(source->GetName(), attribute);
    }
  }

  vtkNew<vtkFloatArray> normals;
  normals->SetName(inNormals && inNormals->GetName() ? inNormals->GetName() : "Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(total);
  vtkIdType id = 0;
  for (const glm::dvec3& n : mesh.normals())
  {
    normals->SetTuple3(id++, n.x, n.y, n.z);
  }
  for (const silsmooth::NewPoint& p : result.NewPoints)
  {
    normals->SetTuple3(id++, p.Normal.x, p.Normal.y, p.Normal.z);
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
    triangles.size() - result.SilhouetteTriangles.size() + result.Replacements.size();
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(outTriangles + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(outTriangles * 3));
  vtkNew<vtkIdList> origin;
  origin->SetNumberOfIds(passThrough + static_cast<vtkIdType>(outTriangles));
  vtkNew<vtkUnsignedCharArray> newGeometry;
  newGeometry->SetName("NewGeometry");
  newGeometry->SetNumberOfValues(origin->GetNumberOfIds());
  for (vtkIdType c = 0; c < passThrough; ++c)
  {
    origin->SetId(c, c);
    newGeometry->SetValue(c, 0);
  }

  vtkIdType* conn = connectivity->GetPointer(0);
  vtkIdType* offs = offsets->GetPointer(0);
  vtkIdType cell = passThrough;
  std::size_t written = 0;
  auto emit = [&](const silsmooth::Triangle& t, vtkIdType from, unsigned char kind) {
    offs[written] = static_cast<vtkIdType>(written * 3);
    std::copy(t.begin(), t.end(), conn + written * 3);
    ++written;
    origin->SetId(cell, from);
    newGeometry->SetValue(cell, kind);
    ++cell;
  };
  std::size_t next = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (next < result.SilhouetteTriangles.size() &&
      result.SilhouetteTriangles[next] == static_cast<silsmooth::Id>(t))
    {
      for (std::size_t r = result.ReplacementOffsets[next]; r < result.ReplacementOffsets[next + 1];
           ++r)
      {
        emit(result.Replacements[r], triangleCell[t], 1);
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
  for (int i = 0; i < in->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* source = in->GetAbstractArray(i);
    if (!source)
    {
      continue;
    }
    auto array = vtk::TakeSmartPointer(source->NewInstance());
    array->SetName(source->GetName());
    array->SetNumberOfComponents(source->GetNumberOfComponents());
    array->SetNumberOfTuples(origin->GetNumberOfIds());
    source->GetTuples(origin, array);
    out->AddArray(array);
    const int attribute = in->IsArrayAnAttribute(i);
    if (attribute >= 0 && source->GetName())
    {
      out->SetActiveAttribute(source->GetName(), attribute);
    }
  }
  vtkNew<vtkIdTypeArray> originalCellId;
  originalCellId->SetName("OriginalCellId");
  originalCellId->SetNumberOfValues(origin->GetNumberOfIds());
  std::copy(origin->begin(), origin->end(), originalCellId->GetPointer(0));
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
    cells->InsertNextCell(static_cast<vtkIdType>(chain.size()));
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

  // The last view seen by GetMTime(), and when it last changed.
  ViewSignature LastView;
  bool HaveView = false;
  vtkTimeStamp ViewTime;

  bool Rebuild(vtkPolyData* input);
};

bool vtkSilhouetteSmoothingFilter::Internals::Rebuild(vtkPolyData* input)
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
  this->Mesh =
    std::make_unique<silsmooth::PreparedMesh>(std::move(points), std::move(triangles), normals);
  this->CachedInput = input;
  this->CachedInputTime = input->GetMTime();
  return true;
}

vtkSilhouetteSmoothingFilter::vtkSilhouetteSmoothingFilter()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
}

vtkSilhouetteSmoothingFilter::~vtkSilhouetteSmoothingFilter()
{
  this->SetCamera(nullptr);
  this->SetProp3D(nullptr);
  this->SetModelMatrix(nullptr);
}

vtkCxxSetObjectMacro(vtkSilhouetteSmoothingFilter, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkSilhouetteSmoothingFilter, Prop3D, vtkProp3D);
vtkCxxSetObjectMacro(vtkSilhouetteSmoothingFilter, ModelMatrix, vtkMatrix4x4);

void vtkSilhouetteSmoothingFilter::SetRenderer(vtkRenderer* renderer)
{
  if (this->Renderer != renderer)
  {
    this->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkSilhouetteSmoothingFilter::GetRenderer()
{
  return this->Renderer;
}

vtkPolyData* vtkSilhouetteSmoothingFilter::GetSilhouetteOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

namespace
{

vtkCamera* ActiveCamera(vtkCamera* camera, vtkRenderer* renderer)
{
  if (camera)
  {
    return camera;
  }
  return renderer ? renderer->GetActiveCamera() : nullptr;
}

void ModelMatrixOf(vtkProp3D* prop, vtkMatrix4x4* matrix, double out[16])
{
  if (prop)
  {
    prop->GetMatrix(out);
  }
  else if (matrix)
  {
    std::copy(&matrix->Element[0][0], &matrix->Element[0][0] + 16, out);
  }
  else
  {
    vtkMatrix4x4::Identity(out);
  }
}

std::array<int, 2> ViewportOf(vtkRenderer* renderer, const int fallback[2])
{
  if (renderer)
  {
    const int* size = renderer->GetSize();
    if (size[0] > 0 && size[1] > 0)
    {
      return { size[0], size[1] };
    }
  }
  return { fallback[0], fallback[1] };
}

} // namespace

vtkMTimeType vtkSilhouetteSmoothingFilter::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  vtkCamera* camera = ActiveCamera(this->Camera, this->Renderer);
  if (!camera)
  {
    return mtime;
  }
  ViewSignature view;
  double* c = view.Camera.data();
  camera->GetPosition(c);
  camera->GetFocalPoint(c + 3);
  camera->GetViewUp(c + 6);
  camera->GetWindowCenter(c + 9);
  c[11] = camera->GetViewAngle();
  c[12] = camera->GetParallelScale();
  c[13] = camera->GetParallelProjection();
  c[14] = camera->GetUseHorizontalViewAngle();
  camera->GetViewShear(c + 15);
  c[18] = camera->GetEyeAngle();
  ModelMatrixOf(this->Prop3D, this->ModelMatrix, view.Model.data());
  view.Viewport = ViewportOf(this->Renderer, this->ViewportSize);
  if (!this->Internal->HaveView || view != this->Internal->LastView)
  {
    this->Internal->LastView = view;
    this->Internal->HaveView = true;
    this->Internal->ViewTime.Modified();
  }
  return std::max(mtime, this->Internal->ViewTime.GetMTime());
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

  vtkCamera* camera = ActiveCamera(this->Camera, this->Renderer);
  if (!camera)
  {
    vtkErrorMacro("No camera: call SetCamera() or SetRenderer() before updating.");
    return 0;
  }

  Internals& internal = *this->Internal;
  if (!internal.Mesh || internal.CachedInput != input ||
    internal.CachedInputTime != input->GetMTime())
  {
    if (!internal.Rebuild(input))
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

  // The view in the data's model coordinates.
  double model[16];
  ModelMatrixOf(this->Prop3D, this->ModelMatrix, model);
  double inverse[16];
  vtkMatrix4x4::Invert(model, inverse);
  const std::array<int, 2> viewport = ViewportOf(this->Renderer, this->ViewportSize);

  silsmooth::ViewGeometry view;
  view.Parallel = camera->GetParallelProjection() != 0;
  view.ViewportWidth = viewport[0];
  view.ViewportHeight = viewport[1];
  double eye[4] = { 0, 0, 0, 1 };
  camera->GetPosition(eye);
  vtkMatrix4x4::MultiplyPoint(inverse, eye, eye);
  view.Eye = glm::dvec3(eye[0], eye[1], eye[2]) / eye[3];
  double toward[4] = { 0, 0, 0, 0 };
  camera->GetDirectionOfProjection(toward);
  toward[0] = -toward[0];
  toward[1] = -toward[1];
  toward[2] = -toward[2];
  vtkMatrix4x4::MultiplyPoint(inverse, toward, toward);
  view.TowardViewer = silsmooth::safeNormalize(glm::dvec3(toward[0], toward[1], toward[2]));

  // Model -> clip = (projection * view) * model, into glm's column-major form.
  double composite[16];
  vtkMatrix4x4::DeepCopy(composite,
    camera->GetCompositeProjectionTransformMatrix(
      static_cast<double>(viewport[0]) / viewport[1], -1.0, 1.0));
  double clip[16];
  vtkMatrix4x4::Multiply4x4(composite, model, clip);
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      view.ModelToClip[col][row] = clip[row * 4 + col];
    }
  }

  silsmooth::SamplingParameters sampling;
  sampling.TolerancePixels = this->Tolerance;
  sampling.MinimumSamples = this->MinimumSamples;
  sampling.MaximumSamples = std::max(this->MinimumSamples, this->MaximumSamples);
  sampling.Rule = this->SamplingRule == WANG_EQUATION_8 ? silsmooth::SamplingRule::WangEquation8
                                                        : silsmooth::SamplingRule::ArcBound;
  const silsmooth::ParallelFor smpFor =
    [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
      vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&body](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
    };
  const silsmooth::SmoothingResult result =
    silsmooth::smoothSilhouettes(*internal.Mesh, view, sampling, smpFor);
  this->UpdateProgress(0.6);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  const vtkIdType numPoints = input->GetNumberOfPoints();
  output->SetPoints(BuildPoints(input, result));
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
  const vtkIdType silhouetteTriangles = static_cast<vtkIdType>(result.SilhouetteTriangles.size());
  const vtkIdType newTriangles = static_cast<vtkIdType>(result.newTriangleCount());
  AddCount(fd, "SilhouetteTriangleCount", silhouetteTriangles);
  AddCount(fd, "NewTriangleCount", newTriangles);
  AddCount(fd, "NewPointCount", static_cast<vtkIdType>(result.NewPoints.size()));
  AddCount(fd, "InputTriangleCount", inputTriangles);
  AddCount(fd, "OutputTriangleCount", inputTriangles - silhouetteTriangles + newTriangles);

  BuildSilhouetteLines(output, result, lines);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkSilhouetteSmoothingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Prop3D: " << this->Prop3D << "\n";
  os << indent << "ModelMatrix: " << this->ModelMatrix << "\n";
  os << indent << "Renderer: " << this->Renderer.GetPointer() << "\n";
  os << indent << "ViewportSize: " << this->ViewportSize[0] << " x " << this->ViewportSize[1]
     << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSamples: " << this->MinimumSamples << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent
     << "SamplingRule: " << (this->SamplingRule == ARC_BOUND ? "ArcBound" : "WangEquation8")
     << "\n";
}
