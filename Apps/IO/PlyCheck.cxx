#include "PlyCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

namespace cli
{
namespace
{

// The PLY format separates the words of a line by spaces (tabs are common
// too): any other byte, a control character or a NUL among them, is part of
// a word, so a number or a name holding one is not what it seems.
constexpr const char* WordSeparators = " \t";

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

// A value of type T from its bytes, already in host order.
template<typename T>
double FromBytes(const unsigned char* raw)
{
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return static_cast<double>(value);
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

class PlyChecker
{
public:
  PlyChecker(const std::string& path, std::string bytes)
    : Path(path)
    , Bytes(std::move(bytes))
  {
  }
  // The cursor points into Bytes: a copy would read the original's.
  PlyChecker(const PlyChecker&) = delete;
  PlyChecker& operator=(const PlyChecker&) = delete;

  PlyFacts Check()
  {
    const Header header = this->ReadHeader();
    this->CheckElements(header);
    this->Body = TextCursor(this->Bytes, header.BodyOffset);
    for (const Element& element : header.Elements)
    {
      for (long long i = 0; i < element.Count; ++i)
      {
        if (header.BodyFormat == Format::Ascii)
        {
          this->CheckAsciiInstance(element, i);
        }
        else
        {
          this->CheckBinaryInstance(element, i, header.BodyFormat == Format::BinaryBigEndian);
        }
      }
    }
    this->CheckEnd(header);
    // vtkPLYReader 9.1 frees a line buffer twice when the last line of an
    // ASCII body has no line end.
    if (header.BodyFormat == Format::Ascii && !this->Bytes.empty() && this->Bytes.back() != '\n')
    {
      this->Unsupported("its last line has no line end, which vtkPLYReader 9.1 cannot read (it "
                        "crashes); end the file with a newline");
    }
    // The reader takes texture coordinates from the vertices when they have
    // them (u and v, or texture_u and texture_v), and then ignores the faces'.
    const auto has = [&header](const char* element, const char* property) {
      return std::any_of(header.Elements.begin(), header.Elements.end(), [&](const Element& e) {
        return e.Name == element &&
          std::any_of(e.Properties.begin(), e.Properties.end(),
            [&](const Property& p) { return p.Name == property; });
      });
    };
    const bool vertexTextures = (has("vertex", "u") && has("vertex", "v")) ||
      (has("vertex", "texture_u") && has("vertex", "texture_v"));
    PlyFacts& facts = this->Facts;
    facts.FaceTextureCoordinates = has("face", "texcoord") && !vertexTextures;
    facts.UnreadVertexTextureCoordinates = !vertexTextures &&
      ((has("vertex", "s") && has("vertex", "t")) ||
        (has("vertex", "texture_s") && has("vertex", "texture_t")));
    return std::move(facts);
  }

private:
  [[noreturn]] void Fail(const std::string& problem) const
  {
    throw RuntimeError("cannot read '" + this->Path + "': malformed PLY: " + problem);
  }

  // For valid PLY that VTK 9.1's reader gets wrong.
  [[noreturn]] void Unsupported(const std::string& problem) const
  {
    throw RuntimeError("cannot read '" + this->Path + "': " + problem);
  }

  Header ReadHeader()
  {
    Header header;
    std::size_t lineNumber = 0;
    bool sawFormat = false;
    TextCursor lines(this->Bytes);
    while (true)
    {
      std::string line;
      bool ended = false;
      if (!lines.NextLine(line, &ended) || !ended)
      {
        this->Fail(lineNumber == 0 ? "empty file" : "the header has no end_header line");
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
          this->Fail("the file does not start with 'ply'");
        }
        continue;
      }
      if (keyword == "format")
      {
        const std::string format = word(1);
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
          this->Fail(where + ": unknown format '" + format + "'");
        }
        sawFormat = true;
      }
      else if (keyword == "element")
      {
        Element element;
        element.Name = word(1);
        if (element.Name.empty() || !ParseWholeInteger(word(2), element.Count) || element.Count < 0)
        {
          this->Fail(where + ": bad element line '" + line + "'");
        }
        header.Elements.push_back(element);
      }
      else if (keyword == "property")
      {
        if (header.Elements.empty())
        {
          this->Fail(where + ": property before any element");
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
            this->Fail(where + ": bad list property '" + line + "'");
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
            this->Fail(where + ": unknown property type '" + type + "'");
          }
          property.Type = *scalar;
        }
        if (property.Name.empty())
        {
          this->Fail(where + ": property without a name");
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
      this->Fail("the header has no format line");
    }
    header.BodyOffset = lines.Position();
    return header;
  }

  // A mesh needs a vertex element with scalar x, y and z. Elements are
  // looked up by name, so a repeated one is ambiguous. Faces need their
  // vertex indices as a list (vertex_indices or vertex_index).
  void CheckElements(const Header& header)
  {
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
          this->Fail("element '" + element.Name + "' appears twice");
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
        this->Unsupported("its element '" + element.Name +
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
        this->Fail("the face element has no 'vertex_indices' list");
      }
    }
    if (!vertices)
    {
      this->Fail("there is no vertex element");
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
        this->Unsupported("its faces come before its vertices, which is valid PLY but "
                          "vtkPLYReader 9.1 cannot read (write the vertex element first)");
      }
    }
    for (const char* axis : { "x", "y", "z" })
    {
      const auto found = std::find_if(vertices->Properties.begin(), vertices->Properties.end(),
        [axis](const Property& property) { return property.Name == axis; });
      if (found == vertices->Properties.end() || found->IsList)
      {
        this->Fail(std::string("the vertex element has no scalar '") + axis + "' property");
      }
    }
    this->VertexCount = vertices->Count;
    this->FindGeometrySlots(*vertices);
  }

