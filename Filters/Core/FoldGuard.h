// The fold guard of the smoothing pass (issue 13): finds, in one frame's
// output, the re-meshed triangles whose new triangles fold, so that the pass
// can re-mesh them more conservatively, and the perturbed points that fold
// their triangles, so that it can leave them in place.
//
// A new triangle folds when
//   - it is turned over: its geometric normal and the normal of the input
//     triangle it replaces lie on opposite sides of the sum S of its
//     corners' shading normals (one points against S, the other does not;
//     either way round, so that the rule does not depend on the winding the
//     output is written in). S stands for the surface's normal where the new
//     triangle is: the new points' normals interpolate the input corners'.
//     Comparing with the input triangle at the same S, not with the input
//     triangle's own corners, matters on coarse meshes: a corner normal may
//     point against its own triangle, and the sub-triangles next to it would
//     count as turned however flat they lie); or
//   - it cuts through another output triangle (TriangleIntersection.h) whose
//     input triangle its own input triangle does not cut through, or through
//     another new triangle of the same input triangle.
// Kept triangles with a corner the perturbation moved are checked by the
// same two rules; their moved corners are the ones to leave in place. (In a
// partial check, so are the kept triangles around points whose move
// changed, moved back ones included.)
//
// Candidates for a cut are the kept, unmoved triangles that meet the box of
// the new triangles of one input triangle (triangleMeetsBox: the triangle,
// not its box, so that a long sliver is a candidate only where it passes),
// and the changed triangles whose boxes, where they are now, meet it (a
// grid of the frame's changed triangles, built per check: a lifted new
// triangle or a moved one can leave its input triangle's box by any
// amount). The kept ones come from the prepared mesh's TriangleGrid when it
// has one; without it, from one pass over the triangles, each looking in
// the cells it passes through of a grid of the boxes the check asks about,
// which costs less than building the mesh's grid and so serves a mesh
// smoothed once (a filter's run, a deforming mesh's frame). Each item's
// candidates are then narrowed to the triangles whose boxes, where they
// are now, meet its own (a grid of earlier positions answers with a
// slack), so both ways give every item the same candidates, in ascending
// order, and the same findings.
//
// Two changed triangles that are both checked are tested against each
// other once, by the first of them in the frame's order unless its
// candidates are crowded (below); the test is symmetric, and a cut found
// marks both, so the findings are those of testing from both sides.
//
// A new triangle that lies in its input triangle (liesIn; every new
// triangle of a straight re-meshing does) is not tested against kept
// triangles, nor against changed ones that lie in theirs: it could cut
// them only where the input triangles touch, which is no fold.
//
// More than CandidateCap (2,048) candidates of either kind for one input
// triangle's new triangles (at the centre of a fan of thousands, every one
// meets them) make them crowded: they are not tested, and are reported as
// folding untested (FoldingRemeshed 2), for the pass to re-mesh them
// straight. That bounds a check's work and memory by the number of new
// triangles times the cap.
//
// Invariant the pass builds on: an output in which every re-meshed triangle
// is cut along the chord between silhouette points on its straight edges,
// every feature segment is straight and no point is moved has no fold by
// these rules, because its new triangles lie in their input triangles with
// the input's orientation; so the fallbacks, each taken once, end. (On a
// piece of a partitioned mesh the pass does not straighten a silhouette
// point or feature segment on a boundary edge: the piece across the seam
// computes the same point and cannot know of the fallback. A fold that only
// that would undo is counted as unresolved.)
#pragma once

#include "MeshTopology.h"
#include "TriangleGrid.h"

#include <glm/vec3.hpp>

#include <functional>
#include <utility>
#include <vector>

namespace silsmooth
{

/// The prepared mesh the frame was made from.
struct FoldGuardMesh
{
  const std::vector<glm::dvec3>& Points;
  const std::vector<glm::dvec3>& Normals;
  const std::vector<Triangle>& Triangles;
  /// The grid of the triangles' boxes, or null (then the check scans).
  const TriangleGrid* Grid = nullptr;
  /// How far a triangle's box may lie from its box in Grid (a grid built for
  /// earlier positions, PreparedMesh::triangleGridSlack): queries are widened
  /// by it, and candidates are narrowed by their boxes where they are now.
  double GridSlack = 0.0;
};

/// One frame's output: the re-meshed input triangles (ascending) with their
/// replacements, the added points (ids from Points.size() on) and the moved
/// input points (ascending ids).
struct FoldGuardFrame
{
  const std::vector<Id>& Remeshed;
  const std::vector<std::size_t>& ReplacementOffsets;
  const std::vector<Triangle>& Replacements;
  const std::vector<glm::dvec3>& NewPositions;
  const std::vector<glm::dvec3>& NewNormals;
  const std::vector<std::pair<Id, glm::dvec3>>& Moved;
  /// When given (both ascending), only the new triangles of these input
  /// triangles and the triangles with a corner among these points are
  /// checked, against everything; a cut found marks both triangles. A caller
  /// that re-meshes a frame again after taking fallbacks passes the input
  /// triangles the fallbacks changed and the points whose move changed:
  /// every other triangle is as it was and was found not to fold, so the
  /// findings are those of a whole check.
  const std::vector<Id>* CheckSources = nullptr;
  const std::vector<Id>* CheckPoints = nullptr;
  /// For tests: test each pair of checked changed triangles from both sides
  /// (the findings must not depend on it).
  bool PairsFromBothSides = false;
};

struct FoldFindings
{
  /// Per entry of Remeshed: 1 when one of its new triangles folds, 2 when
  /// none was found to but some were not tested (crowded, below): the
  /// pass then re-meshes it straight at once, which needs no test.
  std::vector<unsigned char> FoldingRemeshed;
  /// Moved points that are corners of a folding triangle, ascending.
  std::vector<Id> FoldingMovedPoints;
  /// Folding triangles found: turned over, and cutting through another.
  std::size_t Turned = 0;
  std::size_t Cutting = 0;
  /// Triangles not tested, taken as folding: too many candidates near
  /// them (FoldGuard.cpp's CandidateCap; a fan of thousands around a point).
  std::size_t Crowded = 0;

  bool any() const { return this->Turned + this->Cutting + this->Crowded > 0; }
};

/// Same signature as silsmooth::ParallelFor (ParallelFor.h).
using FoldGuardParallelFor =
  std::function<void(std::size_t count, const std::function<void(std::size_t, std::size_t)>& body)>;

/// Checks every new triangle and every kept triangle with a moved corner.
/// The findings do not depend on how parallelFor splits the work.
FoldFindings findFolds(
  const FoldGuardMesh& mesh, const FoldGuardFrame& frame, const FoldGuardParallelFor& parallelFor);

} // namespace silsmooth
