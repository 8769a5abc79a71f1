#ifndef ObjCheck_h
#define ObjCheck_h

#include "FileGeometry.h"

#include <string>

namespace cli
{

/**
 * Checks an OBJ file before vtkOBJReader sees it, by the format's own rules:
 * statements continued after a backslash, vertices and normals of three
 * finite numbers, texture coordinates of one to three, corners written v,
 * v/vt, v//vn or v/vt/vn whose indices (1-based, or negative counting back
 * from their statement) name entries the file has; a UTF-16 file is refused
 * by name. Throws RuntimeError with one line naming the first problem.
 *
 * Returns the file's geometry (FileGeometry.h): its vertices, its faces'
 * corners with the normal and texture coordinate each names, and its counts
 * of line and point statements, to hold the reader's mesh to. What VTK
 * 9.1's reader gets wrong (a hexadecimal or out-of-float-range number read as
 * 0 or FLT_MAX, relative indices it compares as written, faces it drops in a
 * file whose faces index normals apart from their points, a byte-order mark
 * it reads as part of a keyword) then shows as a difference, without this
 * check knowing the reader's ways.
 */
FileGeometry CheckObjFile(const std::string& path);

} // namespace cli

#endif
