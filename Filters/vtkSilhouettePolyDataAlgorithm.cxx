#include "vtkSilhouettePolyDataAlgorithm.h"

#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"

#include "vtkSilhouetteFilterSupport.h"

#include <exception>
#include <new>
#include <string>

vtkSilhouettePolyDataAlgorithm::vtkSilhouettePolyDataAlgorithm() = default;

vtkSilhouettePolyDataAlgorithm::~vtkSilhouettePolyDataAlgorithm() = default;

vtkTypeBool vtkSilhouettePolyDataAlgorithm::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  if (request && request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()) && inputs &&
    this->GetNumberOfInputPorts() > 0)
  {
    if (vtkPolyData* input = vtkPolyData::GetData(inputs[0]))
    {
      const std::string error = vtkSilhouetteFilterSupport::MismatchedArrayError(input);
      if (!error.empty())
      {
        vtkErrorMacro(<< error);
        return 0;
      }
    }
  }
  std::string failure;
  try
  {
    return this->Superclass::ProcessRequest(request, inputs, outputs);
  }
  catch (const std::bad_alloc&)
  {
    failure = "Out of memory: the request needs more memory than the system gives.";
  }
  catch (const std::exception& error)
  {
    failure = std::string("The request failed: ") + error.what();
  }
  catch (...)
  {
    failure = "The request failed with an unknown exception.";
  }
  for (int i = 0; outputs && i < outputs->GetNumberOfInformationObjects(); ++i)
  {
    if (vtkDataObject* output = outputs->GetInformationObject(i)->Get(vtkDataObject::DATA_OBJECT()))
    {
      output->Initialize();
    }
  }
  vtkErrorMacro(<< failure);
  return 0;
}

void vtkSilhouettePolyDataAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
