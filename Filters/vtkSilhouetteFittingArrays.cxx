#include "vtkSilhouetteFittingArrays.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"

#include <utility>
#include <vector>

namespace vtkSilhouetteFilterSupport
{

namespace
{
// Calls `misfit(data, index, description)` for each mismatched array, point
// data first, in the arrays' order.
template<typename Misfit>
void ForEachMismatchedArray(vtkPolyData* input, Misfit misfit)
{
  for (const bool pointData : { true, false })
  {
    vtkFieldData* data = pointData ? static_cast<vtkFieldData*>(input->GetPointData())
                                   : static_cast<vtkFieldData*>(input->GetCellData());
    const vtkIdType items = pointData ? input->GetNumberOfPoints() : input->GetNumberOfCells();
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = data->GetAbstractArray(a);
      if (array && array->GetNumberOfTuples() != items)
      {
        misfit(data, a,
          std::string("the ") + (pointData ? "point" : "cell") + " data array '" +
            (array->GetName() ? array->GetName() : "(unnamed)") + "' (" +
            std::to_string(array->GetNumberOfTuples()) + " tuples for " + std::to_string(items) +
            (pointData ? " points)" : " cells)"));
      }
    }
  }
}
} // namespace

std::string MismatchedArrays(vtkPolyData* input)
{
  std::string found;
  ForEachMismatchedArray(input, [&](vtkFieldData*, int, const std::string& description) {
    found += (found.empty() ? "" : ", ") + description;
  });
  return found;
}

vtkPolyData* FittingArrays::Of(vtkPolyData* input, std::string& leftOut)
{
  leftOut.clear();
  if (this->Copy && input == this->From && input->GetMTime() == this->FromTime)
  {
    return this->Copy;
  }
  this->Copy = nullptr;
  this->From = nullptr;
  const std::string misfits = MismatchedArrays(input);
  if (misfits.empty())
  {
    return input;
  }
  leftOut =
    "Arrays of the wrong length left out of the input (they would be read past their end): " +
    misfits + ".";
  this->Copy = vtkSmartPointer<vtkPolyData>::New();
  this->Copy->ShallowCopy(input); // its own attribute lists, the input's arrays
  std::vector<std::pair<vtkFieldData*, int>> arrays;
  ForEachMismatchedArray(this->Copy,
    [&](vtkFieldData* data, int index, const std::string&) { arrays.emplace_back(data, index); });
  // Last first, so that the indices of the others stay valid.
  for (auto it = arrays.rbegin(); it != arrays.rend(); ++it)
  {
    it->first->RemoveArray(it->second);
  }
  this->From = input;
  this->FromTime = input->GetMTime();
  return this->Copy;
}

} // namespace vtkSilhouetteFilterSupport
