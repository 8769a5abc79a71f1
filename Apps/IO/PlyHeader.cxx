#include "PlyHeader.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <algorithm>
#include <cmath>

namespace cli
{
namespace ply
{
namespace
{

// The PLY format separates the words of a line by spaces (tabs are common
// too): any other byte, a control character or a NUL among them, is part of
// a word, so a number or a name holding one is not what it seems.
constexpr const char* WordSeparators = " \t";

// Throws the header's failures for `Path`.
struct HeaderFailure
{
  const std::string& Path;
  [[noreturn]] void operator()(const std::string& problem) const
  {
    throw RuntimeError("cannot read '" + this->Path + "': malformed PLY: " + problem);
  }
  // For valid PLY that VTK 9.1's reader gets wrong.
  [[noreturn]] void Unsupported(const std::string& problem) const
  {
    throw RuntimeError("cannot read '" + this->Path + "': " + problem);
  }
};

} // namespace

std::optional<ScalarType> ScalarTypeNamed(const std::string& name)
{
  struct Named
  {
    const char* Name;
    ScalarType Type;
  };
  static const Named types[] = { { "char", ScalarType::Int8 }, { "int8", ScalarType::Int8 },
    { "uchar", ScalarType::UInt8 }, { "uint8", ScalarType::UInt8 }, { "short", ScalarType::Int16 },
    { "int16", ScalarType::Int16 }, { "ushort", ScalarType::UInt16 },
    { "uint16", ScalarType::UInt16 }, { "int", ScalarType::Int32 }, { "int32", ScalarType::Int32 },
    { "uint", ScalarType::UInt32 }, { "uint32", ScalarType::UInt32 },
    { "float", ScalarType::Float32 }, { "float32", ScalarType::Float32 },
    { "double", ScalarType::Float64 }, { "float64", ScalarType::Float64 } };
  for (const Named& type : types)
  {
    if (name == type.Name)
    {
      return type.Type;
    }
  }
  return std::nullopt;
}

std::size_t SizeOf(ScalarType type)
{
  switch (type)
  {
    case ScalarType::Int8:
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Float64:
      return 8;
    default:
      return 4;
  }
}

// The values an integer type holds (vtkPLYReader would wrap the others around).
std::pair<double, double> RangeOf(ScalarType type)
{
  switch (type)
  {
    case ScalarType::Int8:
      return { -128.0, 127.0 };
    case ScalarType::UInt8:
      return { 0.0, 255.0 };
    case ScalarType::Int16:
      return { -32768.0, 32767.0 };
    case ScalarType::UInt16:
      return { 0.0, 65535.0 };
    case ScalarType::Int32:
      return { -2147483648.0, 2147483647.0 };
    case ScalarType::UInt32:
      return { 0.0, 4294967295.0 };
    default:
      return { -HUGE_VAL, HUGE_VAL };
  }
}

bool IsInteger(ScalarType type)
{
  return type != ScalarType::Float32 && type != ScalarType::Float64;
}

bool IsVertexIndexList(const Element& element, const Property& property)
{
  return element.Name == "face" && property.IsList &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
}

Header ReadHeader(const std::string& path, const std::string& bytes)
{
  const HeaderFailure fail{ path };
  Header header;
  std::size_t lineNumber = 0;
  bool sawFormat = false;
  TextCursor lines(bytes);
  while (true)
  {
    std::string line;
    bool ended = false;
    if (!lines.NextLine(line, &ended) || !ended)
    {
      fail(lineNumber == 0 ? "empty file" : "the header has no end_header line");
    }
    ++lineNumber;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    const std::vector<std::string> words = WordsOf(line, WordSeparators);
    const auto word = [&words](std::size_t k) {
      return k < words.size() ? words[k] : std::string();
    };
    const std::string keyword = word(0);
    const std::string where = "header line " + std::to_string(lineNumber);
    if (lineNumber == 1)
    {
      if (keyword != "ply")
      {
        fail("the file does not start with 'ply'");
      }
      continue;
    }
    if (keyword == "format")
    {
      const std::string format = word(1);
      // The format's version is part of the line ("format ascii 1.0").
      double version = 0.0;
      if (!ParseWholeNumber(word(2), version))
      {
        fail(
          where + ": the format line has no version (write 'format " + Excerpt(format) + " 1.0')");
      }
      if (format == "ascii")
      {
        header.BodyFormat = Format::Ascii;
      }
      else if (format == "binary_little_endian")
      {
        header.BodyFormat = Format::BinaryLittleEndian;
      }
      else if (format == "binary_big_endian")
      {
        header.BodyFormat = Format::BinaryBigEndian;
      }
      else
      {
        fail(where + ": unknown format '" + format + "'");
      }
      sawFormat = true;
    }
    else if (keyword == "element")
    {
      Element element;
      element.Name = word(1);
      if (element.Name.empty() || !ParseWholeInteger(word(2), element.Count) || element.Count < 0)
      {
        fail(where + ": bad element line '" + line + "'");
      }
      header.Elements.push_back(element);
    }
    else if (keyword == "property")
    {
      if (header.Elements.empty())
      {
        fail(where + ": property before any element");
      }
      Property property;
      const std::string type = word(1);
      if (type == "list")
      {
        property.Name = word(4);
        const auto count = ScalarTypeNamed(word(2));
        const auto item = ScalarTypeNamed(word(3));
        if (!count || !IsInteger(*count) || !item)
        {
          fail(where + ": bad list property '" + line + "'");
        }
        property.IsList = true;
        property.CountType = *count;
        property.Type = *item;
      }
      else
      {
        property.Name = word(2);
        const auto scalar = ScalarTypeNamed(type);
        if (!scalar)
        {
          fail(where + ": unknown property type '" + type + "'");
        }
        property.Type = *scalar;
      }
      if (property.Name.empty())
      {
        fail(where + ": property without a name");
      }
      header.Elements.back().Properties.push_back(property);
    }
    else if (keyword == "end_header")
    {
      break;
    }
    // Any other line is ignored, as vtkPLYReader ignores it: exporters
    // write such lines (Blender 2.4's "Created by ..." without "comment").
  }
  if (!sawFormat)
  {
    fail("the header has no format line");
  }
  header.BodyOffset = lines.Position();
  return header;
}

// A mesh needs a vertex element with scalar x, y and z. Elements are
// looked up by name, so a repeated one is ambiguous. Faces need their
// vertex indices as a list (vertex_indices or vertex_index).
const Element& CheckElements(const std::string& path, const Header& header)
{
  const HeaderFailure fail{ path };
  const Element* vertices = nullptr;
  for (std::size_t e = 0; e < header.Elements.size(); ++e)
  {
    const Element& element = header.Elements[e];
    for (std::size_t other = 0; other < e; ++other)
    {
      // The reader looks the vertices and faces up by name; it skips other
      // elements whatever their names.
      if (header.Elements[other].Name == element.Name &&
        (element.Name == "vertex" || element.Name == "face"))
      {
        fail("element '" + element.Name + "' appears twice");
      }
    }
    if (element.Name == "vertex")
    {
      vertices = &element;
    }
    // The reader reads faces from the face element only: strips (a
    // 'tristrips' element) or faces under another name would be lost.
    const bool indexed =
      std::any_of(element.Properties.begin(), element.Properties.end(), [](const Property& p) {
        return p.IsList && (p.Name == "vertex_indices" || p.Name == "vertex_index");
      });
    if (element.Name != "face" && indexed && element.Count > 0)
    {
      fail.Unsupported("its element '" + element.Name +
        "' holds vertex indices, which vtkPLYReader 9.1 does not read (it reads the 'face' "
        "element only); write them as faces");
    }
    // The reader frees an uninitialised pointer for each face without
    // indices, and crashes closing the file when the face element has none
    // even with no faces (found by fuzz_mesh_io).
    if (element.Name == "face" &&
      std::none_of(element.Properties.begin(), element.Properties.end(),
        [&element](const Property& property) { return IsVertexIndexList(element, property); }))
    {
      fail("the face element has no 'vertex_indices' list");
    }
  }
  if (!vertices)
  {
    fail("there is no vertex element");
  }
  // The reader reads the vertices first wherever they are, and crashes
  // when the faces come before them.
  for (const Element& element : header.Elements)
  {
    if (&element == vertices)
    {
      break;
    }
    if (element.Name == "face" && element.Count > 0)
    {
      fail.Unsupported("its faces come before its vertices, which is valid PLY but "
                       "vtkPLYReader 9.1 cannot read (write the vertex element first)");
    }
  }
  for (const char* axis : { "x", "y", "z" })
  {
    const auto found = std::find_if(vertices->Properties.begin(), vertices->Properties.end(),
      [axis](const Property& property) { return property.Name == axis; });
    if (found == vertices->Properties.end() || found->IsList)
    {
      fail(std::string("the vertex element has no scalar '") + axis + "' property");
    }
  }
  return *vertices;
}

} // namespace ply
} // namespace cli
