#include "ObjCheck.h"

#include "CliErrors.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace cli
{

void CheckObjFile(const std::string& path)
{
  std::ifstream file(path);
  if (!file)
  {
    throw RuntimeError("cannot read '" + path + "': " + std::strerror(errno));
  }
  std::string line;
  long long lineNumber = 0;
  long long vertex = 0;
  while (std::getline(file, line))
  {
    ++lineNumber;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword != "v")
    {
      continue;
    }
    ++vertex;
    const std::string where =
      "'" + path + "': line " + std::to_string(lineNumber) + ", vertex " + std::to_string(vertex);
    std::string word;
    int coordinates = 0;
    // x y z, then optional w or r g b.
    while (words >> word)
    {
      char* end = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (end != word.c_str() + word.size() || !std::isfinite(value)) // a NUL byte stops strtod
      {
        throw RuntimeError("cannot read " + where + ": '" + word + "' is not a finite number");
      }
      ++coordinates;
    }
    if (coordinates < 3)
    {
      throw RuntimeError("cannot read " + where + ": fewer than 3 coordinates");
    }
  }
}

} // namespace cli
