// Where a line crosses an axis-aligned box, in two or three dimensions.
#pragma once

#include <glm/vector_relational.hpp>

#include <algorithm>
#include <utility>

namespace silsmooth
{

/// The part [enter, leave] of the range [first, last] of t where origin +
/// t dir lies in the box from low to high (Liang and Barsky's slabs): empty
/// (enter > leave, or equal where the line only touches the box) when the
/// line misses it.
template<glm::length_t N>
std::pair<double, double> lineInBox(const glm::vec<N, double>& origin,
  const glm::vec<N, double>& dir, const glm::vec<N, double>& low, const glm::vec<N, double>& high,
  double first, double last)
{
  double enter = first;
  double leave = last;
  for (glm::length_t axis = 0; axis < N; ++axis)
  {
    if (dir[axis] == 0.0)
    {
      if (origin[axis] < low[axis] || origin[axis] > high[axis])
      {
        return { 1.0, 0.0 }; // parallel to the slab and outside it: empty
      }
      continue;
    }
    double t0 = (low[axis] - origin[axis]) / dir[axis];
    double t1 = (high[axis] - origin[axis]) / dir[axis];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return { enter, leave };
}

} // namespace silsmooth
