/**
 * @file   vtkOpenSubdivBaseMesh.h
 * @brief  vtkOpenSubdivRefiner's steps 1 to 6: the input's triangles as
 * OpenSubdiv's base mesh, its edges and creases, and the refiner.
 *
 * Private to the FiltersReference module (not wrapped or installed). Each
 * step that can refuse the input returns the error's text ("" when none),
 * which the filter reports with vtkErrorMacro.
 */
#ifndef vtkOpenSubdivBaseMesh_h
#define vtkOpenSubdivBaseMesh_h

#include "vtkType.h"

#include <opensubdiv/far/topologyRefiner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkPolyData;

namespace vtkOpenSubdivBaseMesh
{

namespace Far = OpenSubdiv::Far;

using Triangle = std::array<vtkIdType, 3>;
using Vector = std::array<double, 3>;

inline Vector Sub(const double* a, const double* b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

inline Vector Cross(const Vector& a, const Vector& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

inline double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline double Norm(const Vector& a)
{
  return std::sqrt(Dot(a, a));
}

inline std::uint64_t EdgeKey(int a, int b)
{
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

// Step 1: the input's polygons and strips as triangles, with the input cell
// each came from; cells naming missing points are an error (lines too, as
// they mark creases).
struct TriangleCells
{
  std::vector<Triangle> Triangles;
  std::vector<vtkIdType> Cells;
  vtkIdType Dropped = 0; ///< degenerate triangles, polygons of fewer than 3 points
  std::string Error;
};

TriangleCells ReadTriangleCells(vtkPolyData* input);

// Step 3: the points used by triangles become OpenSubdiv's base vertices, in
// order of first use; their coordinates must be finite.
struct BaseMesh
{
  std::vector<int> BaseIndex;       ///< per input point, its base vertex or -1
  std::vector<vtkIdType> BasePoint; ///< per base vertex, its input point
  std::vector<int> FaceVertices;    ///< three base vertices per triangle
  std::vector<double> Positions;    ///< three coordinates per base vertex
  int numBase() const { return static_cast<int>(this->BasePoint.size()); }
  int numTriangles() const { return static_cast<int>(this->FaceVertices.size() / 3); }
};

std::string MakeBaseMesh(
  vtkPolyData* input, const std::vector<Triangle>& triangles, BaseMesh& base);

// Step 4: the edges, each in one or two triangles used in opposite
// directions (a manifold, consistently oriented surface).
struct EdgeList
{
  std::vector<std::uint64_t> Keys;           ///< ascending (EdgeKey)
  std::vector<std::array<int, 2>> Triangles; ///< the second -1 on a border
};

std::string CollectEdges(
  const BaseMesh& base, const std::vector<vtkIdType>& triangleCell, EdgeList& edges);

// Step 5: the crease edges, as pairs of base vertices: the edges sharper
// than `featureAngle` (when above 0) and the segments of the input's lines
// that are edges of the triangles (the others are counted in Ignored).
struct CreaseEdges
{
  std::vector<int> Pairs;
  vtkIdType Ignored = 0;
  int count() const { return static_cast<int>(this->Pairs.size() / 2); }
};

CreaseEdges FindCreases(
  vtkPolyData* input, const BaseMesh& base, const EdgeList& edges, double featureAngle);

// Step 6: OpenSubdiv's topology with infinitely sharp creases, refined
// uniformly to `level` (the last level's full topology for the limit);
// null when OpenSubdiv refuses the mesh.
std::unique_ptr<Far::TopologyRefiner> MakeRefiner(
  const BaseMesh& base, const CreaseEdges& creases, int level, bool limit);

} // namespace vtkOpenSubdivBaseMesh

#endif
