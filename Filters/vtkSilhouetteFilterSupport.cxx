#include "vtkSilhouetteFilterSupport.h"

#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include "PolygonTriangulation.h"
#include "ShadingNormals.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <numeric>
#include <stdexcept>

namespace vtkSilhouetteFilterSupport
{

vtkCamera* ActiveCamera(vtkCamera* camera, vtkRenderer* renderer)
{
  if (camera)
  {
    return camera;
  }
  return renderer && renderer->IsActiveCameraCreated() ? renderer->GetActiveCamera() : nullptr;
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

namespace
{

bool AllFinite(const double* values, int count)
{
  for (int i = 0; i < count; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      return false;
    }
  }
  return true;
}

// The homogeneous point that `projection` takes to clip x = y = w = 0 (the
// centre of projection; w = 0 for a parallel one): the generalised cross
// product of its rows x, y and w, each entry a signed 3 x 3 minor. Without
// shear those rows have zeros where the minors come out exactly (0, 0, 0, w)
// or (0, 0, z, 0), so an unsheared camera's view is the same to the bit as
// the model-view matrix alone gives.
void CentreOfProjection(vtkMatrix4x4* projection, double centre[4])
{
  const double* r0 = projection->Element[0];
  const double* r1 = projection->Element[1];
  const double* r3 = projection->Element[3];
  auto minor = [&](int a, int b, int c) {
    return r0[a] * (r1[b] * r3[c] - r1[c] * r3[b]) - r0[b] * (r1[a] * r3[c] - r1[c] * r3[a]) +
      r0[c] * (r1[a] * r3[b] - r1[b] * r3[a]);
  };
  centre[0] = minor(1, 2, 3);
  centre[1] = -minor(0, 2, 3);
  centre[2] = minor(0, 1, 3);
  centre[3] = -minor(0, 1, 2);
}

} // namespace

std::string MakeViewGeometry(vtkCamera* camera, const double model[16], std::array<int, 2> viewport,
  silsmooth::ViewGeometry& view, glm::dmat3* normalToEye)
{
  // Model -> eye is the camera's model-view matrix (with its model and
  // user-view transforms) times the model matrix; the eye is its inverse
  // applied to the origin, the direction towards the viewer to +z.
  double modelView[16];
  vtkMatrix4x4::Multiply4x4(
    &camera->GetModelViewTransformMatrix()->Element[0][0], model, modelView);
  const double determinant = vtkMatrix4x4::Determinant(modelView);
  if (!AllFinite(model, 16) || !AllFinite(modelView, 16) || !(std::abs(determinant) > 0.0) ||
    !std::isfinite(determinant) || model[12] != 0.0 || model[13] != 0.0 || model[14] != 0.0 ||
    model[15] != 1.0)
  {
    return "The view is degenerate: the model matrix or the camera is singular, not affine, or "
           "not finite.";
  }
  if (viewport[0] < 1 || viewport[1] < 1)
  {
    return "The viewport size must be at least 1 x 1 pixels, not " + std::to_string(viewport[0]) +
      " x " + std::to_string(viewport[1]) + ".";
  }
  // The projection's own parameters: a NaN or zero here makes a clip matrix
  // that looks valid and projects nothing.
  const double viewAngle = camera->GetViewAngle();
  const double parallelScale = camera->GetParallelScale();
  if (camera->GetParallelProjection() && !(parallelScale > 0.0 && std::isfinite(parallelScale)))
  {
    return "The camera's parallel scale must be positive and finite, not " +
      std::to_string(parallelScale) + ".";
  }
  if (!camera->GetParallelProjection() && !(viewAngle > 0.0 && viewAngle < 180.0))
  {
    return "The camera's view angle must be between 0 and 180 degrees, not " +
      std::to_string(viewAngle) + ".";
  }
  double inverse[16];
  vtkMatrix4x4::Invert(modelView, inverse);
  view.Parallel = camera->GetParallelProjection() != 0;
  view.ViewportWidth = viewport[0];
  view.ViewportHeight = viewport[1];
  const double aspect = static_cast<double>(viewport[0]) / viewport[1];
  // The centre of projection in eye coordinates: the origin, or +z at
  // infinity, unless the projection is sheared (SetViewShear, oblique
  // parallel views, and the eyes of VTK's stereo), which moves it off the
  // view axis; the silhouette is where the surface turns from that point.
  double eye[4];
  CentreOfProjection(camera->GetProjectionTransformMatrix(aspect, -1.0, 1.0), eye);
  if (view.Parallel)
  {
    eye[3] = 0.0;
    const double length = std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
    for (int i = 0; i < 3; ++i)
    {
      eye[i] = eye[2] < 0.0 ? -eye[i] / length : eye[i] / length; // towards the viewer: +z
    }
  }
  else
  {
    for (int i = 0; i < 3; ++i)
    {
      eye[i] /= eye[3];
    }
    eye[3] = 1.0;
  }
  if (!AllFinite(eye, 4))
  {
    return "The view is degenerate: the camera's projection has no centre.";
  }
  double model4[4];
  vtkMatrix4x4::MultiplyPoint(inverse, eye, model4);
  if (view.Parallel)
  {
    view.TowardViewer = silsmooth::safeNormalize(glm::dvec3(model4[0], model4[1], model4[2]));
    double origin[4] = { 0, 0, 0, 1 };
    vtkMatrix4x4::MultiplyPoint(inverse, origin, origin);
    view.Eye = glm::dvec3(origin[0], origin[1], origin[2]) / origin[3];
  }
  else
  {
    view.Eye = glm::dvec3(model4[0], model4[1], model4[2]) / model4[3];
    double toward[4] = { 0, 0, 1, 0 };
    vtkMatrix4x4::MultiplyPoint(inverse, toward, toward);
    view.TowardViewer = silsmooth::safeNormalize(glm::dvec3(toward[0], toward[1], toward[2]));
  }

  // Model -> clip = (projection * view) * model, into glm's column-major form.
  double composite[16];
  vtkMatrix4x4::DeepCopy(
    composite, camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0));
  double clip[16];
  vtkMatrix4x4::Multiply4x4(composite, model, clip);
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      view.ModelToClip[col][row] = clip[row * 4 + col];
    }
  }
  if (normalToEye)
  {
    glm::dmat3 linear;
    for (int row = 0; row < 3; ++row)
    {
      for (int col = 0; col < 3; ++col)
      {
        linear[col][row] = modelView[row * 4 + col];
      }
    }
    *normalToEye = glm::transpose(glm::inverse(linear));
  }
  return std::string();
}

