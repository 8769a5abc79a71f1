#ifndef VtkXmlData_h
#define VtkXmlData_h

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cli
{

/// The start tag of an XML element: its attributes, and where it ends. A
/// value may be quoted with " or with ', and attributes may be separated by
/// any white space.
struct XmlTag
{
  std::size_t End = std::string::npos; ///< its '>', or npos when cut short
  bool Empty = false;                  ///< written <Name ... />
  std::vector<std::pair<std::string, std::string>> Attributes;

  bool Has(const std::string& name) const;
  std::string Attribute(const std::string& name) const;
};

/// The tag whose '<' is at `at`.
XmlTag ParseXmlTag(const std::string& text, std::size_t at);

/// Where the next start tag `<name` (followed by white space, '>' or '/')
/// is in [from, to), or npos.
std::size_t FindXmlElement(
  const std::string& text, const std::string& name, std::size_t from, std::size_t to);

/// A count as VTK writes it: decimal digits only.
bool ParseXmlCount(const std::string& value, std::uint64_t& count);

/// What a VTK XML file holds that the format's rules cannot read (a count
/// that is no count, a value that is no number, an unknown type); the
/// caller decides whether that is the reader's to report.
class XmlUnreadable : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * The data arrays of a VTK XML file, decoded by the format's rules: ASCII,
 * inline binary (base64) or appended (raw or base64) data, with a header of
 * UInt32 or UInt64 words in the file's byte order, uncompressed or in blocks
 * compressed by zlib, LZ4 or LZMA.
 *
 * Rules:
 * - nothing is allocated for what a header declares beyond `Limit()`, the
 *   most a file of its size can hold (1,024 bytes per byte, above zlib's
 *   1,032:1 at most, plus 64 KiB); such a header, and an uncompressed array
 *   that holds fewer bytes than its header declares, throw RuntimeError at
 *   once (`where` starts the message): VTK 9.1's reader allocates what is
 *   declared, and fills a short array from whatever its buffer held;
 * - anything else the rules cannot read throws XmlUnreadable.
 */
class VtkXmlData
{
public:
  VtkXmlData(const std::string& text, std::string where);
  /// It keeps a reference to the text: never a temporary's.
  VtkXmlData(std::string&&, std::string) = delete;

  /// False when the text has no <VTKFile ...> tag (nothing else is then valid).
  bool HasRoot() const { return this->RootEnd != std::string::npos; }
  const XmlTag& Root() const { return this->RootTag; }
  std::size_t XmlStart() const { return this->RootEnd; }
  /// Where the XML ends: appended raw bytes after it may look like tags.
  std::size_t XmlEnd() const { return this->XmlStop; }
  std::uint64_t Limit() const { return this->MostDeclared; }

  /// Throws RuntimeError unless each binary or appended array declares what
  /// the file can hold (rules above), without decoding the arrays.
  void CheckDeclaredSizes() const;

  /// Appends the first `count` values of the array whose tag starts at `at`
  /// to `to`, as numbers; `what` names the array in messages.
  void Numbers(
    std::size_t at, std::uint64_t count, const std::string& what, std::vector<double>& to) const;
  /// The same for an integer array (a real type throws XmlUnreadable).
  void Integers(std::size_t at, std::uint64_t count, const std::string& what,
    std::vector<std::int64_t>& to) const;

  [[noreturn]] void Fail(const std::string& what) const;

private:
  struct Bytes;
  struct Element;
  struct Header;
  bool Locate(const XmlTag& array, Bytes& bytes) const;
  /// The array's header, read once and checked against the file's size
  /// (Fail when it declares more than the file can hold).
  Header ReadHeader(const Bytes& bytes, const std::string& name) const;
  /// The array's data bytes, uncompressed; they start at `first`.
  std::string Decoded(const XmlTag& array, const std::string& what, std::size_t& first) const;
  template<typename Value>
  void Append(
    std::size_t at, std::uint64_t count, const std::string& what, std::vector<Value>& to) const;
  std::vector<std::string> AsciiWords(const XmlTag& array, std::uint64_t count) const;
  Element ElementOf(const XmlTag& array, const std::string& what) const;

  const std::string& Text;
  std::string Where;
  XmlTag RootTag;
  std::size_t RootEnd = std::string::npos;
  std::size_t XmlStop = 0;
  std::uint64_t MostDeclared = 0;
  std::size_t Width = 4;  ///< bytes of a header word
  bool BigEndian = false; ///< byte_order="BigEndian"
  std::string Compressor; ///< empty: none
  /// The appended data, after the '_' that follows its tag (npos: none).
  std::size_t AppendedStart = std::string::npos;
  std::size_t AppendedEnd = 0;
  bool AppendedRaw = true;
  std::vector<std::uint64_t> AppendedOffsets; ///< of the arrays in it
};

} // namespace cli

#endif
