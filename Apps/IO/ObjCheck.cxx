#include "ObjCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cli
{

void CheckObjFile(const std::string& path)
{
  const std::string bytes = ReadFileBytes(path);
  // A byte-order mark of UTF-16: vtkOBJReader reads bytes, and says only
  // that the first "line" is too long.
  const bool utf16 = bytes.size() >= 2 &&
    ((bytes[0] == '\xFE' && bytes[1] == '\xFF') || (bytes[0] == '\xFF' && bytes[1] == '\xFE'));
  if (utf16)
  {
    throw RuntimeError("cannot read '" + path +
      "': it is UTF-16 text; OBJ files are read as ASCII or UTF-8 (convert it, e.g. with iconv)");
  }
  // A UTF-8 byte-order mark: the reader takes it for part of the first
  // statement's keyword and drops that statement (a first vertex lost
  // shifts every index after it). Before a comment or a blank line it is
  // harmless.
  if (bytes.rfind("\xEF\xBB\xBF", 0) == 0)
  {
    const std::size_t end = bytes.find('\n');
    const std::vector<std::string> first =
      WordsOf(bytes.substr(3, end == std::string::npos ? end : end - 3));
    if (!first.empty() && first[0][0] != '#')
    {
      throw RuntimeError("cannot read '" + path +
        "': it starts with a UTF-8 byte-order mark, which vtkOBJReader 9.1 reads as part of the "
        "first line's keyword and so drops that line; remove the mark");
    }
  }
  // Statements, each with the number of its first line: a face, line or
  // point statement that ends in a backslash after white space goes on on
  // the next line, as vtkOBJReader joins them (it joins no other statement:
  // a vertex's backslash is read as the end of its numbers).
  std::vector<std::string> lines;
  std::vector<std::size_t> lineNumbers;
  TextCursor cursor(bytes);
  bool continued = false;
  std::size_t read = 0;
  for (std::string line; cursor.NextLine(line);)
  {
    ++read;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (continued)
    {
      lines.back() += line;
    }
    else
    {
      lines.push_back(line);
      lineNumbers.push_back(read);
    }
    std::string& statement = lines.back();
    const std::vector<std::string> first = WordsOf(statement);
    const bool joinable = !first.empty() && (first[0] == "f" || first[0] == "l" || first[0] == "p");
    continued = joinable && statement.size() >= 2 && statement.back() == '\\' &&
      (statement[statement.size() - 2] == ' ' || statement[statement.size() - 2] == '\t');
    if (continued)
    {
      statement.back() = ' ';
    }
  }
  // The words of statement k; on a vertex or normal, up to a comment (the
  // reader reads the numbers before it).
  const auto wordsOf = [&lines](std::size_t k) {
    std::vector<std::string> words = WordsOf(lines[k]);
    if (!words.empty() && (words[0] == "v" || words[0] == "vn"))
    {
      const auto comment = std::find_if(
        words.begin(), words.end(), [](const std::string& word) { return word[0] == '#'; });
      words.erase(comment, words.end());
    }
    return words;
  };
  // A coordinate of a vertex or a normal: vtkOBJReader 9.1 reads "nan",
  // "inf" and "0x10" as 0, a word that is no number as 0, and a number
  // beyond the range of a float as FLT_MAX or garbage, all without a word.
  // (One too small for a float becomes 0 or a subnormal, as it would in any
  // float reader: that is rounding, not a misread.)
  const auto requireCoordinate = [](const std::string& word, const std::string& where,
                                   const char* what) {
    double value = 0.0;
    if (!ParseWholeNumber(word, value) || !std::isfinite(value)) // a NUL byte stops strtod
    {
      throw RuntimeError("cannot read " + where + ": '" + word + "' is not a finite number");
    }
    if (word.find_first_of("xX") != std::string::npos)
    {
      throw RuntimeError(
        "cannot read " + where + ": '" + word + "' is hexadecimal, which vtkOBJReader reads as 0");
    }
    if (std::isinf(std::strtof(word.c_str(), nullptr)))
    {
      throw RuntimeError(
        "cannot read " + where + ": '" + word + "' is out of range for a float " + what);
    }
  };
  // First the vertices and normals, and the counts of texture coordinates
  // and normals, which faces may refer to before they appear.
  long long vertex = 0, textureCoordinates = 0, normals = 0;
  for (std::size_t k = 0; k < lines.size(); ++k)
  {
    const std::size_t number = lineNumbers[k] - 1;
    const std::vector<std::string> words = wordsOf(k);
    const std::string keyword = words.empty() ? std::string() : words[0];
    textureCoordinates += keyword == "vt";
    if (keyword == "vn")
    {
      ++normals;
      const std::string where = "'" + path + "': line " + std::to_string(number + 1) + ", normal " +
        std::to_string(normals);
      for (std::size_t w = 1; w < words.size(); ++w)
      {
        requireCoordinate(words[w], where, "normal component");
      }
      if (words.size() < 4)
      {
        throw RuntimeError("cannot read " + where + ": fewer than 3 components");
      }
      continue;
    }
    if (keyword != "v")
    {
      continue;
    }
    ++vertex;
    const std::string where =
      "'" + path + "': line " + std::to_string(number + 1) + ", vertex " + std::to_string(vertex);
    // x y z, then optional w or r g b.
    for (std::size_t w = 1; w < words.size(); ++w)
    {
      requireCoordinate(words[w], where, "coordinate");
    }
    if (words.size() < 4)
    {
      throw RuntimeError("cannot read " + where + ": fewer than 3 coordinates");
    }
  }
  // Then the corners of faces, lines and points: v, v/vt, v//vn or v/vt/vn.
  // VTK 9.1's reader crashes on a corner such as "1/" and on a texture
  // coordinate or normal index with none to refer to.
  // A negative index counts back from the points, texture coordinates or
  // normals before its line.
  long long verticesBefore = 0, textureCoordinatesBefore = 0, normalsBefore = 0;
  // Whether a face's texture or normal index differs from its point's, and
  // the line of the first face without normal indices (0: none).
  bool indexedApart = false;
  std::size_t faceWithoutNormals = 0;
  for (std::size_t k = 0; k < lines.size(); ++k)
  {
    const std::size_t number = lineNumbers[k] - 1;
    const std::vector<std::string> words = wordsOf(k);
    const std::string keyword = words.empty() ? std::string() : words[0];
    verticesBefore += keyword == "v";
    textureCoordinatesBefore += keyword == "vt";
    normalsBefore += keyword == "vn";
    if (keyword != "f" && keyword != "l" && keyword != "p")
    {
      continue;
    }
    const std::string where = "cannot read '" + path + "': line " + std::to_string(number + 1);
    bool withNormals = false;
    for (std::size_t w = 1; w < words.size(); ++w)
    {
      const std::string& corner = words[w];
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
        throw RuntimeError(where + ": '" + corner + "' is not v, v/vt, v//vn or v/vt/vn");
      }
      long long point = 0;
      ParseWholeInteger(parts[0], point);
      const long long resolvedPoint = point < 0 ? verticesBefore + point + 1 : point;
      // Here, not after reading: the reader's 0-based, resolved index would
      // not be the one the file says (1-based; negative counts back).
      if (point == 0)
      {
        throw RuntimeError(
          where + ": '" + corner + "' refers to point 0, but OBJ counts points from 1");
      }
      if (point > vertex)
      {
        throw RuntimeError(where + ": '" + corner + "' refers to point " + parts[0] +
          " but there are " + std::to_string(vertex));
      }
      if (resolvedPoint < 1)
      {
        throw RuntimeError(where + ": '" + corner + "' refers to point " + parts[0] + ", " +
          // Negated as unsigned: -LLONG_MIN overflows a long long.
          std::to_string(0ULL - static_cast<unsigned long long>(point)) +
          " back from this line, but only " + std::to_string(verticesBefore) + " come before it");
      }
      const auto requireInRange = [&](const std::string& part, long long count, long long before,
                                    const char* what) {
        if (part.empty() || !ParseWholeInteger(part, index))
        {
          return;
        }
        const long long resolved = index < 0 ? before + index + 1 : index;
        if (index == 0 || index > count)
        {
          throw RuntimeError(where + ": '" + corner + "' refers to " + what + " " + part +
            " but there are " + std::to_string(count));
        }
        if (resolved < 1)
        {
          throw RuntimeError(where + ": '" + corner + "' refers to " + what + " " + part + ", " +
            std::to_string(0ULL - static_cast<unsigned long long>(index)) +
            " back from this line, but only " + std::to_string(before) + " come before it");
        }
        // The reader compares the indices as written: equal ones make it give
        // each point the entry of its own position in the file (the texture
        // coordinate or normal arrays taken whole), which is right only when
        // they resolve to the same entry.
        if (keyword == "f" && index == point && resolved != resolvedPoint)
        {
          throw RuntimeError(where + ": '" + corner + "' refers to point and " + what + " " + part +
            ", which resolve to point " + std::to_string(resolvedPoint) + " and " + what + " " +
            std::to_string(resolved) +
            "; vtkOBJReader 9.1 compares them as written and "
            "would give the point " +
            what + " " + std::to_string(resolvedPoint) + " (write them as counted from the start)");
        }
        if (keyword == "f" && index != point)
        {
          indexedApart = true;
        }
      };
      if (parts.size() > 1)
      {
        requireInRange(
          parts[1], textureCoordinates, textureCoordinatesBefore, "texture coordinate");
      }
      if (parts.size() > 2)
      {
        requireInRange(parts[2], normals, normalsBefore, "normal");
        withNormals = true;
      }
    }
    if (keyword == "f" && !withNormals && faceWithoutNormals == 0)
    {
      faceWithoutNormals = number + 1;
    }
  }
  // Where a face's texture or normal index differs from its point's,
  // vtkOBJReader 9.1 copies the points face by face, and then leaves out
  // every face without normal indices if the file has normals: a warning
  // per face ("Skipping poly"), and a mesh with fewer triangles.
  if (normals > 0 && indexedApart && faceWithoutNormals != 0)
  {
    throw RuntimeError("cannot read '" + path + "': line " + std::to_string(faceWithoutNormals) +
      ": the face has no normal indices in a file with normals ('vn'), and vtkOBJReader 9.1 "
      "would leave it out; give every face normal indices (v//vn or v/vt/vn), or none and no "
      "'vn' lines");
  }
}

} // namespace cli
