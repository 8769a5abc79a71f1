// Silhouette proximity (Mata, Pastor and Rodriguez, section 3): how far each
// point and face of a mesh is, on the image, from the mesh's external
// contour for one view.
//
// 1. Mesh mapping (3.1): the faces are projected to the viewport and a grid
//    of square cells is laid over the projected bounding box, `Resolution`
//    cells along its longer side. A cell is occupied when a projected face
//    overlaps it (an exact 2D triangle/square overlap test, not sampling).
// 2. External contour: unoccupied cells that cannot be reached from outside
//    the grid through unoccupied edge neighbours (holes enclosed by the
//    projection, such as a torus's hole seen from above) are counted as
//    occupied, so the distances are to the external contour only.
// 3. Distance transform (3.2): the two-pass 3-4 chamfer of DistanceTransform.h
//    on the occupancy image; a cell's label is its distance in cells to the
//    nearest background cell (1 for an occupied cell on the contour).
// 4. Labelling (3.3): a face gets the least label of the cells it overlaps,
//    a point the label of the cell it projects into.
//
// Every face is projected, visible or not (the paper's mapping has no depth
// test). Points on or behind the eye plane cannot be projected: they and
// their faces get the label -1 and occupy nothing.
#pragma once

#include "MeshTopology.h"
#include "ViewGeometry.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace silsmooth
{

struct ProximityGrid
{
  int Width = 0;
  int Height = 0;
  /// Cell size in viewport pixels, and the pixel position of the grid's
  /// lower-left corner.
  double CellSize = 1.0;
  double OriginX = 0.0;
  double OriginY = 0.0;
  /// Width * Height, row after row from the bottom: 1 where a face overlaps
  /// the cell, 2 for an enclosed hole filled in step 2, 0 for background.
  std::vector<unsigned char> Occupancy;
  /// The distance label of every cell, in cells (0 for background).
  std::vector<double> Distance;
  /// Per point and per triangle: the label, or -1 where not projected.
  std::vector<double> PointDistance;
  std::vector<double> TriangleDistance;
};

/// `resolution` >= 1 is the number of cells along the longer side of the
/// projected bounding box.
ProximityGrid silhouetteProximity(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const ViewGeometry& view, int resolution);

/// Whether the triangle overlaps the open square (x0, x0 + size) x
/// (y0, y0 + size) (separating axes; touching along a border is no overlap).
/// A triangle of zero area (seen edge-on) overlaps the squares its bounding
/// box overlaps, so that it is not lost.
bool triangleOverlapsSquare(
  const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double x0, double y0, double size);

} // namespace silsmooth
