#ifndef PlyCheck_h
#define PlyCheck_h

#include "FileGeometry.h"

#include <string>

namespace cli
{

/**
 * Checks a PLY file before vtkPLYReader sees it, by the format's own rules:
 * its header (PlyHeader.h), and its whole body (ASCII, one element a line, words split at
 * spaces and tabs; or binary, either byte order). Throws RuntimeError with
 * one line naming the first problem: a value that is no number of its type
 * (an integer in anything but decimal digits among them), an index of no
 * vertex, a body shorter or longer than the header declares, an element the
 * reader would leave out. Three crashes of VTK 9.1's reader on files it
 * could otherwise read are named too (faces before vertices, a face element
 * without indices, no final line end), where the reading process would only
 * report the signal.
 *
 * What the reader then gives is held to the file's geometry
 * (PlyFacts::Geometry, FileGeometry.h), so a misread that leaves the reader
 * with another mesh is refused without this check knowing the reader's
 * limits (its face size, its line buffer, how it splits a line).
 *
 * Returns what the caller must know of the file to read it right (PlyFacts).
 */
struct PlyFacts
{
  /// The faces carry texture coordinates per corner (a `texcoord` list, as
  /// MeshLab writes): vtkPLYReader 9.1's splitting of points for them can
  /// give a face another face's point, so the caller reads them one per
  /// point instead.
  bool FaceTextureCoordinates = false;
  /// The vertices carry texture coordinates the reader does not read (`s`
  /// and `t`, as assimp writes; it reads `u`/`v` and `texture_u`/`texture_v`).
  bool UnreadVertexTextureCoordinates = false;
  /// The vertices' positions and normals and the faces, as the file gives them.
  FileGeometry Geometry;
};
PlyFacts CheckPlyFile(const std::string& path);

} // namespace cli

#endif
