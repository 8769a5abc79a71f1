#include "ObjCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

namespace cli
{
namespace
{

// One statement of the file, its lines joined, with the number of its first
// line.
struct Statement
{
  std::vector<std::string> Words;
  std::size_t Line = 0;
  const std::string& Keyword() const
  {
    static const std::string none;
    return this->Words.empty() ? none : this->Words[0];
  }
};

// How many of the vertices, texture coordinates and normals a corner's
// index may name: the whole file's, and (for a negative index, counted back)
// those before its statement.
struct IndexRange
{
  const char* What;
  long long Count;
  long long Before;
};

class ObjChecker
{
public:
  ObjChecker(const std::string& path, const std::string& bytes)
    : Path(path)
  {
    this->RefuseUtf16(bytes);
    this->SplitStatements(bytes);
  }

  FileGeometry Check()
  {
    this->Geometry.FirstIndex = 1;
    this->RefuseLongMaterialNames();
    this->ReadTables();
    this->ReadCells();
    return std::move(this->Geometry);
  }

private:
  [[noreturn]] void Fail(const Statement& statement, const std::string& problem) const
  {
    throw RuntimeError(
      "cannot read '" + this->Path + "': line " + std::to_string(statement.Line) + problem);
  }

  // A byte-order mark of UTF-16: vtkOBJReader reads bytes, and says only
  // that the first "line" is too long.
  void RefuseUtf16(const std::string& bytes) const
  {
    if (bytes.size() >= 2 &&
      ((bytes[0] == '\xFE' && bytes[1] == '\xFF') || (bytes[0] == '\xFF' && bytes[1] == '\xFE')))
    {
      throw RuntimeError("cannot read '" + this->Path +
        "': it is UTF-16 text; OBJ files are read as ASCII or UTF-8 (convert it, e.g. with iconv)");
    }
  }

  // vtkOBJReader 9.1 copies a material's name (the first word after
  // usemtl, up to white space) into a 100-byte buffer without a bound: a
  // name of 100 characters or more writes past it (a crash from 112 on in a
  // file with texture coordinates; shorter overruns corrupt it silently).
  // A usemtl with no name it refuses, saying only "Error reading 'usemtl'"
  // (assimp's empty_mat.obj): the user is told what to change.
  void RefuseLongMaterialNames() const
  {
    constexpr std::size_t buffer = 100;
    for (const Statement& statement : this->Statements)
    {
      if (statement.Keyword() != "usemtl")
      {
        continue;
      }
      if (statement.Words.size() < 2)
      {
        this->Fail(statement,
          ": 'usemtl' names no material, which vtkOBJReader refuses (name one, or delete the "
          "line)");
      }
      const std::string& name = statement.Words[1];
      const std::size_t length = static_cast<std::size_t>(
        std::find_if(name.begin(), name.end(),
          [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }) -
        name.begin());
      if (length >= buffer)
      {
        this->Fail(statement,
          ": the material name has " + std::to_string(length) +
            " characters; vtkOBJReader overruns its buffer on names of " + std::to_string(buffer) +
            " or more (shorten it)");
      }
    }
  }

  // The statements: a vertex, texture coordinate, normal, face, line or
  // point statement that ends in a backslash goes on on the next line (OBJ's
  // continuation); a comment or a name (mtllib, usemtl, o, g: Windows paths
  // end in backslashes) ends at its line. On a vertex, texture coordinate or
  // normal, a '#' starts a comment.
  void SplitStatements(const std::string& bytes)
  {
    if (bytes.find('\n') == std::string::npos && bytes.find('\r') != std::string::npos)
    {
      throw RuntimeError("cannot read '" + this->Path +
        "': its lines end in a carriage return alone (classic Mac OS); convert them to line "
        "feeds (e.g. with tr '\\r' '\\n')");
    }
    // A UTF-8 byte-order mark says how the text is encoded; it is no part of
    // the first statement.
    TextCursor cursor(bytes, bytes.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0);
    std::string text;
    std::size_t first = 0;
    std::size_t number = 0;
    for (std::string line; cursor.NextLine(line);)
    {
      ++number;
      if (!line.empty() && line.back() == '\r')
      {
        line.pop_back();
      }
      first = text.empty() ? number : first;
      text += line;
      if (!text.empty() && text.back() == '\\' && Continues(text))
      {
        text.back() = ' ';
        continue;
      }
      this->AddStatement(text, first);
      text.clear();
    }
    if (!text.empty())
    {
      this->AddStatement(text, first);
    }
  }

  static std::string Keyword(const std::string& text) { return TextCursor(text).Word(); }

  static bool Continues(const std::string& text)
  {
    const std::string keyword = Keyword(text);
    return keyword == "v" || keyword == "vt" || keyword == "vn" || keyword == "f" ||
      keyword == "l" || keyword == "p";
  }

  void AddStatement(std::string text, std::size_t line)
  {
    const std::string keyword = Keyword(text);
    if (keyword == "v" || keyword == "vt" || keyword == "vn")
    {
      text = text.substr(0, text.find('#'));
    }
    this->Statements.push_back(Statement{ WordsOf(text), line });
  }

