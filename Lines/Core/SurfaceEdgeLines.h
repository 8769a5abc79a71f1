// The lines a drawing takes from the surface itself (issue 16, Kim and Choe
// 2004 3.3): creases and open borders, chained into polylines.
//
// Positions, not point ids, decide what is one vertex: points at equal
// coordinates (or within WeldTolerance of each other) are welded first, because a surface marks its
// creases by giving each side its own copy of the points there (one shading normal per side, as
// vtkSilhouetteSmoothingFilter's output and vtkPolyDataNormals with splitting do), and asset files
// split points along texture seams too. After welding, an edge is
// - a border when one triangle has it;
// - a crease when two triangles have it and the surface's point normals
//   jump across it: at either end, the copies the two triangles use carry
//   normals more than NormalJumpDegrees apart (a texture seam, whose copies
//   share the normal, is not a crease). Without point normals, a crease is
//   an edge whose faces meet at more than CreaseAngleDegrees, as
//   vtkFeatureEdges measures it;
// - a crease too when more than two triangles have it (sheets meeting in a
//   fin are drawn along their common edge).
// Triangles whose corners weld to fewer than three vertices take no part.
//
// Invariants: every returned edge is an edge of the surface, so the lines
// lie on it exactly (hidden-line removal needs no tolerance for them); each
// crease or border edge is in exactly one polyline; polylines stop where
// other than two edges of their kind meet (the corners of a box), and a
// closed loop repeats its first point at the end.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

/// What a line of a drawing is (the VTK filters' `LineKind` cell array).
enum class LineKind : unsigned char
{
  Silhouette = 0,
  Crease = 1,
  Border = 2,
  Intersection = 3 ///< where the surface passes through itself (IntersectionLines.h)
};

struct SurfaceEdgeLineParameters
{
  bool Creases = true;
  bool Borders = true;
  /// With point normals: copies whose normals differ by more than this make
  /// a crease.
  double NormalJumpDegrees = 1.0;
  /// Without point normals: faces meeting at more than this make a crease.
  double CreaseAngleDegrees = 30.0;
  /// 0: points at equal coordinates are one vertex. d > 0: points within d
  /// of each other are, transitively (weldCoincidentPoints), as the
  /// smoothing filter welds with its WeldTolerance. A surface smoothed with
  /// a tolerance must be drawn with the same one: its near copies (an
  /// exporter's rounded points, joined by sliver triangles) would otherwise
  /// cut it, and the slivers' arbitrary facets make creases.
  double WeldTolerance = 0.0;
};

struct SurfaceEdgeLine
{
  /// Point ids of the surface (the lowest id of each welded vertex).
  std::vector<Id> Points;
  LineKind Kind = LineKind::Crease;
};

/// The crease and border polylines of a triangle surface. `normals` is
/// empty or one per point. Polylines come out creases first, each kind in
/// the order of its lowest edge.
std::vector<SurfaceEdgeLine> surfaceEdgeLines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const std::vector<glm::dvec3>& normals,
  const SurfaceEdgeLineParameters& parameters);

} // namespace silsmooth
