#ifndef PlyHeader_h
#define PlyHeader_h

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cli
{
namespace ply
{

/**
 * A PLY file's header, read by the format's rules (PlyCheck.h reads the body
 * with it): the format line, the elements with their scalar and list
 * properties, and where the body starts. Words are split at spaces and tabs
 * only, as PLY separates them; a line that is no keyword the format knows is
 * ignored (exporters write "Created by ..." without "comment").
 *
 * Failures throw RuntimeError with one line: "cannot read 'PATH': malformed
 * PLY: ..." for what breaks the format, "cannot read 'PATH': ..." for valid
 * PLY that vtkPLYReader 9.1 leaves out or crashes on.
 */

enum class ScalarType
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

/// The type a header names ("float", "uint8", ...), if any.
std::optional<ScalarType> ScalarTypeNamed(const std::string& name);
/// Bytes per value in a binary body.
std::size_t SizeOf(ScalarType type);
/// The values an integer type holds (all numbers for the float types).
std::pair<double, double> RangeOf(ScalarType type);
bool IsInteger(ScalarType type);

struct Property
{
  std::string Name;
  ScalarType Type = ScalarType::Float32;
  bool IsList = false;
  ScalarType CountType = ScalarType::UInt8;
};

struct Element
{
  std::string Name;
  long long Count = 0;
  std::vector<Property> Properties;
};

enum class Format
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

struct Header
{
  Format BodyFormat = Format::Ascii;
  std::vector<Element> Elements;
  std::size_t BodyOffset = 0;
};

/// Whether `property` of `element` is a face's vertex index list.
bool IsVertexIndexList(const Element& element, const Property& property);

/// The header of the file `path` whose bytes are `bytes`.
Header ReadHeader(const std::string& path, const std::string& bytes);

/// The elements' rules a mesh needs (below); returns the vertex element.
const Element& CheckElements(const std::string& path, const Header& header);

} // namespace ply
} // namespace cli

#endif
