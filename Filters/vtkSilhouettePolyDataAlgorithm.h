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
 * Also, a data request sees each polygonal input without its arrays of the
 * wrong number of tuples (vtkSilhouetteFilterSupport::FittingArrays: they
 * would be read past their end), with a warning that names them once per
 * input change, so that a filter uses what VTK's own mappers draw (VTK
 * 9.1's OBJ readers give a file of faces and lines group ids for its faces
 * only) and never reads past an array's end.
 *
 * @sa vtkSilhouetteViewAlgorithm
 */
#ifndef vtkSilhouettePolyDataAlgorithm_h
#define vtkSilhouettePolyDataAlgorithm_h

#include "SilhouetteSmoothingFiltersSilhouetteModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // For std::unique_ptr

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
  struct FittingInputs;
  std::unique_ptr<FittingInputs> Fitting;

  vtkSilhouettePolyDataAlgorithm(const vtkSilhouettePolyDataAlgorithm&) = delete;
  void operator=(const vtkSilhouettePolyDataAlgorithm&) = delete;
};

#endif
