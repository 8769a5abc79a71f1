#ifndef ObjCheck_h
#define ObjCheck_h

#include <string>

namespace cli
{

/**
 * Checks the vertex lines of an OBJ file before vtkOBJReader sees it. VTK
 * 9.1's reader silently reads a coordinate it cannot parse, such as "nan" or
 * "inf", as 0, so the bad vertex would never reach the filter's check; this
 * throws RuntimeError with one line naming the first such vertex.
 */
void CheckObjFile(const std::string& path);

} // namespace cli

#endif