namespace
{

// A data array of three components per tuple, as dvec3s: directly from
// float and double arrays (a deforming mesh reads its points every frame),
// through GetTuple otherwise. The callers check the component count.
void ReadVectors(vtkDataArray* array, vtkIdType count, std::vector<glm::dvec3>& out)
{
  if (array->GetNumberOfComponents() != 3)
  {
    out.assign(static_cast<std::size_t>(count), glm::dvec3(std::nan("")));
    return;
  }
  out.resize(static_cast<std::size_t>(count));
  auto copy = [&](const auto* values) {
    for (vtkIdType i = 0; i < count; ++i)
    {
      const auto* v = values + 3 * i;
      out[static_cast<std::size_t>(i)] = glm::dvec3(v[0], v[1], v[2]);
    }
  };
  if (vtkDoubleArray* doubles = vtkDoubleArray::FastDownCast(array))
  {
    copy(doubles->GetPointer(0));
    return;
  }
  if (vtkFloatArray* floats = vtkFloatArray::FastDownCast(array))
  {
    copy(floats->GetPointer(0));
    return;
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    double v[3];
    array->GetTuple(i, v);
    out[static_cast<std::size_t>(i)] = glm::dvec3(v[0], v[1], v[2]);
  }
}

} // namespace

void ReadPoints(vtkPolyData* input, Triangles& out)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  out = Triangles();
  if (numPoints > 0)
  {
    ReadVectors(input->GetPoints()->GetData(), numPoints, out.Points);
  }
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    const glm::dvec3& p = out.Points[static_cast<std::size_t>(i)];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    {
      if (out.NonFinitePoints++ == 0)
      {
        out.FirstNonFinitePoint = i;
      }
    }
  }
  vtkDataArray* given = input->GetPointData()->GetNormals();
  if (given && given->GetNumberOfComponents() == 3 && given->GetNumberOfTuples() == numPoints)
  {
    ReadVectors(given, numPoints, out.Normals);
  }
}

