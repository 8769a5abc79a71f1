// Gaps in a line drawing's outline (issue 16), closed with the surface's own
// contour.
//
// Where the mesh's outline is concave (a spider's waist seen from above),
// its smoothed silhouette curve can run inside the outline the surface
// actually has: the vertices next to the curve face the eye, so the method
// re-meshes the triangles beyond them and leaves their front facets, whose
// edge stays the outline, standing up to 10 pixels beyond the curve. The
// curve is then rightly hidden, and the drawing has no line where the
// shaded image has its outline. The same happens with the face-based
// silhouette of an unsmoothed mesh.
//
// The surface's contour for a view: its edges between a triangle facing the
// viewer and one facing away (joined as OcclusionMesh joins them; an edge of
// more or fewer than two triangles is not one). A contour point is on the
// outline when it is visible and the line of sight through a point
// BesidePixels beside it, across the edge in the image, meets no triangle in
// front of it nor within DepthJump behind it: the surface's image ends
// there, or jumps in depth (a fold of the re-meshing with the surface just
// behind it is not the outline). A drawn line covers a contour point that
// lies within JoinPixels of it, or that it runs alongside within GapPixels
// (the line's nearest point not one of its ends, the direction there near
// the contour's); a gap is a stretch of outline no drawn line covers. The two distances keep apart
// what a user sees as one line and as two: a contour running 2 or 3 px beside a drawn silhouette is
// the same edge of the image (drawing it doubled the stroke), while between two lines that stop
// short of each other the gap runs on to within JoinPixels of their ends.
//
// Invariants: every point of a gap lies on a contour edge of the surface
// (so on the surface), and no drawn line covers it at the probes that
// classified it; gaps shorter than JoinPixels in the image are left out,
// but for those between two ends of drawn lines (each within twice
// JoinPixels of one of the gap's ends, JoinPixels or more apart): a break
// of three or four pixels leaves only such a stretch open, and joined to
// the lines it closes the break.
#pragma once

#include "LineVisibility.h"

#include <glm/vec3.hpp>

#include <limits>
#include <vector>

namespace silsmooth
{

struct OutlineGapParameters
{
  /// A drawn line running alongside a contour point within this many
  /// pixels covers it (the contour would double the stroke): its nearest
  /// point not one of its ends, its direction within the angle whose cosine
  /// is AlongsideCosine of the contour's.
  double GapPixels = 4.0;
  double AlongsideCosine = 0.8; // about 37 degrees
  /// Any drawn point within this many pixels covers it (where a drawn line
  /// ends, the gap runs on to within this distance).
  double JoinPixels = 1.5;
  /// A contour point is on the outline when the line of sight through a
  /// point this many pixels beside it meets no triangle in front of that
  /// point nor within DepthJump behind it.
  double DepthJump = std::numeric_limits<double>::infinity();
  /// How far beside the contour that point is, in pixels.
  double BesidePixels = 1.0;
  /// Whether a contour point is visible, and how finely gaps are found: the
  /// rule for lines lying on the surface exactly (creases), whose
  /// SampleSpacing and Precision also place the probes and the gaps' ends.
  LineVisibilityParameters Visibility;
};

/// The surface's contour for the view, chained into polylines (a closed
/// loop repeats its first point).
std::vector<std::vector<glm::dvec3>> contourPolylines(
  const OcclusionMesh& surface, const ViewGeometry& view);

/// The gaps in the surface's outline that the `drawn` polylines (model
/// coordinates, projected with the view) leave, as polylines along the
/// contour.
std::vector<std::vector<glm::dvec3>> outlineGaps(const OcclusionMesh& surface,
  const ViewGeometry& view, const std::vector<std::vector<glm::dvec3>>& drawn,
  const OutlineGapParameters& parameters);

/// The gaps without the detours: an open gap both of whose ends lie within
/// `pixels` of one drawn line (where a gap stops, the contour has come
/// within the distance that covers it) and every pixel of which lies
/// within `share` times the gap's own length in the image (or `pixels`,
/// when more) of that same line is left out. Such a gap is the contour of
/// facets that stand beyond a curve that is drawn: their distance from it
/// is one of the model, so it grows with the zoom past any distance in
/// pixels, and the gap, joined to the curve at its ends, closed a thin box
/// beside the outline (a user's trial at `--zoom 3`, 2026-12-06). Where the
/// curve is hidden, the gap's ends meet two different pieces of it, and
/// the gap stays: it is the outline there. So does a gap beside a line
/// that passes farther than `pixels` from its ends (another part's
/// outline running alongside), a gap with the end of a drawn line within
/// `pixels` of either of its ends (it bridges a break in that line, which
/// a thin part's other outline may pass beside), and a closed gap.
std::vector<std::vector<glm::dvec3>> withoutDetours(std::vector<std::vector<glm::dvec3>> gaps,
  const ViewGeometry& view, const std::vector<std::vector<glm::dvec3>>& drawn, double pixels,
  double share);

/// The gaps with each open end joined to the drawn lines: where a drawn
/// line passes within `reach` pixels of a gap's end, the line's nearest
/// point (in model coordinates) is added to the gap before its first point
/// or after its last, so that the drawing has no break there (a gap stops
/// JoinPixels short of a line that ends, and the contour can run a pixel or
/// more beside the line it continues). Where that point lies within half a
/// pixel of the line's end, the end itself is added, bit for bit, so that
/// the gap and the line meet at equal points (a brush joins them into one
/// stroke). Closed gaps and ends with no line within reach are left as
/// they are.
std::vector<std::vector<glm::dvec3>> joinedToDrawnLines(std::vector<std::vector<glm::dvec3>> gaps,
  const ViewGeometry& view, const std::vector<std::vector<glm::dvec3>>& drawn, double reach);

} // namespace silsmooth
