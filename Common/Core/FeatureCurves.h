// Feature edges and their smooth feature curves (Wang et al. 2008, III-A), and
// the splitting of feature vertices into one point per smooth group (III-B,
// Fig. 8). All of it is view-independent: built once per input mesh.
//
// Feature edges are grouped into feature polylines. A vertex with exactly two
// feature edges is inside a polyline; any other vertex on a feature edge ends
// one (a crease fading out, or a corner where several meet). Tangents:
//   - inside: the tangent of the circle through the vertex and its two
//     polyline neighbours, T = |W1| W0 + |W0| W1 (eq. 1; the bisector of the
//     two edges' directions), except where a line meets an arc (ours,
//     FeatureLineRatio): the line's direction;
//   - at an end: the tangent of the circle through the end and the next two
//     polyline points (the eq. 1 tangent at the next point, mirrored in the
//     chord's perpendicular bisector).
// Each tangent gets the length that makes the cubic Hermite segment the
// standard approximation of a circular arc (eq. 4 with theta the angle between
// tangent and chord), so consecutive segments join with G1 continuity.
// A polyline of a single edge is not smoothed (the paper); neither is an edge
// between two ends. One more case is ours: a polyline that turns by more than
// FeatureCornerAngleDegrees at a vertex is treated as two polylines meeting at
// a corner there, because a circle through a sharp turn rounds off a corner
// that the mesh clearly has (a square's outline is not a circle).
#pragma once

#include "HermiteCurve.h"
#include "MeshTopology.h"
#include "ParallelFor.h"

#include <glm/vec3.hpp>

#include <array>
#include <utility>
#include <vector>

namespace silsmooth
{

/// An undirected feature edge between two input points, lower id first.
using FeatureEdge = std::pair<Id, Id>;

/// A polyline turning by more than this at a vertex has a corner there.
constexpr double FeatureCornerAngleDegrees = 70.0;

/// Where a line meets an arc tangentially, as CAD tessellations have it (a
/// long straight edge beside the short segments of an arc, the vertex between
/// them turning at most 3/4 as much as the arc's next vertex), the tangent there
/// is the long edge's direction, fully from this ratio of the two edges'
/// lengths on and blended in from half of it: eq. 1 bowed a rounded plate's
/// straight sides by 11 px (docs/real-assets.md).
constexpr double FeatureLineRatio = 4.0;

/// Lower id first, no self-edges, sorted, no repeats.
std::vector<FeatureEdge> normalizedFeatureEdges(std::vector<FeatureEdge> edges);

/// The edges whose two triangles' planes meet at a dihedral angle of more than
/// `angleDegrees` (the angle between the face normals), as vtkFeatureEdges and
/// vtkPolyDataNormals measure it. Only edges with exactly two triangles of
/// non-zero area are considered: boundary and non-manifold edges are not
/// features unless marked. Sorted, low id first.
std::vector<FeatureEdge> featureEdgesByAngle(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, double angleDegrees, const EdgeTable* table = nullptr);

/// Triangles whose normals are this close are flat against each other.
constexpr double FlatNeighbourDegrees = 0.5;

/// Creases between flat faces, the edges of boxes and CAD parts: edges
/// sharper than `angleDegrees` (as featureEdgesByAngle) whose two triangles
/// each lie flat (within FlatNeighbourDegrees) against another neighbour.
/// A planar face split into triangles has such neighbours; a tessellated
/// smooth surface almost never does, even where it is coarse enough to have
/// edges sharper than any fixed angle (measured in docs/real-assets.md).
/// A face of one triangle counts as flat when all three of its edges are
/// sharper than the angle and border flat triangles (a wedge's end beside
/// its rectangular sides). The outline of a flat face of two or more
/// triangles is a crease too where it is sharper than the angle all round,
/// whatever lies beyond (a cone's base beside single side triangles): an
/// organic mesh's rare coplanar neighbours have gentle edges about them. A
/// face that meets a border or a non-manifold edge has no such outline.
/// An edge found so that meets no other found edge nor a border (or
/// non-manifold edge) at either end is left out: a solid's creases meet at
/// its corners and a folded sheet's run to its borders, while a stretched
/// coarse grid has lone sharp edges between its planar quads.
/// `table`, when given, is the edge table of `triangles`.
std::vector<FeatureEdge> flatSidedCreases(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, double angleDegrees, const EdgeTable* table = nullptr);

/// Each edge's first two sides (3t + k, in triangle order; -1 where there
/// are fewer), how many sides it has, counted up to 3, and whether its first
/// two sides walk it the same way (one of their triangles is turned over):
/// the topology the dihedral angles read, kept by a caller that asks for
/// them again over moved points (the dihedral angles then read only the
/// points and these arrays, in edge order).
struct EdgeSides
{
  std::vector<std::array<Id, 2>> First;
  std::vector<unsigned char> Count;
  std::vector<unsigned char> SameWay;
};
EdgeSides edgeSidesOf(const std::vector<Triangle>& triangles, const EdgeTable& table);

/// The cosine of every edge's dihedral angle (between its two triangles'
/// normals, both the right way up), indexed by the edge ids of `table`, the
/// edge table of `triangles` (or of the table `sides` was made from); NaN
/// for an edge that is not between exactly two triangles of non-zero area.
/// Both tests above start from these: a caller asking both computes them
/// once and passes them to the forms below, which give the same edges.
/// The same values whatever parallelFor's split.
std::vector<double> dihedralCosines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const EdgeTable& table);
std::vector<double> dihedralCosines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const EdgeSides& sides,
  const ParallelFor& parallelFor = serialFor);