namespace
{

// The polygon's normal by Newell's method (zero for a degenerate one); false
// when a corner names no point or has no finite position.
bool PolygonNormal(
  const std::vector<glm::dvec3>& points, const vtkIdType* ids, vtkIdType n, glm::dvec3& normal)
{
  normal = glm::dvec3(0.0);
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType a = ids[k];
    const vtkIdType b = ids[(k + 1) % n];
    if (a < 0 || b < 0 || a >= static_cast<vtkIdType>(points.size()) ||
      b >= static_cast<vtkIdType>(points.size()))
    {
      return false;
    }
    const glm::dvec3& p = points[static_cast<std::size_t>(a)];
    const glm::dvec3& q = points[static_cast<std::size_t>(b)];
    normal +=
      glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  return std::isfinite(normal.x) && std::isfinite(normal.y) && std::isfinite(normal.z);
}

glm::dvec3 TriangleNormal(
  const std::vector<glm::dvec3>& points, vtkIdType a, vtkIdType b, vtkIdType c)
{
  const glm::dvec3& p = points[static_cast<std::size_t>(a)];
  return glm::cross(
    points[static_cast<std::size_t>(b)] - p, points[static_cast<std::size_t>(c)] - p);
}

// Whether the fan from the first corner is the polygon: true unless one of
// its triangles faces against the polygon (a concave polygon, which the fan
// would cover beyond its outline: assimp's concave_polygon.obj, a ring with
// a slit, drew as a filled disc). True for what it cannot judge (missing or
// non-finite points, which are reported later, or a polygon of no area).
bool FanCovers(const std::vector<glm::dvec3>& points, const vtkIdType* ids, vtkIdType n)
{
  glm::dvec3 normal;
  if (!PolygonNormal(points, ids, n, normal) || glm::dot(normal, normal) == 0.0)
  {
    return true;
  }
  for (vtkIdType k = 1; k + 1 < n; ++k)
  {
    if (glm::dot(TriangleNormal(points, ids[0], ids[k], ids[k + 1]), normal) < 0.0)
    {
      return false;
    }
  }
  return true;
}

} // namespace

std::string ReadTriangles(vtkPolyData* input, Triangles& out)
{
  ReadPoints(input, out);
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  vtkIdType cellId = input->GetNumberOfVerts() + input->GetNumberOfLines();
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  std::vector<silsmooth::Id> corners; // a concave polygon's, for the ear clipping
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cellId)
  {
    polys->GetCurrentCell(npts, pts);
    out.TooSmallPolygons += npts < 3 ? 1 : 0;
    const std::size_t first = out.Cells.size();
    const bool concave = npts > 3 && !FanCovers(out.Points, pts, npts);
    if (concave)
    {
      corners.assign(pts, pts + npts);
    }
    if (concave &&
      silsmooth::triangulatePolygon(
        out.Points, corners.data(), static_cast<std::size_t>(npts), out.Cells))
    {
      ++out.ConcavePolygons;
    }
    else
    {
      out.UntriangulatedPolygons += concave ? 1 : 0;
      for (vtkIdType k = 1; k + 1 < npts; ++k)
      {
        out.Cells.push_back({ pts[0], pts[k], pts[k + 1] });
      }
    }
    out.CellIds.insert(out.CellIds.end(), out.Cells.size() - first, cellId);
  }
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cellId)
  {
    strips->GetCurrentCell(npts, pts);
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      if (k % 2 == 0)
      {
        out.Cells.push_back({ pts[k], pts[k + 1], pts[k + 2] });
      }
      else
      {
        out.Cells.push_back({ pts[k + 1], pts[k], pts[k + 2] });
      }
      out.CellIds.push_back(cellId);
    }
  }
  for (const silsmooth::Triangle& t : out.Cells)
  {
    for (const silsmooth::Id id : t)
    {
      if (id < 0 || id >= numPoints)
      {
        return "Input cells refer to points that do not exist.";
      }
    }
  }
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
          return "Input cells refer to points that do not exist.";
        }
      }
    }
  }
  return std::string();
}

