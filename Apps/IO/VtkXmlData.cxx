#include "VtkXmlData.h"

#include "CliErrors.h"
#include "TextScanning.h"

#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkLZMADataCompressor.h>
#include <vtkSmartPointer.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

namespace cli
{
namespace
{

// Each byte's value as a base64 digit, -1 for '=', -2 for anything else.
struct Base64Digits
{
  signed char Of[256];
  Base64Digits()
  {
    std::memset(this->Of, -2, sizeof(this->Of));
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int v = 0; v < 64; ++v)
    {
      this->Of[static_cast<unsigned char>(digits[v])] = static_cast<signed char>(v);
    }
    this->Of[static_cast<unsigned char>('=')] = -1;
  }
};

// Runs `emit(byte)` for the first `count` bytes that the base64 text at `at`
// (up to `stop`) decodes to; fewer when the text ends (at '<', white space
// or an invalid character) sooner. A '=' ends a group of four characters,
// and the text may go on after it. Returns the bytes emitted.
template<typename Emit>
std::size_t DecodeBase64(
  const std::string& text, std::size_t at, std::size_t count, std::size_t stop, Emit emit)
{
  static const Base64Digits digits;
  const std::size_t end = std::min(text.size(), stop);
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  std::size_t made = 0;
  unsigned int buffer = 0;
  int bits = 0;
  for (std::size_t i = at; i < end && made < count; ++i)
  {
    const int value = digits.Of[bytes[i]];
    if (value == -1)
    {
      buffer = 0;
      bits = 0;
      continue;
    }
    if (value < 0)
    {
      break;
    }
    buffer = (buffer << 6) | static_cast<unsigned int>(value);
    bits += 6;
    if (bits >= 8)
    {
      bits -= 8;
      emit(static_cast<char>((buffer >> bits) & 0xFFu));
      ++made;
    }
  }
  return made;
}

// The first `count` bytes the base64 text at `at` decodes to (rules above).
std::string DecodeBase64Prefix(
  const std::string& text, std::size_t at, std::size_t count, std::size_t stop = std::string::npos)
{
  std::string bytes;
  bytes.reserve(
    std::min(count, (std::min(text.size(), stop) - std::min(at, text.size())) / 4 * 3 + 3));
  DecodeBase64(text, at, count, stop, [&bytes](char byte) { bytes.push_back(byte); });
  return bytes;
}

// How many bytes of the first `count` the base64 text at `at` holds.
std::size_t Base64Length(
  const std::string& text, std::size_t at, std::size_t count, std::size_t stop)
{
  return DecodeBase64(text, at, count, stop, [](char) {});
}

// The unsigned value of the `width` bytes (1 to 8) at `bytes`, in the
// file's byte order.
std::uint64_t UnsignedAt(const char* bytes, std::size_t width, bool bigEndian)
{
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < width; ++b)
  {
    const std::size_t shift = bigEndian ? width - 1 - b : b;
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[b])) << (8 * shift);
  }
  return value;
}

// Header word `index` of `width` bytes (4 or 8).
std::uint64_t Word(const std::string& bytes, std::size_t index, std::size_t width, bool bigEndian)
{
  return UnsignedAt(bytes.data() + index * width, width, bigEndian);
}

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::string Count(std::uint64_t value)
{
  return std::to_string(value);
}

} // namespace

bool XmlTag::Has(const std::string& name) const
{
  return std::any_of(this->Attributes.begin(), this->Attributes.end(),
    [&name](const auto& attribute) { return attribute.first == name; });
}

std::string XmlTag::Attribute(const std::string& name) const
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

