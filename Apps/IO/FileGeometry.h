#ifndef FileGeometry_h
#define FileGeometry_h

#include <cstdint>
#include <string>
#include <vector>

class vtkPolyData;

namespace cli
{

/**
 * A mesh file's geometry as a format's pre-check reads it, by the format's
 * own rules, to hold VTK's reader to: a reader that succeeds with another
 * mesh (a face cut short, a line split where the file has none, the rest of
 * a body dropped) is refused, whatever made it do so. The pre-check then
 * needs no copy of the reader's limits.
 *
 * Rules of the comparison (RequireReadAsWritten):
 * - the reader's faces (its polygons) are the file's, in the file's order,
 *   with as many corners, each at the file's position for it: by position,
 *   not by index, since a reader may add copies of points (vtkPLYReader's
 *   texture seams); a corner that names no vertex of the file is left to
 *   validation, which refuses it;
 * - when VertexOrderKept, the reader's first points are the file's vertices
 *   in order, and so are its point normals when the file gives normals;
 * - where the file gives a corner its own normal or texture coordinate (OBJ),
 *   the reader's point normal (texture coordinate) at that corner is it,
 *   when the reader gives normals (texture coordinates) at all;
 * - the other kinds of cell the file gives in full (Strips, Lines, Vertices
 *   when Given) are the reader's of that kind, in order, each corner at the
 *   file's position for it;
 * - values are compared as the floats the readers store; a NaN equals a NaN
 *   (validation refuses it later, with its own message).
 */
struct FileCells
{
  bool Given = false;
  std::vector<std::int64_t> Starts{ 0 }; ///< one per cell, and the end
  std::vector<std::int64_t> Corners;     ///< the cells' vertex indices

  std::int64_t Count() const { return static_cast<std::int64_t>(this->Starts.size()) - 1; }
  void EndCell() { this->Starts.push_back(static_cast<std::int64_t>(this->Corners.size())); }
};

struct FileGeometry
{
  bool VertexOrderKept = false;
  std::vector<double> Positions;             ///< three per vertex
  std::vector<double> Normals;               ///< three per vertex, or none
  std::vector<std::int64_t> FaceStarts{ 0 }; ///< one per face, and the end
  std::vector<std::int64_t> FaceCorners;     ///< the faces' vertex indices
  /// Per corner, an index into NormalTable or TextureTable, -1 for none;
  /// empty when the format gives no such thing per corner.
  std::vector<std::int64_t> CornerNormals, CornerTextures;
  std::vector<double> NormalTable;  ///< three per normal
  std::vector<double> TextureTable; ///< two per texture coordinate
  /// For messages: the number the format gives its first vertex, face and
  /// corner (PLY 0, OBJ 1), and each face's line in the file, if known.
  int FirstIndex = 0;
  std::vector<std::size_t> FaceLines;
  /// Line and vertex cells the file holds; -1 when not counted.
  std::int64_t LineCells = -1, VertexCells = -1;
  /// Cells other than faces, when the format gives them in full.
  FileCells Strips, Lines, Vertices;

  std::int64_t VertexCount() const { return static_cast<std::int64_t>(this->Positions.size() / 3); }
  std::int64_t FaceCount() const { return static_cast<std::int64_t>(this->FaceStarts.size()) - 1; }
  void EndFace()
  {
    this->FaceStarts.push_back(static_cast<std::int64_t>(this->FaceCorners.size()));
  }
};

/// Throws RuntimeError, one line naming `path`, `readerName` and the first
/// difference, when `read` is not the mesh `file` describes (rules above).
void RequireReadAsWritten(const FileGeometry& file, vtkPolyData* read, const std::string& path,
  const std::string& readerName);

/// One texture-coordinate array (`TCoords`, active) for a reader that keeps
/// one per texture map, each holding only its faces' corners and (-1, -1)
/// elsewhere (vtkOBJReader does, per material): a point takes the first
/// array's value that is not (-1, -1). Returns the joined arrays' names, or
/// "" when there were fewer than two.
std::string JoinTextureCoordinateArrays(vtkPolyData* read);

/// Removes the reader's point normals (texture coordinates) when the file
/// has some but names them for no corner: a reader that gives vertex i the
/// i-th one (vtkOBJReader does) invents what the file never said. Returns
/// what was removed, for a warning, or "".
std::string DropUnnamedCornerData(const FileGeometry& file, vtkPolyData* read);

/// The line and vertex cells the file holds and `read` lacks, for a
/// warning ("3 of its 5 lines"), or "" when none is lacking or uncounted.
std::string CellsLeftOut(const FileGeometry& file, vtkPolyData* read);

} // namespace cli

#endif
