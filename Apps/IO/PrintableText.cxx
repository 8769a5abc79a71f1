#include "PrintableText.h"

#include <algorithm>
#include <cstdio>

namespace cli
{
namespace
{

// The length of the valid UTF-8 sequence at `at` (2 to 4), or 0.
std::size_t Utf8SequenceLength(const std::string& text, std::size_t at)
{
  const auto byte = [&](std::size_t i) {
    return static_cast<unsigned char>(text[i]);
  };
  const unsigned char lead = byte(at);
  const std::size_t length = lead >= 0xC2 && lead <= 0xDF ? 2
    : lead >= 0xE0 && lead <= 0xEF                        ? 3
    : lead >= 0xF0 && lead <= 0xF4                        ? 4
                                                          : 0;
  if (length == 0 || at + length > text.size())
  {
    return 0;
  }
  for (std::size_t i = 1; i < length; ++i)
  {
    if ((byte(at + i) & 0xC0) != 0x80)
    {
      return 0;
    }
  }
  // Overlong forms, surrogates and code points past U+10FFFF.
  const unsigned char second = byte(at + 1);
  if ((lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) ||
    (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second > 0x8F))
  {
    return 0;
  }
  // U+0080 to U+009F, the C1 controls (CSI among them).
  if (lead == 0xC2 && second <= 0x9F)
  {
    return 0;
  }
  return length;
}

// The length of the printable character at `at` (ASCII or a UTF-8
// letter), or 0 for a byte PrintableText escapes.
std::size_t PrintableLength(const std::string& text, std::size_t at)
{
  const auto byte = static_cast<unsigned char>(text[at]);
  if (byte >= 0x20 && byte < 0x7F)
  {
    return 1;
  }
  return byte >= 0x80 ? Utf8SequenceLength(text, at) : 0;
}

void AppendEscaped(std::string& out, unsigned char byte)
{
  char escaped[5];
  std::snprintf(escaped, sizeof(escaped), "\\x%02X", byte);
  out += escaped;
}

} // namespace

std::string PrintableText(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();)
  {
    const auto byte = static_cast<unsigned char>(text[at]);
    if (byte >= 0x20 && byte < 0x7F)
    {
      out += static_cast<char>(byte);
      ++at;
      continue;
    }
    const std::size_t length = PrintableLength(text, at);
    if (length > 0)
    {
      out.append(text, at, length);
      at += length;
    }
    else
    {
      AppendEscaped(out, byte);
      ++at;
    }
  }
  return out;
}

std::string WithoutBinaryTail(const std::string& text)
{
  std::size_t first = text.size();
  int escaped = 0;
  for (std::size_t at = 0; at < text.size();)
  {
    const std::size_t length = PrintableLength(text, at);
    if (length == 0)
    {
      first = std::min(first, at);
      ++escaped;
    }
    at += length > 0 ? length : 1;
  }
  if (escaped < 4)
  {
    return text;
  }
  std::string cut = text.substr(0, first);
  while (!cut.empty() && cut.back() == ' ')
  {
    cut.pop_back();
  }
  return cut + " [binary data]";
}

} // namespace cli
