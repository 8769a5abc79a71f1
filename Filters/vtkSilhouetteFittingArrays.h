// An input without its arrays of the wrong length (part of
// vtkSilhouetteFilterSupport, in a header of its own with VTK types only, so
// that the render-time mapper's module can use it too). Private to the
// modules' build (not wrapped, not installed).
#ifndef vtkSilhouetteFittingArrays_h
#define vtkSilhouetteFittingArrays_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>

namespace vtkSilhouetteFilterSupport
{

/// The point data arrays without one tuple per point and the cell data
/// arrays without one per cell (a reader's or a user's mistake: VTK 9.1's
/// OBJ readers give a file of faces and lines group ids for its faces only),
/// described for a message ("the cell data array 'GroupIds' (1000 tuples for
/// 1001 cells)", joined by commas), else "". Read as they are, such arrays
/// would be read past their end.
std::string MismatchedArrays(vtkPolyData* input);

/// An input with its mismatched arrays (above) left out, so that a filter
/// smooths what VTK's own mappers draw instead of refusing it. Of() returns
/// the input itself when every array fits; otherwise a shallow copy without
/// the misfits, the same object for as long as the input is the same and
/// unmodified, so that what a filter caches per input object holds across
/// views.
class FittingArrays
{
public:
  /// `leftOut` is a warning that names what was left out when the copy is
  /// made anew (to give once per input change), else "".
  vtkPolyData* Of(vtkPolyData* input, std::string& leftOut);

private:
  vtkSmartPointer<vtkPolyData> Copy;
  vtkPolyData* From = nullptr;
  vtkMTimeType FromTime = 0;
};

} // namespace vtkSilhouetteFilterSupport

#endif
