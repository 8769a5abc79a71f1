#include "vtkIcosphereSource.h"

#include "vtkSilhouetteCheckedSetting.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkIcosphereSource);

vtkSilhouetteCheckedSetterMacro(vtkIcosphereSource, Radius, double, 0.0, VTK_DOUBLE_MAX);

vtkIcosphereSource::vtkIcosphereSource()
{
  this->SetNumberOfInputPorts(0);
}

namespace
{

using Direction = std::array<double, 3>;
using Face = std::array<vtkIdType, 3>;

Direction Normalized(const Direction& d)
{
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return { d[0] / length, d[1] / length, d[2] / length };
}

} // namespace

int vtkIcosphereSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);

  // The icosahedron: vertices on the three golden rectangles, faces outward.
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Direction> directions = { { -1, phi, 0 }, { 1, phi, 0 }, { -1, -phi, 0 },
    { 1, -phi, 0 }, { 0, -1, phi }, { 0, 1, phi }, { 0, -1, -phi }, { 0, 1, -phi }, { phi, 0, -1 },
    { phi, 0, 1 }, { -phi, 0, -1 }, { -phi, 0, 1 } };
  for (Direction& d : directions)
  {
    d = Normalized(d);
  }
  std::vector<Face> faces = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };

  for (int level = 0; level < this->SubdivisionLevel; ++level)
  {
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> midpoints;
    auto midpoint = [&](vtkIdType a, vtkIdType b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      const Direction& da = directions[static_cast<std::size_t>(a)];
      const Direction& db = directions[static_cast<std::size_t>(b)];
      directions.push_back(Normalized({ da[0] + db[0], da[1] + db[1], da[2] + db[2] }));
      const vtkIdType id = static_cast<vtkIdType>(directions.size() - 1);
      midpoints.emplace(key, id);
      return id;
    };
    std::vector<Face> finer;
    finer.reserve(faces.size() * 4);
    for (const Face& f : faces)
    {
      const vtkIdType ab = midpoint(f[0], f[1]);
      const vtkIdType bc = midpoint(f[1], f[2]);
      const vtkIdType ca = midpoint(f[2], f[0]);
      finer.push_back({ f[0], ab, ca });
      finer.push_back({ f[1], bc, ab });
      finer.push_back({ f[2], ca, bc });
      finer.push_back({ ab, bc, ca });
    }
    faces = std::move(finer);
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(directions.size()));
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(points->GetNumberOfPoints());
  for (std::size_t i = 0; i < directions.size(); ++i)
  {
    const Direction& d = directions[i];
    points->SetPoint(static_cast<vtkIdType>(i), this->Center[0] + this->Radius * d[0],
      this->Center[1] + this->Radius * d[1], this->Center[2] + this->Radius * d[2]);
    normals->SetTuple(static_cast<vtkIdType>(i), d.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const Face& f : faces)
  {
    polys->InsertNextCell(3, f.data());
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->SetNormals(normals);
  return 1;
}

void vtkIcosphereSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SubdivisionLevel: " << this->SubdivisionLevel << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Center: (" << this->Center[0] << ", " << this->Center[1] << ", "
     << this->Center[2] << ")\n";
}
