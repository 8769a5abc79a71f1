#include "DataFolder.h"

#include <filesystem>
#include <system_error>

#ifndef SILHOUETTE_DATA_RELATIVE_DIR
#define SILHOUETTE_DATA_RELATIVE_DIR "../share/SilhouetteSmoothing/Data"
#endif

namespace cli
{

std::optional<std::filesystem::path> ProgramFolder()
{
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
  {
    return std::nullopt;
  }
  return program.parent_path();
}

std::string DefaultDataDirectory()
{
  const std::optional<std::filesystem::path> folder = ProgramFolder();
  if (!folder)
  {
    return "Data"; // no /proc: the current folder's, as a last resort
  }
  return (*folder / SILHOUETTE_DATA_RELATIVE_DIR).lexically_normal().string();
}

} // namespace cli
