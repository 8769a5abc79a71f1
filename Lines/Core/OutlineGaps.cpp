#include "OutlineGaps.h"

#include "SilhouettePolylines.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <unordered_map>

namespace silsmooth
{

namespace
{

/// The drawn lines' segments in pixels, filed by the square cells of the
/// viewport (widened by a cell) their boxes meet, to ask whether a drawn
/// line covers a pixel (covers).
class DrawnSegments
{
public:
  DrawnSegments(const ViewGeometry& view, const std::vector<std::vector<glm::dvec3>>& drawn,
    double radius, double alongsideCosine)
    : AlongsideCosine(alongsideCosine)
    , Cell(std::max(4.0 * radius, 8.0))
    , Columns(static_cast<std::int64_t>(std::ceil(view.ViewportWidth / this->Cell)) + 2)
    , Rows(static_cast<std::int64_t>(std::ceil(view.ViewportHeight / this->Cell)) + 2)
  {
    for (std::size_t index = 0; index < drawn.size(); ++index)
    {
      const std::vector<glm::dvec3>& line = drawn[index];
      const std::size_t n = line.size();
      const bool closed = n > 2 && line.front() == line.back();
      glm::dvec2 previous;
      bool havePrevious = false;
      for (std::size_t i = 0; i < n; ++i)
      {
        glm::dvec2 pixel;
        const bool projected = view.toPixels(line[i], pixel);
        if (projected && havePrevious)
        {
          this->file({ previous, pixel, line[i - 1], line[i], !closed && i == 1,
            !closed && i + 1 == n, index });
        }
        previous = pixel;
        havePrevious = projected;
      }
    }
  }

  /// Whether a drawn line covers `pixel` on a contour running along
  /// `contour` (pixels, unit): some drawn point lies within `join` of it, or a
  /// drawn line runs alongside it within `beside`: the line's nearest point
  /// not one of its ends (not the end of one that stops short; judged over
  /// the whole line, since beyond its end a segment before the last has its
  /// nearest point at a vertex inside the line) and the segment it lies on
  /// within the angle of alongsideCosine of the contour's direction (not one
  /// that meets or crosses it).
  bool covers(const glm::dvec2& pixel, const glm::dvec2& contour, double join, double beside) const
  {
    struct Nearest
    {
      std::size_t Line;
      double Distance;
      bool Alongside; ///< not at an end of the line, and along the contour
    };
    std::vector<Nearest> nearest; // per line near
    const bool joined = this->anySegmentNear(
      pixel, std::max(join, beside), [&](const Segment& segment, double along, double distance) {
        if (distance <= join)
        {
          return true;
        }
        if (distance > beside)
        {
          return false;
        }
        const glm::dvec2 ab = segment.B - segment.A;
        const bool atAnEnd =
          (along <= 0.0 && segment.StartsLine) || (along >= 1.0 && segment.EndsLine);
        const bool alongside =
          !atAnEnd && std::abs(glm::dot(ab, contour)) >= this->AlongsideCosine * glm::length(ab);
        auto line = std::find_if(
          nearest.begin(), nearest.end(), [&](const Nearest& n) { return n.Line == segment.Line; });
        if (line == nearest.end())
        {
          nearest.push_back({ segment.Line, distance, alongside });
        }
        else if (std::abs(distance - line->Distance) <= 1e-9)
        {
          // A vertex inside the line, the nearest point of both segments
          // there: alongside when either runs along the contour.
          line->Alongside = line->Alongside || alongside;
        }
        else if (distance < line->Distance)
        {
          *line = { segment.Line, distance, alongside };
        }
        return false;
      });
    return joined ||
      std::any_of(nearest.begin(), nearest.end(), [](const Nearest& n) { return n.Alongside; });
  }

