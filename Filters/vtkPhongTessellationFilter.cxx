#include "vtkPhongTessellationFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include "PhongTessellation.h"

vtkStandardNewMacro(vtkPhongTessellationFilter);

namespace support = vtkSilhouetteFilterSupport;

int vtkPhongTessellationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output polydata.");
    return 0;
  }
  support::Triangles triangles;
  const std::string error = support::ReadTriangles(input, triangles);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (triangles.NonFinitePoints > 0)
  {
    vtkErrorMacro(
      "Input has " << triangles.NonFinitePoints << " points with NaN or infinite coordinates.");
    return 0;
  }
  const silsmooth::PhongTessellationResult result = silsmooth::tessellatePhong(
    triangles.Points, triangles.Cells, triangles.Normals, this->Level, this->ShapeFactor);

  const std::size_t inputPoints = triangles.Points.size();
  const std::vector<glm::dvec3> inputNormals(
    result.Normals.begin(), result.Normals.begin() + static_cast<std::ptrdiff_t>(inputPoints));
  const std::vector<glm::dvec3> addedPoints(
    result.Points.begin() + static_cast<std::ptrdiff_t>(inputPoints), result.Points.end());
  const std::vector<glm::dvec3> addedNormals(
    result.Normals.begin() + static_cast<std::ptrdiff_t>(inputPoints), result.Normals.end());
  std::vector<support::PointSource> sources(addedPoints.size());
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
    originalCell[t] = triangles.CellIds[static_cast<std::size_t>(result.TriangleSource[t])];
  }
  const std::vector<unsigned char> newGeometry(
    result.Triangles.size(), static_cast<unsigned char>(this->Level > 0 ? 1 : 0));
  support::WriteMesh(input, output, inputNormals, addedPoints, addedNormals, sources,
    result.Triangles, originalCell, newGeometry);
  return 1;
}

void vtkPhongTessellationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "ShapeFactor: " << this->ShapeFactor << "\n";
}
