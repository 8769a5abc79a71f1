#include "vtkViewDependentLevelOfDetail.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "QuadricSimplifier.h"
#include "SelectiveRefinement.h"
#include "SurfaceWelding.h"
#include "VertexHierarchy.h"
#include "ViewRefinementTest.h"
#include "vtkSilhouetteFilterSupport.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

vtkStandardNewMacro(vtkViewDependentLevelOfDetail);

vtkSilhouetteCheckedSetterMacro(
  vtkViewDependentLevelOfDetail, ContourTolerance, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(
  vtkViewDependentLevelOfDetail, InteriorTolerance, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(
  vtkViewDependentLevelOfDetail, BackFacingTolerance, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkViewDependentLevelOfDetail, ContourMargin, double, 0.0, 90.0);
vtkSilhouetteCheckedSetterMacro(vtkViewDependentLevelOfDetail, Hysteresis, double, 1e-3, 1.0);
vtkSilhouetteCheckedSetterMacro(vtkViewDependentLevelOfDetail, HysteresisAngle, double, 0.0, 90.0);

void vtkViewDependentLevelOfDetail::SetBaseTriangles(vtkIdType count)
{
  count = count < 0 ? 0 : count;
  if (count != this->BaseTriangles)
  {
    this->BaseTriangles = count;
    this->Modified();
  }
}

namespace
{

// The input's tables the output needs: per triangle its input cell and its
// input points, per point its welded vertex.
struct InputTables
{
  std::vector<vtkIdType> CellIds;
  std::vector<silsmooth::Triangle> InputCorners;
  std::vector<silsmooth::Id> Vertex;
};

} // namespace

// The hierarchy of the input it was built for, and the cut that follows the view.
struct vtkViewDependentLevelOfDetail::Internals
{
  vtkPolyData* Input = nullptr;
  vtkMTimeType InputTime = 0;
  vtkIdType Base = -1;
  std::unique_ptr<silsmooth::VertexHierarchy> Hierarchy;
  std::unique_ptr<silsmooth::SelectiveRefinement> Cut;
  bool Weld = true;
  InputTables Tables;

  bool builtFor(vtkPolyData* input, vtkIdType base, bool weld) const
  {
    return this->Hierarchy && this->Input == input && this->InputTime == input->GetMTime() &&
      this->Base == base && this->Weld == weld;
  }
  void clear()
  {
    this->Cut.reset();
    this->Hierarchy.reset();
    this->Input = nullptr;
    this->Tables = InputTables();
  }
};

vtkViewDependentLevelOfDetail::vtkViewDependentLevelOfDetail()
  : Internal(new Internals)
{
  // A missing camera is an error, as for the other filters whose output is
  // not the input.
  this->WaitForRenderer = false;
}

vtkViewDependentLevelOfDetail::~vtkViewDependentLevelOfDetail() = default;

namespace
{

// Builds the hierarchy of `input` (on its welded surface when `weld`), and
// fills `internal`; returns an error to report, "aborted", or "".
std::string BuildHierarchy(vtkPolyData* input, vtkIdType base, bool weld, vtkAlgorithm* self,
  std::unique_ptr<silsmooth::VertexHierarchy>& hierarchy, InputTables& internal)
{
  vtkSilhouetteFilterSupport::Triangles mesh;
  std::string error = vtkSilhouetteFilterSupport::ReadFiniteTriangles(input, mesh);
  if (!error.empty())
    return error;
  internal.Vertex.resize(mesh.Points.size());
  if (weld)
    internal.Vertex = silsmooth::weldCoincidentPoints(mesh.Points);
  else
    std::iota(internal.Vertex.begin(), internal.Vertex.end(), silsmooth::Id(0));
  const std::vector<silsmooth::Triangle> cells =
    weld ? silsmooth::weldTriangles(mesh.Cells, internal.Vertex) : mesh.Cells;
  silsmooth::SimplificationParameters parameters;
  parameters.TargetTriangles = static_cast<std::size_t>(std::max<vtkIdType>(base, 4));
  parameters.RecordSequence = true;
  parameters.IndependentRounds = true;
  parameters.Progress = [self](double done) {
    return vtkSilhouetteFilterSupport::ReportProgress(self, 0.8 * done);
  };
  const silsmooth::SimplificationResult result =
    silsmooth::simplifyQuadric(mesh.Points, cells, parameters);
  if (result.Aborted)
    return "aborted";
  auto built = std::make_unique<silsmooth::VertexHierarchy>(
    mesh.Points, cells, result.Sequence, mesh.Normals, [self](double done) {
      return vtkSilhouetteFilterSupport::ReportProgress(self, 0.8 + 0.15 * done);
    });
  if (built->aborted())
    return "aborted";
  hierarchy = std::move(built);
  internal.CellIds.assign(mesh.CellIds.begin(), mesh.CellIds.end());
  internal.InputCorners = std::move(mesh.Cells);
  return "";
}

// The cut's mesh with each corner given back as its triangle's own input
// point where the triangle still has that vertex (so texture seams and hard
// edges keep their copies wherever the mesh is at full resolution), else as
// the welded vertex; every copy at its vertex's position in the cut.
silsmooth::ExtractedMesh WithInputCopies(const silsmooth::ExtractedMesh& cut,
  const std::vector<silsmooth::Triangle>& inputCorners, const std::vector<silsmooth::Id>& vertex)
{
  silsmooth::ExtractedMesh out;
  out.TriangleIds = cut.TriangleIds;
  out.Triangles.resize(cut.Triangles.size());
  std::unordered_map<silsmooth::Id, silsmooth::Id> outputOf; // input copy -> output point
  for (std::size_t t = 0; t < cut.Triangles.size(); ++t)
  {
    const silsmooth::Triangle& own = inputCorners[static_cast<std::size_t>(cut.TriangleIds[t])];
    for (std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t at = static_cast<std::size_t>(cut.Triangles[t][k]);
      const silsmooth::Id v = cut.PointIds[at];
      silsmooth::Id copy = v;
      for (const silsmooth::Id c : own)
        copy = vertex[static_cast<std::size_t>(c)] == v ? c : copy;
      const auto [it, added] =
        outputOf.emplace(copy, static_cast<silsmooth::Id>(out.PointIds.size()));
      if (added)
      {
        out.PointIds.push_back(copy);
        out.Points.push_back(cut.Points[at]);
        out.Normals.push_back(cut.Normals[at]);
      }
      out.Triangles[t][k] = it->second;
    }
  }
  return out;
}

} // namespace

namespace
{

// The extracted mesh: its points and triangles.
void WriteMesh(const silsmooth::ExtractedMesh& mesh, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.Points.size()));
  for (std::size_t i = 0; i < mesh.Points.size(); ++i)
  {
    const glm::dvec3& p = mesh.Points[i];
    points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
  }
  const auto count = static_cast<vtkIdType>(mesh.Triangles.size());
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(3 * count);
  for (vtkIdType t = 0; t < count; ++t)
  {
    offsets->SetValue(t, 3 * t);
    for (vtkIdType k = 0; k < 3; ++k)
      connectivity->SetValue(3 * t + k, mesh.Triangles[static_cast<std::size_t>(t)][k]);
  }
  offsets->SetValue(count, 3 * count);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(polys);
}

// Copies the input's tuples `from[i]` to the output's `i`, and adds the ids as
// `idName`.
void CopyTuples(vtkDataSetAttributes* in, vtkDataSetAttributes* out,
  const std::vector<vtkIdType>& from, const char* idName)
{
  vtkNew<vtkIdList> fromIds;
  vtkNew<vtkIdList> toIds;
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName(idName);
  const auto count = static_cast<vtkIdType>(from.size());
  fromIds->SetNumberOfIds(count);
  toIds->SetNumberOfIds(count);
  ids->SetNumberOfValues(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    fromIds->SetId(i, from[static_cast<std::size_t>(i)]);
    toIds->SetId(i, i);
    ids->SetValue(i, from[static_cast<std::size_t>(i)]);
  }
  out->CopyAllocate(in, count);
  out->CopyData(in, fromIds, toIds);
  out->AddArray(ids);
}

// A point that a collapse placed away from its input position gets its
// cluster's normal (ExtractedMesh::Normals): the input's normal belongs to
// the input position (on a sphere with exact normals, merged points sat up
// to 16 degrees off it, and the shading was blotchy). Points at their input
// position keep the input's normal exactly, and so does a copy whose normal
// differs from its welded vertex's (`vertexNormals`) by more than 10
// degrees: it is the other side of a hard edge, which the cluster's normal,
// summed on the vertex's side, would smooth away.
void UseClusterNormalsWhereMoved(const silsmooth::ExtractedMesh& mesh, vtkPoints* inputPoints,
  const std::vector<glm::dvec3>& vertexNormals, const std::vector<silsmooth::Id>& vertex,
  vtkDataArray* normals)
{
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    return;
  }
  const double sameSide = std::cos(10.0 * vtkMath::Pi() / 180.0);
  for (std::size_t i = 0; i < mesh.Points.size(); ++i)
  {
    double at[3];
    inputPoints->GetPoint(static_cast<vtkIdType>(mesh.PointIds[i]), at);
    const glm::dvec3& p = mesh.Points[i];
    if (p.x == at[0] && p.y == at[1] && p.z == at[2])
    {
      continue;
    }
    double own[3];
    normals->GetTuple(static_cast<vtkIdType>(i), own);
    const glm::dvec3 copy(own[0], own[1], own[2]);
    const glm::dvec3& welded =
      vertexNormals[static_cast<std::size_t>(vertex[static_cast<std::size_t>(mesh.PointIds[i])])];
    const double lengths = glm::length(copy) * glm::length(welded);
    if (!(glm::dot(copy, welded) >= sameSide * lengths) && lengths > 0.0)
    {
      continue; // across a hard edge from the vertex's side
    }
    const glm::vec3& n = mesh.Normals[i];
    normals->SetTuple3(static_cast<vtkIdType>(i), n.x, n.y, n.z);
  }
}

