// Vertices where a surface comes to a point, as at a cone's apex: no single
// shading normal serves them. The mean of the triangles' normals there (the
// cone's axis) bends every curve through the apex across the axis, and the
// silhouette smoothed with it rounds the cone into a dome; the true cone's
// normal is constant along each line from the apex and changes only around
// it.
//
// Rule: a vertex is an apex when its triangles' unit normals spread widely
// (their mean is shorter than cos(ApexSpreadDegrees), as for normals all
// that far from one direction) while triangles that share an edge at it turn
// little against each other (the largest angle between two such is below
// 1 / ApexSpreadPerTurn of the largest angle between a normal and the
// mean's direction). A coarse smooth vertex has both large (an
// icosahedron's: 37 and 42 degrees), a fine one both small (a sphere's
// pole), a cone's apex of n sides a spread of 90 degrees less its
// half-angle and a turn of about 360 / n degrees times the spread's sine:
// cones of 12 sides or more are apexes unless blunt (half-angle over 50
// degrees). The thresholds are a choice: a coarse pole of a long
// ellipsoid is a fan like a cone's (16 by 8 segments stretched 4:1 spread
// 38 degrees, 5:1 45 and is taken for an apex), and a cone of 8 sides is
// a coarse round part's vertex as much as a cone's.
#pragma once

#include "MeshTopology.h"

#include <glm/vec3.hpp>

#include <vector>

namespace silsmooth
{

constexpr double ApexSpreadDegrees = 40.0;
constexpr double ApexSpreadPerTurn = 2.0;

/// The apexes among `points` (ascending ids). Only the triangles' shape
/// counts, not the shading normals a file gives (a wrong given normal makes
/// no apex); triangles with a repeated corner or no area count for nothing.
std::vector<Id> coneApexes(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles);

} // namespace silsmooth
