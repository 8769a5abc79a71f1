#include "vtkTorusSurfaceSource.h"

#include "vtkSilhouetteCheckedSetting.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>

vtkStandardNewMacro(vtkTorusSurfaceSource);

vtkSilhouetteCheckedSetterMacro(vtkTorusSurfaceSource, RingRadius, double, 0.0, VTK_DOUBLE_MAX);
vtkSilhouetteCheckedSetterMacro(vtkTorusSurfaceSource, TubeRadius, double, 0.0, VTK_DOUBLE_MAX);

vtkTorusSurfaceSource::vtkTorusSurfaceSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkTorusSurfaceSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const int nu = this->RingResolution;
  const int nv = this->TubeResolution;
  // A resolution of 100,000 each asked for 30 billion values, and the
  // allocation's failure ended the program (a user's trial).
  if (static_cast<double>(nu) * nv > static_cast<double>(MaximumPoints))
  {
    vtkErrorMacro("RingResolution " << nu << " x TubeResolution " << nv << " is "
                                    << static_cast<double>(nu) * nv << " points; at most "
                                    << MaximumPoints << " (2048 x 2048).");
    return 0;
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nu) * nv);
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(points->GetNumberOfPoints());
  auto index = [nu, nv](int i, int j) {
    return static_cast<vtkIdType>((i % nu) * nv + (j % nv));
  };
  for (int i = 0; i < nu; ++i)
  {
    const double u = 2.0 * vtkMath::Pi() * i / nu;
    for (int j = 0; j < nv; ++j)
    {
      const double v = 2.0 * vtkMath::Pi() * j / nv;
      const double n[3] = { std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v) };
      points->SetPoint(index(i, j), this->RingRadius * std::cos(u) + this->TubeRadius * n[0],
        this->RingRadius * std::sin(u) + this->TubeRadius * n[1], this->TubeRadius * n[2]);
      normals->SetTuple(index(i, j), n);
    }
  }
  // (u, v) increases counter-clockwise seen from outside: d/du x d/dv points
  // along the outward normal.
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const vtkIdType a = index(i, j);
      const vtkIdType b = index(i + 1, j);
      const vtkIdType c = index(i + 1, j + 1);
      const vtkIdType d = index(i, j + 1);
      const vtkIdType first[3] = { a, b, c };
      const vtkIdType second[3] = { a, c, d };
      polys->InsertNextCell(3, first);
      polys->InsertNextCell(3, second);
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->SetNormals(normals);
  return 1;
}

void vtkTorusSurfaceSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RingRadius: " << this->RingRadius << "\n";
  os << indent << "TubeRadius: " << this->TubeRadius << "\n";
  os << indent << "RingResolution: " << this->RingResolution << "\n";
  os << indent << "TubeResolution: " << this->TubeResolution << "\n";
}
