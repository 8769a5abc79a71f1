#include "DistanceTransform.h"

#include <algorithm>
#include <limits>

namespace silsmooth
{

std::vector<std::int32_t> chamferDistance34(
  const std::vector<unsigned char>& object, int width, int height)
{
  constexpr std::int32_t Edge = 3;
  constexpr std::int32_t Diagonal = 4;
  const std::int32_t infinity = std::numeric_limits<std::int32_t>::max() / 2;
  std::vector<std::int32_t> d(object.size());
  for (std::size_t i = 0; i < object.size(); ++i)
  {
    d[i] = object[i] ? infinity : 0;
  }
  // Outside the image is background (label 0).
  auto at = [&](int x, int y) -> std::int32_t {
    if (x < 0 || y < 0 || x >= width || y >= height)
    {
      return 0;
    }
    return d[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
      static_cast<std::size_t>(x)];
  };
  // Forward: the neighbours already visited are left, upper-left, up, upper-right.
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      std::int32_t& v = d[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
        static_cast<std::size_t>(x)];
      if (v == 0)
      {
        continue;
      }
      v = std::min({ v, at(x - 1, y) + Edge, at(x, y - 1) + Edge, at(x - 1, y - 1) + Diagonal,
        at(x + 1, y - 1) + Diagonal });
    }
  }
  // Backward: right, lower-right, down, lower-left.
  for (int y = height - 1; y >= 0; --y)
  {
    for (int x = width - 1; x >= 0; --x)
    {
      std::int32_t& v = d[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
        static_cast<std::size_t>(x)];
      if (v == 0)
      {
        continue;
      }
      v = std::min({ v, at(x + 1, y) + Edge, at(x, y + 1) + Edge, at(x + 1, y + 1) + Diagonal,
        at(x - 1, y + 1) + Diagonal });
    }
  }
  return d;
}

} // namespace silsmooth
