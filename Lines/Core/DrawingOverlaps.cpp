#include "DrawingOverlaps.h"

#include "BoxInterval.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace silsmooth
{
namespace
{

// A short piece of a kept line, filed under every cell of a grid that lies
// within Width of it.
struct KeptPiece
{
  glm::dvec2 A;
  glm::dvec2 B;
  glm::dvec2 Direction; // unit
};

class KeptLines
{
public:
  explicit KeptLines(const DrawingOverlapParameters& parameters)
    : Parameters(parameters)
    , Cell(std::max(4.0 * parameters.Width, 1.0))
  {
  }

  /// Files the segment from a to b in pieces no longer than a cell, so that
  /// each lies in a few cells whatever the segment's length.
  void add(const glm::dvec2& a, const glm::dvec2& b)
  {
    const double length = glm::distance(a, b);
    if (!(length > 0.0))
    {
      return;
    }
    const glm::dvec2 direction = (b - a) / length;
    const int pieces = static_cast<int>(std::ceil(length / Cell));
    for (int k = 0; k < pieces; ++k)
    {
      const KeptPiece piece{ a + (b - a) * (double(k) / pieces),
        a + (b - a) * (double(k + 1) / pieces), direction };
      const double w = Parameters.Width;
      const std::int64_t x0 = cellOf(std::min(piece.A.x, piece.B.x) - w);
      const std::int64_t x1 = cellOf(std::max(piece.A.x, piece.B.x) + w);
      const std::int64_t y0 = cellOf(std::min(piece.A.y, piece.B.y) - w);
      const std::int64_t y1 = cellOf(std::max(piece.A.y, piece.B.y) + w);
      for (std::int64_t x = x0; x <= x1; ++x)
      {
        for (std::int64_t y = y0; y <= y1; ++y)
        {
          Cells[key(x, y)].push_back(piece);
        }
      }
    }
  }

  /// Whether a kept piece passes within Width of p, running along `direction`
  /// unless `anyDirection`.
  bool covers(const glm::dvec2& p, const glm::dvec2& direction, bool anyDirection = false) const
  {
    const auto found = Cells.find(key(cellOf(p.x), cellOf(p.y)));
    if (found == Cells.end())
    {
      return false;
    }
    const double width2 = Parameters.Width * Parameters.Width;
    for (const KeptPiece& piece : found->second)
    {
      if (!anyDirection && std::abs(glm::dot(piece.Direction, direction)) < Parameters.AlongCosine)
      {
        continue;
      }
      const glm::dvec2 ab = piece.B - piece.A;
      const double t = std::clamp(glm::dot(p - piece.A, ab) / glm::dot(ab, ab), 0.0, 1.0);
      const glm::dvec2 offset = p - (piece.A + ab * t);
      if (glm::dot(offset, offset) <= width2)
      {
        return true;
      }
    }
    return false;
  }

private:
  std::int64_t cellOf(double v) const { return static_cast<std::int64_t>(std::floor(v / Cell)); }
  static std::uint64_t key(std::int64_t x, std::int64_t y)
  {
    return (static_cast<std::uint64_t>(x) << 32) ^ (static_cast<std::uint64_t>(y) & 0xffffffffu);
  }

  const DrawingOverlapParameters& Parameters;
  const double Cell;
  std::unordered_map<std::uint64_t, std::vector<KeptPiece>> Cells;
};

// A point of a line at which coverage is judged: its position along the
// line (segment index + fraction), where it lies, and how far along the
// line (pixels).
struct Sample
{
  double Position;
  glm::dvec2 Point;
  double Arc;
  bool Covered;
};

// Calls visit(position, point, direction, arc) along `line` every quarter
// of Width (at least 0.01 px): from each segment's start, then at the last
// point. `position` is the point's place as PolylineSpan counts (segment
// index plus fraction), `arc` its distance along the line, `direction` its
// segment's (the last one of length, (1, 0) before any).
template<typename Visit>
void forEachSample(
  const std::vector<glm::dvec2>& line, const DrawingOverlapParameters& parameters, Visit visit)
{
  const double step = std::max(0.25 * parameters.Width, 0.01);
  double arc = 0.0;
  glm::dvec2 direction(1.0, 0.0);
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
  {
    const double length = glm::distance(line[i], line[i + 1]);
    if (length > 0.0)
    {
      direction = (line[i + 1] - line[i]) / length;
    }
    const int count = std::max(1, static_cast<int>(std::ceil(length / step)));
    for (int k = 0; k < count; ++k)
    {
      const double t = double(k) / count;
      visit(double(i) + t, line[i] + (line[i + 1] - line[i]) * t, direction, arc + length * t);
    }
    arc += length;
  }
  if (!line.empty())
  {
    visit(double(line.size() - 1), line.back(), direction, arc);
  }
}

std::vector<Sample> samplesOf(const std::vector<glm::dvec2>& line, const KeptLines& kept,
  const DrawingOverlapParameters& parameters)
{
  std::vector<Sample> samples;
  forEachSample(line, parameters,
    [&](double position, const glm::dvec2& p, const glm::dvec2& direction, double arc) {
      samples.push_back({ position, p, arc, kept.covers(p, direction) });
    });
  return samples;
}

// Covered stretches inside the line (not at its ends) shorter than
// ShortestGap are kept: they are crossings, not lines drawn twice.
void keepShortCoveredStretches(std::vector<Sample>& samples, double shortestGap)
{
  std::size_t i = 0;
  while (i < samples.size())
  {
    if (!samples[i].Covered)
    {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < samples.size() && samples[j + 1].Covered)
    {
      ++j;
    }
    const bool inside = i > 0 && j + 1 < samples.size();
    if (inside && samples[j].Arc - samples[i].Arc < shortestGap)
    {
      for (std::size_t k = i; k <= j; ++k)
      {
        samples[k].Covered = false;
      }
    }
    i = j + 1;
  }
}

// The specks checked again, against every longer span kept: a speck taken
// early (a silhouette's, before the creases) had no ink to lie on yet.
std::vector<PolylineSpan> withoutSpecks(const std::vector<std::vector<glm::dvec2>>& lines,
  std::vector<PolylineSpan> spans, const DrawingOverlapParameters& parameters)
{
  std::vector<std::vector<glm::dvec2>> points(spans.size());
  std::vector<unsigned char> speck(spans.size(), 0);
  KeptLines longer(parameters);
  for (std::size_t s = 0; s < spans.size(); ++s)
  {
    points[s] = valuesAlong(lines[spans[s].Line], spans[s].First, spans[s].Last);
    speck[s] = polylineLength(points[s]) <= parameters.LongestSpeck ? 1 : 0;
    for (std::size_t k = 0; k + 1 < points[s].size() && !speck[s]; ++k)
    {
      longer.add(points[s][k], points[s][k + 1]);
    }
  }
  std::vector<PolylineSpan> kept;
  for (std::size_t s = 0; s < spans.size(); ++s)
  {
    bool onInk = speck[s] != 0;
    if (onInk)
    {
      forEachSample(
        points[s], parameters, [&](double, const glm::dvec2& p, const glm::dvec2&, double) {
          onInk = onInk && longer.covers(p, glm::dvec2(0.0), true);
        });
    }
    if (!onInk)
    {
      kept.push_back(spans[s]);
    }
  }
  return kept;
}

} // namespace

double polylineLength(const std::vector<glm::dvec2>& points)
{
  double length = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k)
  {
    length += glm::distance(points[k], points[k + 1]);
  }
  return length;
}

