#include "vtkPhongTessellationFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include "PhongTessellation.h"

vtkStandardNewMacro(vtkPhongTessellationFilter);

vtkSilhouetteCheckedSetterMacro(vtkPhongTessellationFilter, ShapeFactor, double, 0.0, 1.0);

vtkSilhouetteGuardedProcessRequestMacro(vtkPhongTessellationFilter);

namespace support = vtkSilhouetteFilterSupport;

int vtkPhongTessellationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  vtkSilhouetteFilterSupport::Triangles triangles;
  if (!vtkSilhouetteFilterSupport::ReadSurface(
        this, inputVector, outputVector, input, output, triangles))
  {
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
