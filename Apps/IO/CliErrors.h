#ifndef CliErrors_h
#define CliErrors_h

#include <stdexcept>

namespace cli
{

/// Exit statuses of the program; other tools rely on them.
enum ExitStatus
{
  ExitSuccess = 0,
  ExitFailure = 1, ///< the work failed: a file, the data or VTK
  ExitUsage = 2    ///< the command line is wrong
};

/// A mistake in the command line (unknown option, missing value, bad number).
class UsageError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// A failure while doing the work (unreadable file, malformed data, VTK error).
class RuntimeError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace cli

#endif