  /// The drawn point nearest `pixel`, within `reach` pixels, in model
  /// coordinates (interpolated along its segment as in the image), or no
  /// value; where that point lies within `snap` pixels of an end of an open
  /// line, that end itself, bit for bit (paths and strokes join where ends
  /// are equal). Ties go to the segment looked at first.
  std::optional<glm::dvec3> nearest(const glm::dvec2& pixel, double reach, double snap) const
  {
    const Segment* closest = nullptr;
    double closestAlong = 0.0;
    double best = reach;
    this->anySegmentNear(pixel, reach, [&](const Segment& segment, double along, double distance) {
      if (distance < best || (!closest && distance <= reach))
      {
        best = distance;
        closest = &segment;
        closestAlong = along;
      }
      return false; // every segment near
    });
    if (!closest)
    {
      return std::nullopt;
    }
    const Segment& segment = *closest;
    const glm::dvec2 at = segment.A + closestAlong * (segment.B - segment.A);
    if (segment.StartsLine && glm::length(at - segment.A) <= snap)
    {
      return segment.ModelA;
    }
    if (segment.EndsLine && glm::length(at - segment.B) <= snap)
    {
      return segment.ModelB;
    }
    return segment.ModelA + closestAlong * (segment.ModelB - segment.ModelA);
  }

  /// The drawn lines with a segment within `radius` pixels of `pixel`,
  /// ascending.
  std::vector<std::size_t> linesNear(const glm::dvec2& pixel, double radius) const
  {
    std::vector<std::size_t> lines;
    this->anySegmentNear(pixel, radius, [&](const Segment& segment, double, double distance) {
      if (distance <= radius)
      {
        lines.push_back(segment.Line);
      }
      return false;
    });
    std::sort(lines.begin(), lines.end());
    lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    return lines;
  }

  /// An end of an open drawn line: 2 * line + (0: its first point, 1: its
  /// last), and where it is in the image.
  using LineEnd = std::pair<std::size_t, glm::dvec2>;

  /// The ends of open drawn lines within `radius` pixels of `pixel`.
  std::vector<LineEnd> lineEndsNear(const glm::dvec2& pixel, double radius) const
  {
    std::vector<LineEnd> ends;
    this->anySegmentNear(pixel, radius, [&](const Segment& segment, double, double) {
      if (segment.StartsLine && glm::length(pixel - segment.A) <= radius)
      {
        ends.emplace_back(2 * segment.Line, segment.A);
      }
      if (segment.EndsLine && glm::length(pixel - segment.B) <= radius)
      {
        ends.emplace_back(2 * segment.Line + 1, segment.B);
      }
      return false;
    });
    return ends;
  }

  /// Whether an open drawn line has an end within `radius` pixels of `pixel`.
  bool lineEndNear(const glm::dvec2& pixel, double radius) const
  {
    return !this->lineEndsNear(pixel, radius).empty();
  }

  /// Whether the stretch from `first` to `last` bridges a break between two
  /// drawn lines' ends (or a line's two ends): one within `radius` of
  /// `first`, the other within `radius` of `last`, at least `wide` apart (a
  /// narrower break the line's own width covers).
  bool bridgesBreak(
    const glm::dvec2& first, const glm::dvec2& last, double radius, double wide) const
  {
    const std::vector<LineEnd> before = this->lineEndsNear(first, radius);
    const std::vector<LineEnd> after = this->lineEndsNear(last, radius);
    for (const LineEnd& a : before)
    {
      for (const LineEnd& b : after)
      {
        if (a.first != b.first && glm::length(a.second - b.second) >= wide)
        {
          return true;
        }
      }
    }
    return false;
  }

  /// Whether drawn line `line` has a segment within `radius` pixels of `pixel`.
  bool lineNear(const glm::dvec2& pixel, std::size_t line, double radius) const
  {
    return this->anySegmentNear(
      pixel, radius, [&](const Segment& segment, double, double distance) {
        return segment.Line == line && distance <= radius;
      });
  }

private:
  struct Segment
  {
    glm::dvec2 A;
    glm::dvec2 B;
    glm::dvec3 ModelA; ///< A in model coordinates
    glm::dvec3 ModelB;
    bool StartsLine;  ///< A is the first point of an open drawn line
    bool EndsLine;    ///< B is its last
    std::size_t Line; ///< the drawn line's index
  };

