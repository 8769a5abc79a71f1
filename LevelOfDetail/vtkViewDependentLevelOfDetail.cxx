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
#include "VertexHierarchy.h"
#include "ViewRefinementTest.h"
#include "vtkSilhouetteFilterSupport.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

// The hierarchy of the input it was built for, and the cut that follows the view.
struct vtkViewDependentLevelOfDetail::Internals
{
  vtkPolyData* Input = nullptr;
  vtkMTimeType InputTime = 0;
  vtkIdType Base = -1;
  std::unique_ptr<silsmooth::VertexHierarchy> Hierarchy;
  std::unique_ptr<silsmooth::SelectiveRefinement> Cut;
  std::vector<vtkIdType> CellIds; // per input triangle: its input cell

  bool builtFor(vtkPolyData* input, vtkIdType base) const
  {
    return this->Hierarchy && this->Input == input && this->InputTime == input->GetMTime() &&
      this->Base == base;
  }
  void clear()
  {
    this->Cut.reset();
    this->Hierarchy.reset();
    this->Input = nullptr;
    this->CellIds.clear();
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

// Builds the hierarchy of `input`; returns an error to report, or "".
std::string BuildHierarchy(vtkPolyData* input, vtkIdType base, vtkAlgorithm* self,
  std::unique_ptr<silsmooth::VertexHierarchy>& hierarchy, std::vector<vtkIdType>& cellIds)
{
  vtkSilhouetteFilterSupport::Triangles mesh;
  std::string error = vtkSilhouetteFilterSupport::ReadFiniteTriangles(input, mesh);
  if (!error.empty())
    return error;
  silsmooth::SimplificationParameters parameters;
  parameters.TargetTriangles = static_cast<std::size_t>(std::max<vtkIdType>(base, 4));
  parameters.RecordSequence = true;
  parameters.IndependentRounds = true;
  parameters.Progress = [self](double done) {
    self->UpdateProgress(0.8 * done);
    return !self->GetAbortExecute();
  };
  const silsmooth::SimplificationResult result =
    silsmooth::simplifyQuadric(mesh.Points, mesh.Cells, parameters);
  if (result.Aborted)
    return "aborted";
  auto built = std::make_unique<silsmooth::VertexHierarchy>(
    mesh.Points, mesh.Cells, result.Sequence, mesh.Normals, [self](double done) {
      self->UpdateProgress(0.8 + 0.15 * done);
      return !self->GetAbortExecute();
    });
  if (built->aborted())
    return "aborted";
  hierarchy = std::move(built);
  cellIds.assign(mesh.CellIds.begin(), mesh.CellIds.end());
  return "";
}

} // namespace

int vtkViewDependentLevelOfDetail::RequestViewData(vtkInformation*,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector,
  const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }
  const std::string mismatched = vtkSilhouetteFilterSupport::MismatchedArrayError(input);
  if (!mismatched.empty())
  {
    vtkErrorMacro(<< mismatched);
    return 0;
  }
  Internals& internal = *this->Internal;
  if (!internal.builtFor(input, this->BaseTriangles))
  {
    internal.clear();
    std::unique_ptr<silsmooth::VertexHierarchy> hierarchy;
    std::string error;
    try
    {
      error = BuildHierarchy(input, this->BaseTriangles, this, hierarchy, internal.CellIds);
    }
    catch (const std::invalid_argument& e)
    {
      error = e.what();
    }
    if (error == "aborted")
    {
      output->Initialize(); // VTK's way: an aborted update succeeds, empty
      return 1;
    }
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
    internal.Hierarchy = std::move(hierarchy);
    internal.Cut = std::make_unique<silsmooth::SelectiveRefinement>(*internal.Hierarchy);
    internal.Input = input;
    internal.InputTime = input->GetMTime();
    internal.Base = this->BaseTriangles;
  }

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
  const silsmooth::AdaptStatistics changes = internal.Cut->adapt(
    silsmooth::ViewRefinementTest(*internal.Hierarchy, view.Geometry, tolerances));
  this->UpdateProgress(0.97);

