/**
 * @class   vtkSilhouettePolyDataAlgorithm
 * @brief   superclass of the project's polydata filters: no exception leaves a request
 *
 * ProcessRequest is vtkPolyDataAlgorithm's, except that no exception leaves
 * it: std::bad_alloc (a mesh too large for the memory left) or any other
 * exception becomes an error on the filter, emptied outputs and a failed
 * request, as any other failure of the filter would. VTK's executives do not
 * catch exceptions, so without this an allocation failure deep in a filter
 * would end the program that runs the pipeline.
 *
 * Also, before a data request runs, a polygonal input whose arrays have the
 * wrong number of tuples is refused with an error
 * (vtkSilhouetteFilterSupport::MismatchedArrayError).
 *
 * @sa vtkSilhouetteViewAlgorithm
 */
#ifndef vtkSilhouettePolyDataAlgorithm_h
#define vtkSilhouettePolyDataAlgorithm_h

#include "SilhouetteSmoothingFiltersSilhouetteModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class SILHOUETTESMOOTHINGFILTERSSILHOUETTE_EXPORT vtkSilhouettePolyDataAlgorithm
  : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkSilhouettePolyDataAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The superclass's, except that no exception leaves it (see above).
   */
  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

protected:
  vtkSilhouettePolyDataAlgorithm();
  ~vtkSilhouettePolyDataAlgorithm() override;

private:
  vtkSilhouettePolyDataAlgorithm(const vtkSilhouettePolyDataAlgorithm&) = delete;
  void operator=(const vtkSilhouettePolyDataAlgorithm&) = delete;
};

#endif
