#include "vtkCreaseAndBorderLines.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "IntersectionLines.h"
#include "SurfaceEdgeLines.h"
#include "vtkSilhouetteFilterSupport.h"

#include <unordered_map>

vtkStandardNewMacro(vtkCreaseAndBorderLines);

namespace support = vtkSilhouetteFilterSupport;

vtkCreaseAndBorderLines::vtkCreaseAndBorderLines() = default;
vtkCreaseAndBorderLines::~vtkCreaseAndBorderLines() = default;

vtkSilhouetteCheckedSetterMacro(vtkCreaseAndBorderLines, NormalJumpAngle, double, 0.0, 180.0);
vtkSilhouetteCheckedSetterMacro(vtkCreaseAndBorderLines, FeatureAngle, double, 0.0, 180.0);
vtkSilhouetteCheckedSetterMacro(
  vtkCreaseAndBorderLines, WeldTolerance, double, 0.0, VTK_DOUBLE_MAX);

namespace
{

// The output's points, polylines and LineKind, built a line at a time.
class LineOutput
{
public:
  LineOutput(vtkPolyData* input, vtkPolyData* output, const support::Triangles& triangles)
    : InPD(input->GetPointData())
    , OutPD(output->GetPointData())
    , Surface(triangles)
  {
    this->OutPD->CopyAllocate(this->InPD);
    this->Points->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_FLOAT);
    this->Kinds->SetName("LineKind");
  }

  // A crease or border: points of the surface, each copied once.
  void Add(const silsmooth::SurfaceEdgeLine& line)
  {
    this->Cells->InsertNextCell(static_cast<vtkIdType>(line.Points.size()));
    for (const silsmooth::Id id : line.Points)
    {
      const auto inserted = this->Compact.emplace(id, this->Points->GetNumberOfPoints());
      if (inserted.second)
      {
        const glm::dvec3& p = this->Surface.Points[static_cast<std::size_t>(id)];
        this->Points->InsertNextPoint(p.x, p.y, p.z);
        this->OutPD->CopyData(this->InPD, static_cast<vtkIdType>(id), inserted.first->second);
      }
      this->Cells->InsertCellPoint(inserted.first->second);
    }
    const bool crease = line.Kind == silsmooth::LineKind::Crease;
    ++(crease ? this->CreaseLines : this->BorderLines);
    this->Kinds->InsertNextValue(crease ? support::CreaseLine : support::BorderLine);
  }

  // An intersection curve: new points, each with the point data of the
  // triangle it lies on, interpolated there.
  void Add(const silsmooth::IntersectionLine& line)
  {
    this->Cells->InsertNextCell(static_cast<vtkIdType>(line.Points.size()));
    for (std::size_t i = 0; i < line.Points.size(); ++i)
    {
      const glm::dvec3& p = line.Points[i];
      const vtkIdType id = this->Points->InsertNextPoint(p.x, p.y, p.z);
      const silsmooth::Triangle& t =
        this->Surface.Cells[static_cast<std::size_t>(line.Triangles[i])];
      double weights[3];
      this->BarycentricWeights(t, p, weights);
      vtkNew<vtkIdList> corners;
      for (const silsmooth::Id corner : t)
      {
        corners->InsertNextId(static_cast<vtkIdType>(corner));
      }
      this->OutPD->InterpolatePoint(this->InPD, id, corners, weights);
      this->Cells->InsertCellPoint(id);
    }
    ++this->IntersectionLines;
    this->Kinds->InsertNextValue(support::IntersectionLine);
  }

  void Finish(vtkPolyData* output) const
  {
    output->SetPoints(this->Points);
    output->SetLines(this->Cells);
    output->GetCellData()->AddArray(this->Kinds);
    for (const auto& [name, count] : { std::make_pair("CreaseLineCount", this->CreaseLines),
           std::make_pair("BorderLineCount", this->BorderLines),
           std::make_pair("IntersectionLineCount", this->IntersectionLines) })
    {
      vtkNew<vtkIdTypeArray> array;
      array->SetName(name);
      array->InsertNextValue(count);
      output->GetFieldData()->AddArray(array);
    }
  }

private:
  // p's weights on t's corners (p lies on t, up to rounding), by the areas
  // of the triangles p makes with each side.
  void BarycentricWeights(const silsmooth::Triangle& t, const glm::dvec3& p, double* weights) const
  {
    const glm::dvec3& a = this->Surface.Points[static_cast<std::size_t>(t[0])];
    const glm::dvec3& b = this->Surface.Points[static_cast<std::size_t>(t[1])];
    const glm::dvec3& c = this->Surface.Points[static_cast<std::size_t>(t[2])];
    const double areas[3] = { glm::length(glm::cross(b - p, c - p)),
      glm::length(glm::cross(c - p, a - p)), glm::length(glm::cross(a - p, b - p)) };
    const double sum = areas[0] + areas[1] + areas[2];
    for (int k = 0; k < 3; ++k)
    {
      weights[k] = sum > 0.0 ? areas[k] / sum : 1.0 / 3.0;
    }
  }

  vtkPointData* InPD;
  vtkPointData* OutPD;
  const support::Triangles& Surface;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Cells;
  vtkNew<vtkUnsignedCharArray> Kinds;
  std::unordered_map<silsmooth::Id, vtkIdType> Compact;
  vtkIdType CreaseLines = 0;
  vtkIdType BorderLines = 0;
  vtkIdType IntersectionLines = 0;
};

} // namespace

int vtkCreaseAndBorderLines::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  std::optional<vtkSilhouetteFilterSupport::Surface> surface =
    vtkSilhouetteFilterSupport::ReadSurface(this, inputVector, outputVector);
  if (!surface)
  {
    return 0;
  }
  auto& [input, output, triangles] = *surface;
  if (!support::ReportProgress(this, 0.2))
  {
    return 1; // aborted: the output stays empty
  }

  silsmooth::SurfaceEdgeLineParameters parameters;
  parameters.Creases = this->Creases != 0;
  parameters.Borders = this->Borders != 0;
  parameters.NormalJumpDegrees = this->NormalJumpAngle;
  parameters.CreaseAngleDegrees = this->FeatureAngle;
  parameters.WeldTolerance = this->WeldTolerance;
  const std::vector<silsmooth::SurfaceEdgeLine> lines =
    silsmooth::surfaceEdgeLines(triangles.Points, triangles.Cells, triangles.Normals, parameters);
  if (!support::ReportProgress(this, 0.5))
  {
    return 1;
  }
  const std::vector<silsmooth::IntersectionLine> intersections = this->Intersections
    ? silsmooth::intersectionLines(triangles.Points, triangles.Cells, this->WeldTolerance)
    : std::vector<silsmooth::IntersectionLine>();
  if (!support::ReportProgress(this, 0.8))
  {
    return 1;
  }

  LineOutput out(input, output, triangles);
  for (const silsmooth::SurfaceEdgeLine& line : lines)
  {
    out.Add(line);
  }
  for (const silsmooth::IntersectionLine& line : intersections)
  {
    out.Add(line);
  }
  out.Finish(output);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkCreaseAndBorderLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Creases: " << (this->Creases ? "On" : "Off") << "\n";
  os << indent << "Borders: " << (this->Borders ? "On" : "Off") << "\n";
  os << indent << "Intersections: " << (this->Intersections ? "On" : "Off") << "\n";
  os << indent << "NormalJumpAngle: " << this->NormalJumpAngle << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "WeldTolerance: " << this->WeldTolerance << "\n";
}
