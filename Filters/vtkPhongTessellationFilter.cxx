#include "vtkPhongTessellationFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include "PhongTessellation.h"

vtkStandardNewMacro(vtkPhongTessellationFilter);

vtkSilhouetteCheckedSetterMacro(vtkPhongTessellationFilter, ShapeFactor, double, 0.0, 1.0);

vtkTypeBool vtkPhongTessellationFilter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  return vtkSilhouetteFilterSupport::GuardRequest(this, request, inputs, outputs,
    [&] { return static_cast<int>(this->Superclass::ProcessRequest(request, inputs, outputs)); });
}

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
  const std::string error = support::ReadFiniteTriangles(input, triangles);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  const silsmooth::PhongTessellationResult result = silsmooth::tessellatePhong(
    triangles.Points, triangles.Cells, triangles.Normals, this->Level, this->ShapeFactor);

  support::WriteTessellation(input, output, triangles, result, this->Level);
  return 1;
}

void vtkPhongTessellationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "ShapeFactor: " << this->ShapeFactor << "\n";
}