  /// Calls `visit(segment, along, distance)` for the segments filed in the
  /// cells within `radius` of `pixel` (`along` the nearest point's fraction
  /// of the segment, `distance` its distance in pixels; a segment filed in
  /// several cells may be visited more than once) until it returns true;
  /// returns whether it did.
  template<typename Visit>
  bool anySegmentNear(const glm::dvec2& pixel, double radius, Visit visit) const
  {
    for (std::int64_t r = this->row(pixel.y - radius); r <= this->row(pixel.y + radius); ++r)
    {
      for (std::int64_t c = this->column(pixel.x - radius); c <= this->column(pixel.x + radius);
           ++c)
      {
        const auto filed = this->Filed.find(r * this->Columns + c);
        if (filed == this->Filed.end())
        {
          continue;
        }
        for (const std::size_t s : filed->second)
        {
          const Segment& segment = this->Segments[s];
          const glm::dvec2 ab = segment.B - segment.A;
          const double squared = glm::dot(ab, ab);
          const double along =
            squared > 0.0 ? std::clamp(glm::dot(pixel - segment.A, ab) / squared, 0.0, 1.0) : 0.0;
          if (visit(segment, along, glm::length(pixel - (segment.A + along * ab))))
          {
            return true;
          }
        }
      }
    }
    return false;
  }

  /// Cells of the viewport widened by one cell; beyond, the border cells
  /// (a segment or point out there is filed or looked for at the border).
  std::int64_t column(double x) const
  {
    const double c = std::floor(x / this->Cell) + 1.0;
    return static_cast<std::int64_t>(std::clamp(c, 0.0, static_cast<double>(this->Columns - 1)));
  }
  std::int64_t row(double y) const
  {
    const double r = std::floor(y / this->Cell) + 1.0;
    return static_cast<std::int64_t>(std::clamp(r, 0.0, static_cast<double>(this->Rows - 1)));
  }

  void file(const Segment& segment)
  {
    const glm::dvec2& a = segment.A;
    const glm::dvec2& b = segment.B;
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
    {
      return;
    }
    const std::size_t index = this->Segments.size();
    this->Segments.push_back(segment);
    // By the segment's box, clamped to the widened viewport: a long
    // diagonal is filed in more cells than it passes, never fewer.
    for (std::int64_t r = this->row(std::min(a.y, b.y)); r <= this->row(std::max(a.y, b.y)); ++r)
    {
      for (std::int64_t c = this->column(std::min(a.x, b.x)); c <= this->column(std::max(a.x, b.x));
           ++c)
      {
        this->Filed[r * this->Columns + c].push_back(index);
      }
    }
  }

