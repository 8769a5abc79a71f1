#include "StlCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <vtkSTLReader.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace cli
{
namespace
{

// vtkSTLReader's own ASCII/binary decision (a protected member). It returns
// the VTK_ASCII of vtkSTLReader.cxx, 0, not the VTK_ASCII of vtkWriter.h, 1.
constexpr int StlReaderAscii = 0;

class StlTypeProbe : public vtkSTLReader
{
public:
  static StlTypeProbe* New()
  {
    auto* probe = new StlTypeProbe;
    probe->InitializeObjectBase();
    return probe;
  }
  bool IsBinary(const std::string& path)
  {
    return this->GetSTLFileType(path.c_str()) != StlReaderAscii;
  }
};

constexpr std::uint64_t HeaderBytes = 84; // 80 bytes of text, a 32-bit triangle count
constexpr std::uint64_t TriangleBytes = 50;

// ASCII: the reader reads a vertex's three numbers with strtod, each from
// where the last stopped, and ignores what follows them, so "1,5" reads as 1
// and "1-1" as 1 and -1. A vertex must be three whole numbers.
std::uint64_t CheckAsciiVertices(const std::string& path)
{
  std::uint64_t vertices = 0;
  const std::string bytes = ReadFileBytes(path);
  TextCursor cursor(bytes);
  std::size_t number = 0;
  for (std::string line; cursor.NextLine(line);)
  {
    ++number;
    const std::vector<std::string> words = WordsOf(line);
    if (words.empty() || Lowercase(words[0]) != "vertex")
    {
      continue;
    }
    double value = 0.0;
    const bool three = words.size() == 4 && ParseWholeNumber(words[1], value) &&
      ParseWholeNumber(words[2], value) && ParseWholeNumber(words[3], value);
    if (!three)
    {
      throw RuntimeError("cannot read '" + path + "': ASCII STL: line " + std::to_string(number) +
        ": '" + Excerpt(line) +
        "' is not a vertex of three numbers, which vtkSTLReader would "
        "misread");
    }
    ++vertices;
  }
  return vertices / 3;
}

} // namespace

std::uint64_t CheckStlFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file)
  {
    throw RuntimeError("cannot read '" + path + "': " + std::strerror(errno));
  }
  const auto size = static_cast<std::uint64_t>(file.tellg());
  auto probe = vtkSmartPointer<StlTypeProbe>::New();
  if (!probe->IsBinary(path))
  {
    return CheckAsciiVertices(path);
  }
  const std::string where = "cannot read '" + path + "': binary STL: ";
  if (size < HeaderBytes)
  {
    throw RuntimeError(
      where + "the file has " + std::to_string(size) + " bytes, fewer than the 84-byte header");
  }
  unsigned char count[4];
  file.seekg(80);
  file.read(reinterpret_cast<char*>(count), 4);
  const std::uint64_t declared = count[0] | (count[1] << 8) | (count[2] << 16) |
    (static_cast<std::uint64_t>(count[3]) << 24); // little-endian
  const std::uint64_t held = (size - HeaderBytes) / TriangleBytes;
  if (!file || declared > held)
  {
    throw RuntimeError(where + "the header declares " + std::to_string(declared) +
      " triangles but the file holds " + std::to_string(held) + " (truncated?)");
  }
  // The reader reads records to the end of the file, whatever the count: any
  // beyond it that is not zero padding (which reads as a point, and is left
  // out) would add triangles the header does not declare.
  file.seekg(static_cast<std::streamoff>(HeaderBytes + declared * TriangleBytes));
  std::uint64_t left = (held - declared) * TriangleBytes;
  char buffer[4096];
  while (left > 0)
  {
    const std::uint64_t chunk = left < sizeof buffer ? left : sizeof buffer;
    file.read(buffer, static_cast<std::streamsize>(chunk));
    if (!file)
    {
      break;
    }
    for (std::uint64_t i = 0; i < chunk; ++i)
    {
      if (buffer[i] != 0)
      {
        throw RuntimeError(where + "the header declares " + std::to_string(declared) +
          " triangles but the file holds " + std::to_string(held) +
          ", which vtkSTLReader reads all of; correct the count");
      }
    }
    left -= chunk;
  }
  return declared;
}

} // namespace cli
