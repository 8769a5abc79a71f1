// Lines of a drawing that run over each other (issue 16), found in the
// image so that each stretch of ink is drawn once.
//
// A crease and an intersection curve along one edge, a border that is also
// a crease over part of its length, a thin plate's front and back edges a
// tenth of a pixel apart: in a PNG they are one line, but a pen plotter
// inks each path, and doubled ink shows (a user's trial measured 16% of the
// Wuson's line pixels and 39% of a CAD part's under two paths or more).
//
// The lines are taken in the order given. A point of a line is covered when
// a line taken before it (what is kept of it) passes within Width pixels,
// running within the angle whose cosine is AlongCosine of the point's own
// direction: lines that cross are not covered, only lines that run along.
// What a line keeps is what is not covered, in spans: each span runs from
// the last covered point before it to the first after it, so that a kept
// span ends within Width of the line that covers its neighbour (the
// drawing stays joined). A covered stretch inside a line that is shorter
// than ShortestGap is kept (a shallow crossing: lifting the pen there would
// leave a break for nothing). A span shorter than twice Width between two
// covered stretches is left out (it only wavers beside the line covering
// both sides). And a speck, a span no longer than LongestSpeck that lies
// within Width of kept lines all along, whatever their direction (a stub
// at a corner, a sliver's edge), is left out: a plotter would lower its pen
// on ink already there. Specks are checked again at the end against every
// longer span kept, so one taken before the line it lies on goes too.
//
// Invariants: every kept span lies on its line; no point of a kept span,
// apart from its two ends and the short covered stretches kept, lies
// within Width of an earlier kept span running along it (up to the
// sampling: every quarter of Width, at least a hundredth of a pixel); a
// line that nothing covers is kept whole, as one span from its first point
// to its last. The work is proportional to the lines' length in pixels, so
// lines are clipped to the image first (spansInside): a point just in front
// of the eye projects millions of pixels away.
#pragma once

#include <glm/vec2.hpp>

#include <cstddef>
#include <vector>

namespace silsmooth
{

struct DrawingOverlapParameters
{
  /// Lines whose centres pass within this many pixels draw one line.
  double Width = 1.0;
  /// A covering line's direction is within the angle of this cosine of the
  /// covered point's (about 20 degrees).
  double AlongCosine = 0.94;
  /// A covered stretch inside a line shorter than this many pixels is kept.
  double ShortestGap = 4.0;
  /// A span at most this long lying within Width of kept lines is a speck.
  double LongestSpeck = 2.0;
};

/// A stretch of a polyline between two positions: position i + t lies on
/// the segment from point i to point i + 1, at the fraction t of it.
struct PolylineSpan
{
  std::size_t Line = 0;
  double First = 0.0;
  double Last = 0.0;
};

/// What each of `lines` (image coordinates, pixels) keeps, taken in the
/// order `order` gives (indices into `lines`; a line not named is neither
/// kept nor covers anything). Spans come in that order, and along each
/// line from its start.
std::vector<PolylineSpan> spansNotOverlapping(const std::vector<std::vector<glm::dvec2>>& lines,
  const std::vector<std::size_t>& order, const DrawingOverlapParameters& parameters);

/// The parts of each line inside the rectangle from `low` to `high`
/// (image coordinates), as spans in the order of the lines and along each.
/// A line that touches the rectangle only at a point gives no span, nor
/// does a segment with a coordinate that is not finite.
std::vector<PolylineSpan> spansInside(
  const std::vector<std::vector<glm::dvec2>>& lines, const glm::dvec2& low, const glm::dvec2& high);

/// The length of a polyline (the sum of its segments').
double polylineLength(const std::vector<glm::dvec2>& points);

/// The values along `values` (one per point of a polyline) between two
/// positions of a span, interpolated linearly at its two ends: the points
/// of the span, or any value per point (depths).
template<typename T>
std::vector<T> valuesAlong(const std::vector<T>& values, double first, double last)
{
  std::vector<T> along;
  if (values.empty())
  {
    return along;
  }
  const auto at = [&](double position) {
    const std::size_t i = static_cast<std::size_t>(position);
    if (i + 1 >= values.size())
    {
      return values.back();
    }
    const double t = position - static_cast<double>(i);
    return T(values[i] * (1.0 - t) + values[i + 1] * t);
  };
  along.push_back(at(first));
  for (std::size_t i = static_cast<std::size_t>(first) + 1;
       static_cast<double>(i) < last && i < values.size(); ++i)
  {
    along.push_back(values[i]);
  }
  along.push_back(at(last));
  return along;
}

} // namespace silsmooth