/// The same into `cosines`, with `faceNormals` as scratch: buffers kept from
/// an earlier call (a deforming mesh's previous frame) are filled again
/// without fresh memory, which at 1.3M triangles is 47 MB a frame.
void dihedralCosines(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
  const EdgeSides& sides, const ParallelFor& parallelFor, std::vector<glm::dvec3>& faceNormals,
  std::vector<double>& cosines);
std::vector<FeatureEdge> featureEdgesByAngle(
  const std::vector<double>& cosines, const EdgeTable& table, double angleDegrees);
std::vector<FeatureEdge> flatSidedCreases(const std::vector<double>& cosines,
  const EdgeSides& sides, const EdgeTable& table, double angleDegrees,
  const ParallelFor& parallelFor = serialFor);

/// The end tangent along `chord` whose unit direction is `direction`, with the
/// length that makes the Hermite segment approximate a circular arc. A zero
/// direction gives the chord itself (a straight end).
glm::dvec3 circleTangentAlong(const glm::dvec3& direction, const glm::dvec3& chord);

/// The feature segments of a set of feature edges.
class FeatureCurves
{
public:
  FeatureCurves() = default;
  FeatureCurves(const std::vector<glm::dvec3>& points, std::vector<FeatureEdge> edges);

  /// The feature edges, normalised (see normalizedFeatureEdges).
  const std::vector<FeatureEdge>& edges() const { return this->Edges; }
  bool empty() const { return this->Edges.empty(); }
  /// Index of the undirected edge (a, b) in edges(), or -1.
  Id find(Id a, Id b) const;
  /// Whether edge i is smoothed; its segment always runs from
  /// edges()[i].first to edges()[i].second (straight when not smoothed).
  bool isCurved(Id i) const { return this->Curved[static_cast<std::size_t>(i)] != 0; }
  const HermiteCurve& curve(Id i) const { return this->Curves[static_cast<std::size_t>(i)]; }
  std::size_t curvedCount() const { return this->CurvedCount; }

private:
  std::vector<FeatureEdge> Edges;
  std::vector<HermiteCurve> Curves;
  std::vector<unsigned char> Curved;
  std::size_t CurvedCount = 0;
};

/// The mesh with every feature vertex split into one point per smooth group:
/// the triangles around a vertex that are connected across non-feature edges.
/// Points keep their ids; the extra copies are appended after them. Across a
/// feature edge the two sides then share positions but not point ids, so each
/// side has its own shading normal (Fig. 8), like vtkPolyDataNormals' splitting.
struct FeatureSplit
{
  /// Input triangles with corners re-indexed to the split points.
  std::vector<Triangle> Triangles;
  /// The input point that extra point pointCount + i copies.
  std::vector<Id> CopySources;
  /// Per split point (input points, then copies): 1 if on a feature edge.
  std::vector<unsigned char> OnFeature;
};

FeatureSplit splitAtFeatureEdges(
  std::size_t pointCount, const std::vector<Triangle>& triangles, const FeatureCurves& features);

} // namespace silsmooth
