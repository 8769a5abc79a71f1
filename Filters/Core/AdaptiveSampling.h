// How many points to sample on a silhouette segment so that the polyline
// through them stays within a pixel tolerance of the curve (Wang et al. 2008,
// III-E).
//
// Two rules are offered. The paper's eq. 8, n = ceil(1/2 sqrt(h r / e)) with
// r = sin(alpha/2), under-samples: on the 80-triangle unit sphere at 1024 px
// and e = 0.5 px it gives 2 points to most segments and leaves the outline up
// to about 5 px off (the benchmark `silhouette_sampling_bench` and the test
// `SamplingRules` measure this). The default rule is the circular-arc bound:
// a circular arc of sagitta h cut into k equal pieces has a chord error of
// about h / k^2, so k >= sqrt(h / e) pieces (k + 1 points) keep the error
// within e. The sagitta h is measured in pixels after projection.
#pragma once

#include "HermiteCurve.h"
#include "ViewGeometry.h"

namespace silsmooth
{

enum class SamplingRule
{
  ArcBound,     ///< k >= sqrt(h / e) pieces; keeps the tolerance (default)
  WangEquation8 ///< the paper's eq. 8 as printed; kept for comparison
};

/// Safety factor on the sagitta in the arc bound (see AdaptiveSampling.cpp).
constexpr double ArcBoundMargin = 1.25;

struct SamplingParameters
{
  double TolerancePixels = 0.5;
  /// Points per segment, counting both ends (2 = the straight chord).
  int MinimumSamples = 2;
  int MaximumSamples = 256;
  SamplingRule Rule = SamplingRule::ArcBound;
};

/// The height of the segment in pixels: the distance between the projections
/// of S(1/2) and of the chord's midpoint. Negative when a point cannot be
/// projected (it lies on or behind the eye plane).
double projectedSagittaPixels(const HermiteCurve& segment, const ViewGeometry& view);

/// The number of sample points (both ends included) for `segment`, whose end
/// normals are n0 and n1 (unit), clamped to [MinimumSamples, MaximumSamples].
/// A segment that crosses the eye plane gets MaximumSamples.
int silhouetteSampleCount(const HermiteCurve& segment, const glm::dvec3& n0, const glm::dvec3& n1,
  const ViewGeometry& view, const SamplingParameters& parameters);

} // namespace silsmooth
