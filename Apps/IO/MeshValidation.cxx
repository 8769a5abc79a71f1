#include "MeshValidation.h"

#include "CliErrors.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace cli
{
namespace
{

struct CellKind
{
  vtkCellArray* (vtkPolyData::*Cells)();
  const char* Name;      // "polygon", for messages
  vtkIdType LeastPoints; // fewer is not a cell of its kind
};

const std::array<CellKind, 4> Kinds = { {
  { &vtkPolyData::GetVerts, "vertex cell", 1 },
  { &vtkPolyData::GetLines, "line", 2 },
  { &vtkPolyData::GetPolys, "polygon", 3 },
  { &vtkPolyData::GetStrips, "triangle strip", 3 },
} };

std::string Fail(const std::string& quotedFile, const std::string& why)
{
  return "cannot read " + quotedFile + ": " + why;
}

void RequireFinitePoints(vtkPolyData* mesh, const std::string& quotedFile)
{
  vtkPoints* points = mesh->GetPoints();
  if (!points)
  {
    return;
  }
  vtkIdType bad = 0;
  vtkIdType first = -1;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      first = bad++ == 0 ? i : first;
    }
  }
  if (bad > 0)
  {
    throw RuntimeError(Fail(quotedFile,
      std::to_string(bad) + (bad == 1 ? " point has" : " points have") +
        " a NaN or infinite coordinate (the first is point " + std::to_string(first) + ")"));
  }
}

// Offsets that start at 0, never fall and end at the connectivity's size, and
// ids that name points: what every later loop over the cells relies on.
void RequireValidCells(
  vtkCellArray* cells, const CellKind& kind, vtkIdType pointCount, const std::string& quotedFile)
{
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  const vtkIdType n = offsets->GetNumberOfTuples();
  const vtkIdType size = connectivity->GetNumberOfTuples();
  bool ordered = n == 0 || (offsets->GetTuple1(0) == 0 && offsets->GetTuple1(n - 1) == size);
  for (vtkIdType i = 1; ordered && i < n; ++i)
  {
    ordered = offsets->GetTuple1(i - 1) <= offsets->GetTuple1(i);
  }
  if (!ordered)
  {
    throw RuntimeError(
      Fail(quotedFile, std::string("the ") + kind.Name + "s' offsets are not in order"));
  }
  for (vtkIdType i = 0; i < size; ++i)
  {
    const double id = connectivity->GetTuple1(i);
    if (!(id >= 0 && id < static_cast<double>(pointCount)))
    {
      throw RuntimeError(Fail(quotedFile,
        std::string("a ") + kind.Name + " refers to point " +
          std::to_string(static_cast<long long>(id)) + " but there are " +
          std::to_string(pointCount) + " points"));
    }
  }
}

// An array without one tuple per point (point data) or per cell (cell data).
struct MismatchedArray
{
  vtkFieldData* Data;
  int Index;
  bool PointData;
  std::string Name;
  vtkIdType Values;
  vtkIdType Items;

  std::string Described() const
  {
    return std::string("the ") + (this->PointData ? "point" : "cell") + " data array '" +
      this->Name + "'";
  }
  std::string Counts() const
  {
    return std::to_string(this->Values) + " values for " + std::to_string(this->Items) +
      (this->PointData ? " points" : " cells");
  }
};

// In the order of the arrays, point data first.
std::vector<MismatchedArray> FindMismatchedArrays(vtkPolyData* mesh)
{
  std::vector<MismatchedArray> found;
  for (const bool pointData : { true, false })
  {
    vtkFieldData* data = pointData ? static_cast<vtkFieldData*>(mesh->GetPointData())
                                   : static_cast<vtkFieldData*>(mesh->GetCellData());
    const vtkIdType items = pointData ? mesh->GetNumberOfPoints() : mesh->GetNumberOfCells();
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = data->GetAbstractArray(a);
      if (array && array->GetNumberOfTuples() != items)
      {
        found.push_back({ data, a, pointData, array->GetName() ? array->GetName() : "(unnamed)",
          array->GetNumberOfTuples(), items });
      }
    }
  }
  return found;
}

} // namespace

void RequireConsistentMesh(vtkPolyData* mesh, const std::string& quotedFile)
{
  RequireFinitePoints(mesh, quotedFile);
  const vtkIdType pointCount = mesh->GetNumberOfPoints();
  for (const CellKind& kind : Kinds)
  {
    RequireValidCells((mesh->*kind.Cells)(), kind, pointCount, quotedFile);
  }
  const std::vector<MismatchedArray> mismatched = FindMismatchedArrays(mesh);
  if (!mismatched.empty())
  {
    const MismatchedArray& first = mismatched.front();
    throw RuntimeError(Fail(quotedFile, first.Described() + " has " + first.Counts()));
  }
}

std::string RemoveMismatchedArrays(vtkPolyData* mesh)
{
  const std::vector<MismatchedArray> mismatched = FindMismatchedArrays(mesh);
  std::string what;
  // Last first, so that the indices of the others stay valid.
  for (auto it = mismatched.rbegin(); it != mismatched.rend(); ++it)
  {
    what += std::string(what.empty() ? "" : ", ") + it->Described() + " (" + it->Counts() + ")";
    it->Data->RemoveArray(it->Index);
  }
  return what;
}

std::string RemoveCellsWithTooFewPoints(vtkPolyData* mesh)
{
  std::array<vtkIdType, 4> removed{};
  bool any = false;
  for (std::size_t k = 0; k < Kinds.size(); ++k)
  {
    auto cell = vtk::TakeSmartPointer((mesh->*Kinds[k].Cells)()->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      if (cell->GetCurrentCell()->GetNumberOfIds() < Kinds[k].LeastPoints)
      {
        ++removed[k];
        any = true;
      }
    }
  }
  if (!any)
  {
    return {};
  }

  // Cell data is numbered vertices first, then lines, polygons and strips.
  vtkCellData* oldData = mesh->GetCellData();
  vtkNew<vtkCellData> newData;
  newData->CopyAllocate(oldData);
  vtkIdType oldId = 0;
  vtkIdType newId = 0;
  std::array<vtkSmartPointer<vtkCellArray>, 4> kept;
  for (std::size_t k = 0; k < Kinds.size(); ++k)
  {
    kept[k] = vtkSmartPointer<vtkCellArray>::New();
    auto cell = vtk::TakeSmartPointer((mesh->*Kinds[k].Cells)()->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell(), ++oldId)
    {
      vtkIdList* ids = cell->GetCurrentCell();
      if (ids->GetNumberOfIds() >= Kinds[k].LeastPoints)
      {
        kept[k]->InsertNextCell(ids);
        newData->CopyData(oldData, oldId, newId++);
      }
    }
  }
  mesh->SetVerts(kept[0]);
  mesh->SetLines(kept[1]);
  mesh->SetPolys(kept[2]);
  mesh->SetStrips(kept[3]);
  mesh->GetCellData()->ShallowCopy(newData);

  std::string what;
  for (std::size_t k = 0; k < Kinds.size(); ++k)
  {
    if (removed[k] > 0)
    {
      const vtkIdType least = Kinds[k].LeastPoints;
      what += (what.empty() ? "" : ", ") + std::to_string(removed[k]) + " " + Kinds[k].Name +
        (removed[k] == 1 ? "" : "s") +
        (least == 1      ? " without a point"
            : least == 2 ? " with one point or none"
                         : " with fewer than " + std::to_string(least) + " points");
    }
  }
  return what;
}

} // namespace cli
