#ifndef MeshValidation_h
#define MeshValidation_h

#include <string>

class vtkPolyData;

namespace cli
{

/**
 * Throws RuntimeError("cannot read <quotedFile>: <why>") unless the mesh a
 * reader produced is one the program can trust, whatever the format:
 * - every point is finite;
 * - every cell's point ids lie in [0, number of points);
 * - every point data array has one tuple per point, every cell data array
 *   one tuple per cell.
 */
void RequireConsistentMesh(vtkPolyData* mesh, const std::string& quotedFile);

/**
 * Removes the point data arrays without one tuple per point and the cell data
 * arrays without one per cell, and returns what went as a phrase ("the cell
 * data array 'MaterialIds' (6 values for 18 cells)"), "" if nothing did.
 * vtkOBJReader 9.1 gives a file of points, lines and faces material ids for
 * its faces only; the geometry is sound, the array cannot be matched to it.
 */
std::string RemoveMismatchedArrays(vtkPolyData* mesh);

/**
 * Removes the cells with too few points for their kind (a vertex cell without
 * a point, a line with fewer than two, a polygon or strip with fewer than
 * three), with their cell data, and returns what went as a phrase ("2 empty
 * vertex cells, 1 line with one point"), "" if nothing did. VTK's XML writer
 * crashes on such cells, and they hold nothing to draw.
 */
std::string RemoveCellsWithTooFewPoints(vtkPolyData* mesh);

} // namespace cli

#endif
