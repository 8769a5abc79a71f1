// Stylized strokes of Kim and Choe, "Stylized Silhouette Rendering Using
// Progressive Meshes" (3.4, 3.5): each stroke (a polyline) is parameterised
// by arc length s and every point p(s) is moved in the view plane,
//
//   q(s) = p(s) + v_x(s) T(s) + v_y(s) N(s),
//
// T the stroke's unit tangent made perpendicular to the line of sight at p,
// N = D x T the unit normal in the view plane (D the unit line of sight).
// The paper's brush functions (Table 1), with what we chose where the text
// is vague:
//
//   charcoal  high-frequency sawtooth across the stroke:
//             v_x = 0, v_y = A (2 frac(s / W) - 1)
//   lazy      low-frequency parabolic arcs across the stroke:
//             v_x = 0, v_y = A (1 - (2 frac(s / W) - 1)^2)
//   hand      low-magnitude noise, normal and tangent: v_x = A n_x(s),
//             v_y = A n_y(s), n value noise in [-1, 1] with a knot every W
//             of arc length and smoothstep interpolation between knots
//   rough     high-magnitude noise along the tangent (Table 1): v_x = A r_i,
//             r_i uniform in [-1, 1] drawn per point; v_y = 0
//
// A is the amplitude and W the wavelength, both lengths in the polylines'
// units (the paper's dist_z scale is the caller's choice: the VTK filter
// gives them as fractions of the input's size). Every offset satisfies
// |v_x| <= A and |v_y| <= A exactly (sawtooth and parabola are in [-1, 1]
// and [0, 1]; noise knots are in [-1, 1] and interpolated by convex weights),
// and A = 0 gives every point back unchanged (as does a non-finite A). The noise is deterministic
// and random-access: each value is the splitmix64 hash of (seed, stroke index, channel, knot or
// point index) turned into a double by hand, so strokes do not depend on the standard library or on
// the order they are made in.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace silsmooth
{

enum class Brush
{
  Charcoal,
  Lazy,
  Hand,
  Rough
};

/// "charcoal", "lazy", "hand", "rough".
const char* brushName(Brush brush);

struct StrokeParameters
{
  Brush brush = Brush::Charcoal;
  double amplitude = 0.01;  ///< A: bound on |v_x| and |v_y|
  double wavelength = 0.05; ///< W: period of sawtooth and parabola, noise knot spacing
  /// When > 0, each stroke is first resampled at about this arc-length
  /// spacing (the input points are kept; points are added on its segments),
  /// so brushes shorter than the input's segments show. 0 keeps the points.
  double spacing = 0.0;
  std::uint64_t seed = 1;
};

/// The line of sight: from `eye` to the point (perspective), or `direction`.
struct StrokeView
{
  bool parallel = false;
  glm::dvec3 eye{ 0.0, 0.0, 1.0 };
  glm::dvec3 direction{ 0.0, 0.0, -1.0 };
};

struct StylizedStroke
{
  std::vector<glm::dvec3> points;    ///< q: the stylized stroke
  std::vector<glm::dvec3> base;      ///< p: the (resampled) input stroke
  std::vector<double> arcLength;     ///< s at each point
  std::vector<double> tangentOffset; ///< v_x at each point
  std::vector<double> normalOffset;  ///< v_y at each point
};

/// The brush's (v_x, v_y) at arc length s, for a noise generator seeded for
/// one stroke. Exposed for tests; `stylizeStroke` is what callers use.
class BrushFunction
{
public:
  /// `knotPeriod` > 0 makes the hand noise repeat every that many knots.
  BrushFunction(
    const StrokeParameters& parameters, std::uint64_t strokeIndex, std::uint64_t knotPeriod = 0);
  /// Offsets of the point with arc length s, the `pointIndex`-th of its stroke.
  void offsets(double s, std::uint64_t pointIndex, double& vx, double& vy) const;

private:
  double noise(std::uint64_t channel, std::uint64_t index) const; // in [-1, 1]
  double smoothNoise(std::uint64_t channel, double s) const;

  StrokeParameters Parameters;
  std::uint64_t StrokeIndex;
  std::uint64_t KnotPeriod;
};

/// The largest amplitude a stroke is drawn with, as a share of its length
/// (ours; the paper does not say): a stroke shorter than 4 A is drawn with
/// A = its length / 4.
constexpr double ShortStrokeAmplitude = 0.25;

/// Stylizes one stroke (`strokeIndex` selects its noise). Strokes of fewer
/// than two distinct points are returned unmoved. A closed stroke (three or
/// more points, the last equal to the first) stays closed without a seam:
/// its wavelength becomes L / m (L its length, m = max(1, round(L / W)), so
/// a whole number of periods fits), the hand noise repeats every m knots,
/// the tangents wrap round, and the last point is the first (same offsets).
/// The amplitude is at most ShortStrokeAmplitude times the stroke's length.
StylizedStroke stylizeStroke(const std::vector<glm::dvec3>& stroke, const StrokeView& view,
  const StrokeParameters& parameters, std::uint64_t strokeIndex);

} // namespace silsmooth
