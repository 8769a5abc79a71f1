#include "vtkFaceSilhouetteLines.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include "FaceSilhouetteLines.h"
#include "WeldedSurface.h"
#include "vtkSilhouetteFilterSupport.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkFaceSilhouetteLines);

struct vtkFaceSilhouetteLines::Internals
{
  std::unique_ptr<silsmooth::WeldedSurface> Mesh;
  vtkPolyData* CachedInput = nullptr;
  vtkMTimeType CachedInputTime = 0;
  bool NonFinite = false;
};

vtkFaceSilhouetteLines::vtkFaceSilhouetteLines()
  : Internal(new Internals)
{
  // The viewport plays no part in the lines: a fixed one keeps window
  // resizes from re-running the filter.
  this->ViewportDependent = false;
}

vtkFaceSilhouetteLines::~vtkFaceSilhouetteLines() = default;

int vtkFaceSilhouetteLines::RequestViewData(vtkInformation*, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, const vtkSilhouetteFilterSupport::View& view)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);

  Internals& internal = *this->Internal;
  if (!internal.Mesh || internal.CachedInput != input ||
    internal.CachedInputTime != input->GetMTime())
  {
    internal.Mesh.reset();
    vtkSilhouetteFilterSupport::Triangles mesh;
    const std::string readError = vtkSilhouetteFilterSupport::ReadTriangles(input, mesh);
    if (!readError.empty())
    {
      vtkErrorMacro(<< readError);
      return 0;
    }
    internal.NonFinite = mesh.NonFinitePoints > 0;
    if (!internal.NonFinite)
    {
      // The surface as the smoothing filter prepares it (with its defaults):
      // points at one position are one vertex, triangles oriented, normal
      // seams and flat creases split the normals. Line cells are not creases
      // here: this filter has no FeatureLines option.
      internal.Mesh =
        std::make_unique<silsmooth::WeldedSurface>(std::move(mesh.Points), std::move(mesh.Cells),
          mesh.Normals, std::vector<silsmooth::FeatureEdge>{}, silsmooth::SurfaceOptions{});
    }
    internal.CachedInput = input;
    internal.CachedInputTime = input->GetMTime();
  }
  if (internal.NonFinite)
  {
    vtkErrorMacro("Input has points with NaN or infinite coordinates.");
    return 0;
  }

  if (!vtkSilhouetteFilterSupport::ReportProgress(this, 0.4))
  {
    return 1; // aborted: the output stays empty
  }
  const silsmooth::ParallelFor smpFor =
    [](std::size_t count, const std::function<void(std::size_t, std::size_t)>& body) {
      vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&body](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
    };
  const silsmooth::FaceSilhouette lines =
    silsmooth::faceSilhouette(internal.Mesh->prepared(), view.Geometry, smpFor);
  const silsmooth::PreparedMesh& prepared = internal.Mesh->prepared();
  if (!vtkSilhouetteFilterSupport::ReportProgress(this, 0.7))
  {
    return 1;
  }

  const vtkIdType count = static_cast<vtkIdType>(lines.Crossings.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(count);
  vtkNew<vtkIdTypeArray> ends;
  ends->SetName("EdgeEnds");
  ends->SetNumberOfComponents(2);
  ends->SetNumberOfTuples(count);
  vtkNew<vtkDoubleArray> parameter;
  parameter->SetName("EdgeParameter");
  parameter->SetNumberOfTuples(count);
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyNormalsOff(); // replaced by the normalised interpolation below
  outPD->InterpolateAllocate(inPD, count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const silsmooth::EdgeCrossing& c = lines.Crossings[static_cast<std::size_t>(i)];
    points->SetPoint(i, c.Position.x, c.Position.y, c.Position.z);
    normals->SetTuple3(i, c.Normal.x, c.Normal.y, c.Normal.z);
    // Prepared points are input points or copies of them (feature splits).
    vtkIdType low = prepared.sourcePoint(c.Low);
    vtkIdType high = prepared.sourcePoint(c.High);
    double t = c.T;
    if (low > high)
    {
      std::swap(low, high);
      t = 1.0 - t;
    }
    ends->SetTypedComponent(i, 0, low);
    ends->SetTypedComponent(i, 1, high);
    parameter->SetValue(i, t);
    outPD->InterpolateEdge(inPD, i, low, high, t);
  }
  output->SetPoints(points);
  outPD->AddArray(ends);
  outPD->AddArray(parameter);
  outPD->SetNormals(normals);

  vtkNew<vtkCellArray> polylines;
  for (const std::vector<silsmooth::Id>& chain : lines.Polylines)
  {
    polylines->InsertNextCell(static_cast<vtkIdType>(chain.size()));
    for (const silsmooth::Id id : chain)
    {
      polylines->InsertCellPoint(id);
    }
  }
  output->SetLines(polylines);
  output->GetCellData()->AddArray(vtkSilhouetteFilterSupport::LineKindArray(
    polylines->GetNumberOfCells(), vtkSilhouetteFilterSupport::SilhouetteLine));

  vtkNew<vtkIdTypeArray> triangleCount;
  triangleCount->SetName("SilhouetteTriangleCount");
  triangleCount->SetNumberOfTuples(1);
  triangleCount->SetValue(0, static_cast<vtkIdType>(lines.Triangles.size()));
  output->GetFieldData()->AddArray(triangleCount);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkFaceSilhouetteLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
