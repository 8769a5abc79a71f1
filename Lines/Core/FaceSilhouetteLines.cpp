#include "FaceSilhouetteLines.h"

#include "ShadingNormals.h"
#include "SilhouettePolylines.h"

#include <algorithm>

namespace silsmooth
{

namespace
{

bool isVisible(double g)
{
  return g >= 0.0;
}

} // namespace

FaceSilhouette faceSilhouette(
  const PreparedMesh& mesh, const ViewGeometry& view, const ParallelFor& parallelFor)
{
  const std::vector<double> g = vertexVisibility(mesh, view, parallelFor);
  const std::vector<Triangle>& triangles = mesh.triangles();
  const EdgeTable& edges = mesh.edges();
  FaceSilhouette result;

  // Silhouette triangles, and the crossing index of every mixed edge (the
  // crossings are numbered in ascending edge order, whatever the triangle
  // order, so the output does not depend on how triangles are visited).
  std::vector<Id> crossingOfEdge(edges.edgeCount(), -1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = triangles[t];
    if (hasRepeatedCorner(tri))
    {
      continue;
    }
    const bool v0 = isVisible(g[static_cast<std::size_t>(tri[0])]);
    const bool v1 = isVisible(g[static_cast<std::size_t>(tri[1])]);
    const bool v2 = isVisible(g[static_cast<std::size_t>(tri[2])]);
    if (v0 == v1 && v1 == v2)
    {
      continue;
    }
    result.Triangles.push_back(static_cast<Id>(t));
    for (int k = 0; k < 3; ++k)
    {
      const Id e = edges.sideEdge(static_cast<Id>(t), k);
      const Edge& edge = edges.edge(e);
      if (isVisible(g[static_cast<std::size_t>(edge.low)]) !=
        isVisible(g[static_cast<std::size_t>(edge.high)]))
      {
        crossingOfEdge[static_cast<std::size_t>(e)] = 0; // marked; numbered below
      }
    }
  }
  const std::vector<glm::dvec3>& points = mesh.points();
  const std::vector<glm::dvec3>& normals = mesh.normals();
  for (std::size_t e = 0; e < crossingOfEdge.size(); ++e)
  {
    if (crossingOfEdge[e] < 0)
    {
      continue;
    }
    crossingOfEdge[e] = static_cast<Id>(result.Crossings.size());
    const Edge& edge = edges.edge(static_cast<Id>(e));
    const double gLow = g[static_cast<std::size_t>(edge.low)];
    const double gHigh = g[static_cast<std::size_t>(edge.high)];
    // One end is >= 0 and the other < 0, so the difference is never zero.
    // The clamp only guards rounding: the root of a line through values of
    // opposite signs lies in [0, 1].
    EdgeCrossing c;
    c.EdgeId = static_cast<Id>(e);
    c.Low = edge.low;
    c.High = edge.high;
    c.T = std::clamp(gLow / (gLow - gHigh), 0.0, 1.0);
    const glm::dvec3& a = points[static_cast<std::size_t>(edge.low)];
    const glm::dvec3& b = points[static_cast<std::size_t>(edge.high)];
    c.Position = a + c.T * (b - a);
    c.Normal = safeNormalize((1.0 - c.T) * normals[static_cast<std::size_t>(edge.low)] +
      c.T * normals[static_cast<std::size_t>(edge.high)]);
    result.Crossings.push_back(c);
  }

  // A silhouette triangle has exactly two mixed edges: its vertices take two
  // visibility values, so one vertex differs from the other two, and the two
  // sides at that vertex are the mixed ones.
  std::vector<std::vector<Id>> segments;
  segments.reserve(result.Triangles.size());
  for (const Id t : result.Triangles)
  {
    std::array<Id, 2> ends{ { -1, -1 } };
    int found = 0;
    for (int k = 0; k < 3; ++k)
    {
      const Id c = crossingOfEdge[static_cast<std::size_t>(edges.sideEdge(t, k))];
      if (c >= 0 && found < 2)
      {
        ends[static_cast<std::size_t>(found++)] = c;
      }
    }
    result.Segments.push_back(ends);
    segments.push_back({ ends[0], ends[1] });
  }
  result.Polylines = chainSegments(segments);
  return result;
}

} // namespace silsmooth
