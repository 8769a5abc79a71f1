#include "DataFolder.h"

#include <filesystem>
#include <system_error>

#ifndef SILHOUETTE_DATA_RELATIVE_DIR
#define SILHOUETTE_DATA_RELATIVE_DIR "../share/SilhouetteSmoothing/Data"
#endif

namespace cli
{

std::string DefaultDataDirectory()
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error)
  {
    return "Data"; // no /proc: the current folder's, as a last resort
  }
  return (program.parent_path() / SILHOUETTE_DATA_RELATIVE_DIR).lexically_normal().string();
}

} // namespace cli
