#include "VtpCheck.h"

#include "CliErrors.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

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

// The first `count` bytes that the base64 text at `at` decodes to; fewer when
// the text ends (at '=', '<', white space or an invalid character) sooner.
std::string DecodeBase64Prefix(const std::string& text, std::size_t at, std::size_t count)
{
  std::string bytes;
  unsigned int buffer = 0;
  int bits = 0;
  for (std::size_t i = at; i < text.size() && bytes.size() < count; ++i)
  {
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

// The value of attribute `name` in the tag that starts at `tag` and ends at
// `end`, or empty.
std::string Attribute(
  const std::string& text, std::size_t tag, std::size_t end, const std::string& name)
{
  const std::string key = " " + name + "=\"";
  const std::size_t at = text.find(key, tag);
  if (at == std::string::npos || at > end)
  {
    return std::string();
  }
  const std::size_t value = at + key.size();
  const std::size_t close = text.find('"', value);
  return close == std::string::npos || close > end ? std::string()
                                                   : text.substr(value, close - value);
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
  const std::size_t rootEnd = text.find('>', root);
  if (rootEnd == std::string::npos)
  {
    return;
  }
  const std::size_t width = Attribute(text, root, rootEnd, "header_type") == "UInt64" ? 8 : 4;
  const bool compressed = !Attribute(text, root, rootEnd, "compressor").empty();
  const std::uint64_t limit = 1024 * size + 65536;
  const std::string where = "cannot read '" + path + "': VTK XML: ";

  // The reader also allocates for the counts each Piece declares.
  for (std::size_t piece = text.find("<Piece", rootEnd); piece != std::string::npos;
       piece = text.find("<Piece", piece + 1))
  {
    const std::size_t end = text.find('>', piece);
    if (end == std::string::npos)
    {
      return;
    }
    for (const char* name :
      { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
    {
      const std::string value = Attribute(text, piece, end, name);
      if (value.empty() || value.size() > 19 ||
        value.find_first_not_of("0123456789") != std::string::npos)
      {
        continue; // not a plain count: the reader reports it
      }
      const std::uint64_t count = std::stoull(value);
      if (count > limit)
      {
        std::ostringstream message;
        message << where << "a piece declares " << name << "=" << count << ", more than a file of "
                << size << " bytes can hold";
        throw RuntimeError(message.str());
      }
    }
  }

  for (std::size_t tag = text.find("<DataArray", rootEnd); tag != std::string::npos;
       tag = text.find("<DataArray", tag + 1))
  {
    const std::size_t end = text.find('>', tag);
    if (end == std::string::npos)
    {
      return;
    }
    if (Attribute(text, tag, end, "format") != "binary")
    {
      continue;
    }
    std::size_t data = end + 1;
    while (data < text.size() && std::strchr(" \t\r\n", text[data]) != nullptr && text[data])
    {
      ++data;
    }
    const std::size_t words = compressed ? 3 : 1;
    const std::string header = DecodeBase64Prefix(text, data, words * width);
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
      const std::string sizes = DecodeBase64Prefix(text, data, (3 + blocks) * width);
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
  }
}

} // namespace cli
