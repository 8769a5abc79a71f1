// Hidden-line removal for line drawings (issue 16, Kim and Choe 2004 3.3):
// which parts of a polyline the surface hides from the viewer.
//
// A point of a line is hidden when the ray from it towards the eye (or, for
// parallel projection, towards the viewer) crosses a triangle of the surface
// farther than `Tolerance` from the point. The tolerance is what makes the
// test robust for the lines a drawing has: silhouettes, creases and borders
// lie on the surface, and a silhouette grazes it, so the triangles the line
// lies on (and their neighbours, which a grazing ray may clip at a short
// distance) must not hide it. It is a length in the mesh's units; scale it
// to the mesh (LineVisibilityParameters::forMesh: the mean edge length). An
// occluder nearer the line than that is missed: the price of the rule.
//
// Each polyline is split into pieces that are wholly visible or wholly
// hidden: every vertex is classified, and along a segment whose ends differ
// the change is found by bisection to within `Precision` (model units),
// where a point of the piece is inserted. A change between two vertices
// that agree (a short occluder seen through a gap) is not found: sample the
// lines as finely as the smallest occluder that matters.
//
// Invariants: pieces alternate visible and hidden along a polyline, join end
// to start (a change point ends one and starts the next, bit for bit), and
// together hold every input vertex in order; a polyline no triangle hides is
// one visible piece equal to the input.
#pragma once

#include "MeshTopology.h"
#include "TriangleGrid.h"
#include "ViewGeometry.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

struct LineVisibilityParameters
{
  /// Hits nearer the line's point than this (along the ray) do not hide it.
  double Tolerance = 0.0;
  /// Visibility changes are located to within this distance along the line.
  double Precision = 0.0;
  /// Pieces shorter than this (along the line) join their neighbours, taking
  /// their state (mergeShortPieces); 0 keeps every piece. For lines that lie
  /// on the surface exactly, a visible stub as long as the tolerance remains
  /// where an occluding face meets the line (a box's hidden edge at its
  /// visible corner): a few tolerances remove it.
  double MinimumPieceLength = 0.0;

  /// Tolerance: the mesh's mean edge length; Precision: 1e-6 of its bounding
  /// box's diagonal.
  static LineVisibilityParameters forMesh(
    const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles);
};

/// A surface that hides lines: its triangles and a grid over them, built once.
class OcclusionMesh
{
public:
  OcclusionMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles);

  /// Whether the surface hides `point` from the view (see the header's rule).
  bool hides(const ViewGeometry& view, const glm::dvec3& point, double tolerance) const;

private:
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  TriangleGrid Grid;
  glm::dvec3 Low{ 0.0 };
  glm::dvec3 High{ 0.0 };
  double Step = 0.0; ///< length of the ray pieces whose boxes are queried
};

struct LinePiece
{
  std::vector<glm::dvec3> Points;
  /// Where each point is along the input polyline: vertex i at exactly i, a
  /// change point between vertices i and i + 1 at i + its fraction of the
  /// segment (for interpolating the vertices' attributes).
  std::vector<double> Along;
  bool Visible = true;
};

/// Joins each piece shorter than `minimumLength` with its neighbours, in
/// their state, shortest first; keeps the invariants above.
std::vector<LinePiece> mergeShortPieces(std::vector<LinePiece> pieces, double minimumLength);

/// Splits `polyline` into visible and hidden pieces for the view.
std::vector<LinePiece> splitByVisibility(const OcclusionMesh& surface, const ViewGeometry& view,
  const std::vector<glm::dvec3>& polyline, const LineVisibilityParameters& parameters);

} // namespace silsmooth
