#include "LegacyCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

namespace cli
{
namespace
{

// vtkDataReader reads words (vtkDataReader::ReadString) into 256-character
// buffers: a longer word is read as two.
constexpr std::size_t MaximumWord = 255;

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
    const std::string version = this->Line();
    if (version.rfind("# vtk DataFile Version", 0) != 0)
    {
      this->Fail("the first line is not '# vtk DataFile Version ...'");
    }
    // As vtkDataReader parses it: a version it cannot read as "%d.%d" counts
    // as 0, and cells then have the legacy layout, however 5-like the line.
    int major = 0, minor = 0;
    // It reads the line's first 255 characters (a 256-byte buffer).
    const std::string read = version.substr(0, 255);
    this->MajorVersion =
      std::sscanf(read.c_str(), "# vtk DataFile Version %d.%d", &major, &minor) == 2 ? major : 0;
    this->Line(); // the title
    // The format is a word, not a line: what follows it on its line is read
    // as the next word (the DATASET keyword).
    const std::string format = Lowercase(this->Word());
    this->Binary = format.rfind("binary", 0) == 0;
    if (!this->Binary && format.rfind("ascii", 0) != 0)
    {
      this->Fail("the third line is neither ASCII nor BINARY");
    }
    if (Lowercase(this->Word()) != "dataset" || Lowercase(this->Word()) != "polydata")
    {
      this->Fail("no 'DATASET POLYDATA' line");
    }
    std::vector<std::string> sections; // the geometry's, each at most once
    while (true)
    {
      const std::string keyword = Lowercase(this->Word());
      const bool geometry = keyword == "points" || keyword == "vertices" || keyword == "lines" ||
        keyword == "polygons" || keyword == "triangle_strips";
      if (geometry && std::find(sections.begin(), sections.end(), keyword) != sections.end())
      {
        this->Fail("a second " + Uppercase(keyword) +
          " section, which vtkPolyDataReader reads "
          "in place of the first");
      }
      if (geometry)
      {
        sections.push_back(keyword);
      }
      if (keyword == "points")
      {
        const long long count = this->Count("POINTS");
        const std::string type = Lowercase(this->Word());
        this->Values(3 * count, type, "POINTS");
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
        this->Attributes(this->Count(keyword));
        return;
      }
      else if (keyword == "metadata")
      {
        this->SkipMetadata();
      }
      else
      {
        this->RequireNotAPrefix(keyword);
        return; // the end of the file, or a keyword the reader reports itself
      }
    }
  }

private:
  // vtkPolyDataReader compares keywords by prefix ("POINTS\x02..." is POINTS
  // to it): such a word is an error here, not a section left unchecked.
  void RequireNotAPrefix(const std::string& keyword)
  {
    for (const char* known :
      { "field", "points", "vertices", "lines", "polygons", "triangle_strips", "cell_data",
        "point_data", "scalars", "color_scalars", "lookup_table", "vectors", "normals",
        "texture_coordinates", "tensors", "global_ids", "pedigree_ids", "edge_flags", "metadata" })
    {
      if (keyword.rfind(known, 0) == 0)
      {
        this->Fail("unknown keyword '" + Excerpt(keyword) + "'");
      }
    }
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
  void Attributes(long long count)
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
        values(perTuple, Lowercase(this->Word()));
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
        count = this->Count(keyword);
      }
      else if (keyword == "metadata")
      {
        this->SkipMetadata();
      }
      else
      {
        this->RequireNotAPrefix(keyword);
        return; // the end of the file, or a keyword the reader reports itself
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
  // Words are read as vtkDataReader::ReadString reads them, into 256-byte
  // buffers: a longer word is two (its name, then its type, for a SCALARS
  // line). Numbers are read whole, as iostream reads them.
  std::string Word(std::size_t limit = MaximumWord) { return this->Text.Word(limit); }

  // An ASCII integer as iostream reads it: digits only, in range.
  long long Integer(const std::string& what)
  {
    const std::string word = this->Word(std::string::npos);
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

  // `count` values of `type`; returned (as integers) only when `keep`.
  std::vector<long long> Values(
    long long count, const std::string& type, const std::string& what, bool keep = false)
  {
    std::vector<long long> kept;
    if (count < 0 || count > static_cast<long long>(this->Bytes.size()))
    {
      this->Fail(what + ": " + std::to_string(count) + " values cannot fit in the file");
    }
    if (type == "string" || type == "utf8_string")
    {
      this->Strings(count, what);
      return kept;
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
      this->Text.Skip(static_cast<std::size_t>(count + 7) / 8);
      return kept;
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
      for (long long i = 0; keep && i < count; ++i)
      {
        long long value = 0; // big-endian, signed
        const auto* raw = reinterpret_cast<const unsigned char*>(
          this->Bytes.data() + this->Text.Position() + i * size);
        value = (raw[0] & 0x80) ? -1 : 0;
        for (std::size_t b = 0; b < size; ++b)
        {
          value = static_cast<long long>((static_cast<unsigned long long>(value) << 8) | raw[b]);
        }
        kept.push_back(value);
      }
      this->Text.Skip(static_cast<std::size_t>(count) * size);
      return kept;
    }
    for (long long i = 0; i < count; ++i)
    {
      if (integer)
      {
        const long long value = this->Integer(what);
        // The reader reads an integer and casts it to the array's type: a
        // value beyond the type's range would wrap without a word.
        const std::pair<long double, long double> range = IntegerRange(type);
        if (value < range.first || value > range.second)
        {
          this->Fail(what + ": " + std::to_string(value) + " does not fit in its type, " + type);
        }
        if (keep)
        {
          kept.push_back(value);
        }
        continue;
      }
      const std::string word = this->Word(std::string::npos);
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
      // iostream fails on a value its type cannot hold, and the reader with it.
      if (!std::isfinite(value) ||
        (type == "float" && std::abs(value) > std::numeric_limits<float>::max()))
      {
        this->Fail(what + ": '" + Excerpt(word) + "' does not fit in a " + type);
      }
    }
    return kept;
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

  void Cells(const std::string& keyword)
  {
    const std::string what = Uppercase(keyword);
    const long long first = this->Count(what);
    const long long second = this->Count(what);
    if (this->MajorVersion >= 5)
    {
      // "POLYGONS offsets connectivity", then OFFSETS and CONNECTIVITY arrays.
      if (Lowercase(this->Word()) != "offsets")
      {
        this->Fail(what + ": no OFFSETS array");
      }
      const std::vector<long long> offsets =
        this->Values(first, Lowercase(this->Word()), what + " OFFSETS", true);
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
      this->Values(second, Lowercase(this->Word()), what + " CONNECTIVITY");
      return;
    }
    // Legacy layout: "POLYGONS cells size", then size ints: n id id ... per cell.
    const std::vector<long long> data = this->Values(second, "int", what, true);
    std::size_t at = 0;
    for (long long cell = 0; cell < first; ++cell)
    {
      if (at >= data.size() || data[at] < 0 ||
        static_cast<unsigned long long>(data[at]) >= data.size() - at)
      {
        this->Fail(what + ": cell " + std::to_string(cell) + " does not fit in the declared size");
      }
      at += static_cast<std::size_t>(data[at]) + 1;
    }
    if (at != data.size())
    {
      this->Fail(what + ": the cells do not fill the declared size");
    }
  }

  std::string Path;
  std::string Bytes;
  TextCursor Text;
  int MajorVersion = 0;
  bool Binary = false;
};

} // namespace

void CheckLegacyVtkFile(const std::string& path)
{
  LegacyChecker(path, ReadFileBytes(path)).Check();
}

} // namespace cli
