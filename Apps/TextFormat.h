// Small text helpers the program's reports share: numbers for JSON and for
// people, folders for the files it writes.
#ifndef TextFormat_h
#define TextFormat_h

#include <string>

class vtkPolyData;

namespace cli
{

/// The shortest text that reads back as the same double; null for what
/// JSON cannot hold (NaN, infinity).
std::string JsonNumber(double value);

/// `value` with `digits` digits after the point.
std::string Fixed(double value, int digits);

/// 12345 -> "12,345", for counts people read.
std::string Grouped(long long value);

inline const char* OnOff(bool on)
{
  return on ? "on" : "off";
}

/// The first value of the field data array `name` of `data`, 0 when missing.
long long FieldCount(vtkPolyData* data, const char* name);

/// Makes `directory` and its parents; throws RuntimeError when it cannot.
void CreateDirectory(const std::string& directory);

/// `directory`/`name`.
std::string JoinPath(const std::string& directory, const std::string& name);

} // namespace cli

#endif
