#include "VtpCheck.h"

#include "CliErrors.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>
#include <vector>

namespace cli
{
namespace
{

int Base64Value(char c)
{
  if (c >= 'A' && c <= 'Z')
  {
    return c - 'A';
  }
  if (c >= 'a' && c <= 'z')
  {
    return c - 'a' + 26;
  }
  if (c >= '0' && c <= '9')
  {
    return c - '0' + 52;
  }
  return c == '+' ? 62 : (c == '/' ? 63 : -1);
}

// The first `count` bytes that the base64 text at `at` (up to `stop`) decodes
// to; fewer when the text ends (at '<', white space or an invalid character)
// sooner. A '=' ends a group of four characters, and the text may go on
// after it.
std::string DecodeBase64Prefix(
  const std::string& text, std::size_t at, std::size_t count, std::size_t stop = std::string::npos)
{
  std::string bytes;
  unsigned int buffer = 0;
  int bits = 0;
  for (std::size_t i = at; i < std::min(text.size(), stop) && bytes.size() < count; ++i)
  {
    if (text[i] == '=')
    {
      buffer = 0;
      bits = 0;
      continue;
    }
    const int value = Base64Value(text[i]);
    if (value < 0)
    {
      break;
    }
    buffer = (buffer << 6) | static_cast<unsigned int>(value);
    bits += 6;
    if (bits >= 8)
    {
      bits -= 8;
      bytes.push_back(static_cast<char>((buffer >> bits) & 0xFFu));
    }
  }
  return bytes;
}

// Little-endian unsigned word `index` of `width` bytes (4 or 8).
std::uint64_t Word(const std::string& bytes, std::size_t index, std::size_t width)
{
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < width; ++b)
  {
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[index * width + b]))
      << (8 * b);
  }
  return value;
}

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// The attributes of the start tag at `at` (its '<'), and where it ends (its
// '>', or npos when it does not end as XML's does). A value may be quoted
// with " or with ', and attributes may be separated by any white space.
struct Tag
{
  std::size_t End = std::string::npos;
  std::vector<std::pair<std::string, std::string>> Attributes;

  std::string Attribute(const std::string& name) const
  {
    for (const auto& attribute : this->Attributes)
    {
      if (attribute.first == name)
      {
        return attribute.second;
      }
    }
    return std::string();
  }
};

Tag ParseTag(const std::string& text, std::size_t at)
{
  Tag tag;
  std::size_t i = at + 1;
  while (i < text.size() && !IsSpace(text[i]) && text[i] != '>' && text[i] != '/')
  {
    ++i; // the element's name
  }
  while (i < text.size())
  {
    if (IsSpace(text[i]) || text[i] == '/')
    {
      ++i;
      continue;
    }
    if (text[i] == '>')
    {
      tag.End = i;
      return tag;
    }
    const std::size_t name = i;
    while (
      i < text.size() && !IsSpace(text[i]) && text[i] != '=' && text[i] != '>' && text[i] != '/')
    {
      ++i;
    }
    const std::string attribute = text.substr(name, i - name);
    while (i < text.size() && IsSpace(text[i]))
    {
      ++i;
    }
    if (i >= text.size() || text[i] != '=')
    {
      continue;
    }
    ++i;
    while (i < text.size() && IsSpace(text[i]))
    {
      ++i;
    }
    if (i >= text.size() || (text[i] != '"' && text[i] != '\''))
    {
      return tag;
    }
    const std::size_t close = text.find(text[i], i + 1);
    if (close == std::string::npos)
    {
      return tag;
    }
    tag.Attributes.emplace_back(attribute, text.substr(i + 1, close - i - 1));
    i = close + 1;
  }
  return tag;
}

// A count or offset as VTK writes it: decimal digits only.
bool ParseCount(const std::string& value, std::uint64_t& count)
{
  if (value.empty() || value.size() > 19 ||
    value.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  count = std::stoull(value);
  return true;
}

} // namespace

