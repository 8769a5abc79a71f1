#include "LegacyCheck.h"

#include "CliErrors.h"
#include "FileGeometry.h"
#include "TextScanning.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace cli
{
namespace
{

// Bytes per value of a legacy data type in a BINARY file; 0 if unknown.
std::size_t BinarySize(const std::string& type)
{
  static const std::pair<const char*, std::size_t> sizes[] = { { "char", 1 },
    { "unsigned_char", 1 }, { "short", 2 }, { "unsigned_short", 2 }, { "int", 4 },
    { "unsigned_int", 4 }, { "long", 8 }, { "unsigned_long", 8 }, { "float", 4 }, { "double", 8 },
    { "vtktypeint64", 8 }, { "vtktypeuint64", 8 }, { "signed_char", 1 },
    // vtkDataWriter writes vtkIdType as int, and the reader reads it so.
    { "vtkidtype", 4 } };
  for (const auto& size : sizes)
  {
    if (type == size.first)
    {
      return size.second;
    }
  }
  return 0;
}

// The values an integer type of the legacy format holds (a bit: 0 or 1).
std::pair<long double, long double> IntegerRange(const std::string& type)
{
  if (type == "bit")
  {
    return { 0, 1 };
  }
  if (type == "unsigned_char" || type == "unsigned_short" || type == "unsigned_int" ||
    type == "unsigned_long" || type == "vtktypeuint64")
  {
    return { 0, std::ldexp(1.0L, 8 * static_cast<int>(BinarySize(type))) - 1 };
  }
  const long double half = std::ldexp(1.0L, 8 * static_cast<int>(BinarySize(type)) - 1);
  return { -half, half - 1 };
}

std::string Uppercase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

// A value of a BINARY file: big-endian, integers signed unless their type
// says otherwise.
double BigEndianValue(const char* at, std::size_t size, const std::string& type, bool integer)
{
  const auto* raw = reinterpret_cast<const unsigned char*>(at);
  std::uint64_t bits = 0;
  for (std::size_t b = 0; b < size; ++b)
  {
    bits = (bits << 8) | raw[b];
  }
  if (!integer)
  {
    if (size == 4)
    {
      float value = 0.0F;
      const auto word = static_cast<std::uint32_t>(bits);
      std::memcpy(&value, &word, sizeof value);
      return value;
    }
    double value = 0.0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  if (IntegerRange(type).first == 0)
  {
    return static_cast<double>(bits);
  }
  const int shift = 64 - 8 * static_cast<int>(size); // sign-extend
  return static_cast<double>(static_cast<std::int64_t>(bits << shift) >> shift);
}

class LegacyChecker
{
public:
  LegacyChecker(const std::string& path, std::string bytes)
    : Path(path)
    , Bytes(std::move(bytes))
    , Text(this->Bytes)
  {
  }
  // The cursor points into Bytes: a copy would read the original's.
  LegacyChecker(const LegacyChecker&) = delete;
  LegacyChecker& operator=(const LegacyChecker&) = delete;

  void Check()
  {
    this->MajorVersion = this->Version(this->Line());
    this->Line(); // the title
    // The format is a word, not a line: what follows it on its line is read
    // as the next word (the DATASET keyword).
    const std::string format = Lowercase(this->Word());
    this->Binary = format == "binary";
    if (!this->Binary && format != "ascii")
    {
      this->Fail("the third line is neither ASCII nor BINARY");
    }
    if (Lowercase(this->Word()) != "dataset" || Lowercase(this->Word()) != "polydata")
    {
      this->Fail("no 'DATASET POLYDATA' line");
    }
    // The geometry's sections, each at most once.
    bool points = false;
    while (true)
    {
      const std::string keyword = Lowercase(this->Word());
      if (keyword == "points")
      {
        if (points)
        {
          this->Fail("a second POINTS section");
        }
        points = true;
        const long long count = this->Count("POINTS");
        const std::string type = Lowercase(this->Word());
        this->Values(3 * count, type, "POINTS", &this->Geometry.Positions);
      }
      else if (keyword == "vertices" || keyword == "lines" || keyword == "polygons" ||
        keyword == "triangle_strips")
      {
        this->Cells(keyword);
      }
      else if (keyword == "field")
      {
        this->Field();
      }
      else if (keyword == "point_data" || keyword == "cell_data")
      {
        this->Attributes(keyword, this->Count(keyword));
        return;
      }
      else if (keyword == "metadata")
      {
        this->SkipMetadata();
      }
      else
      {
        this->RequireEnd(keyword, "the geometry");
        return;
      }
    }
  }

  // The geometry read, once Check() has returned.
  FileGeometry Result()
  {
    FileGeometry geometry = std::move(this->Geometry);
    geometry.VertexOrderKept = true;
    geometry.FaceStarts = std::move(this->Faces.Starts);
    geometry.FaceCorners = std::move(this->Faces.Corners);
    if (geometry.Normals.size() != geometry.Positions.size())
    {
      geometry.Normals.clear(); // not one per point: the reader's to refuse
    }
    return geometry;
  }

private:
  FileGeometry Geometry;
  // "# vtk DataFile Version MAJOR.MINOR ...", and the major version.
  int Version(const std::string& line)
  {
    const std::string start = "# vtk DataFile Version";
    if (line.rfind(start, 0) != 0)
    {
      this->Fail("the first line is not '# vtk DataFile Version ...'");
    }
    const std::vector<std::string> words = WordsOf(line.substr(start.size()));
    const std::size_t dot = words.empty() ? std::string::npos : words[0].find('.');
    long long major = -1;
    long long minor = -1;
    // What follows the version on its line is free text, as in the title.
    if (words.empty() || dot == std::string::npos ||
      !ParseWholeInteger(words[0].substr(0, dot), major) ||
      !ParseWholeInteger(words[0].substr(dot + 1), minor) || major < 0 || minor < 0 || major > 99 ||
      !std::isdigit(static_cast<unsigned char>(words[0][0])) ||
      !std::isdigit(static_cast<unsigned char>(words[0][dot + 1])))
    {
      this->Fail("the first line's version is not MAJOR.MINOR, as '5.1'");
    }
    return static_cast<int>(major);
  }

  // What may end a part of the file: its end, or a keyword the part does
  // not have. Keywords are whole words, in any case.
  void RequireEnd(const std::string& keyword, const std::string& part)
  {
    if (keyword.empty())
    {
      return;
    }
    for (const char* known : { "field", "points", "vertices", "lines", "polygons",
           "triangle_strips", "cell_data", "point_data", "scalars", "color_scalars", "lookup_table",
           "vectors", "normals", "texture_coordinates", "tensors", "tensors6", "global_ids",
           "pedigree_ids", "edge_flags", "metadata" })
    {
      if (keyword == known)
      {
        this->Fail("'" + Uppercase(keyword) + "' in " + part + ", where it has no place");
      }
    }
    this->Fail("unknown keyword '" + Excerpt(keyword) + "'");
  }

  // An array's METADATA block (component names, information keys), which
  // VTK 9 writes after the array and ends with a blank line.
  void SkipMetadata()
  {
    this->Text.SkipToNextLine();
    for (std::string line; this->Text.NextLine(line);)
    {
      if (line.find_first_not_of(" \t\r") == std::string::npos)
      {
        return;
      }
    }
  }

  // FIELD name arrays, then per array: name components tuples type, values.
  void Field()
  {
    this->Word(); // the name
    const long long arrays = this->Count("FIELD");
    for (long long a = 0; a < arrays; ++a)
    {
      const std::string name = this->Word();
      if (name == "NULL_ARRAY")
      {
        continue;
      }
      const long long components = this->Count("FIELD array");
      const long long tuples = this->Count("FIELD array");
      if (components > 0 && tuples > static_cast<long long>(this->Bytes.size()) / components)
      {
        this->Fail("FIELD array: " + std::to_string(components) + " x " + std::to_string(tuples) +
          " values cannot fit in the file");
      }
      this->Values(components * tuples, Lowercase(this->Word()), "FIELD array");
    }
  }

  // POINT_DATA / CELL_DATA sections, to the end of the file.
  void Attributes(std::string section, long long count)
  {
    while (true)
    {
      const std::string keyword = Lowercase(this->Word());
      const auto values = [&](long long perTuple, const std::string& type) {
        this->Values(perTuple * count, type, keyword);
      };
      if (keyword == "scalars")
      {
        this->Word();
        const std::string type = Lowercase(this->Word());
        const std::string rest = this->Text.RestOfLine();
        const int components =
          rest.find_first_not_of(" \t\r") == std::string::npos ? 1 : std::atoi(rest.c_str());
        if (components < 1)
        {
          this->Fail("SCALARS: " + std::to_string(components) + " components");
        }
        if (Lowercase(this->Word()) != "lookup_table")
        {
          this->Fail("SCALARS: no LOOKUP_TABLE line");
        }
        this->Word();
        values(components, type);
      }
      else if (keyword == "color_scalars")
      {
        this->Word();
        values(this->Count(keyword), this->Binary ? "unsigned_char" : "float");
      }
      else if (keyword == "lookup_table")
      {
        this->Word();
        const long long size = this->Count(keyword);
        this->Values(4 * size, this->Binary ? "unsigned_char" : "float", keyword);
      }
      else if (keyword == "vectors" || keyword == "normals" || keyword == "tensors" ||
        keyword == "tensors6" || keyword == "global_ids" || keyword == "pedigree_ids" ||
        keyword == "edge_flags")
      {
        this->Word();
        const long long perTuple = keyword == "vectors" || keyword == "normals" ? 3
          : keyword == "tensors"                                                ? 9
          : keyword == "tensors6"                                               ? 6
                                                                                : 1;
        // The points' first NORMALS are their normals.
        const bool pointNormals =
          keyword == "normals" && section == "point_data" && !this->PointNormalsSeen;
        this->PointNormalsSeen = this->PointNormalsSeen || pointNormals;
        this->Values(perTuple * count, Lowercase(this->Word()), keyword,
          pointNormals ? &this->Geometry.Normals : nullptr);
      }
      else if (keyword == "texture_coordinates")
      {
        this->Word();
        const long long dimension = this->Count(keyword);
        if (dimension < 1 || dimension > 3)
        {
          this->Fail("TEXTURE_COORDINATES: dimension " + std::to_string(dimension));
        }
        values(dimension, Lowercase(this->Word()));
      }
      else if (keyword == "field")
      {
        this->Field();
      }
      else if (keyword == "point_data" || keyword == "cell_data")
      {
        section = keyword;
        count = this->Count(keyword);
      }
      else if (keyword == "metadata")
      {
        this->SkipMetadata();
      }
      else
      {
        this->RequireEnd(keyword, Uppercase(section));
        return;
      }
    }
  }

  [[noreturn]] void Fail(const std::string& problem) const
  {
    throw RuntimeError("cannot read '" + this->Path + "': malformed legacy VTK file: " + problem);
  }

  // The version line or the title. Only the version line's start matters,
  // so a long one, a long title say, is read whole: vtkDataReader reads the
  // start of it and skips the rest.
  std::string Line()
  {
    std::string line;
    bool ended = false;
    if (!this->Text.NextLine(line, &ended) || !ended)
    {
      this->Fail("the file ends inside its header");
    }
    return line;
  }

  // The next whitespace-separated word, "" at the end of the file.
  std::string Word() { return this->Text.Word(); }

  // An ASCII integer as iostream reads it: digits only, in range.
  long long Integer(const std::string& what)
  {
    const std::string word = this->Word();
    if (word.empty())
    {
      this->Fail(what + ": the file ends inside the data");
    }
    // At least one digit after an optional sign: a lone "+" is no number to
    // vtkPolyDataReader, which then leaves the array out and crashes (found
    // by fuzz_mesh_io in a FIELD array's tuple count).
    long long value = 0;
    if (!ParseWholeInteger(word, value))
    {
      this->Fail(what + ": '" + Excerpt(word) + "' is not an integer");
    }
    return value;
  }

  long long Count(const std::string& what)
  {
    const long long count = this->Integer(what);
    if (count < 0 || count > static_cast<long long>(this->Bytes.size()))
    {
      this->Fail(what + ": a count of " + std::to_string(count) + " cannot fit in the file");
    }
    return count;
  }

  // `count` values of `type`, appended to `kept` when it is given.
  void Values(long long count, const std::string& type, const std::string& what,
    std::vector<double>* kept = nullptr)
  {
    if (count < 0 || count > static_cast<long long>(this->Bytes.size()))
    {
      this->Fail(what + ": " + std::to_string(count) + " values cannot fit in the file");
    }
    if (type == "string" || type == "utf8_string")
    {
      this->Strings(count, what);
      return;
    }
    if (type == "bit" && this->Binary)
    {
      // Packed, eight values to a byte.
      this->Text.SkipToNextLine();
      if (static_cast<unsigned long long>(count + 7) / 8 >
        this->Bytes.size() - this->Text.Position())
      {
        this->Fail(what + ": the file ends inside the data (truncated binary data)");
      }
      for (long long i = 0; kept && i < count; ++i)
      {
        const auto byte = static_cast<unsigned char>(this->Bytes[this->Text.Position() + i / 8]);
        kept->push_back((byte >> (7 - i % 8)) & 1u);
      }
      this->Text.Skip(static_cast<std::size_t>(count + 7) / 8);
      return;
    }
    // ASCII bits are integers.
    const std::size_t size = type == "bit" ? 1 : BinarySize(type);
    if (size == 0)
    {
      this->Fail(what + ": unknown data type '" + Excerpt(type) + "'");
    }
    const bool integer = type != "float" && type != "double";
    if (this->Binary)
    {
      this->Text.SkipToNextLine();
      if (static_cast<unsigned long long>(count) * size >
        this->Bytes.size() - this->Text.Position())
      {
        this->Fail(what + ": the file ends inside the data (truncated binary data)");
      }
      for (long long i = 0; kept && i < count; ++i)
      {
        kept->push_back(BigEndianValue(
          this->Bytes.data() + this->Text.Position() + i * size, size, type, integer));
      }
      this->Text.Skip(static_cast<std::size_t>(count) * size);
      return;
    }
    for (long long i = 0; i < count; ++i)
    {
      if (integer)
      {
        const long long value = this->Integer(what);
        // Each value must fit in its type (a reader reads an integer and
        // casts it to the array's type).
        const std::pair<long double, long double> range = IntegerRange(type);
        if (value < range.first || value > range.second)
        {
          this->Fail(what + ": " + std::to_string(value) + " does not fit in its type, " + type);
        }
        if (kept)
        {
          kept->push_back(static_cast<double>(value));
        }
        continue;
      }
      const std::string word = this->Word();
      if (word.empty())
      {
        this->Fail(what + ": the file ends inside the data");
      }
      double value = 0.0;
      const bool whole = ParseWholeNumber(word, value);
      const bool plain = std::all_of(word.begin(), word.end(), [](unsigned char c) {
        return std::isdigit(c) || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E';
      });
      if (!whole || !plain)
      {
        this->Fail(what + ": '" + Excerpt(word) + "' is not a number");
      }
      if (!std::isfinite(value) ||
        (type == "float" && std::abs(value) > std::numeric_limits<float>::max()))
      {
        this->Fail(what + ": '" + Excerpt(word) + "' does not fit in a " + type);
      }
      if (kept)
      {
        kept->push_back(value);
      }
    }
  }

  // `count` strings: in ASCII a line each (percent-encoded) after the line
  // of the array's header; in binary each after a big-endian length whose
  // first byte's top two bits say its size (11: one byte, 10: two, 01: four,
  // 00: eight), as vtkDataWriter writes them.
  void Strings(long long count, const std::string& what)
  {
    this->Text.SkipToNextLine();
    for (long long i = 0; i < count; ++i)
    {
      if (!this->Binary)
      {
        std::string line;
        if (!this->Text.NextLine(line))
        {
          this->Fail(what + ": the file ends inside the data");
        }
        continue;
      }
      const std::size_t at = this->Text.Position();
      const std::size_t left = this->Bytes.size() - at;
      const auto* raw = reinterpret_cast<const unsigned char*>(this->Bytes.data() + at);
      const std::size_t header = left == 0 ? 1 : std::size_t{ 1 } << (3 - (raw[0] >> 6));
      if (left < header)
      {
        this->Fail(what + ": the file ends inside the data (truncated binary data)");
      }
      unsigned long long length = raw[0] & 0x3fu; // below the two bits of the size
      for (std::size_t b = 1; b < header; ++b)
      {
        length = (length << 8) | raw[b];
      }
      if (length > left - header)
      {
        this->Fail(what + ": the file ends inside the data (truncated binary data)");
      }
      this->Text.Skip(header + static_cast<std::size_t>(length));
    }
  }

  // A cell section, kept in the geometry: "POLYGONS offsets connectivity"
  // and the two arrays (5.x), or "POLYGONS cells size" and per cell its
  // size and point ids (earlier versions).
  void Cells(const std::string& keyword)
  {
    const std::string what = Uppercase(keyword);
    FileCells& cells = this->CellsOf(keyword);
    cells.Given = true;
    const long long first = this->Count(what);
    const long long second = this->Count(what);
    if (this->MajorVersion >= 5)
    {
      if (Lowercase(this->Word()) != "offsets")
      {
        this->Fail(what + ": no OFFSETS array");
      }
      std::vector<double> offsets;
      this->Values(first, this->IndexType(what + " OFFSETS"), what + " OFFSETS", &offsets);
      for (std::size_t i = 0; i < offsets.size(); ++i)
      {
        if ((i == 0 && offsets[i] != 0) || (i > 0 && offsets[i] < offsets[i - 1]) ||
          offsets[i] > second)
        {
          this->Fail(what + ": offset " + std::to_string(i) + " is out of order or range");
        }
      }
      if (!offsets.empty() && offsets.back() != second)
      {
        this->Fail(what + ": the offsets do not end at the connectivity size");
      }
      if (Lowercase(this->Word()) != "connectivity")
      {
        this->Fail(what + ": no CONNECTIVITY array");
      }
      std::vector<double> ids;
      this->Values(second, this->IndexType(what + " CONNECTIVITY"), what + " CONNECTIVITY", &ids);
      for (std::size_t i = 0; i + 1 < offsets.size(); ++i)
      {
        for (auto k = static_cast<std::size_t>(offsets[i]);
             k < static_cast<std::size_t>(offsets[i + 1]); ++k)
        {
          cells.Corners.push_back(static_cast<std::int64_t>(ids[k]));
        }
        cells.EndCell();
      }
      return;
    }
    std::vector<double> data;
    this->Values(second, "int", what, &data);
    std::size_t at = 0;
    for (long long cell = 0; cell < first; ++cell)
    {
      if (at >= data.size() || data[at] < 0 || data[at] >= static_cast<double>(data.size() - at))
      {
        this->Fail(what + ": cell " + std::to_string(cell) + " does not fit in the declared size");
      }
      const auto size = static_cast<std::size_t>(data[at]);
      for (std::size_t k = 1; k <= size; ++k)
      {
        cells.Corners.push_back(static_cast<std::int64_t>(data[at + k]));
      }
      cells.EndCell();
      at += size + 1;
    }
    if (at != data.size())
    {
      this->Fail(what + ": the cells do not fill the declared size");
    }
  }

  // The type of an array of offsets or point ids: an integer type.
  std::string IndexType(const std::string& what)
  {
    const std::string type = Lowercase(this->Word());
    if (type == "float" || type == "double" || type == "string" || type == "utf8_string" ||
      type == "bit")
    {
      this->Fail(what + ": '" + Excerpt(type) + "' is not an integer type");
    }
    return type;
  }

  FileCells& CellsOf(const std::string& keyword)
  {
    FileCells& cells = keyword == "vertices" ? this->Geometry.Vertices
      : keyword == "lines"                   ? this->Geometry.Lines
      : keyword == "triangle_strips"         ? this->Geometry.Strips
                                             : this->Faces;
    if (cells.Given)
    {
      this->Fail("a second " + Uppercase(keyword) + " section");
    }
    return cells;
  }

  std::string Path;
  std::string Bytes;
  TextCursor Text;
  int MajorVersion = 0;
  bool Binary = false;
  bool PointNormalsSeen = false;
  FileCells Faces;
};

} // namespace

FileGeometry CheckLegacyVtkFile(const std::string& path)
{
  LegacyChecker checker(path, ReadFileBytes(path));
  checker.Check();
  return checker.Result();
}

} // namespace cli
