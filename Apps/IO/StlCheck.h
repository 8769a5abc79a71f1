#ifndef StlCheck_h
#define StlCheck_h

#include <cstdint>
#include <string>

namespace cli
{

/**
 * Checks a binary STL file before vtkSTLReader sees it. VTK 9.1's reader
 * allocates for the triangle count the header declares, however short the
 * file (gigabytes for a 134-byte file), and misreads a file shorter than the
 * 84-byte header, and reads records past the count the header declares;
 * this throws RuntimeError with one line for each. In an ASCII file (as
 * vtkSTLReader tells them apart) every vertex must be three whole numbers:
 * the reader reads "1,5" as 1 and "1-1" as two numbers, without a word.
 */
/// Returns the facets the file holds (the binary header's count, or the
/// ASCII vertices over three).
std::uint64_t CheckStlFile(const std::string& path);

} // namespace cli

#endif