std::optional<Surface> ReadSurface(
  vtkAlgorithm* self, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  Surface surface;
  surface.Input = vtkPolyData::GetData(inputVector[0]);
  surface.Output = vtkPolyData::GetData(outputVector, 0);
  if (!surface.Input || !surface.Output)
  {
    vtkErrorWithObjectMacro(self, "Missing input or output polydata.");
    return std::nullopt;
  }
  const std::string error = ReadFiniteTriangles(surface.Input, surface.Mesh);
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(self, << error);
    return std::nullopt;
  }
  return surface;
}

std::string ReadFiniteTriangles(vtkPolyData* input, Triangles& out)
{
  const std::string error = ReadTriangles(input, out);
  if (!error.empty() || out.NonFinitePoints == 0)
  {
    return error;
  }
  return "Input has " + std::to_string(out.NonFinitePoints) +
    " points with NaN or infinite coordinates.";
}

std::string Triangulate(vtkPolyData* input, vtkPolyData* output)
{
  output->Initialize();
  Triangles mesh;
  const std::string error = ReadTriangles(input, mesh);
  if (!error.empty())
  {
    return error;
  }
  const auto count = static_cast<vtkIdType>(mesh.Cells.size());
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(count, 3 * count);
  for (const silsmooth::Triangle& t : mesh.Cells)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  output->SetPoints(input->GetPoints());
  output->GetPointData()->PassData(input->GetPointData());
  output->SetPolys(polys);
  vtkCellData* outCd = output->GetCellData();
  outCd->CopyAllocate(input->GetCellData(), count);
  for (vtkIdType t = 0; t < count; ++t)
  {
    outCd->CopyData(input->GetCellData(), mesh.CellIds[static_cast<std::size_t>(t)], t);
  }
  output->GetFieldData()->PassData(input->GetFieldData());
  return "";
}

PassedCells PassVertsAndLines(vtkPolyData* input)
{
  const std::array<vtkCellArray*, 2> inputs{ { input->GetVerts(), input->GetLines() } };
  const std::array<vtkIdType, 2> least{ { 1, 2 } };
  const auto tooSmall = [&](std::size_t k, vtkIdType cell) {
    return inputs[k]->GetCellSize(cell) < least[k];
  };
  PassedCells passed;
  for (std::size_t k = 0; k < 2; ++k)
  {
    for (vtkIdType c = 0; c < inputs[k]->GetNumberOfCells(); ++c)
    {
      passed.Dropped += tooSmall(k, c) ? 1 : 0;
    }
  }
  // Nothing left out (the usual case, every frame): the input's own arrays.
  if (passed.Dropped == 0)
  {
    passed.Verts = inputs[0];
    passed.Lines = inputs[1];
    passed.CellIds.resize(
      static_cast<std::size_t>(inputs[0]->GetNumberOfCells() + inputs[1]->GetNumberOfCells()));
    std::iota(passed.CellIds.begin(), passed.CellIds.end(), vtkIdType{ 0 });
    return passed;
  }
  std::array<vtkSmartPointer<vtkCellArray>, 2> kept;
  vtkNew<vtkIdList> ids;
  vtkIdType cellId = 0;
  for (std::size_t k = 0; k < 2; ++k)
  {
    kept[k] = vtkSmartPointer<vtkCellArray>::New();
    for (vtkIdType c = 0; c < inputs[k]->GetNumberOfCells(); ++c, ++cellId)
    {
      if (!tooSmall(k, c))
      {
        inputs[k]->GetCellAtId(c, ids);
        kept[k]->InsertNextCell(ids);
        passed.CellIds.push_back(cellId);
      }
    }
  }
  passed.Verts = kept[0];
  passed.Lines = kept[1];
  return passed;
}

