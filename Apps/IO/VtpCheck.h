#ifndef VtpCheck_h
#define VtpCheck_h

#include <string>

namespace cli
{

/**
 * Checks the binary data arrays of a VTK XML file, inline or appended, before
 * vtkXMLPolyDataReader sees them. VTK 9.1's reader allocates what an array's
 * binary header declares (the uncompressed size and the block count of a
 * compressed array, the byte count of a raw one), however short the file: a
 * fuzzed 4 KB file made it take more than a gigabyte. A header that declares
 * more than 1024 bytes per byte of the file (zlib compresses at most about
 * 1032:1) or more blocks than the file has bytes throws RuntimeError with one
 * line, and so does a Piece declaring more points or cells than that bound.
 * So does an uncompressed array holding fewer bytes than its header
 * declares, which the reader fills up with whatever its buffer held.
 */
void CheckVtpFile(const std::string& path);

} // namespace cli

#endif
