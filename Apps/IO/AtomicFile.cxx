#include "AtomicFile.h"

#include "CliErrors.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace cli
{
namespace
{

[[noreturn]] void Fail(const std::string& path, int error)
{
  throw RuntimeError("cannot write '" + path + "': " + std::strerror(error));
}

// 0 when every byte went, else the errno of the failure.
int WriteAll(int fd, const std::string& bytes)
{
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0)
  {
    const ssize_t written = ::write(fd, data, left);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written < 0)
    {
      return errno;
    }
    if (written == 0)
    {
      return ENOSPC;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return 0;
}

void WriteInPlace(const std::string& path, const std::string& bytes)
{
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0)
  {
    Fail(path, errno);
  }
  const int error = WriteAll(fd, bytes);
  const int closed = ::close(fd);
  if (error != 0)
  {
    Fail(path, error);
  }
  if (closed != 0)
  {
    Fail(path, errno);
  }
}

mode_t NewFileMode()
{
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

} // namespace

FileBatch::~FileBatch()
{
  for (const Pending& file : this->Files)
  {
    if (!file.Temporary.empty())
    {
      ::unlink(file.Temporary.c_str());
    }
  }
}

void FileBatch::Add(const std::string& path, const std::string& bytes)
{
  struct stat existing
  {
  };
  const bool exists = ::stat(path.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode))
  {
    throw RuntimeError("cannot write '" + path + "': it is a directory");
  }
  if (exists && !S_ISREG(existing.st_mode))
  {
    this->Files.push_back({ path, "", "", bytes });
    return;
  }
  // Through a link to its target, so the link stays a link.
  std::string target = path;
  if (exists)
  {
    char resolved[PATH_MAX];
    if (::realpath(path.c_str(), resolved))
    {
      target = resolved;
    }
    // A file the user may not write is not replaced either (a rename in a
    // directory the user may write would: a user's trial replaced another
    // user's read-only drawing), as writing in place would refuse it.
    if (::access(target.c_str(), W_OK) != 0)
    {
      Fail(path, errno);
    }
  }
  const std::string::size_type slash = target.rfind('/');
  const std::string directory = slash == std::string::npos ? "" : target.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? target : target.substr(slash + 1);
  std::string temporary = directory + "." + name + ".XXXXXX";
  std::vector<char> pattern(temporary.begin(), temporary.end());
  pattern.push_back('\0');
  const int fd = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (fd < 0)
  {
    Fail(path, errno);
  }
  temporary = pattern.data();
  int error = WriteAll(fd, bytes);
  if (error == 0 && ::fchmod(fd, exists ? (existing.st_mode & 07777) : NewFileMode()) != 0)
  {
    error = errno;
  }
  if (::close(fd) != 0 && error == 0)
  {
    error = errno;
  }
  if (error != 0)
  {
    ::unlink(temporary.c_str());
    Fail(path, error);
  }
  this->Files.push_back({ path, target, temporary, "" });
}

void FileBatch::Commit()
{
  // Devices and pipes first: they cannot be undone, and a failure there
  // leaves every renamed target untouched.
  for (const Pending& file : this->Files)
  {
    if (file.Temporary.empty())
    {
      WriteInPlace(file.Path, file.Bytes);
    }
  }
  for (Pending& file : this->Files)
  {
    if (!file.Temporary.empty())
    {
      if (::rename(file.Temporary.c_str(), file.Target.c_str()) != 0)
      {
        Fail(file.Path, errno); // the destructor removes the temporaries left
      }
      file.Temporary.clear();
    }
  }
  this->Files.clear();
}

void WriteFileAtomically(const std::string& path, const std::string& bytes)
{
  FileBatch batch;
  batch.Add(path, bytes);
  batch.Commit();
}

} // namespace cli