  double AlongsideCosine;
  double Cell;
  std::int64_t Columns;
  std::int64_t Rows;
  std::vector<Segment> Segments;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> Filed;
};

/// The stretches of `polyline` where `holds(point, direction)` is true
/// (splitWhere's pieces in that state); on a closed loop, a stretch through
/// its first point is one stretch.
template<typename Holds>
std::vector<std::vector<glm::dvec3>> stretchesWhere(
  const std::vector<glm::dvec3>& polyline, double spacing, double precision, Holds holds)
{
  std::vector<std::vector<glm::dvec3>> stretches;
  if (polyline.size() < 2)
  {
    return stretches;
  }
  std::vector<LinePiece> pieces = splitWhere(polyline, spacing, precision, holds);
  const bool closed = polyline.front() == polyline.back();
  if (closed && pieces.size() > 2 && pieces.front().Visible && pieces.back().Visible)
  {
    std::vector<glm::dvec3>& last = pieces.back().Points;
    last.insert(last.end(), pieces.front().Points.begin() + 1, pieces.front().Points.end());
    pieces.front().Points = std::move(last);
    pieces.pop_back();
  }
  for (LinePiece& piece : pieces)
  {
    if (piece.Visible)
    {
      stretches.push_back(std::move(piece.Points));
    }
  }
  return stretches;
}

} // namespace

std::vector<std::vector<glm::dvec3>> contourPolylines(
  const OcclusionMesh& surface, const ViewGeometry& view)
{
  std::vector<std::vector<Id>> segments;
  for (const std::array<Id, 2>& edge : surface.contourEdges(view))
  {
    segments.push_back({ edge[0], edge[1] });
  }
  std::vector<std::vector<glm::dvec3>> polylines;
  for (const std::vector<Id>& chain : chainSegments(segments))
  {
    std::vector<glm::dvec3>& polyline = polylines.emplace_back();
    polyline.reserve(chain.size());
    for (const Id point : chain)
    {
      polyline.push_back(surface.position(point));
    }
  }
  return polylines;
}

std::vector<std::vector<glm::dvec3>> outlineGaps(const OcclusionMesh& surface,
  const ViewGeometry& view, const std::vector<std::vector<glm::dvec3>>& drawn,
  const OutlineGapParameters& parameters)
{
  std::vector<std::vector<glm::dvec3>> gaps;
  const double join = std::min(parameters.JoinPixels, parameters.GapPixels);
  if (!(join > 0.0) || !(parameters.BesidePixels > 0.0))
  {
    return gaps;
  }
  const DrawnSegments drawnSegments(view, drawn, parameters.GapPixels, parameters.AlongsideCosine);
  const LineVisibilityParameters& rule = parameters.Visibility;
  auto inViewport = [&](const glm::dvec2& pixel) {
    return pixel.x >= 0.0 && pixel.y >= 0.0 && pixel.x <= view.ViewportWidth &&
      pixel.y <= view.ViewportHeight;
  };
  // The contour's direction in the image at a point on a segment along
  // `direction` (zero where it has none).
  auto alongInPixels = [&](const glm::dvec3& point, const glm::dvec3& direction,
                         const glm::dvec2& pixel) {
    glm::dvec2 ahead;
    if (!view.toPixels(point + 1e-3 * direction, ahead) || !(glm::length(ahead - pixel) > 0.0))
    {
      return glm::dvec2(0.0);
    }
    return glm::normalize(ahead - pixel);
  };
  // Cheapest first: the image's drawn lines, then the rays.
  auto open = [&](const glm::dvec3& point, const glm::dvec3& direction) {
    glm::dvec2 pixel;
    return view.toPixels(point, pixel) && inViewport(pixel) &&
      !drawnSegments.covers(
        pixel, alongInPixels(point, direction, pixel), join, parameters.GapPixels) &&
      surface.occlusion(view, point, rule) != OcclusionMesh::Occlusion::Hidden &&
      surface.besideTheOutline(
        view, point, direction, parameters.BesidePixels, parameters.DepthJump, rule.Contact);
  };
  auto bridges = [&](const std::vector<glm::dvec3>& gap) {
    glm::dvec2 first;
    glm::dvec2 last;
    return gap.size() >= 2 && view.toPixels(gap.front(), first) &&
      view.toPixels(gap.back(), last) && drawnSegments.bridgesBreak(first, last, 2.0 * join, join);
  };
  for (const std::vector<glm::dvec3>& contour : contourPolylines(surface, view))
  {
    for (std::vector<glm::dvec3>& gap :
      stretchesWhere(contour, rule.SampleSpacing, rule.Precision, open))
    {
      // A shorter stretch is a speck, unless it lies in a break between two
      // lines' ends: a break of up to about three times `join` leaves only
      // such a stretch open (the bunny's ear tip at 400 x 300, 3.5 px).
      if (pixelLength(gap, view) >= join || bridges(gap))
      {
        gaps.push_back(std::move(gap));
      }
    }
  }
  return gaps;
}

std::vector<std::vector<glm::dvec3>> withoutDetours(std::vector<std::vector<glm::dvec3>> gaps,
  const ViewGeometry& view, const std::vector<std::vector<glm::dvec3>>& drawn, double pixels,
  double share)
{
  const DrawnSegments drawnSegments(view, drawn, pixels, 1.0);
  std::vector<std::vector<glm::dvec3>> kept;
  for (std::vector<glm::dvec3>& gap : gaps)
  {
    std::vector<glm::dvec2> image;
    for (const glm::dvec3& point : gap)
    {
      glm::dvec2 pixel;
      if (!view.toPixels(point, pixel))
      {
        break;
      }
      image.push_back(pixel);
    }
    const bool open = gap.size() >= 2 && gap.front() != gap.back() && image.size() == gap.size();
    double length = 0.0;
    for (std::size_t i = 1; i < image.size(); ++i)
    {
      length += glm::length(image[i] - image[i - 1]);
    }
    const double within = std::max(pixels, share * length);
    // Both ends by one line (where the gap stopped, it came within the
    // distance that covers the contour), then every pixel of the gap within
    // `within` of it.
    // A gap with a drawn line ending by either of its ends continues that
    // line: it bridges a break (such as one between two visible pieces of a
    // silhouette), however near another line runs.
    std::vector<std::size_t> candidates;
    if (open && std::isfinite(length) && !drawnSegments.lineEndNear(image.front(), pixels) &&
      !drawnSegments.lineEndNear(image.back(), pixels))
    {
      const std::vector<std::size_t> first = drawnSegments.linesNear(image.front(), pixels);
      const std::vector<std::size_t> last = drawnSegments.linesNear(image.back(), pixels);
      std::set_intersection(
        first.begin(), first.end(), last.begin(), last.end(), std::back_inserter(candidates));
    }
    bool detour = false;
    for (const std::size_t line : candidates)
    {
      detour = true;
      for (std::size_t i = 0; detour && i + 1 < image.size(); ++i)
      {
        const glm::dvec2 step = image[i + 1] - image[i];
        const int samples = std::max(1, static_cast<int>(std::ceil(glm::length(step))));
        for (int k = 0; detour && k <= samples; ++k)
        {
          detour = drawnSegments.lineNear(
            image[i] + (static_cast<double>(k) / samples) * step, line, within);
        }
      }
      if (detour)
      {
        break;
      }
    }
    if (!detour)
    {
      kept.push_back(std::move(gap));
    }
  }
  return kept;
}

std::vector<std::vector<glm::dvec3>> joinedToDrawnLines(std::vector<std::vector<glm::dvec3>> gaps,
  const ViewGeometry& view, const std::vector<std::vector<glm::dvec3>>& drawn, double reach)
{
  const DrawnSegments drawnSegments(view, drawn, reach, 1.0);
  // Within half a pixel of a line's end, the gap joins that end exactly: a
  // point a hair from it (6e-7 of a unit on the coarse bunny's ear tip)
  // kept a brush's strokes apart there.
  constexpr double snap = 0.5;
  for (std::vector<glm::dvec3>& gap : gaps)
  {
    if (gap.size() < 2 || gap.front() == gap.back())
    {
      continue; // a closed loop has no ends
    }
    glm::dvec2 pixel;
    if (view.toPixels(gap.back(), pixel))
    {
      if (const auto to = drawnSegments.nearest(pixel, reach, snap))
      {
        gap.push_back(*to);
      }
    }
    if (view.toPixels(gap.front(), pixel))
    {
      if (const auto to = drawnSegments.nearest(pixel, reach, snap))
      {
        gap.insert(gap.begin(), *to);
      }
    }
  }
  return gaps;
}

} // namespace silsmooth
