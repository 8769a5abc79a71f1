#include "VtpCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
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

// Unsigned word `index` of `width` bytes (4 or 8), in the file's byte order.
std::uint64_t Word(const std::string& bytes, std::size_t index, std::size_t width, bool bigEndian)
{
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < width; ++b)
  {
    const std::size_t shift = bigEndian ? width - 1 - b : b;
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[index * width + b]))
      << (8 * shift);
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

// What the checks of one file share: its text, the limit on what it can
// declare, its header words, and where its appended data is.
struct VtpFile
{
  const std::string& Text;
  std::uint64_t Size = 0;
  std::uint64_t Limit = 0; ///< the most bytes or items a file of Size bytes can declare
  std::size_t Width = 4;   ///< bytes of a header word (UInt32 or UInt64)
  bool BigEndian = false;  ///< byte_order="BigEndian"
  bool Compressed = false;
  std::string Where; ///< the start of every message
  std::size_t RootEnd = 0;
  std::size_t XmlEnd = 0; ///< where the appended data's raw bytes may start
  /// The appended data, after the '_' that follows its tag (npos: none).
  std::size_t AppendedStart = std::string::npos;
  std::size_t AppendedEnd = 0;
  bool AppendedRaw = true;
  std::vector<std::uint64_t> AppendedOffsets; ///< of the arrays in it

  [[noreturn]] void fail(const std::string& what) const { throw RuntimeError(this->Where + what); }
};

