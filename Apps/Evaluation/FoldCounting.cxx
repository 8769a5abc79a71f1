#include "FoldCounting.h"

#include "TriangleIntersection.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace silhouette_eval
{
namespace
{

using silsmooth::TriangleCorners;

struct Triangles
{
  std::vector<std::array<vtkIdType, 3>> Corners;
};

Triangles TrianglesOf(vtkPolyData* mesh)
{
  Triangles result;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    result.Corners.push_back(n == 3 ? std::array<vtkIdType, 3>{ { ids[0], ids[1], ids[2] } }
                                    : std::array<vtkIdType, 3>{ { -1, -1, -1 } });
  }
  return result;
}

TriangleCorners CornersOf(vtkPolyData* mesh, const std::array<vtkIdType, 3>& ids)
{
  TriangleCorners t;
  for (int k = 0; k < 3; ++k)
  {
    double p[3];
    mesh->GetPoint(ids[k], p);
    t.P[k] = glm::dvec3(p[0], p[1], p[2]);
  }
  return t;
}

// The sum of the corners' normals.
glm::dvec3 NormalSum(vtkDataArray* normals, const std::array<vtkIdType, 3>& ids)
{
  glm::dvec3 sum(0.0);
  for (int k = 0; k < 3; ++k)
  {
    double n[3];
    normals->GetTuple(ids[k], n);
    sum += glm::dvec3(n[0], n[1], n[2]);
  }
  return sum;
}

struct Box
{
  glm::dvec3 Low{ 0.0 };
  glm::dvec3 High{ 0.0 };
};

Box BoxOf(const TriangleCorners& t)
{
  Box b{ t.P[0], t.P[0] };
  for (int k = 1; k < 3; ++k)
  {
    b.Low = glm::min(b.Low, t.P[k]);
    b.High = glm::max(b.High, t.P[k]);
  }
  return b;
}

bool Overlap(const Box& a, const Box& b)
{
  return a.Low.x <= b.High.x && b.Low.x <= a.High.x && a.Low.y <= b.High.y && b.Low.y <= a.High.y &&
    a.Low.z <= b.High.z && b.Low.z <= a.High.z;
}

} // namespace

