#ifndef StlCheck_h
#define StlCheck_h

#include "FileGeometry.h"

#include <cstdint>
#include <string>

namespace cli
{

/// What the STL check read of a file.
struct StlFacts
{
  /// The facets as the file gives them, each with three corners of its own
  /// (compared by position), needles left out.
  FileGeometry Geometry;
  /// Facets with two corners at one point (as floats): vtkSTLReader merges
  /// equal points and drops them, so they are left out of Geometry too, and
  /// counted for a warning.
  std::uint64_t Needles = 0;
};

/**
 * Reads an STL file's facets by the format's rules, to hold vtkSTLReader to
 * them (FileGeometry.h), ASCII or binary as vtkSTLReader tells them apart.
 * Throws RuntimeError with one line, before the reader sees the file, for a
 * binary file shorter than its 84-byte header or than the triangle count
 * the header declares (the reader allocates for the count), or holding
 * records beyond the count that are not zero padding (the reader reads to
 * the end of the file); and for an ASCII vertex that is not three whole
 * numbers (the reader reads "1,5" as 1 and "1-1" as two numbers, without a
 * word).
 */
StlFacts CheckStlFile(const std::string& path);

} // namespace cli

#endif
