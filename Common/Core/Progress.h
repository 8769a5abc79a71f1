// Progress from inside the core's long loops, and the caller's way to stop
// them (VTK's AbortExecute): a callback that takes the fraction done, in
// [0, 1], and returns false to stop the work. The loops call it every so
// many steps, not every step, so that it costs nothing measurable; an
// empty callback never stops them.
#pragma once

#include <functional>

namespace silsmooth
{

using ProgressCallback = std::function<bool(double fraction)>;

/// Calls `progress` (when set) with `fraction`; returns whether to go on.
inline bool reportProgress(const ProgressCallback& progress, double fraction)
{
  return !progress || progress(fraction);
}

} // namespace silsmooth
