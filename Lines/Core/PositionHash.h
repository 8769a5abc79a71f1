// A hash of a point's exact coordinates, for welding points at one position
// (LineVisibility). -0 and +0 hash alike when the caller
// adds 0.0 first.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <cstring>
#include <functional>

namespace silsmooth
{

struct PositionHash
{
  std::size_t operator()(const glm::dvec3& p) const
  {
    std::size_t seed = 0;
    for (int k = 0; k < 3; ++k)
    {
      std::uint64_t bits = 0;
      const double value = p[k];
      std::memcpy(&bits, &value, sizeof bits);
      seed ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
    }
    return seed;
  }
};

} // namespace silsmooth
