#include "StlCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <vtkSTLReader.h>

#include <algorithm>
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

// A facet, three corners, into the geometry, or counted as a needle when
// two corners are one point as the reader stores them (floats).
void AddFacet(const double corners[9], std::size_t line, StlFacts& facts)
{
  const auto same = [corners](int a, int b) {
    for (int c = 0; c < 3; ++c)
    {
      if (static_cast<float>(corners[3 * a + c]) != static_cast<float>(corners[3 * b + c]))
      {
        return false;
      }
    }
    return true;
  };
  if (same(0, 1) || same(0, 2) || same(1, 2))
  {
    ++facts.Needles;
    return;
  }
  FileGeometry& geometry = facts.Geometry;
  for (int k = 0; k < 3; ++k)
  {
    geometry.FaceCorners.push_back(geometry.VertexCount());
    geometry.Positions.insert(geometry.Positions.end(), corners + 3 * k, corners + 3 * k + 3);
  }
  geometry.EndFace();
  if (line > 0)
  {
    geometry.FaceLines.push_back(line);
  }
}

// ASCII: every three vertex lines are a facet. The reader reads a vertex's
// three numbers with strtod, each from where the last stopped, and ignores
// what follows them, so "1,5" reads as 1 and "1-1" as 1 and -1. A vertex
// must be three whole numbers.
void ReadAsciiFacets(const std::string& path, StlFacts& facts)
{
  const std::string bytes = ReadFileBytes(path);
  TextCursor cursor(bytes);
  std::size_t number = 0;
  double corners[9];
  int corner = 0;
  std::size_t facetLine = 0;
  for (std::string line; cursor.NextLine(line);)
  {
    ++number;
    const std::vector<std::string> words = WordsOf(line);
    if (words.empty() || Lowercase(words[0]) != "vertex")
    {
      continue;
    }
    const bool three = words.size() == 4 && ParseWholeNumber(words[1], corners[3 * corner]) &&
      ParseWholeNumber(words[2], corners[3 * corner + 1]) &&
      ParseWholeNumber(words[3], corners[3 * corner + 2]);
    if (!three)
    {
      throw RuntimeError("cannot read '" + path + "': ASCII STL: line " + std::to_string(number) +
        ": '" + Excerpt(line) +
        "' is not a vertex of three numbers, which vtkSTLReader would "
        "misread");
    }
    facetLine = corner == 0 ? number : facetLine;
    if (++corner == 3)
    {
      AddFacet(corners, facetLine, facts);
      corner = 0;
    }
  }
}

// The little-endian 32-bit word at `bytes` (binary STL's byte order).
std::uint32_t LittleEndian32(const unsigned char* bytes)
{
  return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
    (static_cast<std::uint32_t>(bytes[2]) << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
}

// A binary record's corners: 12 little-endian floats after the normal.
void ReadBinaryFacet(const unsigned char* record, double corners[9])
{
  for (int v = 0; v < 9; ++v)
  {
    const std::uint32_t bits = LittleEndian32(record + 12 + 4 * v);
    float value = 0;
    std::memcpy(&value, &bits, 4);
    corners[v] = value;
  }
}

} // namespace

StlFacts CheckStlFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file)
  {
    throw RuntimeError("cannot read '" + path + "': " + std::strerror(errno));
  }
  const auto size = static_cast<std::uint64_t>(file.tellg());
  StlFacts facts;
  facts.Geometry.FirstIndex = 1; // facets numbered from 1 in messages
  auto probe = vtkSmartPointer<StlTypeProbe>::New();
  if (!probe->IsBinary(path))
  {
    ReadAsciiFacets(path, facts);
    return facts;
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
  const std::uint64_t declared = LittleEndian32(count);
  const std::uint64_t held = (size - HeaderBytes) / TriangleBytes;
  if (!file || declared > held)
  {
    throw RuntimeError(where + "the header declares " + std::to_string(declared) +
      " triangles but the file holds " + std::to_string(held) + " (truncated?)");
  }
  // The declared records, in chunks.
  std::vector<unsigned char> records(4096 * TriangleBytes);
  double corners[9];
  for (std::uint64_t read = 0; read < declared;)
  {
    const std::uint64_t chunk = std::min<std::uint64_t>(declared - read, 4096);
    file.read(
      reinterpret_cast<char*>(records.data()), static_cast<std::streamsize>(chunk * TriangleBytes));
    if (!file)
    {
      throw RuntimeError(where + "the file could not be read to its end");
    }
    for (std::uint64_t r = 0; r < chunk; ++r)
    {
      ReadBinaryFacet(records.data() + r * TriangleBytes, corners);
      AddFacet(corners, 0, facts);
    }
    read += chunk;
  }
  // The reader reads records to the end of the file, whatever the count: any
  // beyond it that is not zero padding (which reads as a point, and is left
  // out) would add triangles the header does not declare.
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
  return facts;
}

} // namespace cli