XmlTag ParseXmlTag(const std::string& text, std::size_t at)
{
  XmlTag tag;
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
      tag.Empty = text[i - 1] == '/';
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

std::size_t FindXmlElement(
  const std::string& text, const std::string& name, std::size_t from, std::size_t to)
{
  const std::string open = "<" + name;
  for (std::size_t at = text.find(open, from); at < to && at != std::string::npos;
       at = text.find(open, at + 1))
  {
    const std::size_t after = at + open.size();
    if (after < text.size() && (IsSpace(text[after]) || text[after] == '>' || text[after] == '/'))
    {
      return at;
    }
  }
  return std::string::npos;
}

bool ParseXmlCount(const std::string& value, std::uint64_t& count)
{
  if (value.empty() || value.size() > 19 ||
    value.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  count = std::stoull(value);
  return true;
}

// Where a binary or appended array's header and data are, and up to where
// they may go.
struct VtkXmlData::Bytes
{
  std::size_t Data = 0;
  std::size_t Stop = 0;
  bool Raw = false; ///< raw bytes, not base64

  // The first `count` bytes from Data (fewer where the array stops sooner).
  std::string prefix(const std::string& text, std::uint64_t count) const
  {
    const std::uint64_t available = this->Stop - this->Data;
    return this->Raw ? text.substr(this->Data, static_cast<std::size_t>(std::min(count, available)))
                     : DecodeBase64Prefix(text, this->Data,
                         static_cast<std::size_t>(std::min(count, available)), this->Stop);
  }
};

// An array's type: bytes per value, and how to read them.
struct VtkXmlData::Element
{
  std::size_t Size = 0;
  char Kind = 'i'; ///< 'i' signed, 'u' unsigned, 'f' real

  // Value `index` of `data`, in the file's byte order, as a double and (for
  // the integer types) as the integer it is; `whole` says whether that fits
  // an int64.
  double value(const char* data, std::size_t index, bool bigEndian, std::int64_t* integer = nullptr,
    bool* whole = nullptr) const
  {
    const std::uint64_t bits = UnsignedAt(data + index * this->Size, this->Size, bigEndian);
    if (this->Kind == 'f')
    {
      if (this->Size == 4)
      {
        float real = 0;
        const auto word = static_cast<std::uint32_t>(bits);
        std::memcpy(&real, &word, 4);
        return real;
      }
      double real = 0;
      std::memcpy(&real, &bits, 8);
      return real;
    }
    std::int64_t value = 0;
    bool fits = true;
    if (this->Kind == 'i' && this->Size < 8 && (bits >> (8 * this->Size - 1)) != 0)
    {
      value = static_cast<std::int64_t>(bits) - (std::int64_t{ 1 } << (8 * this->Size));
    }
    else if (this->Kind == 'u' && bits > static_cast<std::uint64_t>(INT64_MAX))
    {
      fits = false;
    }
    else
    {
      std::memcpy(&value, &bits, 8);
    }
    if (integer)
    {
      *integer = value;
    }
    if (whole)
    {
      *whole = fits;
    }
    return this->Kind == 'u' && !fits ? static_cast<double>(bits) : static_cast<double>(value);
  }
};

VtkXmlData::VtkXmlData(const std::string& text, std::string where)
  : Text(text)
  , Where(std::move(where))
{
  const std::size_t root = FindXmlElement(text, "VTKFile", 0, text.size());
  if (root == std::string::npos)
  {
    return;
  }
  this->RootTag = ParseXmlTag(text, root);
  if (this->RootTag.End == std::string::npos)
  {
    return;
  }
  this->RootEnd = this->RootTag.End;
  const auto size = static_cast<std::uint64_t>(text.size());
  this->MostDeclared = 1024 * size + 65536;
  this->Width = this->RootTag.Attribute("header_type") == "UInt64" ? 8 : 4;
  this->BigEndian = this->RootTag.Attribute("byte_order") == "BigEndian";
  this->Compressor = this->RootTag.Attribute("compressor");
  const std::size_t appended = FindXmlElement(text, "AppendedData", this->RootEnd, text.size());
  this->XmlStop = std::min(appended, text.size());
  this->AppendedEnd = text.size();
  if (appended != std::string::npos)
  {
    const XmlTag tag = ParseXmlTag(text, appended);
    const std::size_t marker = tag.End == std::string::npos ? tag.End : text.find('_', tag.End);
    if (marker != std::string::npos)
    {
      this->AppendedStart = marker + 1;
      this->AppendedRaw = tag.Attribute("encoding") != "base64";
      const std::size_t close = text.rfind("</AppendedData>");
      this->AppendedEnd =
        close != std::string::npos && close >= this->AppendedStart ? close : text.size();
    }
  }
  // Where every appended array starts, string arrays (<Array>) included.
  for (const char* element : { "DataArray", "Array" })
  {
    for (std::size_t at = FindXmlElement(text, element, this->RootEnd, this->XmlStop);
         at != std::string::npos; at = FindXmlElement(text, element, at + 1, this->XmlStop))
    {
      const XmlTag array = ParseXmlTag(text, at);
      std::uint64_t offset = 0;
      if (array.Attribute("format") == "appended" &&
        ParseXmlCount(array.Attribute("offset"), offset))
      {
        this->AppendedOffsets.push_back(offset);
      }
    }
  }
  std::sort(this->AppendedOffsets.begin(), this->AppendedOffsets.end());
}

void VtkXmlData::Fail(const std::string& what) const
{
  throw RuntimeError(this->Where + what);
}

// False for an array that is not binary or appended, or whose appended
// offset lies beyond the appended data.
bool VtkXmlData::Locate(const XmlTag& array, Bytes& bytes) const
{
  const std::string& text = this->Text;
  const std::string format = array.Attribute("format");
  bytes.Stop = text.size();
  if (format == "binary")
  {
    bytes.Data = array.End + 1;
    while (bytes.Data < text.size() && IsSpace(text[bytes.Data]))
    {
      ++bytes.Data;
    }
    return !array.Empty;
  }
  if (format != "appended" || this->AppendedStart == std::string::npos)
  {
    return false;
  }
  std::uint64_t offset = 0;
  if (!ParseXmlCount(array.Attribute("offset"), offset) ||
    offset >= this->AppendedEnd - this->AppendedStart)
  {
    return false;
  }
  bytes.Data = this->AppendedStart + static_cast<std::size_t>(offset);
  bytes.Stop = this->AppendedEnd;
  bytes.Raw = this->AppendedRaw;
  // Appended arrays follow each other: an array's bytes end where the next
  // one's start (sorted offsets, so each lookup is a search).
  const auto next =
    std::upper_bound(this->AppendedOffsets.begin(), this->AppendedOffsets.end(), offset);
  if (next != this->AppendedOffsets.end() && this->AppendedStart + *next < bytes.Stop)
  {
    bytes.Stop = this->AppendedStart + static_cast<std::size_t>(*next);
  }
  return true;
}

// A binary or appended array's header: an uncompressed array's byte count,
// or a compressed one's blocks, block size, last block's size, then each
// block's compressed size.
struct VtkXmlData::Header
{
  bool Complete = false;                      ///< false: the array's bytes stop inside it
  std::uint64_t Declared = 0;                 ///< the uncompressed bytes it declares
  std::uint64_t Length = 0;                   ///< bytes of the header itself
  std::uint64_t BlockSize = 0;                ///< compressed arrays: every block's but the last's
  std::vector<std::uint64_t> CompressedSizes; ///< compressed arrays: a word a block
};

VtkXmlData::Header VtkXmlData::ReadHeader(const Bytes& bytes, const std::string& name) const
{
  Header header;
  const std::size_t width = this->Width;
  const std::size_t words = this->Compressor.empty() ? 1 : 3;
  const std::string front = bytes.prefix(this->Text, words * width);
  if (front.size() < words * width)
  {
    return header;
  }
  const auto size = static_cast<std::uint64_t>(this->Text.size());
  std::uint64_t declared = Word(front, 0, width, this->BigEndian);
  header.Length = words * width;
  if (!this->Compressor.empty())
  {
    const std::uint64_t blocks = declared;
    const std::uint64_t blockSize = Word(front, 1, width, this->BigEndian);
    const std::uint64_t lastSize = Word(front, 2, width, this->BigEndian);
    if (blocks > size)
    {
      this->Fail("a compressed data array declares " + Count(blocks) +
        " blocks, more than a file of " + Count(size) + " bytes can hold");
    }
    // The block sizes must lie in the array's own bytes: a header that
    // cannot is cut short (no copy of what it declares).
    const std::uint64_t available =
      bytes.Raw ? bytes.Stop - bytes.Data : (bytes.Stop - bytes.Data) / 4 * 3 + 3;
    if (blocks > available / width)
    {
      return header;
    }
    // Each block's compressed bytes are in the file: VTK 9.1's reader
    // allocates a buffer of that size before it finds the data short.
    header.Length = (3 + blocks) * width;
    const std::string sizes = bytes.prefix(this->Text, header.Length);
    for (std::uint64_t b = 0; (3 + b + 1) * width <= sizes.size(); ++b)
    {
      const std::uint64_t compressedSize = Word(sizes, 3 + b, width, this->BigEndian);
      if (compressedSize > size)
      {
        this->Fail("a compressed block declares " + Count(compressedSize) +
          " bytes, more than a file of " + Count(size) + " bytes holds");
      }
      header.CompressedSizes.push_back(compressedSize);
    }
    // blocks - 1 full blocks and the last (lastSize, or a full one when 0);
    // a block size counts only when a full block is used. Checked against
    // the limit before multiplying: 64-bit words can wrap.
    const std::uint64_t last = lastSize != 0 ? lastSize : blockSize;
    const bool fullBlocks = blocks > 1 || lastSize == 0;
    if (blocks > 0 &&
      (last > this->MostDeclared ||
        (fullBlocks &&
          blockSize > (this->MostDeclared - last) / std::max<std::uint64_t>(blocks - 1, 1))))
    {
      this->Fail("a compressed data array declares " + Count(blocks) + " blocks of " +
        Count(blockSize) + " bytes (the last " + Count(lastSize) + "), more than a file of " +
        Count(size) + " bytes can hold");
    }
    declared = blocks == 0 ? 0 : (blocks - 1) * blockSize + last;
    header.BlockSize = blockSize;
    if (header.CompressedSizes.size() < blocks)
    {
      return header; // cut short in the block sizes
    }
  }
  if (declared > this->MostDeclared)
  {
    this->Fail("a data array declares " + Count(declared) + " bytes, more than a file of " +
      Count(size) + " bytes can hold");
  }
  // VTK 9.1's reader takes the byte count in an uncompressed array's header
  // at its word: when the data stops sooner, it keeps what its buffer held
  // for the rest (uninitialised memory, or the closing tags after appended
  // data) and reports nothing.
  if (this->Compressor.empty())
  {
    const std::uint64_t held = bytes.Raw
      ? bytes.Stop - bytes.Data - width
      : Base64Length(this->Text, bytes.Data, width + declared, bytes.Stop) - width;
    if (held < declared)
    {
      this->Fail(name + " declares " + Count(declared) + " bytes but holds " + Count(held));
    }
  }
  header.Declared = declared;
  header.Complete = true;
  return header;
}

void VtkXmlData::CheckDeclaredSizes() const
{
  for (std::size_t at = FindXmlElement(this->Text, "DataArray", this->RootEnd, this->XmlStop);
       at != std::string::npos; at = FindXmlElement(this->Text, "DataArray", at + 1, this->XmlStop))
  {
    const XmlTag array = ParseXmlTag(this->Text, at);
    Bytes bytes;
    if (array.End == std::string::npos || !this->Locate(array, bytes))
    {
      continue; // ASCII, cut short or out of place: read by the format's rules, or refused
    }
    const std::string name = array.Attribute("Name").empty()
      ? std::string("a data array")
      : "data array '" + array.Attribute("Name") + "'";
    this->ReadHeader(bytes, name);
  }
}

// The data bytes of a binary or appended array, after its header,
// uncompressed.
std::string VtkXmlData::Decoded(
  const XmlTag& array, const std::string& what, std::size_t& first) const
{
  first = 0;
  Bytes bytes;
  if (!this->Locate(array, bytes))
  {
    throw XmlUnreadable(what + " has no data where its tag says (format '" +
      array.Attribute("format") + "', offset '" + array.Attribute("offset") + "')");
  }
  const Header header = this->ReadHeader(bytes, what);
  if (!header.Complete)
  {
    throw XmlUnreadable(what + "'s header is cut short");
  }
  if (this->Compressor.empty())
  {
    first = header.Length;
    return bytes.prefix(this->Text, header.Length + header.Declared);
  }
  std::uint64_t compressed = 0;
  for (const std::uint64_t size : header.CompressedSizes)
  {
    compressed += size;
  }
  const std::string all = bytes.prefix(this->Text, header.Length + compressed);
  if (all.size() < header.Length + compressed)
  {
    throw XmlUnreadable(what + " declares " + Count(compressed) + " compressed bytes but holds " +
      Count(all.size() - header.Length));
  }
  vtkSmartPointer<vtkDataCompressor> codec;
  if (this->Compressor == "vtkZLibDataCompressor")
  {
    codec = vtkSmartPointer<vtkZLibDataCompressor>::New();
  }
  else if (this->Compressor == "vtkLZ4DataCompressor")
  {
    codec = vtkSmartPointer<vtkLZ4DataCompressor>::New();
  }
  else if (this->Compressor == "vtkLZMADataCompressor")
  {
    codec = vtkSmartPointer<vtkLZMADataCompressor>::New();
  }
  else
  {
    throw XmlUnreadable("the compressor '" + Excerpt(this->Compressor) + "' is not one of VTK's");
  }
  const std::uint64_t blocks = header.CompressedSizes.size();
  std::string data(static_cast<std::size_t>(header.Declared), '\0');
  std::uint64_t from = header.Length;
  for (std::uint64_t b = 0; b < blocks; ++b)
  {
    const std::uint64_t size = header.CompressedSizes[b];
    const std::uint64_t expected =
      b + 1 < blocks ? header.BlockSize : header.Declared - b * header.BlockSize;
    const std::size_t got = codec->Uncompress(
      reinterpret_cast<const unsigned char*>(all.data() + from), static_cast<std::size_t>(size),
      reinterpret_cast<unsigned char*>(&data[static_cast<std::size_t>(b * header.BlockSize)]),
      static_cast<std::size_t>(expected));
    if (got != expected)
    {
      throw XmlUnreadable(what + ": block " + Count(b + 1) + " of " + Count(blocks) +
        " does not decompress to the " + Count(expected) + " bytes its header declares");
    }
    from += size;
  }
  return data;
}

std::vector<std::string> VtkXmlData::AsciiWords(const XmlTag& array, std::uint64_t count) const
{
  std::vector<std::string> words;
  if (array.Empty)
  {
    return words;
  }
  const std::size_t stop = std::min(this->Text.find('<', array.End + 1), this->Text.size());
  std::size_t at = array.End + 1;
  while (words.size() < count)
  {
    while (at < stop && IsSpace(this->Text[at]))
    {
      ++at;
    }
    if (at >= stop)
    {
      break;
    }
    const std::size_t start = at;
    while (at < stop && !IsSpace(this->Text[at]))
    {
      ++at;
    }
    words.push_back(this->Text.substr(start, at - start));
  }
  return words;
}

VtkXmlData::Element VtkXmlData::ElementOf(const XmlTag& array, const std::string& what) const
{
  const std::string type = array.Attribute("type");
  Element element;
  element.Kind = type.rfind("Float", 0) == 0 ? 'f' : type.rfind("UInt", 0) == 0 ? 'u' : 'i';
  const std::string bits = type.substr(type.find_first_of("0123456789") == std::string::npos
      ? type.size()
      : type.find_first_of("0123456789"));
  const std::string stem = type.substr(0, type.size() - bits.size());
  const bool known = ((stem == "Int" || stem == "UInt") &&
                       (bits == "8" || bits == "16" || bits == "32" || bits == "64")) ||
    (stem == "Float" && (bits == "32" || bits == "64"));
  if (!known)
  {
    throw XmlUnreadable(what + " has the type '" + Excerpt(type) + "', not one of the format's");
  }
  element.Size = static_cast<std::size_t>(std::stoi(bits) / 8);
  return element;
}

// Up to `count` values of an array, as numbers or (Value an integer type)
// as whole numbers: ASCII words read whole, binary values converted from
// their type, in the file's byte order.
template<typename Value>
void VtkXmlData::Append(
  std::size_t at, std::uint64_t count, const std::string& what, std::vector<Value>& to) const
{
  constexpr bool whole = std::is_integral<Value>::value;
  const XmlTag array = ParseXmlTag(this->Text, at);
  if (array.End == std::string::npos)
  {
    throw XmlUnreadable(what + "'s tag is cut short");
  }
  if (array.Attribute("format") == "ascii")
  {
    const std::vector<std::string> words = this->AsciiWords(array, count + 1);
    if (words.size() > count)
    {
      this->Fail(what + " holds more than the " + Count(count) + " values its piece gives it");
    }
    for (const std::string& word : words)
    {
      long long integer = 0;
      double number = 0;
      if (whole ? !ParseWholeInteger(word, integer) : !ParseWholeNumber(word, number))
      {
        throw XmlUnreadable(what + " holds '" + Excerpt(word) + "', which is not a " +
          (whole ? "whole number" : "number"));
      }
      to.push_back(whole ? static_cast<Value>(integer) : static_cast<Value>(number));
    }
    if (words.size() < count)
    {
      throw XmlUnreadable(what + " holds " + Count(words.size()) + " values, fewer than the " +
        Count(count) + " the piece needs");
    }
    return;
  }
  const Element element = this->ElementOf(array, what);
  if (whole && element.Kind == 'f')
  {
    throw XmlUnreadable(
      what + " is of type " + array.Attribute("type") + ", where the format wants whole numbers");
  }
  std::size_t first = 0;
  const std::string data = this->Decoded(array, what, first);
  // As many values as the piece's counts give the array: more (a type
  // relabelled narrower, an offset into another array, a count lowered)
  // would be read as another mesh without a word.
  const std::uint64_t bytes = data.size() - first;
  if (count > bytes / element.Size || bytes != count * element.Size)
  {
    this->Fail(what + " holds " + Count(bytes) + " bytes, where its piece gives it " +
      Count(count) + " values of " + array.Attribute("type") + " (" + Count(count * element.Size) +
      " bytes)");
  }
  to.reserve(to.size() + count);
  for (std::size_t i = 0; i < count; ++i)
  {
    std::int64_t integer = 0;
    bool fits = true;
    const double number = element.value(data.data() + first, i, this->BigEndian, &integer, &fits);
    if (whole && !fits)
    {
      throw XmlUnreadable(what + " holds a value beyond the largest cell index");
    }
    to.push_back(whole ? static_cast<Value>(integer) : static_cast<Value>(number));
  }
}

void VtkXmlData::Numbers(
  std::size_t at, std::uint64_t count, const std::string& what, std::vector<double>& to) const
{
  this->Append(at, count, what, to);
}

void VtkXmlData::Integers(
  std::size_t at, std::uint64_t count, const std::string& what, std::vector<std::int64_t>& to) const
{
  this->Append(at, count, what, to);
}

} // namespace cli
