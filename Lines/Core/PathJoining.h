// A drawing's lines joined end to end into longer paths (issue 16), so that
// a pen plotter lifts its pen, and inks a corner, once where lines meet.
//
// Lines meet where their ends have the same key (the caller's rounding of
// the end's position: the SVG writer's hundredth of a pixel) and they are of
// one group (the same kind, visible or hidden). Where two ends meet they are
// joined; where more meet, the two that continue each other most straightly
// are joined first (their directions leaving the point most nearly
// opposite), then the next two, and an end left over starts or ends a path.
// A line is not joined to itself (a closed loop is one path already).
//
// Invariants: every line is in exactly one path, once, and each path's
// lines are consecutive: a line's last point (its first, when turned round)
// has the key of the next line's first point (its last, turned round).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace silsmooth
{

struct JoinedLine
{
  std::size_t Line = 0;
  bool Reversed = false; ///< drawn from its last point to its first
};

/// The lines (image coordinates, two points or more each) joined into
/// paths. `groups` gives each line's group, `keyOf` an end's position key.
/// Paths come in the order of their first line; lines in a closed chain
/// start at its lowest line.
std::vector<std::vector<JoinedLine>> joinedPaths(const std::vector<std::vector<glm::dvec2>>& lines,
  const std::vector<int>& groups,
  std::pair<std::int64_t, std::int64_t> (*keyOf)(const glm::dvec2&));

/// The same for lines in space (model coordinates, two points or more
/// each), one group: ends meet where they lie within `tolerance` of each
/// other, directly or through other ends (0: at equal positions only).
std::vector<std::vector<JoinedLine>> joinedPaths(
  const std::vector<std::vector<glm::dvec3>>& lines, double tolerance);

} // namespace silsmooth
