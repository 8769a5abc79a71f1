#ifndef VtkErrorLog_h
#define VtkErrorLog_h

#include <string>
#include <vector>

class vtkObject;

namespace cli
{

/**
 * Keeps VTK's multi-line messages off the terminal and remembers them, so a
 * failure can be reported as one line of ours instead.
 *
 * Errors reach the log two ways: from ErrorEvent observers on the objects we
 * watch (readers, the filter, writers), and from VTK's output window for
 * everything else (the executive, helper classes). vtkObject's global warning
 * display must stay on: with it off, VTK raises no ErrorEvent at all.
 */
class VtkErrorLog
{
public:
  /// The one log of the program.
  static VtkErrorLog& Instance();

  /// Routes VTK's output window and vtkLogger into this log; call once at start-up.
  void InstallMessageCapture();

  /// Records the errors `object` raises (through an ErrorEvent observer).
  void Watch(vtkObject* object);

  /// Forgets what was recorded, before the next stage of the work.
  void Clear();

  bool HasErrors() const;

  /// The warnings recorded, one line each, without repeats, in order.
  std::vector<std::string> Warnings() const;

  /// The most telling message recorded, reduced to one line, or "" if none.
  std::string Summary() const;

  /// Throws RuntimeError("<what>: <summary>") if an error was recorded.
  void ThrowIfErrors(const std::string& what) const;

  enum class Kind
  {
    Error,
    Warning
  };
  /// Used by the observers and the output window.
  void Record(Kind kind, bool fromWatchedObject, const char* text);

private:
  struct Message
  {
    Kind Severity;
    bool FromWatchedObject;
    std::string Text; // already one line
  };
  std::vector<Message> Messages;
};

/// Reduces one of VTK's messages ("ERROR: In file, line N\nvtkClass (0x..): text")
/// to its first line of text, without the source location and object address,
/// cut after 300 characters (with " [...]").
std::string EssenceOfVtkMessage(const std::string& text);

} // namespace cli

#endif