void WriteMesh(vtkPolyData* input, vtkPolyData* output, const std::vector<glm::dvec3>& inputNormals,
  const std::vector<glm::dvec3>& addedPoints, const std::vector<glm::dvec3>& addedNormals,
  const std::vector<PointSource>& addedSources, const std::vector<silsmooth::Triangle>& triangles,
  const std::vector<vtkIdType>& originalCell, const std::vector<unsigned char>& newGeometry)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType total = numPoints + static_cast<vtkIdType>(addedPoints.size());

  vtkNew<vtkPoints> points;
  vtkPoints* inPoints = input->GetPoints();
  points->SetDataType(inPoints ? inPoints->GetDataType() : VTK_FLOAT);
  points->SetNumberOfPoints(total);
  if (numPoints > 0)
  {
    points->GetData()->InsertTuples(0, numPoints, 0, inPoints->GetData());
  }
  vtkIdType id = numPoints;
  for (const glm::dvec3& p : addedPoints)
  {
    points->SetPoint(id++, p.x, p.y, p.z);
  }
  output->SetPoints(points);

  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  vtkDataArray* inNormals = inPD->GetNormals();
  outPD->CopyAllOn();
  outPD->CopyNormalsOff();
  outPD->InterpolateAllocate(inPD, total);
  if (numPoints > 0)
  {
    outPD->CopyData(inPD, 0, numPoints, 0);
  }
  vtkNew<vtkIdList> sources;
  sources->SetNumberOfIds(3);
  id = numPoints;
  for (const PointSource& s : addedSources)
  {
    for (int k = 0; k < 3; ++k)
    {
      sources->SetId(k, s.Ids[static_cast<std::size_t>(k)]);
    }
    double weights[3] = { s.Weights[0], s.Weights[1], s.Weights[2] };
    outPD->InterpolatePoint(inPD, id++, sources, weights);
  }
  if (inNormals && inNormals->GetName() && outPD->GetArray(inNormals->GetName()))
  {
    outPD->RemoveArray(inNormals->GetName());
  }
  vtkNew<vtkFloatArray> normals;
  normals->SetName(inNormals && inNormals->GetName() ? inNormals->GetName() : "Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(total);
  float* n = normals->GetPointer(0);
  for (const std::vector<glm::dvec3>* list : { &inputNormals, &addedNormals })
  {
    for (const glm::dvec3& normal : *list)
    {
      *n++ = static_cast<float>(normal.x);
      *n++ = static_cast<float>(normal.y);
      *n++ = static_cast<float>(normal.z);
    }
  }
  outPD->SetNormals(normals);

  const PassedCells passed = PassVertsAndLines(input);
  output->SetVerts(passed.Verts);
  output->SetLines(passed.Lines);
  const vtkIdType passThrough = static_cast<vtkIdType>(passed.CellIds.size());
  const vtkIdType outCells = passThrough + static_cast<vtkIdType>(triangles.size());
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles.size() + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(triangles.size() * 3));
  for (std::size_t t = 0; t <= triangles.size(); ++t)
  {
    offsets->SetValue(static_cast<vtkIdType>(t), static_cast<vtkIdType>(t * 3));
  }
  vtkIdType* conn = connectivity->GetPointer(0);
  for (const silsmooth::Triangle& t : triangles)
  {
    *conn++ = t[0];
    *conn++ = t[1];
    *conn++ = t[2];
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);

  vtkNew<vtkIdTypeArray> originalCellId;
  originalCellId->SetName("OriginalCellId");
  originalCellId->SetNumberOfValues(outCells);
  vtkNew<vtkUnsignedCharArray> kinds;
  kinds->SetName("NewGeometry");
  kinds->SetNumberOfValues(outCells);
  vtkIdType* origin = originalCellId->GetPointer(0);
  std::copy(passed.CellIds.begin(), passed.CellIds.end(), origin);
  std::copy(originalCell.begin(), originalCell.end(), origin + passThrough);
  unsigned char* kind = kinds->GetPointer(0);
  std::fill(kind, kind + passThrough, static_cast<unsigned char>(0));
  std::copy(newGeometry.begin(), newGeometry.end(), kind + passThrough);

  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  if (inCD->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> source;
    source->SetNumberOfIds(outCells);
    std::copy(origin, origin + outCells, source->begin());
    vtkNew<vtkIdList> destination;
    destination->SetNumberOfIds(outCells);
    std::iota(destination->begin(), destination->end(), vtkIdType{ 0 });
    outCD->CopyAllOn();
    outCD->CopyAllocate(inCD, outCells);
    outCD->CopyData(inCD, source, destination);
  }
  outCD->AddArray(kinds);
  outCD->AddArray(originalCellId);
}

