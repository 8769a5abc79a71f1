#ifndef ObjCheck_h
#define ObjCheck_h

#include <string>

namespace cli
{

/**
 * Checks an OBJ file before vtkOBJReader sees it. VTK 9.1's reader silently
 * reads a coordinate it cannot parse, such as "nan", "inf" or "0x10", as 0,
 * so the bad vertex would never reach the filter's check, and one beyond the
 * range of a float, such as 1e39, as FLT_MAX (a normal's components, in "vn"
 * lines, alike); and it crashes on a face
 * corner such as "1/" or one that names a texture coordinate or normal the
 * file does not have. This throws RuntimeError with one line naming the
 * first such vertex or corner.
 */
void CheckObjFile(const std::string& path);

} // namespace cli

#endif
