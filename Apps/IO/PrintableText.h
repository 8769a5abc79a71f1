#ifndef PrintableText_h
#define PrintableText_h

#include <string>

namespace cli
{

/**
 * `text` made safe for one line of a terminal: control bytes (C0, DEL, the
 * C1 controls encoded in UTF-8) and bytes that are not valid UTF-8 become
 * `\xNN`, and a backslash stays a backslash. Valid UTF-8 letters pass as they
 * are. File names and words from files reach our messages; an escape
 * sequence in one must not recolour, move or retitle the user's terminal.
 */
std::string PrintableText(const std::string& text);

/**
 * `text` cut before its binary tail, with " [binary data]" in its place: from
 * the first byte PrintableText would escape, when at least four bytes from
 * there on would be (a reader quoting a line of a file of random bytes).
 * Text with fewer such bytes is returned as it is.
 */
std::string WithoutBinaryTail(const std::string& text);

} // namespace cli

#endif
