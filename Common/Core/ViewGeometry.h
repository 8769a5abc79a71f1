// The view as the core sees it, in the mesh's model coordinates: where the eye
// is (or which way the viewer looks, for parallel projection), and how model
// points map to viewport pixels (for the pixel tolerance of the sampling).
#pragma once

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace silsmooth
{

struct ViewGeometry
{
  /// Parallel projection: visibility uses TowardViewer; perspective: Eye.
  bool Parallel = false;
  /// Eye position in model coordinates (perspective).
  glm::dvec3 Eye{ 0.0, 0.0, 1.0 };
  /// Unit vector pointing from the scene towards the viewer (parallel), i.e.
  /// minus the direction of projection, in model coordinates.
  glm::dvec3 TowardViewer{ 0.0, 0.0, 1.0 };
  /// Model coordinates to clip coordinates (projection * view * model).
  glm::dmat4 ModelToClip{ 1.0 };
  /// Viewport size in pixels.
  int ViewportWidth = 1024;
  int ViewportHeight = 768;

  /// D_V of the paper: the direction from V towards the viewer (not unit).
  glm::dvec3 towardViewerFrom(const glm::dvec3& point) const
  {
    return this->Parallel ? this->TowardViewer : this->Eye - point;
  }

  /// The visibility value g(V) = N_V . D_V; V is visible when g >= 0 (paper II).
  /// Inline: the visibility pass calls it for every vertex every frame.
  double visibility(const glm::dvec3& point, const glm::dvec3& normal) const
  {
    return glm::dot(normal, this->towardViewerFrom(point));
  }

  /// Projects a model point to viewport pixels. Returns false when the point
  /// is on or behind the eye plane (no finite pixel position).
  bool toPixels(const glm::dvec3& point, glm::dvec2& pixel) const;

  /// Row i of ModelToClip (0: x, 1: y, 2: z, 3: w): clip coordinate i of a
  /// model point p is dot(row.xyz, p) + row.w.
  glm::dvec4 clipRow(int i) const
  {
    const glm::dmat4& m = this->ModelToClip;
    return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]);
  }

  /// An upper bound, in pixels, on how far the image of a point moves when
  /// the point moves by `distance` or less, for any point that stays within
  /// `distance` of the triangle (a, b, c) as it moves. It bounds the
  /// projection's derivative over that region (its w and its x and y in
  /// clip space from the corners'), so it holds in perspective and
  /// parallel alike. Infinite when the region may reach the eye plane.
  double pixelShiftBound(
    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double distance) const;
};

} // namespace silsmooth
