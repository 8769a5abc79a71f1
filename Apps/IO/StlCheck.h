#ifndef StlCheck_h
#define StlCheck_h

#include <string>

namespace cli
{

/**
 * Checks a binary STL file before vtkSTLReader sees it. VTK 9.1's reader
 * allocates for the triangle count the header declares, however short the
 * file (gigabytes for a 134-byte file), and misreads a file shorter than the
 * 84-byte header; this throws RuntimeError with one line for either. ASCII
 * files (as vtkSTLReader tells them apart) are left to the reader.
 */
void CheckStlFile(const std::string& path);

} // namespace cli

#endif
