#include "FoldCounting.h"

#include "FiniteVector.h"
#include "TriangleGrid.h"
#include "TriangleIntersection.h"
#include "WeldedSurface.h"

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

// Per input triangle, whether the filter's output writes it turned over
// (its defaults weld and orient); empty when the input's points are not all
// finite (the filter refuses such input).
std::vector<unsigned char> WrittenTurnedOver(vtkPolyData* input, const Triangles& in)
{
  std::vector<glm::dvec3> points(static_cast<std::size_t>(input->GetNumberOfPoints()));
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    double x[3];
    input->GetPoint(static_cast<vtkIdType>(p), x);
    points[p] = glm::dvec3(x[0], x[1], x[2]);
    if (!silsmooth::isFinite(points[p]))
    {
      return {};
    }
  }
  std::vector<glm::dvec3> normals;
  if (vtkDataArray* given = input->GetPointData()->GetNormals())
  {
    normals.resize(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
    {
      double n[3];
      given->GetTuple(static_cast<vtkIdType>(p), n);
      normals[p] = glm::dvec3(n[0], n[1], n[2]);
    }
  }
  std::vector<silsmooth::Triangle> triangles;
  for (const auto& t : in.Corners)
  {
    triangles.push_back(
      t[0] < 0 ? silsmooth::Triangle{ { 0, 0, 0 } } : silsmooth::Triangle{ { t[0], t[1], t[2] } });
  }
  const silsmooth::WeldedSurface surface(
    std::move(points), triangles, normals, {}, silsmooth::SurfaceOptions{});
  std::vector<unsigned char> turned(triangles.size(), 0);
  for (std::size_t t = 0; t < turned.size(); ++t)
  {
    turned[t] = surface.writtenTurnedOver(static_cast<silsmooth::Id>(t)) ? 1 : 0;
  }
  return turned;
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
  // Boxes of the output's triangles; non-triangles stay out of the grid.
  std::vector<glm::dvec3> lows(n, glm::dvec3(HUGE_VAL));
  std::vector<glm::dvec3> highs(n, glm::dvec3(-HUGE_VAL));
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
    lows[t] = glm::min(corners[t].P[0], glm::min(corners[t].P[1], corners[t].P[2]));
    highs[t] = glm::max(corners[t].P[0], glm::max(corners[t].P[1], corners[t].P[2]));
    const vtkIdType cell = static_cast<vtkIdType>(t) + cellOffset;
    source[t] = static_cast<vtkIdType>(sources->GetTuple1(cell)) - inputCellOffset;
    bool isChanged = kinds->GetTuple1(cell) != 0;
    for (int k = 0; k < 3 && !isChanged; ++k)
    {
      isChanged = ids[k] < inputPoints && moved[static_cast<std::size_t>(ids[k])];
    }
    changed[t] = isChanged ? 1 : 0;
  }

  // The output writes each connected part with one winding, its majority's
  // (WeldedSurface.h): an input triangle against it is written turned over,
  // and is compared as written.
  const std::vector<unsigned char> turnedOver = WrittenTurnedOver(input, in);
  auto inputTriangle = [&](vtkIdType s, TriangleCorners& t) {
    if (s < 0 || static_cast<std::size_t>(s) >= in.Corners.size() ||
      in.Corners[static_cast<std::size_t>(s)][0] < 0)
    {
      return false;
    }
    t = CornersOf(input, in.Corners[static_cast<std::size_t>(s)]);
    if (!turnedOver.empty() && turnedOver[static_cast<std::size_t>(s)])
    {
      std::swap(t.P[1], t.P[2]);
    }
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
  // theirs, found in a grid of the output's boxes (the core's, which the
  // fold guard uses too).
  const silsmooth::TriangleGrid grid(lows, highs);
  std::vector<silsmooth::Id> candidates;
  for (std::size_t a = 0; a < n; ++a)
  {
    if (!changed[a])
    {
      continue;
    }
    grid.query(lows[a], highs[a], candidates);
    const silsmooth::TriangleShape shapeA = silsmooth::shapeOf(corners[a]);
    for (const silsmooth::Id candidate : candidates)
    {
      // Each pair once: a changed pair from its lower index.
      const std::size_t b = static_cast<std::size_t>(candidate);
      if (b == a || (changed[b] && b < a))
      {
        continue;
      }
      if (!silsmooth::trianglesIntersect(shapeA, silsmooth::shapeOf(corners[b])))
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
