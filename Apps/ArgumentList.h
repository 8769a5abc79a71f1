#ifndef ArgumentList_h
#define ArgumentList_h

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cli
{

/// An option word split at its first '=': "--size=800x600" -> "--size", "800x600".
struct Option
{
  std::string Name;
  std::optional<std::string> InlineValue;
};

/// The words of a command line, taken one at a time by the option parsers.
class ArgumentList
{
public:
  explicit ArgumentList(std::vector<std::string> words);

  bool AtEnd() const;
  std::string Take();

  /// The one value of `option`: its "=value" or the next word; UsageError if
  /// there is none or it is empty.
  std::string TakeValue(const Option& option);
  /// The three values of `option` ("--focal-point X Y Z"), as numbers.
  std::array<double, 3> TakeTriple(const Option& option);

private:
  std::vector<std::string> Words;
  std::size_t Next = 0;
};

/// True for "-o", "--json", "--size=..."; false for "-1.5" and plain words.
bool LooksLikeOption(const std::string& word);
Option SplitOption(const std::string& word);
/// Throws UsageError if `option` came with an "=value" it cannot take.
void RejectInlineValue(const Option& option);

/// The whole of `text` as a finite number, or UsageError naming `option`.
double ParseNumber(const std::string& option, const std::string& text);
/// The whole of `text` as a whole number from low to high, or UsageError
/// naming `option`.
int ParseCount(const Option& option, const std::string& text, int low, int high);

} // namespace cli

#endif
