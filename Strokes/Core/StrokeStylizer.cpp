#include "StrokeStylizer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{

namespace
{

std::uint64_t splitmix64(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// frac(x) in [0, 1); guards the rounding of x - floor(x) up to 1.
double fraction(double x)
{
  const double f = x - std::floor(x);
  return f < 1.0 ? f : 0.0;
}

glm::dvec3 lineOfSight(const StrokeView& view, const glm::dvec3& p)
{
  glm::dvec3 d = view.parallel ? view.direction : p - view.eye;
  const double length = glm::length(d);
  return length > 0.0 ? d / length : glm::dvec3(0.0, 0.0, -1.0);
}

// Adds points on the segments so none is longer than about `spacing`.
std::vector<glm::dvec3> resample(const std::vector<glm::dvec3>& stroke, double spacing)
{
  if (!(spacing > 0.0) || stroke.size() < 2)
  {
    return stroke;
  }
  std::vector<glm::dvec3> out;
  out.push_back(stroke.front());
  for (std::size_t i = 1; i < stroke.size(); ++i)
  {
    const glm::dvec3& a = stroke[i - 1];
    const glm::dvec3& b = stroke[i];
    const double length = glm::distance(a, b);
    const double pieces = std::min(std::ceil(length / spacing), 1.0e5);
    const int n = std::max(1, static_cast<int>(pieces));
    for (int k = 1; k < n; ++k)
    {
      const double t = static_cast<double>(k) / n;
      out.push_back(a + t * (b - a));
    }
    out.push_back(b);
  }
  return out;
}

} // namespace

const char* brushName(Brush brush)
{
  switch (brush)
  {
    case Brush::Lazy:
      return "lazy";
    case Brush::Hand:
      return "hand";
    case Brush::Rough:
      return "rough";
    case Brush::Charcoal:
    default:
      return "charcoal";
  }
}

BrushFunction::BrushFunction(
  const StrokeParameters& parameters, std::uint64_t strokeIndex, std::uint64_t knotPeriod)
  : Parameters(parameters)
  , StrokeIndex(strokeIndex)
  , KnotPeriod(knotPeriod)
{
}

double BrushFunction::noise(std::uint64_t channel, std::uint64_t index) const
{
  std::uint64_t h = splitmix64(this->Parameters.seed);
  h = splitmix64(h ^ this->StrokeIndex);
  h = splitmix64(h ^ (channel * 0x632BE59BD9B4E019ull));
  h = splitmix64(h ^ index);
  // 53 random bits to [0, 1], then [-1, 1]; both ends are reachable exactly.
  const double unit = static_cast<double>(h >> 11) / 9007199254740991.0;
  return 2.0 * unit - 1.0;
}

double BrushFunction::smoothNoise(std::uint64_t channel, double s) const
{
  const double w = this->Parameters.wavelength;
  const double x = w > 0.0 ? std::max(0.0, s / w) : 0.0;
  const double cell = std::floor(x);
  double t = std::clamp(x - cell, 0.0, 1.0);
  t = t * t * (3.0 - 2.0 * t); // smoothstep: weights 1 - t and t, both in [0, 1]
  const auto k = static_cast<std::uint64_t>(std::min(cell, 1.0e15));
  const std::uint64_t period = this->KnotPeriod;
  const double a = this->noise(channel, period > 0 ? k % period : k);
  const double b = this->noise(channel, period > 0 ? (k + 1) % period : k + 1);
  const double value = (1.0 - t) * a + t * b;
  return std::clamp(value, -1.0, 1.0);
}

void BrushFunction::offsets(double s, std::uint64_t pointIndex, double& vx, double& vy) const
{
  const double amplitude = std::abs(this->Parameters.amplitude);
  const double w = this->Parameters.wavelength;
  vx = 0.0;
  vy = 0.0;
  if (amplitude == 0.0 || !std::isfinite(amplitude))
  {
    return; // no amplitude, or none that can be bounded: the stroke unmoved
  }
  switch (this->Parameters.brush)
  {
    case Brush::Charcoal:
    {
      const double f = w > 0.0 ? fraction(s / w) : 0.0;
      vy = amplitude * std::clamp(2.0 * f - 1.0, -1.0, 1.0);
      break;
    }
    case Brush::Lazy:
    {
      const double f = w > 0.0 ? fraction(s / w) : 0.0;
      const double u = 2.0 * f - 1.0;
      vy = amplitude * std::clamp(1.0 - u * u, 0.0, 1.0);
      break;
    }
    case Brush::Hand:
      vx = amplitude * this->smoothNoise(0, s);
      vy = amplitude * this->smoothNoise(1, s);
      break;
    case Brush::Rough:
      vx = amplitude * this->noise(2, pointIndex);
      break;
  }
}

StylizedStroke stylizeStroke(const std::vector<glm::dvec3>& stroke, const StrokeView& view,
  const StrokeParameters& parameters, std::uint64_t strokeIndex)
{
  StylizedStroke result;
  result.base = resample(stroke, parameters.spacing);
  const std::size_t n = result.base.size();
  result.points = result.base;
  result.arcLength.assign(n, 0.0);
  result.tangentOffset.assign(n, 0.0);
  result.normalOffset.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
  {
    result.arcLength[i] =
      result.arcLength[i - 1] + glm::distance(result.base[i - 1], result.base[i]);
  }
  if (n < 2 || !(result.arcLength.back() > 0.0))
  {
    return result;
  }
  const double length = result.arcLength.back();
  const bool closed = n >= 3 && result.base.front() == result.base.back();
  StrokeParameters effective = parameters;
  std::uint64_t knotPeriod = 0;
  if (closed && std::isfinite(length) && parameters.wavelength > 0.0 &&
    std::isfinite(parameters.wavelength))
  {
    const double periods = std::clamp(std::round(length / parameters.wavelength), 1.0, 1.0e15);
    effective.wavelength = length / periods;
    knotPeriod = static_cast<std::uint64_t>(periods);
  }
  // A brush's offsets stay within a quarter of its stroke's length: a short
  // stroke (a speck, a piece of a tuft of lines) moved by the full amplitude
  // became a scribble or a straight spike many times its length (the rough
  // brush moves points along the tangent).
  if (std::isfinite(parameters.amplitude) && std::isfinite(length))
  {
    effective.amplitude =
      std::copysign(std::min(std::abs(parameters.amplitude), ShortStrokeAmplitude * length),
        parameters.amplitude);
  }
  const BrushFunction brush(effective, strokeIndex, knotPeriod);
  for (std::size_t i = 0; i < n; ++i)
  {
    double vx = 0.0;
    double vy = 0.0;
    if (closed && i == n - 1)
    {
      // The last point is the first: same offsets, same position.
      result.tangentOffset[i] = result.tangentOffset[0];
      result.normalOffset[i] = result.normalOffset[0];
      result.points[i] = result.points[0];
      continue;
    }
    brush.offsets(result.arcLength[i], i, vx, vy);
    result.tangentOffset[i] = vx;
    result.normalOffset[i] = vy;
    if (vx == 0.0 && vy == 0.0)
    {
      continue;
    }
    // Tangent by the neighbours (one-sided at the ends of an open stroke,
    // across the seam of a closed one), skipping repeated points.
    std::size_t before = i;
    while (before > 0 && result.base[before] == result.base[i])
    {
      --before;
    }
    std::size_t after = i;
    while (after + 1 < n && result.base[after] == result.base[i])
    {
      ++after;
    }
    if (closed && i == 0)
    {
      before = n - 1;
      while (before > 1 && result.base[before] == result.base[0])
      {
        --before;
      }
    }
    const glm::dvec3 d = lineOfSight(view, result.base[i]);
    glm::dvec3 tangent = result.base[after] - result.base[before];
    tangent -= glm::dot(tangent, d) * d;
    const double tangentLength = glm::length(tangent);
    if (!(tangentLength > 0.0))
    {
      // Stroke along the line of sight here: nothing to offset against.
      result.tangentOffset[i] = 0.0;
      result.normalOffset[i] = 0.0;
      continue;
    }
    tangent /= tangentLength;
    const glm::dvec3 normal = glm::normalize(glm::cross(d, tangent));
    result.points[i] = result.base[i] + vx * tangent + vy * normal;
  }
  return result;
}

} // namespace silsmooth
