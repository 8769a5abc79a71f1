// Face-based silhouette lines (Hertzmann and Zorin 2000; Xing's Fig. 6b): the
// silhouette of the piecewise-linear visibility field g = N . (E - V).
//
// g is interpolated linearly over each triangle, so its zero set crosses a
// silhouette triangle (vertices of both signs, the visibility rule of
// ViewGeometry::visibility: visible when g >= 0) in one straight segment
// between the linear zero crossings of its two mixed edges. A crossing is
// computed once per undirected edge, from the edge's lower point id to its
// higher one, so the two triangles of an edge share it bit for bit and the
// segments chain into crack-free polylines. Nothing is re-meshed: this is the
// unsmoothed reference line drawing that the smoothed silhouette replaces.
#pragma once

#include "MeshTopology.h"
#include "PreparedMesh.h"
#include "ViewGeometry.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

/// A zero crossing of g on a mixed edge: the point
/// (1 - T) * points[Low] + T * points[High], Low < High being the edge's ends.
struct EdgeCrossing
{
  Id EdgeId = -1;
  Id Low = -1;
  Id High = -1;
  double T = 0.0;
  glm::dvec3 Position{ 0.0 };
  /// The linearly interpolated shading normal, normalised.
  glm::dvec3 Normal{ 0.0 };
};

struct FaceSilhouette
{
  /// One crossing per mixed edge of a silhouette triangle, ascending edge id.
  std::vector<EdgeCrossing> Crossings;
  /// The silhouette triangles (prepared triangle ids, ascending), and for each
  /// the indices into Crossings of the ends of its segment.
  std::vector<Id> Triangles;
  std::vector<std::array<Id, 2>> Segments;
  /// The segments chained into polylines of Crossings indices; a closed loop
  /// repeats its first index at the end (chainSegments' rule).
  std::vector<std::vector<Id>> Polylines;
};

/// The face-based silhouette of the prepared mesh for the view. Uses the
/// per-vertex values of g (vertexVisibility): the crossing needs g itself,
/// not only its sign. Triangles naming a point twice are skipped.
FaceSilhouette faceSilhouette(
  const PreparedMesh& mesh, const ViewGeometry& view, const ParallelFor& parallelFor = serialFor);

} // namespace silsmooth
