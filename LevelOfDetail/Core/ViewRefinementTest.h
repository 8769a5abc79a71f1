// The per-view refinement criteria of issue 18, as one RefinementTest over a
// VertexHierarchy's node bounds (sphere, normal cone, error):
//
// - Kim and Choe's normal-cone classes (3.2): a node is CONTOUR when some
//   normal of its cone may be orthogonal to some line of sight through its
//   sphere (the contour may pass through it), FRONT when every normal faces
//   the viewer, BACK when none does. The test is conservative: the cone's
//   angle to the line of sight to the centre, widened by the cone's half-angle,
//   the sphere's angular radius seen from the eye and ContourMarginDegrees,
//   straddles 90 degrees.
// - Mata's threshold function (2.3, 3.4): error f * e near the external contour
//   and e elsewhere becomes a tolerance per class, in pixels: ContourPixels for
//   CONTOUR nodes (f * e), InteriorPixels for FRONT ones (e), BackPixels for
//   BACK ones (infinite by default: back faces are never refined). Mata's
//   distance interval becomes the margin angle: CONTOUR takes every node whose
//   normals come within that angle of the contour.
// - View-frustum culling: a node whose sphere lies outside one of the four side
//   planes of the frustum is OUTSIDE and never refined (the near and far planes
//   are left out: a renderer resets them every frame to hold the whole scene).
// - Screen-space error: the node's error times the pixels a model unit covers
//   at the nearest depth of its sphere; a sphere that reaches the eye plane
//   has an infinite error.
//
// needs(node) is error > tolerance (a tolerance of 0 asks for every node of its
// class, even one of no error: the input back). keeps(node) is the same with
// the tolerance scaled by Hysteresis (< 1) and the margin widened by
// HysteresisDegrees: a node applied stays until the view has moved past it by
// a margin, so the cut does not flicker between two frames.
//
// Monotone in the bounds: a node's sphere, cone and error contain its
// children's, so its class is at least as near the contour, its pixels at
// least as many, and the test needs it whenever it needs a child.
#pragma once

#include "SelectiveRefinement.h"
#include "VertexHierarchy.h"
#include "ViewGeometry.h"

#include <limits>

namespace silsmooth
{

struct ViewRefinementTolerances
{
  double ContourPixels = 0.5;
  double InteriorPixels = 1.0;
  double BackPixels = std::numeric_limits<double>::infinity();
  double ContourMarginDegrees = 0.0;
  bool CullOutsideFrustum = true;
  /// keeps(): tolerances times this (in (0, 1]), margin plus HysteresisDegrees.
  double Hysteresis = 0.8;
  double HysteresisDegrees = 2.0;
};

class ViewRefinementTest : public RefinementTest
{
public:
  enum class NodeClass
  {
    Contour,
    Front,
    Back,
    Outside
  };

  ViewRefinementTest(const VertexHierarchy& hierarchy, const ViewGeometry& view,
    const ViewRefinementTolerances& tolerances);

  bool needs(VertexHierarchy::Index node) const override;
  bool keeps(VertexHierarchy::Index node) const override;

  NodeClass classify(VertexHierarchy::Index node, double marginRadians) const;
  /// The node's error in pixels (infinite when its sphere reaches the eye plane).
  double screenError(VertexHierarchy::Index node) const;

private:
  bool refine(VertexHierarchy::Index node, double scale, double marginRadians) const;
  double tolerance(NodeClass nodeClass) const;

  const VertexHierarchy& Hierarchy;
  ViewGeometry View;
  ViewRefinementTolerances Tolerances;
  glm::dvec4 Rows[4];           // rows of ModelToClip
  glm::dvec4 SidePlanes[4];     // x >= -w, x <= w, y >= -w, y <= w, unit normals
  double PixelsPerClipUnit = 0; // half the larger viewport side per unit of x/w or y/w
  double DepthPerUnit = 0;      // how fast w changes per model unit, at most
  double Margin = 0.0;
  double HysteresisMargin = 0.0;
};

} // namespace silsmooth
