// Chains per-triangle silhouette segments into polylines across triangles:
// consecutive segments share the silhouette point of the edge between their
// triangles. Closed silhouette loops come out as polylines whose last id
// equals their first.
#pragma once

#include "MeshTopology.h"

#include <vector>

namespace silsmooth
{

/// Each segment is a list of point ids from one end to the other (at least
/// two). Chains stop where an end is shared by other than two segments.
std::vector<std::vector<Id>> chainSegments(const std::vector<std::vector<Id>>& segments);

} // namespace silsmooth
