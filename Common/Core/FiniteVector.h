// Whether a point or vector has finite coordinates: the test every unit that
// takes points from a file makes before it measures them (a NaN compares
// false with everything, and an infinity overflows what it meets).
#pragma once

#include <glm/vec3.hpp>

#include <cmath>

namespace silsmooth
{

inline bool isFinite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace silsmooth
