// Hidden-line removal for line drawings (issue 16, Kim and Choe 2004 3.3):
// which parts of a polyline the surface hides from the viewer.
//
// A point of a line is hidden when the ray from it towards the eye (or, for
// parallel projection, towards the viewer) crosses a triangle of the surface
// that may hide it. The lines a drawing has lie on the surface: silhouettes,
// creases and borders. A silhouette grazes it, so the triangles around the
// point (the sheet it lies on) meet its ray at short distances without
// hiding it. The rule, with the point's tolerance t: `Tolerance` (a length
// in the mesh's units, scaled to the mesh: forMesh takes the mean edge
// length), or, when less, `LocalToleranceFactor` times the longest side of
// the triangles the point lies on (within `Contact`). A grazing ray leaves
// the surface within about a triangle of the point, and a mesh's small
// triangles are where its thin parts are (a spider's legs: with the mean
// edge length alone, their far silhouettes, up to 0.025 of the diagonal
// behind their near side, were drawn):
//   - a hit farther than t always hides the point;
//   - a hit nearer than t hides it unless the triangle belongs to the
//     point's local sheet: the triangles connected to the ones the point lies
//     on (within `Contact`) through shared vertices, without leaving the ball
//     of radius t around the point. Vertices are shared where points
//     have one position and, when the surface has point normals, one normal:
//     a crease (one normal per side) bounds a sheet, so a plate's face hides
//     the silhouette of a bore that runs into it, however near;
//   - a point that lies on no triangle (a line off the surface) keeps the
//     plain rule: no hit nearer than Tolerance hides it.
// The price: an occluder of the same sheet nearer than t (a fold of the
// surface over itself) is missed.
//
// Each polyline is split into pieces that are wholly visible or wholly
// hidden: every vertex is classified, and so are probes every `SampleSpacing`
// along each segment (a long straight crease can pass behind an occluder
// between its ends); where consecutive probes differ, the change is found by
// bisection to within `Precision` (model units), where a point of the piece
// is inserted. An occluder narrower than the spacing can be missed.
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

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace silsmooth
{

struct LineVisibilityParameters
{
  /// Hits nearer the line's point than this (along the ray) do not hide it.
  double Tolerance = 0.0;
  /// Visibility changes are located to within this distance along the line.
  double Precision = 0.0;
  /// Probes at most this far apart along each segment are classified too; 0
  /// classifies the vertices only.
  double SampleSpacing = 0.0;
  /// Points within this distance of a triangle lie on it (the seeds of their
  /// local sheet); 0 turns the local-sheet rule off.
  double Contact = 0.0;
  /// A point's tolerance is at most this times the longest side of the
  /// triangles it lies on (see the header; 1.5 measured best on real meshes:
  /// docs/line-drawings.md); 0 keeps Tolerance everywhere.
  double LocalToleranceFactor = 1.5;
  /// Pieces shorter than this (along the line) join their neighbours, taking
  /// their state (mergeShortPieces); 0 keeps every piece. For lines that lie
  /// on the surface exactly, a visible stub as long as the tolerance remains
  /// where an occluding face meets the line (a box's hidden edge at its
  /// visible corner): a few tolerances remove it.
  double MinimumPieceLength = 0.0;
  /// A point the rule hides is visible all the same when a point this many
  /// pixels beside it, across the line in the image, meets no triangle on
  /// its way to the viewer: the surface's outline passes within that
  /// distance. A smoothed surface's flat triangles can stand a pixel or two
  /// beyond its silhouette curve, and hide it where it is the outline
  /// (docs/line-drawings.md). The other way round, a point visible only
  /// because its own sheet is exempt is hidden when the points 1.5 times
  /// that many pixels beside it on both sides are hidden (insideTheOutline: the far
  /// silhouette of a thin part). Needs the view's projection and viewport
  /// (ViewGeometry::toPixels); 0 turns both off. Meant for silhouettes:
  /// a crease in a valley has its faces in front of it on both sides.
  double OutlinePixels = 0.0;
  /// Whether a hidden piece shorter than OcclusionMesh::InsideGapOutlines
  /// times OutlinePixels in the image, between two visible pieces, that only
  /// insideTheOutline hides is drawn (the line as if never split there): so
  /// the outline has no break where the smoothed curve dips a little inside
  /// a coarse part's image. Off where the drawing closes the outline's gaps
  /// with the surface's own contour (OutlineGaps.h), which draws the outline
  /// there as the surface has it, not the dip's chord across a tip.
  bool DrawShortDips = true;

  /// Tolerance: the mesh's mean edge length; Precision: 1e-6 of its bounding
  /// box's diagonal; SampleSpacing: 1/400 of it; Contact: 1e-5 of it.
  static LineVisibilityParameters forMesh(
    const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles);
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

/// A surface that hides lines: its triangles and a grid over them, built once.
class OcclusionMesh
{
public:
  /// `normals`: empty, or one per point (copies of a point with different
  /// normals are not one vertex: see the header's rule).
  OcclusionMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
    const std::vector<glm::dvec3>& normals = {});

  /// Whether the surface hides `point` from the view by the header's rule.
  bool hides(
    const ViewGeometry& view, const glm::dvec3& point, const LineVisibilityParameters& rule) const;

  enum class Occlusion
  {
    /// No triangle meets the ray farther than Contact.
    Clear,
    /// Only triangles of the point's local sheet, within its tolerance:
    /// visible by the header's rule.
    BehindItsOwnSheet,
    Hidden
  };
  /// The header's rule, telling apart the two ways a point is visible.
  Occlusion occlusion(
    const ViewGeometry& view, const glm::dvec3& point, const LineVisibilityParameters& rule) const;

  /// The plain rule alone: whether a triangle farther than `tolerance` from
  /// `point` along its ray hides it.
  bool hides(const ViewGeometry& view, const glm::dvec3& point, double tolerance) const;

  /// OutlinePixels' rule for a point the rule hides, on a line running along
  /// `direction`: whether a point that many pixels to either side of it,
  /// across the line in the image, meets no triangle farther than Contact on
  /// its way to the viewer, while only the point's own local sheet, within
  /// OutlineSheetTolerances tolerances, hides the point itself.
  bool nearTheOutline(const ViewGeometry& view, const glm::dvec3& point,
    const glm::dvec3& direction, const LineVisibilityParameters& rule) const;

  /// OutlinePixels' rule for a point visible only by its sheet's exemption
  /// (Occlusion::BehindItsOwnSheet), on a line running along `direction`:
  /// whether points InsideOutlineFactor times that many pixels to both sides
  /// of it, across the line in the image, are hidden (by hits farther than
  /// Contact), so that the point lies inside the surface's image and is not
  /// its outline. A silhouette's
  /// own sheet turns away from the eye on one side of it, so the point
  /// beside it on that side is clear; the far silhouette of a part thinner
  /// than the tolerance (a spider's leg) has the near side in front of it on
  /// both.
  bool insideTheOutline(const ViewGeometry& view, const glm::dvec3& point,
    const glm::dvec3& direction, const LineVisibilityParameters& rule) const;

  /// Whether the line of sight through a point `pixels` beside `point`, on
  /// one side or the other across the line along `direction` in the image,
  /// meets no triangle in front of it, nor within `behind` behind it a
  /// triangle of `point`'s own sheet (the triangles joined to those within
  /// `contact` of it, within `behind` of it; every triangle when `behind`
  /// is not finite or `contact` finds none): the surface's image ends
  /// there, or jumps in depth, or another part lies just behind. False when
  /// the image gives no such points.
  bool besideTheOutline(const ViewGeometry& view, const glm::dvec3& point,
    const glm::dvec3& direction, double pixels, double behind, double contact = 0.0) const;

  /// Whether the line of sight through `point` meets a triangle in front of
  /// the point or within `behind` behind it (infinity: anywhere behind; the
  /// surface's image covers the point's pixel).
  bool covers(const ViewGeometry& view, const glm::dvec3& point, double behind) const;

  /// The surface's contour edges for the view, as pairs of vertices (point
  /// ids, one per welded vertex): the edges of exactly two triangles, one
  /// facing the viewer (its corners' winding counter-clockwise seen from
  /// there) and one not. Each edge once, in the order of its front triangle.
  std::vector<std::array<Id, 2>> contourEdges(const ViewGeometry& view) const;

  bool empty() const { return this->Triangles.empty(); }
  const glm::dvec3& position(Id point) const
  {
    return this->Points[static_cast<std::size_t>(point)];
  }

  /// How far inside the surface's image (in OutlinePixels) a silhouette its
  /// own sheet exempts may lie and still be drawn. 1.5 measured best on real
  /// meshes (docs/line-drawings.md): 1 lost outline where the smoothed curve
  /// runs a little inside a coarse thin part, 2 and 3 kept more strays.
  static constexpr double InsideOutlineFactor = 1.5;

  /// Hidden pieces shorter than this many OutlinePixels in the image, between
  /// two visible pieces, that only insideTheOutline hides (no probe of them
  /// hidden by the ray rule) are drawn, the line then as if never split
  /// there (splitByVisibility): where
  /// the smoothed curve dips a little inside a coarse part's outline for a
  /// few pixels (the bunny's ear tip), leaving it out opens the outline.
  static constexpr double InsideGapOutlines = 8.0;

  /// How far (in Tolerances) the surface may stand beyond a silhouette for
  /// OutlinePixels' rule: the Wuson's smoothed back stood 1 to 2.6 beyond.
  static constexpr double OutlineSheetTolerances = 4.0;

private:
  /// Whether the ray from `point` towards the viewer meets, farther than
  /// `from` and not beyond `to`, a triangle for which counts(triangle id,
  /// distance) is true.
  template<typename Counts>
  bool anyHit(
    const ViewGeometry& view, const glm::dvec3& point, double from, double to, Counts counts) const;
  /// Whether the points `pixels` to both sides of `point`, across the line
  /// along `direction` in the image, are hidden by hits farther than
  /// `contact` (the outline rules' test); nullopt when the image gives no
  /// such points (no projection there, or a line along the ray).
  /// The points `pixels` to both sides of `point`, across the line along
  /// `direction` in the image, at its depth; nullopt when the image gives
  /// no such points (no projection there, or a line along the ray).
  std::optional<std::array<glm::dvec3, 2>> besidePoints(const ViewGeometry& view,
    const glm::dvec3& point, const glm::dvec3& direction, double pixels) const;
  std::optional<bool> hiddenOnBothSides(const ViewGeometry& view, const glm::dvec3& point,
    const glm::dvec3& direction, double pixels, double contact) const;
  /// The triangles within `contact` of the point: the ones it lies on.
  std::vector<Id> trianglesUnder(const glm::dvec3& point, double contact) const;
  /// The tolerance of a point lying on the triangles `under` (see the
  /// header's rule).
  double toleranceAt(const std::vector<Id>& under, const LineVisibilityParameters& rule) const;
  /// The local sheet (sorted triangle ids) of a point lying on the
  /// triangles `under`, or empty when there are none.
  std::vector<Id> localSheet(const glm::dvec3& point, std::vector<Id> under, double radius) const;
  double distanceTo(const glm::dvec3& point, Id triangle) const;
  void weldVertices(const std::vector<glm::dvec3>& normals);

  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  /// Triangles around each vertex (points welded by position and normal).
  std::vector<Id> VertexOf;
  std::vector<std::size_t> VertexTriangleOffsets;
  std::vector<Id> VertexTriangles;
  TriangleGrid Grid;
  glm::dvec3 Low{ 0.0 };
  glm::dvec3 High{ 0.0 };
  double Step = 0.0;     ///< length of the ray pieces whose boxes are queried
  glm::dvec3 Pad{ 0.0 }; ///< added around each piece's box
};

/// The length of the polyline's image in pixels, counted up to `enough`
/// (the count stops there), or infinity when a point has no image.
double pixelLength(const std::vector<glm::dvec3>& points, const ViewGeometry& view,
  double enough = std::numeric_limits<double>::infinity());

/// Joins each piece shorter than `minimumLength` with its neighbours, in
/// their state, shortest first; keeps the invariants above.
std::vector<LinePiece> mergeShortPieces(std::vector<LinePiece> pieces, double minimumLength);

/// Splits `polyline` where `holds(point, direction)` changes: probes at most
/// `spacing` apart along each segment (the last at its end), and between two
/// probes that differ, bisection to within `precision` (model units).
/// `direction` is the segment's vector (at a repeated point, the last real
/// segment's, or the first real one's). The pieces alternate in state
/// (LinePiece::Visible is what `holds` said) and each starts at the
/// change point the one before ends at. `pieceEnds(state)`, when given, is
/// called as each piece ends, after every probe that decided its end and
/// before any later probe.
std::vector<LinePiece> splitWhere(const std::vector<glm::dvec3>& polyline, double spacing,
  double precision, const std::function<bool(const glm::dvec3&, const glm::dvec3&)>& holds,
  const std::function<void(bool)>& pieceEnds = {});

/// Splits `polyline` into visible and hidden pieces for the view.
std::vector<LinePiece> splitByVisibility(const OcclusionMesh& surface, const ViewGeometry& view,
  const std::vector<glm::dvec3>& polyline, const LineVisibilityParameters& parameters);

} // namespace silsmooth
