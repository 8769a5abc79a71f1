#include "TextFormat.h"

#include "CliErrors.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace cli
{

std::string JsonNumber(double value)
{
  if (!std::isfinite(value))
  {
    return "null"; // JSON has no NaN or infinity
  }
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string Fixed(double value, int digits)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

std::string Grouped(long long value)
{
  std::string digits = std::to_string(value < 0 ? -value : value);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
  {
    digits.insert(static_cast<std::size_t>(i), ",");
  }
  return (value < 0 ? "-" : "") + digits;
}

long long FieldCount(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > 0 ? static_cast<long long>(array->GetTuple1(0)) : 0;
}

void CreateDirectory(const std::string& directory)
{
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
  {
    throw RuntimeError("cannot create the folder '" + directory + "'" +
      (error ? ": " + error.message() : std::string()));
  }
}

std::string JoinPath(const std::string& directory, const std::string& name)
{
  return (std::filesystem::path(directory) / name).string();
}

} // namespace cli
