#include "vtkBoundaryCurveSmoothingFilter.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include "BoundaryCurveSmoother.h"
#include "SurfaceWelding.h"

#include <algorithm>

vtkStandardNewMacro(vtkBoundaryCurveSmoothingFilter);

vtkSilhouetteCheckedSetterMacro(
  vtkBoundaryCurveSmoothingFilter, Tolerance, double, 1e-3, VTK_DOUBLE_MAX);

namespace support = vtkSilhouetteFilterSupport;

struct vtkBoundaryCurveSmoothingFilter::Internals
{
  std::unique_ptr<silsmooth::BoundaryCurveMesh> Mesh;
  std::vector<vtkIdType> TriangleCell;
  vtkIdType NonFinitePoints = 0;
  vtkPolyData* CachedInput = nullptr;
  vtkMTimeType CachedInputTime = 0;
};

vtkBoundaryCurveSmoothingFilter::vtkBoundaryCurveSmoothingFilter()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
  // The renderer asks for the bounds before it creates its camera (to reset
  // it): give the input, and run for real once the camera exists.
  this->PassInputWithoutCamera = true;
}

vtkBoundaryCurveSmoothingFilter::~vtkBoundaryCurveSmoothingFilter() = default;

vtkPolyData* vtkBoundaryCurveSmoothingFilter::GetSilhouetteOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkBoundaryCurveSmoothingFilter::RequestViewData(vtkInformation*,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector,
  const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* lines = vtkPolyData::GetData(outputVector, 1);

  Internals& internal = *this->Internal;
  if (!internal.Mesh || internal.CachedInput != input ||
    internal.CachedInputTime != input->GetMTime())
  {
    internal.Mesh.reset();
    support::Triangles triangles;
    const std::string error = support::ReadTriangles(input, triangles);
    if (!error.empty())
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    internal.NonFinitePoints = triangles.NonFinitePoints;
    internal.TriangleCell = std::move(triangles.CellIds);
    // The 2003 method joins triangles by point ids: points that only share a
    // position (texture seams, triangle soups) leave borders it cannot smooth.
    std::size_t shared = 0;
    const std::vector<silsmooth::Id> vertex = silsmooth::weldCoincidentPoints(triangles.Points);
    for (std::size_t i = 0; i < vertex.size(); ++i)
    {
      shared += vertex[i] != static_cast<silsmooth::Id>(i) ? 1 : 0;
    }
    if (shared > 0 && internal.NonFinitePoints == 0)
    {
      vtkWarningMacro(<< shared
                      << " points share their position with another point (texture seams or a "
                         "triangle soup): this method joins triangles by point ids, so the edges "
                         "there are borders to it. Merge the points first (vtkCleanPolyData), "
                         "or use vtkSilhouetteSmoothingFilter, which welds them itself.");
    }
    internal.Mesh = std::make_unique<silsmooth::BoundaryCurveMesh>(
      std::move(triangles.Points), std::move(triangles.Cells), triangles.Normals);
    internal.CachedInput = input;
    internal.CachedInputTime = input->GetMTime();
  }
  if (internal.NonFinitePoints > 0)
  {
    vtkErrorMacro(
      "Input has " << internal.NonFinitePoints << " points with NaN or infinite coordinates.");
    return 0;
  }

  if (!support::ReportProgress(this, 0.4))
  {
    return 1; // aborted: the outputs stay empty
  }
  silsmooth::BoundaryCurveParameters parameters;
  parameters.SamplesPerCurve = this->SamplesPerCurve;
  parameters.TolerancePixels = this->Tolerance;
  const silsmooth::BoundaryCurveResult result =
    internal.Mesh->smooth(view.Geometry, view.NormalToEye, parameters);
  if (!support::ReportProgress(this, 0.7))
  {
    return 1;
  }

  std::vector<vtkIdType> originalCell(result.TriangleSource.size());
  for (std::size_t t = 0; t < originalCell.size(); ++t)
  {
    originalCell[t] = internal.TriangleCell[static_cast<std::size_t>(result.TriangleSource[t])];
  }
  std::vector<support::PointSource> sources(result.NewPointSources.size());
  for (std::size_t i = 0; i < sources.size(); ++i)
  {
    const silsmooth::BoundaryCurvePointSource& s = result.NewPointSources[i];
    sources[i].Ids = { { s.Points[0], s.Points[1], s.Points[2] } };
    sources[i].Weights = s.Weights;
  }
  support::WriteMesh(input, output, internal.Mesh->normals(), result.NewPoints, result.NewNormals,
    sources, result.Triangles, originalCell, result.TriangleIsNew);

  vtkFieldData* fd = output->GetFieldData();
  fd->PassData(input->GetFieldData());
  auto addCount = [fd](const char* name, std::size_t value) {
    vtkNew<vtkIdTypeArray> array;
    array->SetName(name);
    array->SetNumberOfTuples(1);
    array->SetValue(0, static_cast<vtkIdType>(value));
    fd->AddArray(array);
  };
  addCount("SilhouetteEdgeCount", result.SilhouetteEdgeCount);
  addCount("SilhouetteTriangleCount", result.RemeshedTriangleCount);
  addCount("NewPointCount", result.NewPoints.size());
  addCount("InputTriangleCount", internal.Mesh->triangles().size());
  addCount("OutputTriangleCount", result.Triangles.size());

  // Port 1: one polyline per silhouette edge, over the output's points.
  vtkNew<vtkCellArray> curves;
  for (const std::vector<silsmooth::Id>& curve : result.Curves)
  {
    curves->InsertNextCell(static_cast<int>(curve.size()));
    for (const silsmooth::Id id : curve)
    {
      curves->InsertCellPoint(id);
    }
  }
  lines->SetPoints(output->GetPoints());
  lines->GetPointData()->SetNormals(output->GetPointData()->GetNormals());
  lines->SetLines(curves);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkBoundaryCurveSmoothingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesPerCurve: " << this->SamplesPerCurve << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
}