// The input's own (angle-weighted) normals, when it gives none: a coarse part
// is then shaded as the fine surface is, not as its few facets are.
void AddComputedNormals(const std::vector<glm::dvec3>& normals,
  const std::vector<silsmooth::Id>& vertex, const std::vector<vtkIdType>& pointIds,
  vtkPointData* out)
{
  vtkNew<vtkFloatArray> outNormals;
  outNormals->SetName("Normals");
  outNormals->SetNumberOfComponents(3);
  outNormals->SetNumberOfTuples(static_cast<vtkIdType>(pointIds.size()));
  for (std::size_t i = 0; i < pointIds.size(); ++i)
  {
    const glm::dvec3& n =
      normals[static_cast<std::size_t>(vertex[static_cast<std::size_t>(pointIds[i])])];
    outNormals->SetTuple3(static_cast<vtkIdType>(i), n.x, n.y, n.z);
  }
  out->SetNormals(outNormals);
}

void AddCount(vtkPolyData* output, const char* name, double first, double second = -1.0)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(second < 0.0 ? 1 : 2);
  if (second < 0.0)
    array->InsertNextTuple1(first);
  else
    array->InsertNextTuple2(first, second);
  output->GetFieldData()->AddArray(array);
}

} // namespace

int vtkViewDependentLevelOfDetail::EnsureHierarchy(vtkPolyData* input)
{
  Internals& internal = *this->Internal;
  if (internal.builtFor(input, this->BaseTriangles, this->WeldCoincidentPoints))
    return 1;
  internal.clear();
  std::unique_ptr<silsmooth::VertexHierarchy> hierarchy;
  std::string error;
  try
  {
    error = BuildHierarchy(
      input, this->BaseTriangles, this->WeldCoincidentPoints, this, hierarchy, internal.Tables);
  }
  catch (const std::invalid_argument& e)
  {
    error = e.what();
  }
  if (error == "aborted")
    return -1;
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() > 0)
  {
    vtkWarningMacro("The input's " << input->GetNumberOfVerts() << " vertex and "
                                   << input->GetNumberOfLines()
                                   << " line cells are left out: only surfaces are refined.");
  }
  if (hierarchy->baseFaces().empty())
  {
    vtkWarningMacro("The input has no triangles to refine: the output is empty.");
  }
  else if (hierarchy->nodeCount() == 0 && hierarchy->baseFaces().size() > 4)
  {
    vtkWarningMacro("No edge of the input could be collapsed (each is on a border or shared by "
                    "more than two triangles"
      << (this->WeldCoincidentPoints ? "" : "; WeldCoincidentPoints is off")
      << "): every view gets the whole input.");
  }
  internal.Hierarchy = std::move(hierarchy);
  internal.Cut = std::make_unique<silsmooth::SelectiveRefinement>(*internal.Hierarchy);
  internal.Input = input;
  internal.InputTime = input->GetMTime();
  internal.Base = this->BaseTriangles;
  internal.Weld = this->WeldCoincidentPoints;
  return 1;
}

