#include "TextScanning.h"

#include "CliErrors.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace cli
{

std::string ReadFileBytes(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    throw RuntimeError("cannot read '" + path + "': " + std::strerror(errno));
  }
  // In chunks into room for the whole file: a character at a time, a large
  // file took three times the reader's own time.
  // A pipe cannot seek (read it as it comes); a directory's size is no
  // size (reading it fails below, with the system's reason).
  std::string bytes;
  file.seekg(0, std::ios::end);
  const std::streamoff size = file ? static_cast<std::streamoff>(file.tellg()) : -1;
  file.clear();
  file.seekg(0, std::ios::beg);
  const bool rewound = static_cast<bool>(file);
  file.clear();
  if (rewound && size > 0 && static_cast<std::uint64_t>(size) < bytes.max_size() / 2)
  {
    bytes.reserve(static_cast<std::size_t>(size));
  }
  std::vector<char> chunk(std::size_t{ 1 } << 20);
  while (file.read(chunk.data(), static_cast<std::streamsize>(chunk.size())), file.gcount() > 0)
  {
    bytes.append(chunk.data(), static_cast<std::size_t>(file.gcount()));
  }
  if (file.bad())
  {
    throw RuntimeError("cannot read '" + path + "': " + std::strerror(errno));
  }
  return bytes;
}

bool TextCursor::NextLine(std::string& line, bool* ended)
{
  line.clear();
  if (this->AtEnd())
  {
    if (ended)
    {
      *ended = false;
    }
    return false;
  }
  const std::size_t end = this->Bytes->find('\n', this->At);
  const std::size_t stop = end == std::string::npos ? this->Bytes->size() : end;
  line.assign(*this->Bytes, this->At, stop - this->At);
  this->At = end == std::string::npos ? this->Bytes->size() : end + 1;
  if (ended)
  {
    *ended = end != std::string::npos;
  }
  return true;
}

std::string TextCursor::RestOfLine()
{
  const std::size_t end = std::min(this->Bytes->find('\n', this->At), this->Bytes->size());
  std::string rest = this->Bytes->substr(this->At, end - this->At);
  this->At = end;
  return rest;
}

void TextCursor::SkipToNextLine()
{
  const std::size_t end = this->Bytes->find('\n', this->At);
  this->At = end == std::string::npos ? this->Bytes->size() : end + 1;
}

std::string TextCursor::Word(std::size_t limit)
{
  const auto space = [](char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
  };
  while (this->At < this->Bytes->size() && space((*this->Bytes)[this->At]))
  {
    ++this->At;
  }
  const std::size_t start = this->At;
  while (
    this->At < this->Bytes->size() && !space((*this->Bytes)[this->At]) && this->At - start < limit)
  {
    ++this->At;
  }
  return this->Bytes->substr(start, this->At - start);
}

std::vector<std::string> WordsOf(const std::string& line)
{
  std::vector<std::string> words;
  TextCursor cursor(line);
  for (std::string word = cursor.Word(); !word.empty(); word = cursor.Word())
  {
    words.push_back(std::move(word));
  }
  return words;
}

std::vector<std::string> WordsOf(const std::string& line, const char* separators)
{
  std::vector<std::string> words;
  std::size_t start = line.find_first_not_of(separators);
  while (start != std::string::npos)
  {
    const std::size_t end = line.find_first_of(separators, start);
    words.push_back(line.substr(start, end == std::string::npos ? std::string::npos : end - start));
    start = end == std::string::npos ? end : line.find_first_not_of(separators, end);
  }
  return words;
}

bool ParseWholeInteger(const std::string& word, long long& value)
{
  const std::size_t start = !word.empty() && (word[0] == '-' || word[0] == '+') ? 1 : 0;
  const bool digits = word.size() > start &&
    std::all_of(word.begin() + static_cast<std::ptrdiff_t>(start), word.end(),
      [](unsigned char c) { return std::isdigit(c) != 0; });
  if (!digits)
  {
    return false;
  }
  errno = 0;
  value = std::strtoll(word.c_str(), nullptr, 10);
  return errno != ERANGE;
}

bool ParseWholeNumber(const std::string& word, double& value)
{
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size();
}

std::string Excerpt(const std::string& text)
{
  std::string excerpt = text.substr(0, 40);
  for (char& c : excerpt)
  {
    if (!std::isprint(static_cast<unsigned char>(c)))
    {
      c = '?';
    }
  }
  return excerpt;
}

std::string Lowercase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

} // namespace cli
