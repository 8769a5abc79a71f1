#ifndef DataFolder_h
#define DataFolder_h

#include <string>

namespace cli
{

/**
 * The folder of the meshes the program uses by default (the coarse bunny of
 * `view`, the bunny of `compare` and `figure`): share/SilhouetteSmoothing/Data
 * beside the program's bin folder, in an installed prefix (wherever it was
 * moved) and in the build tree alike (the build copies the files there). No
 * path of the machine the program was built on is compiled in.
 */
std::string DefaultDataDirectory();

} // namespace cli

#endif
