#ifndef PlyCheck_h
#define PlyCheck_h

#include <string>

namespace cli
{

/**
 * Checks a PLY file before vtkPLYReader sees it. VTK 9.1's reader crashes on
 * a truncated body or a face index out of range, reads misspelt property
 * types as zeros, wraps faces of more than 255 vertices around, takes a blank
 * body line for the end of the file and ignores what follows the elements
 * the header declares; this walks the header and the whole body (ASCII or
 * binary, either byte order) and throws RuntimeError with one line naming the
 * first problem.
 */
void CheckPlyFile(const std::string& path);

} // namespace cli

#endif