void CheckVtpFile(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    throw RuntimeError("cannot read '" + path + "': " + std::strerror(errno));
  }
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto size = static_cast<std::uint64_t>(text.size());
  const std::size_t root = text.find("<VTKFile");
  if (root == std::string::npos)
  {
    return; // not XML as VTK writes it: the reader reports that itself
  }
  const Tag rootTag = ParseTag(text, root);
  if (rootTag.End == std::string::npos)
  {
    return;
  }
  const std::size_t rootEnd = rootTag.End;
  const std::size_t width = rootTag.Attribute("header_type") == "UInt64" ? 8 : 4;
  const bool compressed = !rootTag.Attribute("compressor").empty();
  const std::uint64_t limit = 1024 * size + 65536;
  const std::string where = "cannot read '" + path + "': VTK XML: ";
  // The XML ends where the appended data starts: raw bytes after it may look
  // like tags.
  const std::size_t xmlEnd = std::min(text.find("<AppendedData", rootEnd), text.size());

  // The reader also allocates for the counts each Piece declares.
  for (std::size_t piece = text.find("<Piece", rootEnd); piece < xmlEnd;
       piece = text.find("<Piece", piece + 1))
  {
    const Tag pieceTag = ParseTag(text, piece);
    if (pieceTag.End == std::string::npos)
    {
      return;
    }
    for (const char* name :
      { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
    {
      std::uint64_t count = 0;
      if (!ParseCount(pieceTag.Attribute(name), count))
      {
        continue; // not a plain count: the reader reports it
      }
      if (count > limit)
      {
        std::ostringstream message;
        message << where << "a piece declares " << name << "=" << count << ", more than a file of "
                << size << " bytes can hold";
        throw RuntimeError(message.str());
      }
    }
  }

  // Where the appended data starts (after the '_' that follows its tag) and
  // ends, and the offsets of the arrays in it.
  std::size_t appendedStart = std::string::npos;
  std::size_t appendedEnd = text.size();
  bool appendedRaw = true;
  if (xmlEnd < text.size())
  {
    const Tag appended = ParseTag(text, xmlEnd);
    const std::size_t marker =
      appended.End == std::string::npos ? appended.End : text.find('_', appended.End);
    if (marker != std::string::npos)
    {
      appendedStart = marker + 1;
      appendedRaw = appended.Attribute("encoding") != "base64";
      const std::size_t close = text.rfind("</AppendedData>");
      appendedEnd = close != std::string::npos && close >= appendedStart ? close : text.size();
    }
  }
  std::vector<std::uint64_t> appendedOffsets;
  for (std::size_t tag = text.find("<DataArray", rootEnd); tag < xmlEnd;
       tag = text.find("<DataArray", tag + 1))
  {
    const Tag array = ParseTag(text, tag);
    std::uint64_t offset = 0;
    if (array.Attribute("format") == "appended" && ParseCount(array.Attribute("offset"), offset))
    {
      appendedOffsets.push_back(offset);
    }
  }

  for (std::size_t tag = text.find("<DataArray", rootEnd); tag < xmlEnd;
       tag = text.find("<DataArray", tag + 1))
  {
    const Tag array = ParseTag(text, tag);
    if (array.End == std::string::npos)
    {
      return;
    }
    const std::string format = array.Attribute("format");
    const std::string name = array.Attribute("Name").empty()
      ? std::string("a data array")
      : "data array '" + array.Attribute("Name") + "'";
    // Where the array's header and data are, and up to where they may go.
    std::size_t data = 0;
    std::size_t stop = text.size();
    bool raw = false;
    if (format == "binary")
    {
      data = array.End + 1;
      while (data < text.size() && IsSpace(text[data]))
      {
        ++data;
      }
    }
    else if (format == "appended" && appendedStart != std::string::npos)
    {
      std::uint64_t offset = 0;
      if (!ParseCount(array.Attribute("offset"), offset) || offset >= appendedEnd - appendedStart)
      {
        continue; // the reader reports it
      }
      data = appendedStart + static_cast<std::size_t>(offset);
      stop = appendedEnd;
      raw = appendedRaw;
      if (!raw)
      {
        // Base64 arrays follow each other with nothing between them.
        for (const std::uint64_t next : appendedOffsets)
        {
          if (next > offset && appendedStart + next < stop)
          {
            stop = appendedStart + static_cast<std::size_t>(next);
          }
        }
      }
    }
    else
    {
      continue; // ASCII data: the reader finds it short itself
    }
    const std::size_t words = compressed ? 3 : 1;
    const std::string header = raw ? text.substr(data, std::min(words * width, stop - data))
                                   : DecodeBase64Prefix(text, data, words * width, stop);
    if (header.size() < words * width)
    {
      continue; // too short to declare anything: the reader reports it
    }
    std::uint64_t declared = 0;
    if (compressed)
    {
      const std::uint64_t blocks = Word(header, 0, width);
      const std::uint64_t blockSize = Word(header, 1, width);
      const std::uint64_t lastSize = Word(header, 2, width);
      if (blocks > size)
      {
        std::ostringstream message;
        message << where << "a compressed data array declares " << blocks
                << " blocks, more than a file of " << size << " bytes can hold";
        throw RuntimeError(message.str());
      }
      // Each block's compressed bytes are in the file: VTK 9.1's reader
      // allocates a buffer of that size before it finds the data short.
      const std::string sizes = raw
        ? text.substr(data, std::min<std::size_t>((3 + blocks) * width, stop - data))
        : DecodeBase64Prefix(text, data, (3 + blocks) * width, stop);
      for (std::uint64_t b = 0; (3 + b + 1) * width <= sizes.size(); ++b)
      {
        const std::uint64_t compressedSize = Word(sizes, 3 + b, width);
        if (compressedSize > size)
        {
          std::ostringstream message;
          message << where << "a compressed block declares " << compressedSize
                  << " bytes, more than a file of " << size << " bytes holds";
          throw RuntimeError(message.str());
        }
      }
      // Overflow-safe: blocks <= size, and sizes beyond the limit fail anyway.
      if (blocks > 0)
      {
        const std::uint64_t last = lastSize != 0 ? lastSize : blockSize;
        declared =
          (blockSize > limit || last > limit) ? limit + 1 : (blocks - 1) * blockSize + last;
      }
    }
    else
    {
      declared = Word(header, 0, width);
    }
    if (declared > limit)
    {
      std::ostringstream message;
      message << where << "a data array declares " << declared << " bytes, more than a file of "
              << size << " bytes can hold";
      throw RuntimeError(message.str());
    }
    // VTK 9.1's reader takes the byte count in an uncompressed array's header
    // at its word: when the data stops sooner, it keeps what its buffer held
    // for the rest (uninitialised memory, or the closing tags after appended
    // data) and reports nothing. A compressed array it finds short itself.
    if (!compressed)
    {
      const std::size_t held = raw
        ? stop - data - width
        : DecodeBase64Prefix(text, data, width + declared, stop).size() - width;
      if (held < declared)
      {
        std::ostringstream message;
        message << where << name << " declares " << declared << " bytes but holds " << held;
        throw RuntimeError(message.str());
      }
    }
  }
}

} // namespace cli
