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
 * first problem. An integer is read as the reader reads it (its leading
 * decimal digits), so one written otherwise ("0x1", "1e1") is refused.
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
};
PlyFacts CheckPlyFile(const std::string& path);

} // namespace cli

#endif
