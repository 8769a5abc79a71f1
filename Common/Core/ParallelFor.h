// How the core runs a loop in parallel without knowing VTK: the caller
// injects the loop (the VTK adapters pass vtkSMPTools). Every user of it
// writes each index's result in a slot of its own, so results are the same
// bit for bit whatever the split and the thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace silsmooth
{

/// Runs body(begin, end) over sub-ranges covering [0, count). The VTK adapter
/// passes vtkSMPTools; the default is a plain loop. Results never depend on
/// how the range is split.
using ParallelFor =
  std::function<void(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)>;
inline void serialFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)
{
  if (count > 0)
  {
    body(0, count);
  }
}

} // namespace silsmooth