  // Which of the vertex element's properties are the position (slots 0 to
  // 2) and the normal (3 to 5, all three or none), as the reader maps them.
  void FindGeometrySlots(const Element& vertices)
  {
    static const char* const names[6] = { "x", "y", "z", "nx", "ny", "nz" };
    const std::vector<Property>& properties = vertices.Properties;
    this->VertexSlot.assign(properties.size(), -1);
    int normals = 0;
    for (int slot = 0; slot < 6; ++slot)
    {
      // The first of a repeated name, as the reader looks it up.
      const auto found = std::find_if(properties.begin(), properties.end(),
        [&](const Property& property) { return !property.IsList && property.Name == names[slot]; });
      if (found != properties.end())
      {
        this->VertexSlot[static_cast<std::size_t>(found - properties.begin())] = slot;
        normals += slot >= 3 ? 1 : 0;
      }
    }
    this->Facts.Geometry.VertexOrderKept = true;
    this->HasNormals = normals == 3;
  }

  static bool IsVertexIndexList(const Element& element, const Property& property)
  {
    return element.Name == "face" && property.IsList &&
      (property.Name == "vertex_indices" || property.Name == "vertex_index");
  }

  void CheckVertexIndex(double index, long long face) const
  {
    if (!(index >= 0.0 && index < static_cast<double>(this->VertexCount)))
    {
      std::ostringstream problem;
      problem << "face " << face << " refers to vertex " << std::fixed << std::setprecision(0)
              << index << " but there are " << this->VertexCount << " vertices";
      this->Fail(problem.str());
    }
    // Indices in a list of floats: the reader truncates them.
    if (index != std::trunc(index))
    {
      std::ostringstream problem;
      problem << "face " << face << " refers to vertex " << index
              << ", which is not a whole number (vtkPLYReader would take vertex "
              << static_cast<long long>(index) << ")";
      this->Fail(problem.str());
    }
  }

