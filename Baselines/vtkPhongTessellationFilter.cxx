#include "vtkPhongTessellationFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include "PhongTessellation.h"

vtkStandardNewMacro(vtkPhongTessellationFilter);

vtkSilhouetteCheckedSetterMacro(vtkPhongTessellationFilter, ShapeFactor, double, 0.0, 1.0);

namespace support = vtkSilhouetteFilterSupport;

int vtkPhongTessellationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return support::RequestTessellation(this, inputVector, outputVector, this->Level,
    [this](const support::Triangles& mesh, const silsmooth::ProgressCallback& progress) {
      return silsmooth::tessellatePhong(
        mesh.Points, mesh.Cells, mesh.Normals, this->Level, this->ShapeFactor, progress);
    });
}

void vtkPhongTessellationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "ShapeFactor: " << this->ShapeFactor << "\n";
}
