// The order a pen plotter draws a drawing's lines in (issue 16): little
// travel with the pen up.
//
// Greedy nearest neighbour: from the start (where the pen rests), each next
// line is the one with an end nearest the pen, drawn from that end, so
// turned round when its last point is the nearer; the pen is then at its
// other end. Ties go to the lower line index, and to the first point before
// the last. The ends are filed in a grid of about two ends a cell, searched
// in rings around the pen until no nearer end can lie farther out, so a
// drawing of n lines orders in about n log n where the lines are spread
// over the page (the n-squared scan it replaces stopped at 4,000 lines).
//
// A loop (a closed line) may be entered at any of its points, and the pen
// is back there when it has gone round: its points are all ends.
//
// Invariant: every line appears once; each step's line has, of the lines
// left, an end at the least distance from the pen (the greedy choice made
// exactly, not approximately).
#pragma once

#include <glm/vec2.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace silsmooth
{

struct PenStep
{
  std::size_t Line = 0;
  bool Reversed = false; ///< drawn from its last point to its first
  /// For a loop, the point it is entered at (its index among the loop's
  /// points; never Reversed); 0 otherwise.
  std::size_t Entry = 0;
};

/// The order to draw lines whose ends (first point, last point) are given,
/// from `start`. With `backToEntry`, drawing a line brings the pen back to
/// the end it entered by (a filled outline goes round its line and closes
/// there), so the next line is looked for from that end. Where `loops` is
/// given and loops[i] is not empty, line i is a loop through those points
/// (its ends are not used). Ties go to the lower line, then the lower
/// point (a line's first before its last).
std::vector<PenStep> penOrder(const std::vector<std::array<glm::dvec2, 2>>& ends,
  const glm::dvec2& start, bool backToEntry = false,
  const std::vector<std::vector<glm::dvec2>>& loops = {});

} // namespace silsmooth
