#include "vtkPNTriangleFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include "PNTriangles.h"

vtkStandardNewMacro(vtkPNTriangleFilter);

vtkSilhouetteGuardedProcessRequestMacro(vtkPNTriangleFilter);

namespace support = vtkSilhouetteFilterSupport;

int vtkPNTriangleFilter::RequestData(
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
  const silsmooth::PNTriangleResult result = silsmooth::tessellatePNTriangles(
    triangles.Points, triangles.Cells, triangles.Normals, this->Level);

  support::WriteTessellation(input, output, triangles, result, this->Level);
  return 1;
}

void vtkPNTriangleFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
}