// The reader also allocates for the counts each Piece declares. False when a
// tag is cut short (the reader reports that itself).
//
// Several pieces: vtkXMLPolyDataReader 9.1 offsets a piece's cells by the
// points of the pieces before it only when an earlier piece has cells of
// that kind, so cells of a kind that first appears after a piece with points
// would take that piece's points.
bool CheckPieceCounts(const VtpFile& file)
{
  const std::string& text = file.Text;
  static const char* const cellKinds[] = { "NumberOfVerts", "NumberOfLines", "NumberOfStrips",
    "NumberOfPolys" };
  std::uint64_t pointsBefore = 0;
  bool kindSeen[4] = { false, false, false, false };
  int index = 0;
  for (std::size_t piece = text.find("<Piece", file.RootEnd); piece < file.XmlEnd;
       piece = text.find("<Piece", piece + 1), ++index)
  {
    const Tag pieceTag = ParseTag(text, piece);
    if (pieceTag.End == std::string::npos)
    {
      return false;
    }
    for (const char* name :
      { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
    {
      std::uint64_t count = 0;
      if (!ParseCount(pieceTag.Attribute(name), count))
      {
        continue; // not a plain count: the reader reports it
      }
      if (count > file.Limit)
      {
        std::ostringstream message;
        message << "a piece declares " << name << "=" << count << ", more than a file of "
                << file.Size << " bytes can hold";
        file.fail(message.str());
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      std::uint64_t cells = 0;
      if (!ParseCount(pieceTag.Attribute(cellKinds[k]), cells) || cells == 0)
      {
        continue;
      }
      if (!kindSeen[k] && pointsBefore > 0)
      {
        std::ostringstream message;
        message << "piece " << index + 1 << " has the first " << (cellKinds[k] + 8)
                << " after pieces with points, which vtkXMLPolyDataReader 9.1 would attach to "
                   "those pieces' points; write the pieces as one, or give the first piece its "
                << (cellKinds[k] + 8);
        file.fail(message.str());
      }
      kindSeen[k] = true;
    }
    std::uint64_t points = 0;
    if (ParseCount(pieceTag.Attribute("NumberOfPoints"), points))
    {
      pointsBefore += points;
    }
  }
  return true;
}

// Where the appended data starts and ends, and the offsets of its arrays.
void FindAppendedData(VtpFile& file)
{
  const std::string& text = file.Text;
  file.AppendedEnd = text.size();
  if (file.XmlEnd < text.size())
  {
    const Tag appended = ParseTag(text, file.XmlEnd);
    const std::size_t marker =
      appended.End == std::string::npos ? appended.End : text.find('_', appended.End);
    if (marker != std::string::npos)
    {
      file.AppendedStart = marker + 1;
      file.AppendedRaw = appended.Attribute("encoding") != "base64";
      const std::size_t close = text.rfind("</AppendedData>");
      file.AppendedEnd =
        close != std::string::npos && close >= file.AppendedStart ? close : text.size();
    }
  }
  for (std::size_t tag = text.find("<DataArray", file.RootEnd); tag < file.XmlEnd;
       tag = text.find("<DataArray", tag + 1))
  {
    const Tag array = ParseTag(text, tag);
    std::uint64_t offset = 0;
    if (array.Attribute("format") == "appended" && ParseCount(array.Attribute("offset"), offset))
    {
      file.AppendedOffsets.push_back(offset);
    }
  }
}

// Where a binary or appended array's header and data are, and up to where
// they may go.
struct ArrayBytes
{
  std::size_t Data = 0;
  std::size_t Stop = 0;
  bool Raw = false; ///< raw bytes, not base64

  // The first `count` bytes from Data (fewer where the array stops sooner).
  std::string prefix(const std::string& text, std::size_t count) const
  {
    return this->Raw ? text.substr(this->Data, std::min(count, this->Stop - this->Data))
                     : DecodeBase64Prefix(text, this->Data, count, this->Stop);
  }
};

// False for an array whose data the reader checks itself (ASCII, or an
// appended offset out of range).
bool LocateArrayBytes(const VtpFile& file, const Tag& array, ArrayBytes& bytes)
{
  const std::string& text = file.Text;
  const std::string format = array.Attribute("format");
  bytes.Stop = text.size();
  if (format == "binary")
  {
    bytes.Data = array.End + 1;
    while (bytes.Data < text.size() && IsSpace(text[bytes.Data]))
    {
      ++bytes.Data;
    }
    return true;
  }
  if (format != "appended" || file.AppendedStart == std::string::npos)
  {
    return false; // ASCII data: the reader finds it short itself
  }
  std::uint64_t offset = 0;
  if (!ParseCount(array.Attribute("offset"), offset) ||
    offset >= file.AppendedEnd - file.AppendedStart)
  {
    return false; // the reader reports it
  }
  bytes.Data = file.AppendedStart + static_cast<std::size_t>(offset);
  bytes.Stop = file.AppendedEnd;
  bytes.Raw = file.AppendedRaw;
  if (!bytes.Raw)
  {
    // Base64 arrays follow each other with nothing between them.
    for (const std::uint64_t next : file.AppendedOffsets)
    {
      if (next > offset && file.AppendedStart + next < bytes.Stop)
      {
        bytes.Stop = file.AppendedStart + static_cast<std::size_t>(next);
      }
    }
  }
  return true;
}

// The uncompressed bytes a compressed array declares (its header: blocks,
// block size, last block's size, then each block's compressed size).
std::uint64_t CompressedBytes(
  const VtpFile& file, const ArrayBytes& bytes, const std::string& header)
{
  const std::size_t width = file.Width;
  const std::uint64_t blocks = Word(header, 0, width, file.BigEndian);
  const std::uint64_t blockSize = Word(header, 1, width, file.BigEndian);
  const std::uint64_t lastSize = Word(header, 2, width, file.BigEndian);
  if (blocks > file.Size)
  {
    std::ostringstream message;
    message << "a compressed data array declares " << blocks << " blocks, more than a file of "
            << file.Size << " bytes can hold";
    file.fail(message.str());
  }
  // Each block's compressed bytes are in the file: VTK 9.1's reader
  // allocates a buffer of that size before it finds the data short.
  const std::string sizes = bytes.prefix(file.Text, (3 + blocks) * width);
  for (std::uint64_t b = 0; (3 + b + 1) * width <= sizes.size(); ++b)
  {
    const std::uint64_t compressedSize = Word(sizes, 3 + b, width, file.BigEndian);
    if (compressedSize > file.Size)
    {
      std::ostringstream message;
      message << "a compressed block declares " << compressedSize << " bytes, more than a file of "
              << file.Size << " bytes holds";
      file.fail(message.str());
    }
  }
  // Overflow-safe: blocks <= size, and sizes beyond the limit fail anyway.
  if (blocks == 0)
  {
    return 0;
  }
  const std::uint64_t last = lastSize != 0 ? lastSize : blockSize;
  return (blockSize > file.Limit || last > file.Limit) ? file.Limit + 1
                                                       : (blocks - 1) * blockSize + last;
}

// A binary or appended array declares no more bytes than the file can hold,
// and an uncompressed one holds what it declares.
void CheckDataArray(const VtpFile& file, const Tag& array)
{
  const std::string& text = file.Text;
  ArrayBytes bytes;
  if (!LocateArrayBytes(file, array, bytes))
  {
    return;
  }
  const std::string name = array.Attribute("Name").empty()
    ? std::string("a data array")
    : "data array '" + array.Attribute("Name") + "'";
  const std::size_t width = file.Width;
  const std::size_t words = file.Compressed ? 3 : 1;
  const std::string header = bytes.prefix(text, words * width);
  if (header.size() < words * width)
  {
    return; // too short to declare anything: the reader reports it
  }
  const std::uint64_t declared =
    file.Compressed ? CompressedBytes(file, bytes, header) : Word(header, 0, width, file.BigEndian);
  if (declared > file.Limit)
  {
    std::ostringstream message;
    message << "a data array declares " << declared << " bytes, more than a file of " << file.Size
            << " bytes can hold";
    file.fail(message.str());
  }
  // VTK 9.1's reader takes the byte count in an uncompressed array's header
  // at its word: when the data stops sooner, it keeps what its buffer held
  // for the rest (uninitialised memory, or the closing tags after appended
  // data) and reports nothing. A compressed array it finds short itself.
  if (!file.Compressed)
  {
    const std::size_t held = bytes.Raw
      ? bytes.Stop - bytes.Data - width
      : DecodeBase64Prefix(text, bytes.Data, width + declared, bytes.Stop).size() - width;
    if (held < declared)
    {
      std::ostringstream message;
      message << name << " declares " << declared << " bytes but holds " << held;
      file.fail(message.str());
    }
  }
}

} // namespace

void CheckVtpFile(const std::string& path)
{
  const std::string text = ReadFileBytes(path);
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
  VtpFile file{ text };
  file.Size = static_cast<std::uint64_t>(text.size());
  file.Limit = 1024 * file.Size + 65536;
  file.Width = rootTag.Attribute("header_type") == "UInt64" ? 8 : 4;
  file.BigEndian = rootTag.Attribute("byte_order") == "BigEndian";
  file.Compressed = !rootTag.Attribute("compressor").empty();
  file.Where = "cannot read '" + path + "': VTK XML: ";
  file.RootEnd = rootTag.End;
  // The XML ends where the appended data starts: raw bytes after it may look
  // like tags.
  file.XmlEnd = std::min(text.find("<AppendedData", file.RootEnd), text.size());
  if (!CheckPieceCounts(file))
  {
    return;
  }
  FindAppendedData(file);
  for (std::size_t tag = text.find("<DataArray", file.RootEnd); tag < file.XmlEnd;
       tag = text.find("<DataArray", tag + 1))
  {
    const Tag array = ParseTag(text, tag);
    if (array.End == std::string::npos)
    {
      return;
    }
    CheckDataArray(file, array);
  }
}

} // namespace cli
