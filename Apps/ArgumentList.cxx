#include "ArgumentList.h"

#include "CliErrors.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace cli
{

ArgumentList::ArgumentList(std::vector<std::string> words)
  : Words(std::move(words))
{
}

bool ArgumentList::AtEnd() const
{
  return this->Next >= this->Words.size();
}

std::string ArgumentList::Take()
{
  return this->AtEnd() ? std::string() : this->Words[this->Next++];
}

std::string ArgumentList::TakeValue(const Option& option)
{
  std::string value;
  if (option.InlineValue)
  {
    value = *option.InlineValue;
  }
  // "-o --json" means the value was forgotten, not a file named "--json".
  else if (this->AtEnd() || this->Words[this->Next].rfind("--", 0) == 0)
  {
    throw UsageError("option '" + option.Name + "' needs a value");
  }
  else
  {
    value = this->Take();
  }
  // No option has a use for an empty value ("-o \"$unset\"" is a mistake).
  if (value.empty())
  {
    throw UsageError("option '" + option.Name + "' needs a value, got an empty one");
  }
  return value;
}

std::array<double, 3> ArgumentList::TakeTriple(const Option& option)
{
  std::array<double, 3> values{};
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    std::string word;
    if (i == 0 && option.InlineValue)
    {
      word = *option.InlineValue;
    }
    else if (this->AtEnd() || LooksLikeOption(this->Words[this->Next]))
    {
      throw UsageError("option '" + option.Name + "' needs three numbers (X Y Z)");
    }
    else
    {
      word = this->Take();
    }
    values[i] = ParseNumber(option.Name, word);
  }
  return values;
}

bool LooksLikeOption(const std::string& word)
{
  if (word.size() < 2 || word[0] != '-')
  {
    return false;
  }
  // Negative numbers are values, not options.
  const char second = word[1];
  return !(std::isdigit(static_cast<unsigned char>(second)) || second == '.');
}

Option SplitOption(const std::string& word)
{
  const std::size_t equals = word.find('=');
  if (equals == std::string::npos)
  {
    return { word, std::nullopt };
  }
  return { word.substr(0, equals), word.substr(equals + 1) };
}

void RejectInlineValue(const Option& option)
{
  if (option.InlineValue)
  {
    throw UsageError("option '" + option.Name + "' takes no value");
  }
}

double ParseNumber(const std::string& option, const std::string& text)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  // strtod also accepts "nan", "inf" and hex; only plain finite numbers make sense here.
  if (text.empty() || end != begin + text.size() || !std::isfinite(value))
  {
    throw UsageError("option '" + option + "' needs a number, got '" + text + "'");
  }
  if (errno == ERANGE)
  {
    throw UsageError("option '" + option + "' needs a number within the range of a double " +
      "(magnitudes from 2.2e-308 to 1.8e308, or 0), got '" + text + "'");
  }
  return value;
}

int ParseCount(const Option& option, const std::string& text, int low, int high)
{
  const double value = ParseNumber(option.Name, text);
  if (value != static_cast<double>(static_cast<long long>(value)) || value < low || value > high)
  {
    throw UsageError("option '" + option.Name + "' needs a whole number from " +
      std::to_string(low) + " to " + std::to_string(high) + ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

} // namespace cli