FoldCount CountFolds(vtkPolyData* input, vtkPolyData* output)
{
  FoldCount count;
  vtkDataArray* kinds = output->GetCellData()->GetArray("NewGeometry");
  vtkDataArray* sources = output->GetCellData()->GetArray("OriginalCellId");
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  if (!kinds || !sources || !normals || !output->GetPoints() || !input->GetPoints())
  {
    return count;
  }
  const Triangles in = TrianglesOf(input);
  const Triangles out = TrianglesOf(output);
  const vtkIdType cellOffset = output->GetNumberOfVerts() + output->GetNumberOfLines();
  const vtkIdType inputCellOffset = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const vtkIdType inputPoints = input->GetNumberOfPoints();

  // Moved: an input point the output holds at another position.
  std::vector<unsigned char> moved(static_cast<std::size_t>(inputPoints), 0);
  for (vtkIdType p = 0; p < inputPoints && p < output->GetNumberOfPoints(); ++p)
  {
    double a[3];
    double b[3];
    input->GetPoint(p, a);
    output->GetPoint(p, b);
    moved[static_cast<std::size_t>(p)] = (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) ? 1 : 0;
  }

  const std::size_t n = out.Corners.size();
  std::vector<TriangleCorners> corners(n);
  std::vector<Box> boxes(n);
  std::vector<vtkIdType> source(n, -1);
  std::vector<unsigned char> changed(n, 0);
  for (std::size_t t = 0; t < n; ++t)
  {
    const auto& ids = out.Corners[t];
    if (ids[0] < 0)
    {
      continue;
    }
    corners[t] = CornersOf(output, ids);
    boxes[t] = BoxOf(corners[t]);
    const vtkIdType cell = static_cast<vtkIdType>(t) + cellOffset;
    source[t] = static_cast<vtkIdType>(sources->GetTuple1(cell)) - inputCellOffset;
    bool isChanged = kinds->GetTuple1(cell) != 0;
    for (int k = 0; k < 3 && !isChanged; ++k)
    {
      isChanged = ids[k] < inputPoints && moved[static_cast<std::size_t>(ids[k])];
    }
    changed[t] = isChanged ? 1 : 0;
  }

  auto inputTriangle = [&](vtkIdType s, TriangleCorners& t) {
    if (s < 0 || static_cast<std::size_t>(s) >= in.Corners.size() ||
      in.Corners[static_cast<std::size_t>(s)][0] < 0)
    {
      return false;
    }
    t = CornersOf(input, in.Corners[static_cast<std::size_t>(s)]);
    return true;
  };

  // Turned over.
  for (std::size_t t = 0; t < n; ++t)
  {
    if (!changed[t])
    {
      continue;
    }
    ++count.Changed;
    const glm::dvec3 sum = NormalSum(normals, out.Corners[t]);
    TriangleCorners original;
    if (inputTriangle(source[t], original) &&
      silsmooth::turnedOverAgainst(corners[t], original, sum))
    {
      ++count.Flipped;
    }
  }

  // Cut through: changed triangles against every triangle whose box meets
  // theirs, found in a uniform grid of the output's boxes.
  Box all{ glm::dvec3(HUGE_VAL), glm::dvec3(-HUGE_VAL) };
  double size = 0.0;
  std::size_t valid = 0;
  for (std::size_t t = 0; t < n; ++t)
  {
    if (source[t] >= 0 || out.Corners[t][0] >= 0)
    {
      all.Low = glm::min(all.Low, boxes[t].Low);
      all.High = glm::max(all.High, boxes[t].High);
      const glm::dvec3 d = boxes[t].High - boxes[t].Low;
      size += std::max({ d.x, d.y, d.z });
      ++valid;
    }
  }
  if (valid == 0)
  {
    return count;
  }
  const double cell = std::max(size / static_cast<double>(valid), 1e-300);
  auto key = [&](int i, int j, int k) {
    return (static_cast<std::int64_t>(i) * 73856093) ^ (static_cast<std::int64_t>(j) * 19349663) ^
      (static_cast<std::int64_t>(k) * 83492791);
  };
  auto cellOf = [&](double x, double low) {
    return static_cast<int>((x - low) / cell);
  };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;
  for (std::size_t t = 0; t < n; ++t)
  {
    if (out.Corners[t][0] < 0)
    {
      continue;
    }
    for (int i = cellOf(boxes[t].Low.x, all.Low.x); i <= cellOf(boxes[t].High.x, all.Low.x); ++i)
      for (int j = cellOf(boxes[t].Low.y, all.Low.y); j <= cellOf(boxes[t].High.y, all.Low.y); ++j)
        for (int k = cellOf(boxes[t].Low.z, all.Low.z); k <= cellOf(boxes[t].High.z, all.Low.z);
             ++k)
          grid[key(i, j, k)].push_back(t);
  }
  std::vector<std::size_t> candidates;
  for (std::size_t a = 0; a < n; ++a)
  {
    if (!changed[a])
    {
      continue;
    }
    candidates.clear();
    for (int i = cellOf(boxes[a].Low.x, all.Low.x); i <= cellOf(boxes[a].High.x, all.Low.x); ++i)
      for (int j = cellOf(boxes[a].Low.y, all.Low.y); j <= cellOf(boxes[a].High.y, all.Low.y); ++j)
        for (int k = cellOf(boxes[a].Low.z, all.Low.z); k <= cellOf(boxes[a].High.z, all.Low.z);
             ++k)
        {
          const auto found = grid.find(key(i, j, k));
          if (found != grid.end())
          {
            candidates.insert(candidates.end(), found->second.begin(), found->second.end());
          }
        }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (const std::size_t b : candidates)
    {
      // Each pair once: a changed pair from its lower index.
      if (b == a || (changed[b] && b < a) || !Overlap(boxes[a], boxes[b]))
      {
        continue;
      }
      if (!silsmooth::trianglesIntersect(corners[a], corners[b]))
      {
        continue;
      }
      TriangleCorners sa;
      TriangleCorners sb;
      const bool inputsCut = source[a] != source[b] && inputTriangle(source[a], sa) &&
        inputTriangle(source[b], sb) && silsmooth::trianglesTouch(sa, sb);
      count.Intersecting += inputsCut ? 0 : 1;
    }
  }
  return count;
}

} // namespace silhouette_eval
