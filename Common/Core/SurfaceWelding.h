// The surface behind a mesh as asset files store it. Exporters give a point
// of the surface one mesh point per texture chart, per hard edge, or per
// triangle corner (a triangle soup), so point ids say little about which
// triangles meet. Here points at one position are one surface vertex, and
// points at one position whose normals differ mark a crease (the asset's
// hard edge). View-independent: built once per input.
#pragma once

#include "FeatureCurves.h"
#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

/// Normals at one position that differ by more than this many degrees make a
/// normal seam. Files round normals to 4-6 digits (well under 0.01 degrees);
/// exporters that split normals at hard edges differ there by tens of degrees.
constexpr double NormalSeamAngleDegrees = 1.0;

/// The surface vertex of every point: the lowest id among the points it is
/// welded with. Invariant: vertex[vertex[i]] == vertex[i], and vertex[i] <= i.
/// With tolerance 0, points are welded when their coordinates are equal;
/// with tolerance d > 0, when they are within distance d of each other,
/// transitively (a chain of close points is one vertex). Points with
/// non-finite coordinates are never welded.
std::vector<Id> weldCoincidentPoints(const std::vector<glm::dvec3>& points, double tolerance = 0.0);

/// For each triangle, whether another triangle lies on the same three
/// corners with the opposite winding (its back-to-back twin: the two sides
/// of a double-sided sheet). `table` is the triangles' edge table; only
/// triangles on an edge with three sides or more are looked at (a twin pair
/// alone is not found). O(triangles) on a manifold mesh.
std::vector<unsigned char> backToBackTwins(
  const std::vector<Triangle>& triangles, const EdgeTable& table);

/// Each triangle's sheet: the lowest id among the triangles joined to it
/// across shared sides of `table` (their edge table; a side whose ends are
/// one point joins nothing). Parts that only touch at a point are sheets of
/// their own. With `backToBackApart`, the two sides of a double-sided sheet
/// (each triangle repeated on the same corners with the opposite winding,
/// as exporters write foliage and cloth) are sheets of their own too: a
/// triangle with such a twin joins, across a side, only triangles that run
/// along that side the other way and are not its twin. O(triangles).
std::vector<std::size_t> sheetsOf(
  const std::vector<Triangle>& triangles, const EdgeTable& table, bool backToBackApart = false);

/// The weld `vertex` (as weldCoincidentPoints gives it) kept within sheets:
/// points welded together stay one vertex only where their triangles are
/// joined across sides once welded. Parts that only touch at a point (two
/// solids with a corner in common, a sphere's equator point on a grid point
/// of a face) keep a vertex each there, so that neither's normals blend into
/// the other's; so do the two sides of a double-sided sheet written with a
/// copy of each point per side (sheetsOf's `backToBackApart`), whose
/// normals would cancel. A group with a point whose own triangles lie on two sheets
/// (a pinched surface) stays whole; points no triangle uses stay with their
/// group's lowest point. The same invariants as weldCoincidentPoints.
/// `weldedTable` is the edge table of weldTriangles(triangles, vertex).
/// O(points + triangles).
std::vector<Id> weldWithinSheets(
  const std::vector<Triangle>& triangles, std::vector<Id> vertex, const EdgeTable& weldedTable);

/// Edges far shorter than the mesh: what exporters leave where they write
/// one point twice with rounded coordinates (OpenSCAD's STL writes copies
/// 1e-5 to 1e-4 apart, joined by sliver triangles). Welding equal
/// coordinates keeps such copies apart: each carries the normals of one side
/// only, and a copy used by slivers alone gets a sliver's normal.
struct NearCopies
{
  /// Edges between distinct points at most `relative` times the points'
  /// bounding-box diagonal long (each edge once).
  std::size_t EdgeCount = 0;
  /// The longest of them: a weld tolerance just above it joins their ends.
  double LongestEdge = 0.0;
};

/// The near copies joined by an edge of `table` (built over `points`'
/// ids). Non-finite points are left out; a mesh whose size overflows has
/// none (everything would be near against it). O(points + edges).
NearCopies nearCopyEdges(
  const std::vector<glm::dvec3>& points, const EdgeTable& table, double relative = 1e-5);

/// The triangles with every corner replaced by its surface vertex.
std::vector<Triangle> weldTriangles(
  const std::vector<Triangle>& triangles, const std::vector<Id>& vertex);

/// Normal seams: the edges of the welded triangles (pairs of surface
/// vertices, lower first, sorted) shared by exactly two triangles of non-zero
/// extent whose own points at one end of the edge have normals more than
/// `angleDegrees` apart. `triangles` are the input's (their own point ids),
/// `normals` one per point. Zero or non-finite normals never make a seam.
/// `interiorEdges`, when given, receives the number of edges shared by
/// exactly two such triangles (the candidates). `welded` and `table`, when
/// given, are weldTriangles(triangles, vertex) and its edge table (saves
/// building them again).
std::vector<FeatureEdge> normalSeamEdges(const std::vector<Triangle>& triangles,
  const std::vector<Id>& vertex, const std::vector<glm::dvec3>& normals,
  double angleDegrees = NormalSeamAngleDegrees, std::size_t* interiorEdges = nullptr,
  const std::vector<Triangle>* welded = nullptr, const EdgeTable* table = nullptr);

} // namespace silsmooth
