// The earlier method the 2008 paper compares with ("Wang's method [20]"):
// B. Wang, W. Wang, J. Wu, J. Sun, "Silhouette Smoothing by Boundary Curve
// Interpolation", CAD/Graphics 2003 (seeds/001_6bdf65727afcfd50.txt).
//
// Silhouette *edges* (mesh edges between a front- and a back-facing triangle)
// are projected to the view plane; each becomes a 2D cubic Hermite curve whose
// end tangents are the projected vertex normals turned by pi/2 (section 3.2),
// with magnitudes v0 = 4 rho (Q - X0), v1 = 4 rho (X1 - Q), Q the intersection
// of the two tangent lines and theta half the angle between them. The curve is
// back-projected to 3D and the two triangles of the edge are fanned from their
// opposite vertices to its samples (section 3.3, Fig. 3); new points get
// linearly interpolated normals.
//
// Choices the paper leaves open, and one correction:
// - rho: the text prints rho = cos(theta)(1 + cos(theta)), which for a straight
//   edge (theta = 0) gives tangents 4 times the chord and loops; the value that
//   makes the Hermite curve reproduce a circular arc (the paper's stated aim,
//   after Mortenson) is rho = cos(theta) / (1 + cos(theta)): then |v| = 4 r
//   tan(theta / 2), the classical arc tangent. That is the one used
//   (`rhoForHalfAngle`; the core test checks the arc).
// - Projected normal: the normal in eye coordinates with its depth component
//   dropped (for a contour point, this is the outline's normal in the image,
//   in perspective and parallel projection alike).
// - When the tangent lines do not meet ahead of both ends (an S-shaped edge or
//   parallel tangents), each end gets |v_i| = 2 |X1 - X0| / (1 + cos phi_i),
//   phi_i the angle between its tangent and the chord (the circle's value for
//   that end alone). Lengths are capped at 3 chords.
// - Back-projection: the point on the view ray through the 2D curve point, at
//   the depth of the straight edge at the same parameter (clip z and w
//   interpolated linearly, which is exact for points of the edge).
// - Sampling: either a fixed count per curve (the paper uses 3 to 5 points), or
//   (count 0) adaptive, the same chord-error bound as the 2008 filter's
//   (second differences of the 2D Bezier control points) with the pixel
//   tolerance, so the two methods differ in their curves, not their sampling.
// - A triangle with two or three silhouette edges (the paper's fan has no
//   single opposite vertex then) is fanned from an added centre point.
// - Every silhouette edge is smoothed, visible or hidden (the paper takes the
//   visible ones; finding them needs a depth test).
// Crack-free by construction: each edge's curve is computed once, from its
// lower point id, and shared by its two triangles.
#pragma once

#include "MeshTopology.h"
#include "ViewGeometry.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace silsmooth
{

/// rho of Wang et al. 2003 for half the subtended angle theta, given as
/// cos(theta) (see the header comment for why it is not the printed formula).
double rhoForHalfAngle(double cosTheta);

/// A 2D cubic Hermite curve (pixels).
struct HermiteCurve2D
{
  glm::dvec2 P0{ 0.0 };
  glm::dvec2 P1{ 0.0 };
  glm::dvec2 T0{ 0.0 };
  glm::dvec2 T1{ 0.0 };

  glm::dvec2 at(double u) const;
};

/// The boundary curve through the projected ends x0, x1 with projected
/// (image-plane) normals n0, n1 (any length; zero: no direction known).
HermiteCurve2D boundaryCurve(
  const glm::dvec2& x0, const glm::dvec2& x1, const glm::dvec2& n0, const glm::dvec2& n1);

struct BoundaryCurveParameters
{
  /// Points per curve, both ends counted; 0 = adaptive with TolerancePixels.
  int SamplesPerCurve = 0;
  double TolerancePixels = 0.5;
  int MinimumSamples = 2;
  int MaximumSamples = 256;
};

/// Number of samples (both ends) that keeps the polyline within `tolerance`
/// pixels of `curve`.
int boundaryCurveSampleCount(const HermiteCurve2D& curve, const BoundaryCurveParameters& p);

/// An added point: a weighted combination of up to three input points (for
/// interpolating point data; weights sum to one).
struct BoundaryCurvePointSource
{
  std::array<Id, 3> Points{ { 0, 0, 0 } };
  std::array<double, 3> Weights{ { 0.0, 0.0, 0.0 } };
};

struct BoundaryCurveResult
{
  /// Output triangles; ids below the input point count are input points, the
  /// rest index NewPoints (id - inputPointCount).
  std::vector<Triangle> Triangles;
  /// The input triangle each output triangle came from.
  std::vector<Id> TriangleSource;
  /// 1 for triangles made by re-meshing, 0 for kept ones.
  std::vector<unsigned char> TriangleIsNew;
  std::vector<glm::dvec3> NewPoints;
  std::vector<glm::dvec3> NewNormals;
  std::vector<BoundaryCurvePointSource> NewPointSources;
  /// The smoothed silhouette: one polyline (point ids) per silhouette edge.
  std::vector<std::vector<Id>> Curves;
  std::size_t SilhouetteEdgeCount = 0;
  std::size_t RemeshedTriangleCount = 0;
};

/// The view-independent part, built once per input: edge table, the
/// triangles of each edge, unit shading normals.
class BoundaryCurveMesh
{
public:
  /// `normals` may be empty (angle-weighted normals are computed); zero or
  /// non-finite given normals are replaced by the computed ones.
  BoundaryCurveMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
    const std::vector<glm::dvec3>& normals);

  const std::vector<glm::dvec3>& points() const { return this->Points; }
  const std::vector<Triangle>& triangles() const { return this->Triangles; }
  const std::vector<glm::dvec3>& normals() const { return this->Normals; }

  /// One frame. `normalToEye` takes model normals to eye coordinates (the
  /// inverse transpose of the model-view matrix's 3x3 part).
  BoundaryCurveResult smooth(const ViewGeometry& view, const glm::dmat3& normalToEye,
    const BoundaryCurveParameters& parameters) const;

private:
  // smooth()'s steps.
  std::vector<unsigned char> frontFacing(const ViewGeometry& view) const;
  void curveEdge(std::size_t e, const ViewGeometry& view, const glm::dmat4& clipToModel,
    const glm::dmat3& normalToEye, const BoundaryCurveParameters& parameters,
    std::vector<Id>& edgeCurve, BoundaryCurveResult& result) const;
  void remeshTriangle(
    std::size_t t, const std::vector<Id>& edgeCurve, BoundaryCurveResult& result) const;

  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<glm::dvec3> Normals;
  std::vector<glm::dvec3> FaceNormals;
  EdgeTable Edges;
  /// The two triangles of each edge (-1: none); edges of three or more
  /// triangles are marked non-manifold and never smoothed.
  std::vector<std::array<Id, 2>> EdgeTriangles;
  std::vector<unsigned char> EdgeManifold;
};

} // namespace silsmooth