silsmooth::ViewRefinementTolerances vtkViewDependentLevelOfDetail::Tolerances() const
{
  silsmooth::ViewRefinementTolerances tolerances;
  tolerances.ContourPixels = this->ContourTolerance;
  tolerances.InteriorPixels = this->InteriorTolerance;
  tolerances.BackPixels = this->BackFacingTolerance >= VTK_DOUBLE_MAX
    ? std::numeric_limits<double>::infinity()
    : this->BackFacingTolerance;
  tolerances.ContourMarginDegrees = this->ContourMargin;
  tolerances.CullOutsideFrustum = this->FrustumCulling != 0;
  tolerances.Hysteresis = this->Hysteresis;
  tolerances.HysteresisDegrees = this->HysteresisAngle;
  return tolerances;
}

int vtkViewDependentLevelOfDetail::RequestViewData(vtkInformation*,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector,
  const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const int built = this->EnsureHierarchy(input);
  if (built <= 0)
  {
    output->Initialize(); // aborted (VTK's way: the update succeeds, empty), or failed
    return built < 0 ? 1 : 0;
  }
  Internals& internal = *this->Internal;
  const silsmooth::AdaptStatistics changes = internal.Cut->adapt(
    silsmooth::ViewRefinementTest(*internal.Hierarchy, view.Geometry, this->Tolerances()));
  this->UpdateProgress(0.97);

  silsmooth::ExtractedMesh cut;
  internal.Cut->extract(cut);
  const silsmooth::ExtractedMesh mesh =
    WithInputCopies(cut, internal.Tables.InputCorners, internal.Tables.Vertex);
  WriteMesh(mesh, output);
  const std::vector<vtkIdType> pointIds(mesh.PointIds.begin(), mesh.PointIds.end());
  CopyTuples(input->GetPointData(), output->GetPointData(), pointIds, "OriginalPointId");
  if (!output->GetPointData()->GetNormals())
  {
    AddComputedNormals(
      internal.Hierarchy->pointNormals(), internal.Tables.Vertex, pointIds, output->GetPointData());
  }
  UseClusterNormalsWhereMoved(mesh, input->GetPoints(), internal.Hierarchy->pointNormals(),
    internal.Tables.Vertex, output->GetPointData()->GetNormals());
  std::vector<vtkIdType> cellIds(mesh.TriangleIds.size());
  for (std::size_t t = 0; t < cellIds.size(); ++t)
    cellIds[t] = internal.Tables.CellIds[static_cast<std::size_t>(mesh.TriangleIds[t])];
  CopyTuples(input->GetCellData(), output->GetCellData(), cellIds, "OriginalCellId");

  AddCount(output, "LevelOfDetailSplits", static_cast<double>(internal.Cut->appliedCount()),
    static_cast<double>(internal.Hierarchy->nodeCount()));
  AddCount(output, "LevelOfDetailChanges", static_cast<double>(changes.Applied),
    static_cast<double>(changes.Undone));
  AddCount(
    output, "LevelOfDetailInputTriangles", static_cast<double>(internal.Hierarchy->faceCount()));
  this->UpdateProgress(1.0);
  return 1;
}

void vtkViewDependentLevelOfDetail::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ContourTolerance: " << this->ContourTolerance << "\n";
  os << indent << "InteriorTolerance: " << this->InteriorTolerance << "\n";
  os << indent << "BackFacingTolerance: " << this->BackFacingTolerance << "\n";
  os << indent << "ContourMargin: " << this->ContourMargin << "\n";
  os << indent << "Hysteresis: " << this->Hysteresis << "\n";
  os << indent << "HysteresisAngle: " << this->HysteresisAngle << "\n";
  os << indent << "FrustumCulling: " << this->FrustumCulling << "\n";
  os << indent << "BaseTriangles: " << this->BaseTriangles << "\n";
  os << indent << "WeldCoincidentPoints: " << this->WeldCoincidentPoints << "\n";
}
