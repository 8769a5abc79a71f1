#include "vtkSilhouetteAttributeSources.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace vtkSilhouetteFilterSupport
{

PointSource PointSource::Copy(vtkIdType point)
{
  PointSource source;
  source.Copied = point;
  source.Ids = { { point, point, point } };
  return source;
}

vtkIdType PointSource::Nearest() const
{
  if (this->Copied >= 0)
  {
    return this->Copied;
  }
  const std::array<double, 3>& w = this->Weights;
  const std::size_t k = w[0] >= w[1] && w[0] >= w[2] ? 0 : (w[1] >= w[2] ? 1 : 2);
  return this->Ids[k];
}

void AddUncopiedArrays(vtkDataSetAttributes* in, vtkDataSetAttributes* out,
  const std::vector<vtkIdType>& from, const char* skip)
{
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = in->GetAbstractArray(a);
    if (!array->GetName() || out->GetAbstractArray(array->GetName()) ||
      (skip && std::strcmp(array->GetName(), skip) == 0))
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> copy = vtk::TakeSmartPointer(array->NewInstance());
    copy->SetName(array->GetName());
    copy->SetNumberOfComponents(array->GetNumberOfComponents());
    copy->SetNumberOfTuples(static_cast<vtkIdType>(from.size()));
    for (std::size_t i = 0; i < from.size(); ++i)
    {
      copy->SetTuple(static_cast<vtkIdType>(i), from[i], array);
    }
    out->AddArray(copy);
  }
}

void FillPointData(vtkPointData* in, vtkPointData* out, vtkIdType leadingCopies,
  const std::vector<PointSource>& rest)
{
  const vtkIdType total = leadingCopies + static_cast<vtkIdType>(rest.size());
  vtkDataArray* inNormals = in->GetNormals();
  vtkDataArray* inOriginal = in->GetArray("OriginalPointId");
  out->CopyAllOn();
  out->CopyNormalsOff();
  out->InterpolateAllocate(in, total);
  if (leadingCopies > 0)
  {
    out->CopyData(in, 0, leadingCopies, 0);
  }
  vtkNew<vtkIdList> sources;
  sources->SetNumberOfIds(3);
  vtkIdType id = leadingCopies;
  for (const PointSource& source : rest)
  {
    if (source.Copied >= 0)
    {
      out->CopyData(in, source.Copied, id++);
      continue;
    }
    std::copy(source.Ids.begin(), source.Ids.end(), sources->begin());
    double weights[3] = { source.Weights[0], source.Weights[1], source.Weights[2] };
    out->InterpolatePoint(in, id++, sources, weights);
  }
  if (inNormals && inNormals->GetName() && out->GetArray(inNormals->GetName()))
  {
    out->RemoveArray(inNormals->GetName());
  }

  std::vector<vtkIdType> from(static_cast<std::size_t>(total));
  std::iota(from.begin(), from.begin() + leadingCopies, vtkIdType{ 0 });
  std::transform(rest.begin(), rest.end(), from.begin() + leadingCopies,
    [](const PointSource& source) { return source.Nearest(); });
  AddUncopiedArrays(in, out, from, inNormals ? inNormals->GetName() : nullptr);

  vtkNew<vtkIdTypeArray> original;
  original->SetName("OriginalPointId");
  original->SetNumberOfValues(total);
  vtkIdType* ids = original->GetPointer(0);
  for (vtkIdType i = 0; i < total; ++i)
  {
    const vtkIdType copied =
      i < leadingCopies ? i : rest[static_cast<std::size_t>(i - leadingCopies)].Copied;
    ids[i] =
      copied >= 0 && inOriginal ? static_cast<vtkIdType>(inOriginal->GetTuple1(copied)) : copied;
  }
  if (out->GetAbstractArray("OriginalPointId"))
  {
    out->RemoveArray("OriginalPointId");
  }
  out->AddArray(original);
}

void FillCellData(vtkCellData* in, vtkCellData* out, const std::vector<vtkIdType>& origin,
  vtkUnsignedCharArray* newGeometry)
{
  const vtkIdType count = static_cast<vtkIdType>(origin.size());
  if (in->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> source;
    source->SetNumberOfIds(count);
    std::copy(origin.begin(), origin.end(), source->begin());
    vtkNew<vtkIdList> destination;
    destination->SetNumberOfIds(count);
    std::iota(destination->begin(), destination->end(), vtkIdType{ 0 });
    out->CopyAllOn();
    out->CopyAllocate(in, count);
    out->CopyData(in, source, destination);
    AddUncopiedArrays(in, out, origin, "OriginalCellId");
  }
  vtkDataArray* inOriginal = in->GetArray("OriginalCellId");
  vtkNew<vtkIdTypeArray> originalCellId;
  originalCellId->SetName("OriginalCellId");
  originalCellId->SetNumberOfValues(count);
  vtkIdType* originalIds = originalCellId->GetPointer(0);
  for (vtkIdType c = 0; c < count; ++c)
  {
    const vtkIdType from = origin[static_cast<std::size_t>(c)];
    originalIds[c] = inOriginal ? static_cast<vtkIdType>(inOriginal->GetTuple1(from)) : from;
  }
  if (out->GetAbstractArray("OriginalCellId"))
  {
    out->RemoveArray("OriginalCellId");
  }
  out->AddArray(newGeometry);
  out->AddArray(originalCellId);
}

bool RefillAttributes(vtkPolyData* input, const AttributeSources& sources, vtkPolyData* mesh)
{
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  const vtkIdType inputCells = input->GetNumberOfCells();
  vtkUnsignedCharArray* newGeometry =
    vtkArrayDownCast<vtkUnsignedCharArray>(mesh->GetCellData()->GetArray("NewGeometry"));
  const bool pointsNamed =
    std::all_of(sources.Points.begin(), sources.Points.end(), [inputPoints](const PointSource& s) {
      return s.Copied < inputPoints &&
        std::all_of(s.Ids.begin(), s.Ids.end(),
          [inputPoints](vtkIdType p) { return p >= 0 && p < inputPoints; });
    });
  const bool cellsNamed = std::all_of(sources.Cells.begin(), sources.Cells.end(),
    [inputCells](vtkIdType c) { return c >= 0 && c < inputCells; });
  if (!newGeometry || newGeometry->GetNumberOfValues() != mesh->GetNumberOfCells() ||
    static_cast<vtkIdType>(sources.Points.size()) != mesh->GetNumberOfPoints() ||
    static_cast<vtkIdType>(sources.Cells.size()) != mesh->GetNumberOfCells() || !pointsNamed ||
    !cellsNamed)
  {
    return false;
  }
  vtkSmartPointer<vtkUnsignedCharArray> keptNewGeometry = newGeometry;
  vtkSmartPointer<vtkDataArray> keptNormals = mesh->GetPointData()->GetNormals();
  vtkNew<vtkPointData> points;
  FillPointData(input->GetPointData(), points, 0, sources.Points);
  if (keptNormals)
  {
    points->SetNormals(keptNormals);
  }
  vtkNew<vtkCellData> cells;
  FillCellData(input->GetCellData(), cells, sources.Cells, keptNewGeometry);
  mesh->GetPointData()->ShallowCopy(points);
  mesh->GetCellData()->ShallowCopy(cells);
  return true;
}

} // namespace vtkSilhouetteFilterSupport
