// Quadric edge-collapse simplification (Garland and Heckbert 1997) with the
// silhouette-aware error rule of Mata, Pastor and Rodriguez (section 3.4):
// where a point is near the external contour (its distance label is in a
// chosen interval, SilhouetteProximity.h) the error allowed is f * e, and e
// elsewhere.
//
// Quadrics: every input triangle contributes the plane quadric of its plane
// (unit normal, not area-weighted) to its three points, so a point's error
// Q(v) is the sum of squared distances from v to the planes of the input
// triangles merged into it. Collapsing edge (a, b) puts the merged point
// where Qa + Qb is least (the 3x3 solve; the best of a, b and the midpoint
// when the system is near singular); its cost is that least value.
//
// The rule with a triangle budget: a collapse near the contour is ranked by
// cost / f, any other by its cost, and collapses are taken cheapest rank
// first until the mesh has at most the requested number of triangles. The
// largest rank taken is e: every point far from the contour then has error
// at most e, and every point near it at most f * e (the error of a point is
// the cost of the last collapse into it, and a point is near once any point
// merged into it is near). f = 0 forbids collapses near the contour; the
// target may then be out of reach (ReachedTarget tells).
//
// Topology: an edge collapses only when the link condition holds (the
// points next to both ends are exactly the two opposite corners, and those
// two do not make a triangle with each end: a tetrahedron's edge would fold
// two triangles onto each other), it has
// exactly two triangles, and no remaining triangle around it turns over or
// degenerates; so a closed manifold stays a closed manifold of the same
// genus. Points on boundary or non-manifold edges never move, nor do points
// whose triangles form more than one fan around them (two sheets touching
// at a point): no collapse involves them.
#pragma once

#include "MeshTopology.h"
#include "Progress.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

struct SimplificationParameters
{
  /// Stop once the mesh has at most this many triangles (at least 4).
  std::size_t TargetTriangles = 0;
  /// Per input point: non-zero when near the contour. Empty: nothing is near.
  std::vector<unsigned char> Near;
  /// f of the paper: near points may have f times the error of the others.
  double NearFactor = 1.0;
  /// Called with the share of the collapses to the target done, every 256
  /// collapses; false stops the simplification (SimplificationResult::Aborted).
  ProgressCallback Progress;
  /// Keep every collapse taken, in order (SimplificationResult::Sequence):
  /// the edge-collapse sequence a view-dependent hierarchy is built from.
  bool RecordSequence = false;
  /// Collapse in rounds of independent collapses: within a round, cheapest
  /// first, a collapse is put off to the next round when a point of its
  /// triangles (either end or a point next to one) was touched by a collapse
  /// of this round. The sequence then has few levels, so a view-dependent
  /// hierarchy built from it has short chains of dependencies (its refinement
  /// stays local, as in Xia and Varshney's or El-Sana's merge trees); the
  /// mesh reached is a little worse than cheapest-first alone.
  bool IndependentRounds = false;
};

/// One collapse as taken: `Removed` went into `Kept`, which moved from its
/// position then to `Position`. Point ids are the input's.
struct CollapseRecord
{
  Id Kept = 0;
  Id Removed = 0;
  glm::dvec3 Position{ 0.0 };
  double Cost = 0.0;
};

struct SimplificationResult
{
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
  /// Per output point: the input point it kept the id of, its quadric error
  /// Q(v), and whether it is near the contour.
  std::vector<Id> SourcePoint;
  std::vector<double> PointError;
  std::vector<unsigned char> PointNear;
  /// e: the largest rank (cost, or cost / f near the contour) collapsed.
  double Threshold = 0.0;
  std::size_t Collapses = 0;
  bool ReachedTarget = false;
  /// With RecordSequence: every collapse taken, first to last. Replaying
  /// them on the input (its triangles that name no point twice) gives the
  /// output mesh.
  std::vector<CollapseRecord> Sequence;
  /// Stopped by the progress callback: the result is empty.
  bool Aborted = false;
};

/// Triangles that name a point twice are dropped first.
SimplificationResult simplifyQuadric(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const SimplificationParameters& parameters);

} // namespace silsmooth