std::vector<PolylineSpan> spansInside(
  const std::vector<std::vector<glm::dvec2>>& lines, const glm::dvec2& low, const glm::dvec2& high)
{
  std::vector<PolylineSpan> spans;
  for (std::size_t index = 0; index < lines.size(); ++index)
  {
    const std::vector<glm::dvec2>& line = lines[index];
    bool open = false; // a span runs on from the last segment
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
    {
      const auto [enter, leave] = lineInBox(line[i], line[i + 1] - line[i], low, high, 0.0, 1.0);
      const bool finite = std::isfinite(line[i].x + line[i].y + line[i + 1].x + line[i + 1].y);
      if (!finite || !(enter < leave))
      {
        open = false;
        continue;
      }
      if (open && enter == 0.0)
      {
        spans.back().Last = double(i) + leave;
      }
      else
      {
        spans.push_back({ index, double(i) + enter, double(i) + leave });
      }
      open = leave == 1.0;
    }
  }
  return spans;
}

std::vector<PolylineSpan> spansNotOverlapping(const std::vector<std::vector<glm::dvec2>>& lines,
  const std::vector<std::size_t>& order, const DrawingOverlapParameters& parameters)
{
  std::vector<PolylineSpan> spans;
  if (!(parameters.Width > 0.0))
  {
    // Nothing covers anything.
    for (const std::size_t index : order)
    {
      if (lines[index].size() >= 2)
      {
        spans.push_back({ index, 0.0, double(lines[index].size() - 1) });
      }
    }
    return spans;
  }
  KeptLines kept(parameters);
  for (const std::size_t index : order)
  {
    const std::vector<glm::dvec2>& line = lines[index];
    if (line.size() < 2)
    {
      continue;
    }
    std::vector<Sample> samples = samplesOf(line, kept, parameters);
    keepShortCoveredStretches(samples, parameters.ShortestGap);
    const std::size_t firstSpan = spans.size();
    std::size_t i = 0;
    while (i < samples.size())
    {
      if (samples[i].Covered)
      {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j + 1 < samples.size() && !samples[j + 1].Covered)
      {
        ++j;
      }
      // From the covered sample before the run to the one after it.
      const std::size_t from = i > 0 ? i - 1 : i;
      const std::size_t to = j + 1 < samples.size() ? j + 1 : j;
      const bool between = i > 0 && j + 1 < samples.size();
      const double length = samples[to].Arc - samples[from].Arc;
      const bool waver = between && length < 2.0 * parameters.Width;
      const bool speck = length <= parameters.LongestSpeck &&
        std::all_of(samples.begin() + std::ptrdiff_t(from),
          samples.begin() + std::ptrdiff_t(to) + 1,
          [&](const Sample& sample) { return kept.covers(sample.Point, glm::dvec2(0.0), true); });
      if (!waver && !speck && samples[to].Position > samples[from].Position)
      {
        spans.push_back({ index, samples[from].Position, samples[to].Position });
      }
      i = j + 1;
    }
    // Filed once the line is done: a line does not cover itself.
    for (std::size_t s = firstSpan; s < spans.size(); ++s)
    {
      const std::vector<glm::dvec2> points = valuesAlong(line, spans[s].First, spans[s].Last);
      for (std::size_t k = 0; k + 1 < points.size(); ++k)
      {
        kept.add(points[k], points[k + 1]);
      }
    }
  }
  return withoutSpecks(lines, std::move(spans), parameters);
}

} // namespace silsmooth
