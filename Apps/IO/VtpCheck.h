#ifndef VtpCheck_h
#define VtpCheck_h

#include "FileGeometry.h"

#include <cstdint>
#include <string>

namespace cli
{

/// What the VTK XML check read of a file.
struct VtpFacts
{
  /// True when the format's rules read the file's mesh (then Geometry holds
  /// it); false when they could not, and Unreadable says why.
  bool Read = false;
  FileGeometry Geometry;
  std::string Unreadable;
  /// The pieces, and the points of the first (vtkXMLPolyDataReader 9.1
  /// cannot read a file whose first piece has none).
  int Pieces = 0;
  std::uint64_t FirstPiecePoints = 0;
};

/**
 * Reads a VTK XML PolyData file's mesh by the format's rules
 * (`VtkXmlData.h`: every encoding and compressor VTK writes), to hold
 * vtkXMLPolyDataReader to it (FileGeometry.h): the points of every piece in
 * order, the active point normals when every piece gives them, and each
 * piece's vertices, lines, strips and polygons, with the piece's indices
 * offset by the points of the pieces before it.
 *
 * Throws RuntimeError with one line, before the reader sees the file, for a
 * header or a Piece that declares more than the file can hold and for an
 * uncompressed array that holds fewer bytes than its header declares (the
 * reader would allocate it, or fill it from its buffer). A cell that names
 * a point beyond its piece's, or offsets that go back, are refused too.
 * Whatever else the rules cannot read is left to the reader (`Read` false):
 * the caller refuses the file if the reader then reads it.
 */
VtpFacts CheckVtpFile(const std::string& path);

} // namespace cli

#endif