  std::vector<glm::dvec3> points;
  std::vector<silsmooth::Triangle> triangles;
  std::vector<silsmooth::Id> pointIds;
  std::vector<silsmooth::Id> triangleIds;
  internal.Cut->extract(points, triangles, pointIds, triangleIds);

  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataTypeToDouble();
  outPoints->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    outPoints->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()) + 1);
  connectivity->SetNumberOfValues(3 * static_cast<vtkIdType>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    offsets->SetValue(static_cast<vtkIdType>(t), 3 * static_cast<vtkIdType>(t));
    for (std::size_t k = 0; k < 3; ++k)
      connectivity->SetValue(static_cast<vtkIdType>(3 * t + k), triangles[t][k]);
  }
  offsets->SetValue(
    static_cast<vtkIdType>(triangles.size()), 3 * static_cast<vtkIdType>(triangles.size()));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  output->Initialize();
  output->SetPoints(outPoints);
  output->SetPolys(polys);

  vtkNew<vtkIdList> from;
  vtkNew<vtkIdList> to;
  vtkNew<vtkIdTypeArray> originalPoint;
  originalPoint->SetName("OriginalPointId");
  originalPoint->SetNumberOfValues(static_cast<vtkIdType>(pointIds.size()));
  from->SetNumberOfIds(static_cast<vtkIdType>(pointIds.size()));
  to->SetNumberOfIds(static_cast<vtkIdType>(pointIds.size()));
  for (std::size_t i = 0; i < pointIds.size(); ++i)
  {
    from->SetId(static_cast<vtkIdType>(i), pointIds[i]);
    to->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
    originalPoint->SetValue(static_cast<vtkIdType>(i), pointIds[i]);
  }
  output->GetPointData()->CopyAllocate(input->GetPointData(), from->GetNumberOfIds());
  output->GetPointData()->CopyData(input->GetPointData(), from, to);
  output->GetPointData()->AddArray(originalPoint);
  if (!output->GetPointData()->GetNormals())
  {
    // The input's own (angle-weighted) normals, so that a coarse part is
    // shaded as the fine surface is, not as its few facets are.
    const std::vector<glm::dvec3>& normals = internal.Hierarchy->pointNormals();
    vtkNew<vtkFloatArray> outNormals;
    outNormals->SetName("Normals");
    outNormals->SetNumberOfComponents(3);
    outNormals->SetNumberOfTuples(static_cast<vtkIdType>(pointIds.size()));
    for (std::size_t i = 0; i < pointIds.size(); ++i)
    {
      const glm::dvec3& n = normals[static_cast<std::size_t>(pointIds[i])];
      outNormals->SetTuple3(static_cast<vtkIdType>(i), n.x, n.y, n.z);
    }
    output->GetPointData()->SetNormals(outNormals);
  }

  vtkNew<vtkIdTypeArray> originalCell;
  originalCell->SetName("OriginalCellId");
  originalCell->SetNumberOfValues(static_cast<vtkIdType>(triangleIds.size()));
  from->SetNumberOfIds(static_cast<vtkIdType>(triangleIds.size()));
  to->SetNumberOfIds(static_cast<vtkIdType>(triangleIds.size()));
  for (std::size_t t = 0; t < triangleIds.size(); ++t)
  {
    const vtkIdType cell = internal.CellIds[static_cast<std::size_t>(triangleIds[t])];
    from->SetId(static_cast<vtkIdType>(t), cell);
    to->SetId(static_cast<vtkIdType>(t), static_cast<vtkIdType>(t));
    originalCell->SetValue(static_cast<vtkIdType>(t), cell);
  }
  output->GetCellData()->CopyAllocate(input->GetCellData(), from->GetNumberOfIds());
  output->GetCellData()->CopyData(input->GetCellData(), from, to);
  output->GetCellData()->AddArray(originalCell);

  vtkNew<vtkIdTypeArray> splits;
  splits->SetName("LevelOfDetailSplits");
  splits->SetNumberOfComponents(2);
  splits->InsertNextTuple2(static_cast<double>(internal.Cut->appliedCount()),
    static_cast<double>(internal.Hierarchy->nodeCount()));
  output->GetFieldData()->AddArray(splits);
  vtkNew<vtkIdTypeArray> changed;
  changed->SetName("LevelOfDetailChanges");
  changed->SetNumberOfComponents(2);
  changed->InsertNextTuple2(
    static_cast<double>(changes.Applied), static_cast<double>(changes.Undone));
  output->GetFieldData()->AddArray(changed);
  vtkNew<vtkIdTypeArray> inputTriangles;
  inputTriangles->SetName("LevelOfDetailInputTriangles");
  inputTriangles->InsertNextValue(static_cast<vtkIdType>(internal.Hierarchy->faceCount()));
  output->GetFieldData()->AddArray(inputTriangles);
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
}
