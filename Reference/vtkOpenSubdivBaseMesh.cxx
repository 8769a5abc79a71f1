#include "vtkOpenSubdivBaseMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <functional>
#include <limits>

namespace vtkOpenSubdivBaseMesh
{

namespace Sdc = OpenSubdiv::Sdc;

namespace
{

// One use of an undirected edge by a triangle, for sorting.
struct EdgeUse
{
  std::uint64_t Key;
  int Triangle;
  bool Forward; // the triangle runs from the lower to the higher base index
};

} // namespace

TriangleCells ReadTriangleCells(vtkPolyData* input)
{
  TriangleCells read;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkIdType badCell = -1;
  vtkIdType badPoint = -1;
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType cellId) {
    if (a == b || b == c || c == a)
    {
      ++read.Dropped;
      return;
    }
    read.Triangles.push_back({ a, b, c });
    read.Cells.push_back(cellId);
  };
  auto validIds = [&](vtkIdType npts, const vtkIdType* pts, vtkIdType cellId) {
    for (vtkIdType i = 0; i < npts; ++i)
    {
      if (pts[i] < 0 || pts[i] >= numPoints)
      {
        badCell = cellId;
        badPoint = pts[i];
        return false;
      }
    }
    return true;
  };
  // Walks one cell array, cell ids from `firstId`, until a bad cell.
  auto walk = [&](vtkCellArray* cells, vtkIdType firstId, auto&& triangulate) {
    vtkIdType cellId = firstId;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      it->GetCurrentCell(npts, pts);
      if (!validIds(npts, pts, cellId))
      {
        return;
      }
      triangulate(npts, pts, cellId);
    }
  };
  const vtkIdType numVerts = input->GetNumberOfVerts();
  const vtkIdType numLines = input->GetNumberOfLines();
  const vtkIdType numPolys = input->GetNumberOfPolys();
  walk(input->GetPolys(), numVerts + numLines,
    [&](vtkIdType npts, const vtkIdType* pts, vtkIdType cellId) {
      read.Dropped += npts < 3 ? 1 : 0;
      for (vtkIdType i = 1; i + 1 < npts; ++i)
      {
        addTriangle(pts[0], pts[i], pts[i + 1], cellId);
      }
    });
  if (badCell < 0)
  {
    walk(input->GetStrips(), numVerts + numLines + numPolys,
      [&](vtkIdType npts, const vtkIdType* pts, vtkIdType cellId) {
        read.Dropped += npts < 3 ? 1 : 0;
        for (vtkIdType i = 0; i + 2 < npts; ++i)
        {
          if (i % 2 == 0)
          {
            addTriangle(pts[i], pts[i + 1], pts[i + 2], cellId);
          }
          else
          {
            addTriangle(pts[i + 1], pts[i], pts[i + 2], cellId);
          }
        }
      });
  }
  if (badCell < 0)
  {
    walk(input->GetLines(), numVerts, [](vtkIdType, const vtkIdType*, vtkIdType) {});
  }
  if (badCell >= 0)
  {
    std::ostringstream message;
    message << "Cell " << badCell << " refers to point " << badPoint << ", but the input has "
            << numPoints << " points.";
    read.Error = message.str();
  }
  return read;
}

std::string MakeBaseMesh(vtkPolyData* input, const std::vector<Triangle>& triangles, BaseMesh& base)
{
  vtkPoints* inPoints = input->GetPoints();
  base.BaseIndex.assign(static_cast<std::size_t>(input->GetNumberOfPoints()), -1);
  base.FaceVertices.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
  {
    for (vtkIdType id : t)
    {
      int& index = base.BaseIndex[static_cast<std::size_t>(id)];
      if (index < 0)
      {
        double p[3];
        inPoints->GetPoint(id, p);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        {
          return "Point " + std::to_string(id) + " has a NaN or infinite coordinate.";
        }
        index = static_cast<int>(base.BasePoint.size());
        base.BasePoint.push_back(id);
      }
      base.FaceVertices.push_back(index);
    }
  }
  base.Positions.resize(3 * base.BasePoint.size());
  for (int v = 0; v < base.numBase(); ++v)
  {
    inPoints->GetPoint(base.BasePoint[static_cast<std::size_t>(v)], &base.Positions[3 * v]);
  }
  return "";
}

