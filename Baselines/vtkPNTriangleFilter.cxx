#include "vtkPNTriangleFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include "PNTriangles.h"

vtkStandardNewMacro(vtkPNTriangleFilter);

namespace support = vtkSilhouetteFilterSupport;

int vtkPNTriangleFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return support::RequestTessellation(this, inputVector, outputVector, this->Level,
    [this](const support::Triangles& mesh, const silsmooth::ProgressCallback& progress) {
      return silsmooth::tessellatePNTriangles(
        mesh.Points, mesh.Cells, mesh.Normals, this->Level, progress);
    });
}

void vtkPNTriangleFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
}
