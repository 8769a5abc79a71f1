#include "vtkProgressiveMeshFilter.h"

#include "vtkSilhouetteFilterSupport.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "ProgressiveMesh.h"
#include "SurfaceWelding.h"

#include <algorithm>
#include <cmath>
#include <optional>

vtkStandardNewMacro(vtkProgressiveMeshFilter);

vtkSilhouetteCheckedSetterMacro(vtkProgressiveMeshFilter, Fraction, double, 0.0, 1.0);

struct vtkProgressiveMeshFilter::Internal
{
  std::optional<silsmooth::ProgressiveMesh> Mesh;
  vtkPolyData* Input = nullptr;
  vtkMTimeType InputTime = 0;
  bool Weld = true;
  // Per triangle read, its input cell.
  std::vector<vtkIdType> CellIds;
  // When welded: per input triangle its own input points, per input point
  // its vertex (the lowest id at its position).
  std::vector<silsmooth::Triangle> InputCorners;
  std::vector<silsmooth::Id> Vertex;
};

vtkProgressiveMeshFilter::vtkProgressiveMeshFilter()
  : Cache(new Internal)
{
}

vtkProgressiveMeshFilter::~vtkProgressiveMeshFilter() = default;

namespace
{

void AddCount(vtkPolyData* output, const char* name, std::size_t value)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->InsertNextValue(static_cast<vtkIdType>(value));
  output->GetFieldData()->AddArray(array);
}

// The level's corners given back as input points: a corner is its
// triangle's own input point where that point is a copy of the corner's
// vertex (always so at the full level), else another copy of the vertex
// the triangle has, else the vertex itself. `points` and `pointIds` become
// the input points used, in input order, each at its vertex's position.
void WithInputCopies(std::vector<glm::dvec3>& points, std::vector<silsmooth::Triangle>& triangles,
  std::vector<silsmooth::Id>& pointIds, const std::vector<silsmooth::Id>& triangleIds,
  const std::vector<silsmooth::Triangle>& inputCorners, const std::vector<silsmooth::Id>& vertex)
{
  std::vector<silsmooth::Id> copies; // per corner, 3 per triangle
  copies.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const silsmooth::Triangle& own = inputCorners[static_cast<std::size_t>(triangleIds[t])];
    for (std::size_t k = 0; k < 3; ++k)
    {
      const silsmooth::Id v = pointIds[static_cast<std::size_t>(triangles[t][k])];
      silsmooth::Id copy = v;
      for (std::size_t j = 0; j < 3; ++j)
      {
        // Its own corner k first: a triangle welded to a repeated corner
        // keeps each of its points in place.
        const silsmooth::Id c = own[(k + j) % 3];
        if (vertex[static_cast<std::size_t>(c)] == v)
        {
          copy = c;
          break;
        }
      }
      copies.push_back(copy);
    }
  }
  std::vector<silsmooth::Id> used = copies;
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  // Where each vertex is at this level.
  std::vector<std::pair<silsmooth::Id, glm::dvec3>> at(pointIds.size());
  for (std::size_t i = 0; i < pointIds.size(); ++i)
  {
    at[i] = { pointIds[i], points[i] };
  }
  std::sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  auto positionOf = [&](silsmooth::Id v) {
    return std::lower_bound(at.begin(), at.end(), v, [](const auto& entry, silsmooth::Id id) {
      return entry.first < id;
    })->second;
  };
  points.resize(used.size());
  for (std::size_t i = 0; i < used.size(); ++i)
  {
    points[i] = positionOf(vertex[static_cast<std::size_t>(used[i])]);
  }
  for (std::size_t c = 0; c < copies.size(); ++c)
  {
    triangles[c / 3][c % 3] = static_cast<silsmooth::Id>(
      std::lower_bound(used.begin(), used.end(), copies[c]) - used.begin());
  }
  pointIds = std::move(used);
}

} // namespace

int vtkProgressiveMeshFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    return 0;
  }
  Internal& cache = *this->Cache;
  if (!cache.Mesh || cache.Input != input || cache.InputTime != input->GetMTime() ||
    cache.Weld != this->WeldCoincidentPoints)
  {
    cache.Mesh.reset();
    cache.CellIds.clear();
    cache.InputCorners.clear();
    cache.Vertex.clear();
    // Polygons and strips as triangles, as the module's other filters read
    // them (a concave polygon by ear clipping).
    vtkSilhouetteFilterSupport::Triangles read;
    const std::string error = vtkSilhouetteFilterSupport::ReadFiniteTriangles(input, read);
    if (!error.empty())
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    std::vector<glm::dvec3> points = std::move(read.Points);
    std::vector<silsmooth::Triangle> triangles = std::move(read.Cells);
    cache.CellIds = std::move(read.CellIds);
    if (this->WeldCoincidentPoints)
    {
      cache.Vertex = silsmooth::weldCoincidentPoints(points);
      cache.InputCorners = triangles;
      triangles = silsmooth::weldTriangles(cache.InputCorners, cache.Vertex);
    }
    this->UpdateProgress(0.1);
    cache.Mesh.emplace(std::move(points), std::move(triangles), 0, [this](double done) {
      return vtkSilhouetteFilterSupport::ReportProgress(this, 0.1 + 0.8 * done);
    });
    if (cache.Mesh->aborted())
    {
      cache.Mesh.reset();
      return 1; // the output stays empty
    }
    cache.Input = input;
    cache.InputTime = input->GetMTime();
    cache.Weld = this->WeldCoincidentPoints;
    this->UpdateProgress(0.9);
  }
  silsmooth::ProgressiveMesh& mesh = *cache.Mesh;
  const std::size_t full = mesh.fullTriangleCount();
  const std::size_t wanted = this->TriangleCount >= 0
    ? static_cast<std::size_t>(this->TriangleCount)
    : static_cast<std::size_t>(std::ceil(this->Fraction * static_cast<double>(full)));
  mesh.setTriangleCount(wanted);

  std::vector<glm::dvec3> points;
  std::vector<silsmooth::Triangle> triangles;
  std::vector<silsmooth::Id> pointIds;
  std::vector<silsmooth::Id> triangleIds;
  mesh.compact(points, triangles, pointIds, triangleIds);
  if (!cache.Vertex.empty())
  {
    WithInputCopies(points, triangles, pointIds, triangleIds, cache.InputCorners, cache.Vertex);
  }

  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataTypeToDouble();
  outPoints->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  vtkPointData* inPd = input->GetPointData();
  vtkPointData* outPd = output->GetPointData();
  outPd->CopyAllocate(inPd, static_cast<vtkIdType>(points.size()));
  vtkNew<vtkIdTypeArray> originalPoint;
  originalPoint->SetName("OriginalPointId");
  originalPoint->SetNumberOfValues(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const auto id = static_cast<vtkIdType>(i);
    outPoints->SetPoint(id, points[i].x, points[i].y, points[i].z);
    outPd->CopyData(inPd, static_cast<vtkIdType>(pointIds[i]), id);
    originalPoint->SetValue(id, static_cast<vtkIdType>(pointIds[i]));
  }
  outPd->AddArray(originalPoint);

  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(
    static_cast<vtkIdType>(triangles.size()), 3 * static_cast<vtkIdType>(triangles.size()));
  vtkCellData* inCd = input->GetCellData();
  vtkCellData* outCd = output->GetCellData();
  outCd->CopyAllocate(inCd, static_cast<vtkIdType>(triangles.size()));
  vtkNew<vtkIdTypeArray> originalCell;
  originalCell->SetName("OriginalCellId");
  originalCell->SetNumberOfValues(static_cast<vtkIdType>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const vtkIdType ids[3] = { static_cast<vtkIdType>(triangles[t][0]),
      static_cast<vtkIdType>(triangles[t][1]), static_cast<vtkIdType>(triangles[t][2]) };
    polys->InsertNextCell(3, ids);
    const vtkIdType inputCell = cache.CellIds[static_cast<std::size_t>(triangleIds[t])];
    outCd->CopyData(inCd, inputCell, static_cast<vtkIdType>(t));
    originalCell->SetValue(static_cast<vtkIdType>(t), inputCell);
  }
  outCd->AddArray(originalCell);
  output->SetPoints(outPoints);
  output->SetPolys(polys);
  AddCount(output, "BaseTriangleCount", mesh.baseTriangleCount());
  AddCount(output, "FullTriangleCount", full);
  AddCount(output, "SplitCount", mesh.splitCount());
  AddCount(output, "Level", mesh.level());
  return 1;
}

void vtkProgressiveMeshFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TriangleCount: " << this->TriangleCount << "\n";
  os << indent << "Fraction: " << this->Fraction << "\n";
  os << indent << "WeldCoincidentPoints: " << (this->WeldCoincidentPoints ? "On" : "Off") << "\n";
}
