#include "VtkErrorLog.h"

#include "CliErrors.h"
#include "PrintableText.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

namespace cli
{
namespace
{

// VTK's output window, replaced: nothing is printed, everything is logged.
class LoggingOutputWindow : public vtkOutputWindow
{
public:
  static LoggingOutputWindow* New();
  vtkTypeMacro(LoggingOutputWindow, vtkOutputWindow);

  void DisplayText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    VtkErrorLog::Instance().Record(VtkErrorLog::Kind::Error, false, text);
  }
  void DisplayWarningText(const char* text) override
  {
    VtkErrorLog::Instance().Record(VtkErrorLog::Kind::Warning, false, text);
  }
  void DisplayGenericWarningText(const char* text) override
  {
    VtkErrorLog::Instance().Record(VtkErrorLog::Kind::Warning, false, text);
  }

protected:
  LoggingOutputWindow() = default;
};
vtkStandardNewMacro(LoggingOutputWindow);

// Some VTK code (vtkPLY, the executive) logs through vtkLogger as well as, or
// instead of, the output window.
void OnLoggerMessage(void*, const vtkLogger::Message& message)
{
  const bool isError = message.verbosity <= vtkLogger::VERBOSITY_ERROR;
  VtkErrorLog::Instance().Record(
    isError ? VtkErrorLog::Kind::Error : VtkErrorLog::Kind::Warning, false, message.message);
}

void OnErrorEvent(vtkObject*, unsigned long, void*, void* callData)
{
  VtkErrorLog::Instance().Record(
    VtkErrorLog::Kind::Error, true, static_cast<const char*>(callData));
}

// The executive's "Algorithm X returned failure for request" only says that
// something failed; any other message says more.
bool IsGenericFailure(const std::string& text)
{
  return text.find("returned failure for request") != std::string::npos;
}

std::string Trim(const std::string& text)
{
  const auto first =
    std::find_if_not(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c); });
  const auto last = std::find_if_not(text.rbegin(), text.rend(), [](unsigned char c) {
    return std::isspace(c);
  }).base();
  return first < last ? std::string(first, last) : std::string();
}

} // namespace

VtkErrorLog& VtkErrorLog::Instance()
{
  static VtkErrorLog log;
  return log;
}

void VtkErrorLog::InstallMessageCapture()
{
  vtkNew<LoggingOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkLogger::AddCallback("silhouette", &OnLoggerMessage, nullptr, vtkLogger::VERBOSITY_WARNING);
}

void VtkErrorLog::Watch(vtkObject* object)
{
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(OnErrorEvent);
  object->AddObserver(vtkCommand::ErrorEvent, observer);
}

void VtkErrorLog::Clear()
{
  this->Messages.clear();
}

bool VtkErrorLog::HasErrors() const
{
  return std::any_of(this->Messages.begin(), this->Messages.end(),
    [](const Message& m) { return m.Severity == Kind::Error; });
}

void VtkErrorLog::Record(Kind kind, bool fromWatchedObject, const char* text)
{
  std::string essence = EssenceOfVtkMessage(text ? text : "");
  if (!essence.empty())
  {
    this->Messages.push_back({ kind, fromWatchedObject, std::move(essence) });
  }
}

std::vector<std::string> VtkErrorLog::Warnings() const
{
  std::vector<std::string> warnings;
  for (const Message& m : this->Messages)
  {
    if (m.Severity == Kind::Warning && !m.Text.empty() &&
      std::find(warnings.begin(), warnings.end(), m.Text) == warnings.end())
    {
      warnings.push_back(m.Text);
    }
  }
  return warnings;
}

std::string VtkErrorLog::Summary() const
{
  // Most telling first: an error of the object we asked for, any specific
  // error, a warning (readers often warn just before they fail), and only
  // then the executive's bare "returned failure".
  const auto firstWhere = [this](auto&& predicate) -> const Message* {
    const auto found = std::find_if(this->Messages.begin(), this->Messages.end(), predicate);
    return found == this->Messages.end() ? nullptr : &*found;
  };
  const Message* best = firstWhere([](const Message& m) {
    return m.Severity == Kind::Error && m.FromWatchedObject && !IsGenericFailure(m.Text);
  });
  if (!best)
  {
    best = firstWhere(
      [](const Message& m) { return m.Severity == Kind::Error && !IsGenericFailure(m.Text); });
  }
  if (!best)
  {
    best = firstWhere([](const Message& m) { return m.Severity == Kind::Warning; });
  }
  if (!best && !this->Messages.empty())
  {
    best = &this->Messages.front();
  }
  return best ? best->Text : std::string();
}

void VtkErrorLog::ThrowIfErrors(const std::string& what) const
{
  if (this->HasErrors())
  {
    throw RuntimeError(what + ": " + this->Summary());
  }
}

std::string EssenceOfVtkMessage(const std::string& text)
{
  constexpr std::size_t MessageLength = 300;
  std::istringstream lines(text);
  std::string line;
  std::string essence;
  while (std::getline(lines, line))
  {
    line = Trim(line);
    // Skip the source location VTK puts first.
    if (line.empty() || line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
      line.rfind("Generic Warning: In ", 0) == 0)
    {
      continue;
    }
    // A reader may quote a whole line of the file (vtkOBJReader quotes
    // one of 256 KiB): a message is one line of a terminal.
    essence = line.substr(0, 2 * MessageLength);
    break;
  }
  // "vtkPLYReader (0x55d0c0): message" -> "message"; the class name and the
  // address mean nothing to the user of a command-line program.
  static const std::regex objectPrefix(
    R"(^[A-Za-z_][A-Za-z0-9_]*\s*\(\s*(0x)?[0-9A-Fa-f]+\)\s*:\s*)");
  essence = std::regex_replace(essence, objectPrefix, "");
  static const std::regex address(R"(\s*\(0x[0-9A-Fa-f]+\))");
  essence = std::regex_replace(essence, address, "");
  // Messages often end with a period or stray colon; ours add their own context.
  while (!essence.empty() && (essence.back() == '.' || essence.back() == ':'))
  {
    essence.pop_back();
  }
  essence = Trim(WithoutBinaryTail(essence));
  if (essence.size() > MessageLength)
  {
    essence = essence.substr(0, MessageLength) + " [...]";
  }
  return essence;
}

} // namespace cli
