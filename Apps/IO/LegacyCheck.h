#ifndef LegacyCheck_h
#define LegacyCheck_h

#include "FileGeometry.h"

#include <string>

namespace cli
{

/**
 * Reads a legacy .vtk POLYDATA file by the format's rules before
 * vtkPolyDataReader sees it: the header ("# vtk DataFile Version MAJOR.MINOR",
 * a title, ASCII or BINARY, DATASET POLYDATA), POINTS, VERTICES, LINES,
 * POLYGONS and TRIANGLE_STRIPS (each at most once; cells in the 5.x
 * OFFSETS/CONNECTIVITY layout from version 5 on, as size and ids before),
 * FIELD data and the POINT_DATA/CELL_DATA attributes (METADATA blocks
 * skipped). Keywords are whole words in any case; ASCII numbers are decimal
 * and fit their type; BINARY data is big-endian and within the file. Throws
 * RuntimeError with one line naming the first problem (VTK 9.1's reader
 * crashes on short or unparsable cell sections, so they are found here).
 *
 * Returns the file's geometry (FileGeometry.h): its points, its points'
 * first NORMALS and every cell, to hold the reader's mesh to.
 */
FileGeometry CheckLegacyVtkFile(const std::string& path);

} // namespace cli

#endif
