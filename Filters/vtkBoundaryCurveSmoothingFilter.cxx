#include "vtkBoundaryCurveSmoothingFilter.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"

#include "vtkSilhouetteFilterSupport.h"

#include "BoundaryCurveSmoother.h"

#include <algorithm>

vtkStandardNewMacro(vtkBoundaryCurveSmoothingFilter);

namespace support = vtkSilhouetteFilterSupport;

struct vtkBoundaryCurveSmoothingFilter::Internals
{
  std::unique_ptr<silsmooth::BoundaryCurveMesh> Mesh;
  std::vector<vtkIdType> TriangleCell;
  vtkIdType NonFinitePoints = 0;
  vtkPolyData* CachedInput = nullptr;
  vtkMTimeType CachedInputTime = 0;
  support::ViewTracker View;
};

vtkBoundaryCurveSmoothingFilter::vtkBoundaryCurveSmoothingFilter()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(2);
}

vtkBoundaryCurveSmoothingFilter::~vtkBoundaryCurveSmoothingFilter()
{
  this->SetCamera(nullptr);
  this->SetModelMatrix(nullptr);
}

vtkCxxSetObjectMacro(vtkBoundaryCurveSmoothingFilter, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkBoundaryCurveSmoothingFilter, ModelMatrix, vtkMatrix4x4);

void vtkBoundaryCurveSmoothingFilter::SetProp3D(vtkProp3D* prop)
{
  if (this->Prop3D != prop)
  {
    this->Prop3D = prop;
    this->Modified();
  }
}

vtkProp3D* vtkBoundaryCurveSmoothingFilter::GetProp3D()
{
  return this->Prop3D;
}

void vtkBoundaryCurveSmoothingFilter::SetRenderer(vtkRenderer* renderer)
{
  if (this->Renderer != renderer)
  {
    this->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkBoundaryCurveSmoothingFilter::GetRenderer()
{
  return this->Renderer;
}

vtkPolyData* vtkBoundaryCurveSmoothingFilter::GetSilhouetteOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

vtkMTimeType vtkBoundaryCurveSmoothingFilter::GetMTime()
{
  const vtkMTimeType mtime = this->Superclass::GetMTime();
  vtkCamera* camera = support::ActiveCamera(this->Camera, this->Renderer);
  if (!camera)
  {
    return mtime;
  }
  double model[16];
  support::ModelMatrixOf(this->Prop3D, this->ModelMatrix, model);
  return std::max(mtime,
    this->Internal->View.Update(
      camera, model, support::ViewportOf(this->Renderer, this->ViewportSize)));
}

int vtkBoundaryCurveSmoothingFilter::RequestData(
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
  vtkCamera* camera = support::ActiveCamera(this->Camera, this->Renderer);
  if (!camera && this->Renderer)
  {
    output->ShallowCopy(input); // the renderer asks for bounds before it makes its camera
    lines->Initialize();
    return 1;
  }
  if (!camera)
  {
    vtkErrorMacro("No camera: call SetCamera() or SetRenderer() before updating.");
    return 0;
  }

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

  double model[16];
  support::ModelMatrixOf(this->Prop3D, this->ModelMatrix, model);
  silsmooth::ViewGeometry view;
  glm::dmat3 normalToEye(1.0);
  const std::string viewError = support::MakeViewGeometry(
    camera, model, support::ViewportOf(this->Renderer, this->ViewportSize), view, &normalToEye);
  if (!viewError.empty())
  {
    vtkErrorMacro(<< viewError);
    return 0;
  }
  silsmooth::BoundaryCurveParameters parameters;
  parameters.SamplesPerCurve = this->SamplesPerCurve;
  parameters.TolerancePixels = this->Tolerance;
  const silsmooth::BoundaryCurveResult result =
    internal.Mesh->smooth(view, normalToEye, parameters);

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
  return 1;
}

void vtkBoundaryCurveSmoothingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "Prop3D: " << this->Prop3D.GetPointer() << "\n";
  os << indent << "ModelMatrix: " << this->ModelMatrix << "\n";
  os << indent << "Renderer: " << this->Renderer.GetPointer() << "\n";
  os << indent << "ViewportSize: " << this->ViewportSize[0] << " x " << this->ViewportSize[1]
     << "\n";
  os << indent << "SamplesPerCurve: " << this->SamplesPerCurve << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
}
