#include "vtkSilhouettePolyDataAlgorithm.h"

#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "vtkSilhouetteFilterSupport.h"

#include <exception>
#include <map>
#include <new>
#include <string>
#include <utility>
#include <vector>

struct vtkSilhouettePolyDataAlgorithm::FittingInputs
{
  // Per (port, connection).
  std::map<std::pair<int, int>, vtkSilhouetteFilterSupport::FittingArrays> Inputs;
};

vtkSilhouettePolyDataAlgorithm::vtkSilhouettePolyDataAlgorithm()
  : Fitting(new FittingInputs)
{
}

vtkSilhouettePolyDataAlgorithm::~vtkSilhouettePolyDataAlgorithm() = default;

vtkTypeBool vtkSilhouettePolyDataAlgorithm::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  const int ports = this->GetNumberOfInputPorts();
  std::vector<vtkInformationVector*> seen(inputs, inputs + (inputs ? ports : 0));
  // Where an input had to be replaced, the data request sees copies of the
  // executive's information vectors that hold the replacement.
  std::vector<vtkSmartPointer<vtkInformationVector>> replaced;
  if (request && request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()) && inputs)
  {
    for (int port = 0; port < ports; ++port)
    {
      for (int c = 0; inputs[port] && c < inputs[port]->GetNumberOfInformationObjects(); ++c)
      {
        vtkPolyData* input = vtkPolyData::GetData(inputs[port], c);
        if (!input)
        {
          continue;
        }
        std::string leftOut;
        vtkPolyData* usable = this->Fitting->Inputs[{ port, c }].Of(input, leftOut);
        if (!leftOut.empty())
        {
          vtkWarningMacro(<< leftOut);
        }
        if (usable == input)
        {
          continue;
        }
        if (seen[port] == inputs[port])
        {
          auto copy = vtkSmartPointer<vtkInformationVector>::New();
          copy->Copy(inputs[port], 1); // new information objects, not the executive's
          replaced.push_back(copy);
          seen[port] = copy;
        }
        seen[port]->GetInformationObject(c)->Set(vtkDataObject::DATA_OBJECT(), usable);
      }
    }
    inputs = seen.data();
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
