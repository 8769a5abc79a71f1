// How many points to sample on a silhouette segment so that the polyline
// through them stays within a pixel tolerance of the curve (Wang et al. 2008,
// III-E).
//
// Two rules are offered. The default bounds the chord error of the projected
// cubic directly: write the segment as a Bezier curve with control points
// b0 = P0, b1 = P0 + T0/3, b2 = P1 - T1/3, b3 = P1, project them to pixels
// (q0..q3) and let M = max(|q0 - 2 q1 + q2|, |q1 - 2 q2 + q3|). The curve's
// second derivative is at most 6 M, and k equal pieces of a curve with
// |S''| <= D deviate from their chords by at most D / (8 k^2), so
// k >= sqrt(0.75 M / e) pieces keep the error within e pixels. The bound is
// exact for parallel projection and close for perspective. An earlier rule
// measured only the sagitta at S(1/2) as if every segment were a circular arc;
// on real meshes 31% of the coarse bunny's segments then missed the tolerance
// (up to 9.9 times), because asymmetric and S-shaped segments are not arcs.
//
// The paper's eq. 8, n = ceil(1/2 sqrt(h r / e)) with r = sin(alpha/2), is kept
// for comparison: it under-samples badly (TestSphereAccuracy measures it).
#pragma once

#include "HermiteCurve.h"
#include "ViewGeometry.h"

namespace silsmooth
{

enum class SamplingRule
{
  SecondDifference, ///< k >= sqrt(0.75 M / e) pieces: keeps the tolerance (default)
  WangEquation8     ///< the paper's eq. 8 as printed; kept for comparison
};

struct SamplingParameters
{
  double TolerancePixels = 0.5;
  /// Points per segment, counting both ends (2 = the straight chord).
  int MinimumSamples = 2;
  int MaximumSamples = 256;
  SamplingRule Rule = SamplingRule::SecondDifference;
};

/// The height of the segment in pixels: the distance between the projections
/// of S(1/2) and of the chord's midpoint (the h of eq. 8). Negative when a
/// point cannot be projected (it lies on or behind the eye plane).
double projectedSagittaPixels(const HermiteCurve& segment, const ViewGeometry& view);

/// M above: the largest second difference of the projected Bezier control
/// points, in pixels. Negative when a control point cannot be projected.
double projectedSecondDifferencePixels(const HermiteCurve& segment, const ViewGeometry& view);

/// The number of sample points (both ends included) for `segment`, whose end
/// normals are n0 and n1 (unit), clamped to [MinimumSamples, MaximumSamples].
/// A segment that reaches behind the eye plane cannot be measured in pixels
/// and is mostly or wholly out of sight: it gets MinimumSamples.
int silhouetteSampleCount(const HermiteCurve& segment, const glm::dvec3& n0, const glm::dvec3& n1,
  const ViewGeometry& view, const SamplingParameters& parameters);

} // namespace silsmooth
