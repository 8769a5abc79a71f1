#include "vtkSilhouetteQuadricDecimation.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "QuadricSimplifier.h"
#include "SurfaceWelding.h"
#include "vtkSilhouetteFilterSupport.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkSilhouetteQuadricDecimation);

vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteQuadricDecimation, NearMinimum, double, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteQuadricDecimation, NearMaximum, double, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(
  vtkSilhouetteQuadricDecimation, NearFactor, double, 0.0, VTK_DOUBLE_MAX);

void vtkSilhouetteQuadricDecimation::SetDistanceArrayName(const std::string& name)
{
  if (this->DistanceArrayName != name)
  {
    this->DistanceArrayName = name;
    this->Modified();
  }
}

int vtkSilhouetteQuadricDecimation::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  std::optional<vtkSilhouetteFilterSupport::Surface> surface =
    vtkSilhouetteFilterSupport::ReadSurface(this, inputVector, outputVector);
  if (!surface)
  {
    return 0;
  }
  auto& [input, output, mesh] = *surface;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<glm::dvec3>& points = mesh.Points;
  std::vector<silsmooth::Triangle>& triangles = mesh.Cells;
  std::vector<vtkIdType>& triangleCell = mesh.CellIds;

  silsmooth::SimplificationParameters parameters;
  parameters.TargetTriangles = static_cast<std::size_t>(this->TargetTriangles);
  parameters.NearFactor = this->NearFactor;
  vtkDataArray* labels = this->DistanceArrayName.empty()
    ? nullptr
    : input->GetPointData()->GetArray(this->DistanceArrayName.c_str());
  if (labels && labels->GetNumberOfComponents() == 1 && labels->GetNumberOfTuples() == numPoints)
  {
    parameters.Near.resize(static_cast<std::size_t>(numPoints));
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      const double d = labels->GetTuple1(i);
      parameters.Near[static_cast<std::size_t>(i)] =
        d >= 0.0 && d >= this->NearMinimum && d <= this->NearMaximum ? 1 : 0;
    }
  }
  parameters.Progress = [this](double done) {
    return vtkSilhouetteFilterSupport::ReportProgress(this, 0.1 + 0.8 * done);
  };
  const silsmooth::SimplificationResult result =
    silsmooth::simplifyQuadric(points, triangles, parameters);
  if (result.Aborted)
  {
    return 1; // the output stays empty
  }
  if (!result.ReachedTarget)
  {
    // Points repeating another's coordinates (texture seams, a triangle
    // soup) make borders, whose points stay: a user's trial of an asset OBJ
    // stopped at its input's count and was not told why.
    const std::vector<silsmooth::Id> vertex = silsmooth::weldCoincidentPoints(points);
    std::size_t repeated = 0;
    for (std::size_t i = 0; i < vertex.size(); ++i)
    {
      repeated += vertex[i] != static_cast<silsmooth::Id>(i) ? 1 : 0;
    }
    std::ostringstream why;
    if (repeated > 0)
    {
      why << " " << repeated
          << " of the input's points repeat another's coordinates (texture seams, or a triangle "
             "soup), so its triangles do not share them and their edges are borders, whose "
             "points stay: merge them first (vtkCleanPolyData, tolerance 0).";
    }
    vtkWarningMacro("Stopped at " << result.Triangles.size() << " triangles, above the target "
                                  << this->TargetTriangles
                                  << ": no more collapse keeps the topology and the error rule."
                                  << why.str());
  }

  const vtkIdType outPoints = static_cast<vtkIdType>(result.Points.size());
  vtkNew<vtkPoints> newPoints;
  newPoints->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_FLOAT);
  newPoints->SetNumberOfPoints(outPoints);
  vtkNew<vtkDoubleArray> error;
  error->SetName("QuadricError");
  error->SetNumberOfTuples(outPoints);
  vtkNew<vtkUnsignedCharArray> near;
  near->SetName("NearContour");
  near->SetNumberOfTuples(outPoints);
  vtkNew<vtkIdTypeArray> original;
  original->SetName("OriginalPointId");
  original->SetNumberOfTuples(outPoints);
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(input->GetPointData(), outPoints);
  for (vtkIdType i = 0; i < outPoints; ++i)
  {
    const std::size_t k = static_cast<std::size_t>(i);
    newPoints->SetPoint(i, result.Points[k].x, result.Points[k].y, result.Points[k].z);
    error->SetValue(i, result.PointError[k]);
    near->SetValue(i, result.PointNear[k]);
    original->SetValue(i, result.SourcePoint[k]);
    outPD->CopyData(input->GetPointData(), result.SourcePoint[k], i);
  }
  output->SetPoints(newPoints);
  outPD->AddArray(error);
  outPD->AddArray(near);
  outPD->AddArray(original);
  vtkNew<vtkCellArray> polys;
  for (const silsmooth::Triangle& t : result.Triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  output->SetPolys(polys);

  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkDoubleArray> threshold;
  threshold->SetName("ErrorThreshold");
  threshold->InsertNextValue(result.Threshold);
  fd->AddArray(threshold);
  vtkNew<vtkIntArray> reached;
  reached->SetName("ReachedTarget");
  reached->InsertNextValue(result.ReachedTarget ? 1 : 0);
  fd->AddArray(reached);
  for (const auto& [name, value] :
    { std::make_pair("InputTriangleCount", static_cast<vtkIdType>(triangles.size())),
      std::make_pair("OutputTriangleCount", static_cast<vtkIdType>(result.Triangles.size())) })
  {
    vtkNew<vtkIdTypeArray> count;
    count->SetName(name);
    count->InsertNextValue(value);
    fd->AddArray(count);
  }
  return 1;
}

void vtkSilhouetteQuadricDecimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetTriangles: " << this->TargetTriangles << "\n";
  os << indent << "NearMinimum: " << this->NearMinimum << "\n";
  os << indent << "NearMaximum: " << this->NearMaximum << "\n";
  os << indent << "NearFactor: " << this->NearFactor << "\n";
  os << indent << "DistanceArrayName: " << this->DistanceArrayName << "\n";
}
