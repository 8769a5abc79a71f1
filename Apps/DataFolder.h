#ifndef DataFolder_h
#define DataFolder_h

#include <filesystem>
#include <optional>
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

/// The folder of the running program (/proc/self/exe's), if the system says:
/// what the data folder and the OSMesa library are found relative to.
std::optional<std::filesystem::path> ProgramFolder();

} // namespace cli

#endif