void WriteTessellation(vtkPolyData* input, vtkPolyData* output, const Triangles& mesh,
  const silsmooth::TessellationResult& result, int level)
{
  const std::size_t inputPoints = mesh.Points.size();
  const std::vector<glm::dvec3> inputNormals(
    result.Normals.begin(), result.Normals.begin() + static_cast<std::ptrdiff_t>(inputPoints));
  const std::vector<glm::dvec3> addedPoints(
    result.Points.begin() + static_cast<std::ptrdiff_t>(inputPoints), result.Points.end());
  const std::vector<glm::dvec3> addedNormals(
    result.Normals.begin() + static_cast<std::ptrdiff_t>(inputPoints), result.Normals.end());
  std::vector<PointSource> sources(addedPoints.size());
  for (std::size_t i = 0; i < sources.size(); ++i)
  {
    const std::array<silsmooth::Id, 3>& ids = result.SourcePoints[inputPoints + i];
    const glm::dvec3& w = result.SourceWeights[inputPoints + i];
    sources[i].Ids = { { ids[0], ids[1], ids[2] } };
    sources[i].Weights = { { w.x, w.y, w.z } };
  }
  std::vector<vtkIdType> originalCell(result.TriangleSource.size());
  for (std::size_t t = 0; t < originalCell.size(); ++t)
  {
    originalCell[t] = mesh.CellIds[static_cast<std::size_t>(result.TriangleSource[t])];
  }
  const std::vector<unsigned char> newGeometry(
    result.Triangles.size(), static_cast<unsigned char>(level > 0 ? 1 : 0));
  WriteMesh(input, output, inputNormals, addedPoints, addedNormals, sources, result.Triangles,
    originalCell, newGeometry);
}

int RequestTessellation(vtkAlgorithm* self, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, int level,
  const std::function<silsmooth::TessellationResult(
    const Triangles&, const silsmooth::ProgressCallback&)>& tessellate)
{
  const std::optional<Surface> surface = ReadSurface(self, inputVector, outputVector);
  if (!surface)
  {
    return 0;
  }
  const silsmooth::TessellationResult result =
    tessellate(surface->Mesh, [self](double done) { return ReportProgress(self, done); });
  if (result.Aborted)
  {
    return 1; // the output stays empty
  }
  WriteTessellation(surface->Input, surface->Output, surface->Mesh, result, level);
  return 1;
}

bool ReportProgress(vtkAlgorithm* self, double fraction)
{
  self->UpdateProgress(fraction);
  return !self->GetAbortExecute();
}

vtkSmartPointer<vtkUnsignedCharArray> LineKindArray(vtkIdType count, LineKindValue kind)
{
  auto array = vtkSmartPointer<vtkUnsignedCharArray>::New();
  array->SetName("LineKind");
  array->SetNumberOfTuples(count);
  array->FillValue(kind);
  return array;
}

} // namespace vtkSilhouetteFilterSupport
