#include "PlyCheck.h"

#include "CliErrors.h"
#include "PlyHeader.h"
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

// Words of an ASCII body line: PLY separates them by spaces (and tabs).
constexpr const char* WordSeparators = " \t";

using namespace ply;

// A value of type T from its bytes, already in host order.
template<typename T>
double FromBytes(const unsigned char* raw)
{
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return static_cast<double>(value);
}

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
    const Header header = ReadHeader(this->Path, this->Bytes);
    const Element& vertices = CheckElements(this->Path, header);
    this->VertexCount = vertices.Count;
    this->FindGeometrySlots(vertices);
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