  // The first `count` numbers of a statement (missing ones 0, when fewer
  // than `least` are missing): finite numbers, as OBJ writes them.
  std::vector<double> Numbers(
    const Statement& statement, std::size_t count, std::size_t least, const std::string& what) const
  {
    std::vector<double> values(count, 0.0);
    for (std::size_t w = 1; w < statement.Words.size(); ++w)
    {
      double value = 0.0;
      const std::string& word = statement.Words[w];
      if (!ParseWholeNumber(word, value) || !std::isfinite(value))
      {
        this->Fail(statement, ", " + what + ": '" + Excerpt(word) + "' is not a finite number");
      }
      if (w <= count)
      {
        values[w - 1] = value;
      }
    }
    if (statement.Words.size() < least + 1)
    {
      this->Fail(statement, ", " + what + ": fewer than " + std::to_string(least) + " values");
    }
    return values;
  }

  // The vertices, normals and texture coordinates: faces may name them
  // before they appear.
  void ReadTables()
  {
    long long vertices = 0, normals = 0, textures = 0;
    for (const Statement& statement : this->Statements)
    {
      const std::string& keyword = statement.Keyword();
      std::vector<double>* table = nullptr;
      std::vector<double> values;
      if (keyword == "v")
      {
        // x y z, then optional w or r g b.
        values = this->Numbers(statement, 3, 3, "vertex " + std::to_string(++vertices));
        table = &this->Geometry.Positions;
      }
      else if (keyword == "vn")
      {
        values = this->Numbers(statement, 3, 3, "normal " + std::to_string(++normals));
        table = &this->Geometry.NormalTable;
      }
      else if (keyword == "vt")
      {
        values = this->Numbers(statement, 2, 1, "texture coordinate " + std::to_string(++textures));
        table = &this->Geometry.TextureTable;
      }
      if (table)
      {
        table->insert(table->end(), values.begin(), values.end());
      }
    }
  }

  // The corners of faces, lines and points: v, v/vt, v//vn or v/vt/vn, each
  // index 1-based, or negative counting back from its statement.
  void ReadCells()
  {
    IndexRange points{ "point", this->Geometry.VertexCount(), 0 };
    IndexRange textures{ "texture coordinate",
      static_cast<long long>(this->Geometry.TextureTable.size() / 2), 0 };
    IndexRange normals{ "normal", static_cast<long long>(this->Geometry.NormalTable.size() / 3),
      0 };
    this->Geometry.LineCells = 0;
    this->Geometry.VertexCells = 0;
    for (const Statement& statement : this->Statements)
    {
      const std::string& keyword = statement.Keyword();
      points.Before += keyword == "v";
      textures.Before += keyword == "vt";
      normals.Before += keyword == "vn";
      this->Geometry.LineCells += keyword == "l";
      this->Geometry.VertexCells += keyword == "p";
      if (keyword != "f" && keyword != "l" && keyword != "p")
      {
        continue;
      }
      for (std::size_t w = 1; w < statement.Words.size(); ++w)
      {
        const std::string& corner = statement.Words[w];
        const std::vector<std::string> parts = this->CornerParts(statement, corner);
        const long long point = this->Resolve(statement, corner, parts[0], points);
        const long long texture =
          parts.size() > 1 ? this->Resolve(statement, corner, parts[1], textures) : 0;
        const long long normal =
          parts.size() > 2 ? this->Resolve(statement, corner, parts[2], normals) : 0;
        if (keyword == "f")
        {
          this->Geometry.FaceCorners.push_back(point - 1);
          this->Geometry.CornerTextures.push_back(texture - 1);
          this->Geometry.CornerNormals.push_back(normal - 1);
        }
      }
      if (keyword == "f")
      {
        this->Geometry.EndFace();
        this->Geometry.FaceLines.push_back(statement.Line);
      }
    }
  }

  std::vector<std::string> CornerParts(const Statement& statement, const std::string& corner) const
  {
    std::vector<std::string> parts(1);
    for (const char c : corner)
    {
      if (c == '/')
      {
        parts.emplace_back();
      }
      else
      {
        parts.back() += c;
      }
    }
    long long index = 0;
    const bool wellFormed = parts.size() <= 3 && ParseWholeInteger(parts[0], index) &&
      (parts.size() < 2 || ParseWholeInteger(parts[1], index) ||
        (parts.size() == 3 && parts[1].empty())) &&
      (parts.size() < 3 || ParseWholeInteger(parts[2], index));
    if (!wellFormed)
    {
      this->Fail(statement, ": '" + corner + "' is not v, v/vt, v//vn or v/vt/vn");
    }
    return parts;
  }

  // The 1-based entry an index names, 0 for an empty one (v//vn's texture).
  long long Resolve(const Statement& statement, const std::string& corner, const std::string& part,
    const IndexRange& range) const
  {
    long long index = 0;
    if (part.empty() || !ParseWholeInteger(part, index))
    {
      return 0;
    }
    const std::string named = ": '" + corner + "' refers to " + range.What + " " + part;
    if (index == 0)
    {
      this->Fail(statement, named + ", but OBJ counts " + range.What + "s from 1");
    }
    if (index > range.Count)
    {
      this->Fail(statement, named + " but there are " + std::to_string(range.Count));
    }
    const long long resolved = index < 0 ? range.Before + index + 1 : index;
    if (resolved < 1)
    {
      // Negated as unsigned: -LLONG_MIN overflows a long long.
      this->Fail(statement,
        named + ", " + std::to_string(0ULL - static_cast<unsigned long long>(index)) +
          " back from this line, but only " + std::to_string(range.Before) + " come before it");
    }
    return resolved;
  }

  std::string Path;
  std::vector<Statement> Statements;
  FileGeometry Geometry;
};

} // namespace

FileGeometry CheckObjFile(const std::string& path)
{
  return ObjChecker(path, ReadFileBytes(path)).Check();
}

} // namespace cli
