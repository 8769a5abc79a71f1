#ifndef LegacyCheck_h
#define LegacyCheck_h

#include <string>

namespace cli
{

/**
 * Checks the geometry of a legacy .vtk POLYDATA file before vtkPolyDataReader
 * reads it. VTK 9.1's reader closes the file when a cell section is short or
 * holds a value it cannot parse, then reads on from the closed stream and
 * crashes; and it walks a legacy cell array by the counts it holds, past the
 * end when they do not add up. This walks the whole file as the reader
 * would: the header, POINTS, VERTICES, LINES, POLYGONS and TRIANGLE_STRIPS
 * (ASCII or BINARY, legacy or 5.x OFFSETS/CONNECTIVITY layout), FIELD data and
 * the POINT_DATA/CELL_DATA attributes (skipping METADATA blocks), and throws
 * RuntimeError with one line naming the first problem.
 */
void CheckLegacyVtkFile(const std::string& path);

} // namespace cli

#endif