std::string CollectEdges(
  const BaseMesh& base, const std::vector<vtkIdType>& triangleCell, EdgeList& edges)
{
  std::vector<EdgeUse> uses;
  uses.reserve(base.FaceVertices.size());
  for (int t = 0; t < base.numTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = base.FaceVertices[3 * t + k];
      const int b = base.FaceVertices[3 * t + (k + 1) % 3];
      uses.push_back({ EdgeKey(a, b), t, a < b });
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return x.Key < y.Key || (x.Key == y.Key && x.Triangle < y.Triangle);
  });
  for (std::size_t i = 0; i < uses.size();)
  {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].Key == uses[i].Key)
    {
      ++j;
    }
    const vtkIdType pointA = base.BasePoint[static_cast<std::size_t>(uses[i].Key >> 32)];
    const vtkIdType pointB = base.BasePoint[static_cast<std::size_t>(uses[i].Key & 0xffffffffu)];
    std::ostringstream message;
    if (j - i > 2)
    {
      message << "Non-manifold input: the edge between points " << pointA << " and " << pointB
              << " is shared by " << (j - i) << " triangles.";
      return message.str();
    }
    if (j - i == 2 && uses[i].Forward == uses[i + 1].Forward)
    {
      message << "Inconsistent orientation: cells "
              << triangleCell[static_cast<std::size_t>(uses[i].Triangle)] << " and "
              << triangleCell[static_cast<std::size_t>(uses[i + 1].Triangle)]
              << " run through the edge between points " << pointA << " and " << pointB
              << " in the same direction.";
      return message.str();
    }
    edges.Keys.push_back(uses[i].Key);
    edges.Triangles.push_back({ uses[i].Triangle, j - i == 2 ? uses[i + 1].Triangle : -1 });
    i = j;
  }
  return "";
}

CreaseEdges FindCreases(
  vtkPolyData* input, const BaseMesh& base, const EdgeList& edges, double featureAngle)
{
  std::vector<char> isCrease(edges.Keys.size(), 0);
  if (featureAngle > 0.0)
  {
    std::vector<Vector> normals(static_cast<std::size_t>(base.numTriangles()));
    for (int t = 0; t < base.numTriangles(); ++t)
    {
      const double* p0 = &base.Positions[3 * base.FaceVertices[3 * t]];
      const double* p1 = &base.Positions[3 * base.FaceVertices[3 * t + 1]];
      const double* p2 = &base.Positions[3 * base.FaceVertices[3 * t + 2]];
      Vector n = Cross(Sub(p1, p0), Sub(p2, p0));
      const double length = Norm(n);
      normals[t] = length > 0.0 ? Vector{ n[0] / length, n[1] / length, n[2] / length }
                                : Vector{ 0.0, 0.0, 0.0 };
    }
    const double cosLimit = std::cos(vtkMath::RadiansFromDegrees(featureAngle));
    for (std::size_t e = 0; e < edges.Keys.size(); ++e)
    {
      const std::array<int, 2>& pair = edges.Triangles[e];
      if (pair[1] < 0)
      {
        continue;
      }
      const Vector& n0 = normals[static_cast<std::size_t>(pair[0])];
      const Vector& n1 = normals[static_cast<std::size_t>(pair[1])];
      if (Dot(n0, n0) > 0.0 && Dot(n1, n1) > 0.0 && Dot(n0, n1) < cosLimit)
      {
        isCrease[e] = 1;
      }
    }
  }
  CreaseEdges creases;
  auto lines = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    lines->GetCurrentCell(npts, pts);
    for (vtkIdType i = 0; i + 1 < npts; ++i)
    {
      if (pts[i] == pts[i + 1])
      {
        continue;
      }
      const int a = base.BaseIndex[static_cast<std::size_t>(pts[i])];
      const int b = base.BaseIndex[static_cast<std::size_t>(pts[i + 1])];
      const std::uint64_t key = a >= 0 && b >= 0 ? EdgeKey(a, b) : 0;
      const auto found = std::lower_bound(edges.Keys.begin(), edges.Keys.end(), key);
      if (a < 0 || b < 0 || found == edges.Keys.end() || *found != key)
      {
        ++creases.Ignored;
        continue;
      }
      isCrease[static_cast<std::size_t>(found - edges.Keys.begin())] = 1;
    }
  }
  for (std::size_t e = 0; e < edges.Keys.size(); ++e)
  {
    if (isCrease[e])
    {
      creases.Pairs.push_back(static_cast<int>(edges.Keys[e] >> 32));
      creases.Pairs.push_back(static_cast<int>(edges.Keys[e] & 0xffffffffu));
    }
  }
  return creases;
}

std::unique_ptr<Far::TopologyRefiner> MakeRefiner(
  const BaseMesh& base, const CreaseEdges& creases, int level, bool limit)
{
  std::vector<int> vertsPerFace(static_cast<std::size_t>(base.numTriangles()), 3);
  const std::vector<float> creaseWeights(
    static_cast<std::size_t>(creases.count()), Sdc::Crease::SHARPNESS_INFINITE);
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = base.numBase();
  descriptor.numFaces = base.numTriangles();
  descriptor.numVertsPerFace = vertsPerFace.data();
  descriptor.vertIndicesPerFace = base.FaceVertices.data();
  descriptor.numCreases = creases.count();
  descriptor.creaseVertexIndexPairs = creases.Pairs.data();
  descriptor.creaseWeights = creaseWeights.data();

  Sdc::Options schemeOptions;
  schemeOptions.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_LOOP, schemeOptions)));
  if (refiner && level > 0)
  {
    Far::TopologyRefiner::UniformOptions uniform(level);
    uniform.fullTopologyInLastLevel = limit;
    refiner->RefineUniform(uniform);
  }
  return refiner;
}

} // namespace vtkOpenSubdivBaseMesh
