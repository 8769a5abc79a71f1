// Surface options for the smoothing core's tests of welded surfaces.
#pragma once

#include "WeldedSurface.h"

namespace coretest
{

/// Surface options without the flat-sided crease detection, for meshes
/// whose creases the tests name themselves.
inline silsmooth::SurfaceOptions plainOptions()
{
  silsmooth::SurfaceOptions options;
  options.DetectFlatCreases = false;
  return options;
}

} // namespace coretest
