// Triangle-mesh topology for the silhouette-smoothing core: the undirected edge
// table and which edge each side of each triangle is. View-independent, so it is
// built once per input mesh and cached across frames.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace silsmooth
{

using Id = std::int64_t;
using Triangle = std::array<Id, 3>;

/// An undirected edge, stored with the lower point id first so that both
/// triangles of the edge see the same orientation (the crack-free rule).
struct Edge
{
  Id low;
  Id high;
};

class EdgeTable
{
public:
  EdgeTable() = default;
  /// Builds the table; triangles whose ids repeat still get edges (a side
  /// (a, a) is recorded like any other) so that every side has an edge id.
  EdgeTable(const std::vector<Triangle>& triangles);

  std::size_t edgeCount() const { return this->Edges.size(); }
  const Edge& edge(Id e) const { return this->Edges[static_cast<std::size_t>(e)]; }
  /// Edge id of side k of triangle t; side k joins corner k to corner (k+1)%3.
  Id sideEdge(Id t, int k) const { return this->SideEdges[static_cast<std::size_t>(t) * 3 + k]; }
  /// Three per triangle.
  std::size_t sideCount() const { return this->SideEdges.size(); }

  /// The table of the same triangles with those marked in `reversed` turned
  /// over as oriented() turns them (corners 1 and 2 exchanged): the same
  /// edges and edge ids, sides 0 and 2 exchanged. O(triangles), no sorting.
  EdgeTable withSidesReversed(const std::vector<unsigned char>& reversed) const;

private:
  std::vector<Edge> Edges;
  std::vector<Id> SideEdges;
};

/// True when the triangle names one point twice (it has no area and no
/// well-defined silhouette; such cells pass through unchanged).
inline bool hasRepeatedCorner(const Triangle& t)
{
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}

} // namespace silsmooth
