#ifndef TextScanning_h
#define TextScanning_h

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace cli
{

/**
 * What the format pre-checks (`*Check.cxx`) share to read a file's text: the
 * file's bytes, a cursor over its lines and words, and whole-word numbers.
 * Each check decides how its reader splits the text (PLY one element per
 * line, legacy VTK a stream of words, OBJ one statement per line); this unit
 * only gives them one way to do each split.
 *
 * Rules: a line ends at '\n' and keeps a '\r' before it; words are split at
 * the bytes std::isspace calls white space, or at the separators a format
 * names; a number is the whole word or
 * nothing (std::strtoll or std::strtod would stop early at a letter, a NUL
 * byte or a second sign, where the readers disagree with each other).
 */

/// The whole file, as bytes; a RuntimeError naming the file and the system's
/// reason when it cannot be read.
std::string ReadFileBytes(const std::string& path);

/// A read position in a file's bytes (which it does not own).
class TextCursor
{
public:
  explicit TextCursor(const std::string& bytes, std::size_t position = 0)
    : Bytes(&bytes)
    , At(position)
  {
  }
  /// The cursor keeps a pointer to the bytes: never a temporary's.
  TextCursor(std::string&&, std::size_t = 0) = delete;

  std::size_t Position() const { return this->At; }
  bool AtEnd() const { return this->At >= this->Bytes->size(); }

  /// The line from here to the next '\n' (without it), and moves past the
  /// '\n'. `ended` says whether a '\n' ended the line; without one the line
  /// runs to the end of the file. False, with `line` empty, at the end.
  bool NextLine(std::string& line, bool* ended = nullptr);

  /// The rest of the current line, leaving the position at its '\n'.
  std::string RestOfLine();

  /// Moves past the current line's '\n' (to the end when there is none).
  void SkipToNextLine();

  /// Moves `count` bytes on (to the end at most): past binary data.
  void Skip(std::size_t count)
  {
    this->At += std::min(count, this->Bytes->size() - std::min(this->At, this->Bytes->size()));
  }

  /// The next word (leading white space skipped), at most `limit` bytes: a
  /// longer word is cut there and its rest is the next word. "" at the end.
  std::string Word(std::size_t limit = std::string::npos);

private:
  const std::string* Bytes;
  std::size_t At;
};

/// The words of `line`, split at white space.
std::vector<std::string> WordsOf(const std::string& line);

/// The words of `line`, split at the bytes of `separators` only (PLY's
/// spaces and tabs): any other byte belongs to a word.
std::vector<std::string> WordsOf(const std::string& line, const char* separators);

/// The whole word as a base-10 integer (an optional sign, then digits only):
/// false for anything else and for a value out of range.
bool ParseWholeInteger(const std::string& word, long long& value);

/// The whole word as a number, as std::strtod reads one: false when any byte
/// of it is left over (or the word is empty).
bool ParseWholeNumber(const std::string& word, double& value);

/// For messages: the first 40 bytes of `text`, each byte that is not
/// printable ASCII as '?'.
std::string Excerpt(const std::string& text);

/// `text` in lower case (ASCII).
std::string Lowercase(std::string text);

} // namespace cli

#endif