  // The values of one element, as they are read: a vertex's position and
  // normal, a face's vertex indices, go to the file's geometry.
  class InstanceRecorder
  {
  public:
    InstanceRecorder(PlyChecker& checker, const Element& element)
      : Checker(checker)
      , IsVertex(element.Name == "vertex")
      , IsFace(element.Name == "face")
    {
    }
    void Scalar(std::size_t property, double value)
    {
      if (this->IsVertex && this->Checker.VertexSlot[property] >= 0)
      {
        this->Vertex[this->Checker.VertexSlot[property]] = value;
      }
    }
    // The face's first index list is its corners (the reader reads one).
    bool TakesCorners(const Element& element, const Property& property)
    {
      const bool takes =
        this->IsFace && !this->CornersTaken && IsVertexIndexList(element, property);
      this->CornersTaken = this->CornersTaken || takes;
      return takes;
    }
    void Corner(double index)
    {
      this->Checker.Facts.Geometry.FaceCorners.push_back(static_cast<std::int64_t>(index));
    }
    void End()
    {
      FileGeometry& geometry = this->Checker.Facts.Geometry;
      if (this->IsVertex)
      {
        geometry.Positions.insert(geometry.Positions.end(), this->Vertex, this->Vertex + 3);
        if (this->Checker.HasNormals)
        {
          geometry.Normals.insert(geometry.Normals.end(), this->Vertex + 3, this->Vertex + 6);
        }
      }
      else if (this->IsFace)
      {
        geometry.EndFace();
      }
    }

  private:
    PlyChecker& Checker;
    bool IsVertex;
    bool IsFace;
    bool CornersTaken = false;
    double Vertex[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  };

