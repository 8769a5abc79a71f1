#include "ViewGeometry.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace silsmooth
{

bool ViewGeometry::toPixels(const glm::dvec3& point, glm::dvec2& pixel) const
{
  const glm::dvec4 clip = this->ModelToClip * glm::dvec4(point, 1.0);
  // w is the distance along the view axis for perspective and 1 for parallel.
  // Any positive w projects (a model at 1e-150 scale has w near 1e-150).
  if (!(clip.w > 0.0))
  {
    return false;
  }
  pixel.x = (clip.x / clip.w + 1.0) * 0.5 * this->ViewportWidth;
  pixel.y = (clip.y / clip.w + 1.0) * 0.5 * this->ViewportHeight;
  return std::isfinite(pixel.x) && std::isfinite(pixel.y);
}

} // namespace silsmooth