  // The next line of the ASCII body that holds anything, without its '\r'.
  bool NextAsciiLine(std::string& text)
  {
    while (this->Body.NextLine(text))
    {
      if (!text.empty() && text.back() == '\r')
      {
        text.pop_back();
      }
      if (text.find_first_not_of(WordSeparators) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }

  // ASCII: one element a line, each line exactly the element's values. A
  // line of white space holds no element (vtkPLYReader 9.1 stops there: the
  // comparison with the file's geometry refuses what it then reads).
  void CheckAsciiInstance(const Element& element, long long instance)
  {
    const std::string where = element.Name + " " + std::to_string(instance);
    std::string text;
    if (!this->NextAsciiLine(text))
    {
      this->Fail("the file ends before " + where);
    }
    const std::vector<std::string> words = WordsOf(text, WordSeparators);
    std::size_t next = 0;
    const auto number = [&](ScalarType type) {
      if (next >= words.size())
      {
        this->Fail(where + " has too few values");
      }
      const std::string& word = words[next++];
      double value = 0.0;
      if (!ParseWholeNumber(word, value) || (IsInteger(type) && std::trunc(value) != value))
      {
        this->Fail(where + " has a bad value '" + Excerpt(word) + "'");
      }
      if (value < RangeOf(type).first || value > RangeOf(type).second)
      {
        this->Fail(where + " has a value out of range for its type: '" + Excerpt(word) + "'");
      }
      // An integer in decimal digits: vtkPLYReader reads an integer's leading
      // decimal digits (atoi), so "1e2" or "0x10" in a colour would be read
      // as another value, which no comparison of the geometry would see.
      const long long leading = std::strtoll(word.c_str(), nullptr, 10);
      if (IsInteger(type) && static_cast<double>(leading) != value)
      {
        this->Fail(where + " has the integer '" + Excerpt(word) +
          "', which vtkPLYReader reads as " + std::to_string(leading) +
          "; write it in decimal digits");
      }
      return value;
    };
    InstanceRecorder record(*this, element);
    for (std::size_t p = 0; p < element.Properties.size(); ++p)
    {
      const Property& property = element.Properties[p];
      if (!property.IsList)
      {
        record.Scalar(p, number(property.Type));
        continue;
      }
      const double count = number(property.CountType);
      if (count < 0)
      {
        this->Fail(where + " has a negative list length");
      }
      const bool corners = record.TakesCorners(element, property);
      for (long long k = 0; k < static_cast<long long>(count); ++k)
      {
        const double value = number(property.Type);
        if (IsVertexIndexList(element, property))
        {
          this->CheckVertexIndex(value, instance);
        }
        if (corners)
        {
          record.Corner(value);
        }
      }
    }
    if (next != words.size())
    {
      this->Fail(where + " has too many values");
    }
    record.End();
  }

  double ReadBinary(ScalarType type, bool bigEndian, const std::string& where)
  {
    const std::size_t size = SizeOf(type);
    if (this->Bytes.size() - this->Body.Position() < size)
    {
      this->Fail("the file ends inside " + where + " (truncated binary body)");
    }
    unsigned char raw[8];
    std::memcpy(raw, this->Bytes.data() + this->Body.Position(), size);
    this->Body.Skip(size);
    // Assemble the value in host order from the file's byte order.
    const bool hostIsLittle = [] {
      const std::uint16_t one = 1;
      unsigned char first;
      std::memcpy(&first, &one, 1);
      return first == 1;
    }();
    if (bigEndian == hostIsLittle)
    {
      std::reverse(raw, raw + size);
    }
    switch (type)
    {
      case ScalarType::Int8:
        return FromBytes<std::int8_t>(raw);
      case ScalarType::UInt8:
        return FromBytes<std::uint8_t>(raw);
      case ScalarType::Int16:
        return FromBytes<std::int16_t>(raw);
      case ScalarType::UInt16:
        return FromBytes<std::uint16_t>(raw);
      case ScalarType::Int32:
        return FromBytes<std::int32_t>(raw);
      case ScalarType::UInt32:
        return FromBytes<std::uint32_t>(raw);
      case ScalarType::Float32:
        return FromBytes<float>(raw);
      case ScalarType::Float64:
      default:
        return FromBytes<double>(raw);
    }
  }

  void CheckBinaryInstance(const Element& element, long long instance, bool bigEndian)
  {
    const std::string where = element.Name + " " + std::to_string(instance);
    InstanceRecorder record(*this, element);
    for (std::size_t p = 0; p < element.Properties.size(); ++p)
    {
      const Property& property = element.Properties[p];
      if (!property.IsList)
      {
        record.Scalar(p, this->ReadBinary(property.Type, bigEndian, where));
        continue;
      }
      const double count = this->ReadBinary(property.CountType, bigEndian, where);
      if (count < 0)
      {
        this->Fail(where + " has a negative list length");
      }
      if (static_cast<double>(this->Bytes.size() - this->Body.Position()) <
        count * static_cast<double>(SizeOf(property.Type)))
      {
        this->Fail("the file ends inside " + where + " (truncated binary body)");
      }
      const bool corners = record.TakesCorners(element, property);
      for (long long k = 0; k < static_cast<long long>(count); ++k)
      {
        const double value = this->ReadBinary(property.Type, bigEndian, where);
        if (IsVertexIndexList(element, property))
        {
          this->CheckVertexIndex(value, instance);
        }
        if (corners)
        {
          record.Corner(value);
        }
      }
    }
    record.End();
  }

  // vtkPLYReader stops after the elements the header declares and ignores the
  // rest: with a count too small it drops faces without a word. Only white
  // space (a final newline, say) may follow the last element.
  void CheckEnd(const Header& header) const
  {
    const std::size_t from = this->Body.Position();
    const std::size_t extra = this->Bytes.find_first_not_of(" \t\r\n", from);
    if (extra == std::string::npos)
    {
      return;
    }
    const Element& last = header.Elements.back();
    const bool one = last.Count == 1;
    const std::string declared = std::to_string(last.Count) +
      (last.Name == "vertex"    ? (one ? " vertex" : " vertices")
          : last.Name == "face" ? (one ? " face" : " faces")
                                : " '" + last.Name + (one ? "' element" : "' elements"));
    if (header.BodyFormat == Format::Ascii)
    {
      const auto line = 1 + std::count(this->Bytes.begin(), this->Bytes.begin() + extra, '\n');
      this->Fail("the body holds more than the " + declared + " its header declares (line " +
        std::to_string(line) + ")");
    }
    this->Fail("the body holds " + std::to_string(this->Bytes.size() - from) +
      " bytes more than the " + declared + " its header declares");
  }

  std::string Path;
  std::string Bytes;
  TextCursor Body{ this->Bytes }; // where the body is read
  long long VertexCount = 0;
  std::vector<int> VertexSlot; // per vertex property: FindGeometrySlots
  bool HasNormals = false;
  PlyFacts Facts;
};

} // namespace

PlyFacts CheckPlyFile(const std::string& path)
{
  return PlyChecker(path, ReadFileBytes(path)).Check();
}

} // namespace cli
