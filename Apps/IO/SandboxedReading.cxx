#include "SandboxedReading.h"

#include "CliErrors.h"
#include "VtkErrorLog.h"

#include <vtkCharArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <new>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SILHOUETTE_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SILHOUETTE_SANITIZED 1
#endif
#endif

namespace cli
{
namespace
{

// The child's answer is a sequence of frames: one kind byte, an 8-byte
// length, then that many bytes.
enum class Frame : char
{
  Warning = 'W',
  Error = 'E',
  Mesh = 'M'
};

constexpr std::uint64_t MiB = 1024 * 1024;

// ---------------------------------------------------------------- the child

bool WriteAll(int fd, const char* data, std::size_t size)
{
  while (size > 0)
  {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written <= 0)
    {
      return false;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

bool SendFrame(int fd, Frame kind, const std::string& payload)
{
  char header[9];
  header[0] = static_cast<char>(kind);
  const std::uint64_t length = payload.size();
  std::memcpy(header + 1, &length, sizeof(length));
  return WriteAll(fd, header, sizeof(header)) && WriteAll(fd, payload.data(), payload.size());
}

// The address space the process has now (VmSize), so the limit adds to it.
std::uint64_t CurrentAddressSpace()
{
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

void SetLimit(int resource, rlim_t value)
{
  const rlimit limit{ value, value };
  ::setrlimit(resource, &limit);
}

void ConfineChild(const ReadLimits& limits)
{
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  // A crash ends the child by its signal, whatever handlers the parent has
  // (libFuzzer's would report the child's crash as the fuzzer's own).
  for (const int signal : { SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGXCPU })
  {
    std::signal(signal, SIG_DFL);
  }
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0)
  {
    ::dup2(null, STDIN_FILENO);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::close(null);
  }
  SetLimit(RLIMIT_CORE, 0);
  SetLimit(RLIMIT_FSIZE, 0);
  // The soft limit sends SIGXCPU, the hard one a second later SIGKILL.
  const rlimit cpu{ limits.CpuSeconds, limits.CpuSeconds + 1 };
  ::setrlimit(RLIMIT_CPU, &cpu);
#ifndef SILHOUETTE_SANITIZED
  SetLimit(RLIMIT_AS, CurrentAddressSpace() + limits.MemoryBytes);
#endif
}

// Legacy binary VTK, not VTP: array names come from files and need not be
// UTF-8, which the XML parser refuses (assimp's regr01.obj has one).
std::string MeshAsLegacyVtk(vtkPolyData* mesh)
{
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->WriteToOutputStringOn();
  writer->SetFileTypeToBinary();
  if (!writer->Write())
  {
    throw RuntimeError("could not pass the mesh back from the reading process");
  }
  return std::string(
    writer->GetOutputString(), static_cast<std::size_t>(writer->GetOutputStringLength()));
}

[[noreturn]] void RunChild(int fd, const std::string& quotedFile,
  const std::function<vtkSmartPointer<vtkPolyData>()>& read, const ReadLimits& limits)
{
  ConfineChild(limits);
  VtkErrorLog& log = VtkErrorLog::Instance();
  try
  {
    vtkSmartPointer<vtkPolyData> mesh = read();
    for (const std::string& warning : log.Warnings())
    {
      SendFrame(fd, Frame::Warning, warning);
    }
    SendFrame(fd, Frame::Mesh, MeshAsLegacyVtk(mesh));
  }
  catch (const RuntimeError& error)
  {
    SendFrame(fd, Frame::Error, error.what());
  }
  catch (const std::bad_alloc&)
  {
    SendFrame(fd, Frame::Error,
      "cannot read " + quotedFile + ": reading it needed more than the " +
        std::to_string(limits.MemoryBytes / MiB) + " MiB of memory allowed for a file of its size");
  }
  catch (const std::exception& error)
  {
    SendFrame(fd, Frame::Error, "cannot read " + quotedFile + ": " + error.what());
  }
  ::close(fd);
  ::_exit(0);
}

// --------------------------------------------------------------- the parent

struct ChildAnswer
{
  std::string Bytes;
  bool TimedOut = false;
  bool TooLong = false;
};

ChildAnswer Collect(int fd, pid_t child, const ReadLimits& limits)
{
  ChildAnswer answer;
  const auto deadline = std::chrono::steady_clock::now() +
    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(limits.WallSeconds));
  char buffer[1 << 16];
  for (;;)
  {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      deadline - std::chrono::steady_clock::now())
                        .count();
    if (left <= 0)
    {
      answer.TimedOut = true;
      break;
    }
    pollfd watched{ fd, POLLIN, 0 };
    const int ready = ::poll(&watched, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
    if (ready < 0 && errno == EINTR)
    {
      continue;
    }
    if (ready == 0)
    {
      continue; // the deadline check above ends the wait
    }
    const ssize_t got = ::read(fd, buffer, sizeof(buffer));
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got <= 0)
    {
      break; // the child closed the pipe: it finished or died
    }
    if (answer.Bytes.size() + static_cast<std::uint64_t>(got) > limits.OutputBytes)
    {
      answer.TooLong = true;
      break;
    }
    answer.Bytes.append(buffer, static_cast<std::size_t>(got));
  }
  if (answer.TimedOut || answer.TooLong)
  {
    ::kill(child, SIGKILL);
  }
  return answer;
}

struct ChildEnd
{
  int Status = 0;
  double CpuSeconds = 0.0;
};

ChildEnd WaitFor(pid_t child)
{
  ChildEnd end;
  rusage usage{};
  while (::wait4(child, &end.Status, 0, &usage) < 0 && errno == EINTR)
  {
  }
  end.CpuSeconds = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
    1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  return end;
}

std::string SignalName(int signal)
{
  const char* name = ::strsignal(signal);
  return "signal " + std::to_string(signal) + (name ? std::string(", ") + name : std::string());
}

std::string WhyTheChildFailed(
  const ChildEnd& end, const ChildAnswer& answer, const ReadLimits& limits)
{
  const int status = end.Status;
  if (answer.TimedOut)
  {
    return "reading took longer than " + std::to_string(static_cast<long>(limits.WallSeconds)) +
      " s, the limit for a file of its size";
  }
  if (answer.TooLong)
  {
    return "the mesh read from it is larger than the " + std::to_string(limits.OutputBytes / MiB) +
      " MiB allowed for a file of its size";
  }
  if (WIFSIGNALED(status))
  {
    const int signal = WTERMSIG(status);
    if (signal == SIGXCPU || (signal == SIGKILL && end.CpuSeconds >= limits.CpuSeconds))
    {
      return "reading used more than the " + std::to_string(limits.CpuSeconds) +
        " s of processor time allowed for a file of its size";
    }
    if (signal == SIGKILL)
    {
      return "the reading process was killed (" + SignalName(signal) +
        "), perhaps by the system for want of memory";
    }
    return "VTK's reader crashed on it (" + SignalName(signal) + ")";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
  {
    return "the reading process failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
  }
  return "the reading process stopped without an answer";
}

vtkSmartPointer<vtkPolyData> MeshFromLegacyVtk(
  const std::string& bytes, const std::string& quotedFile)
{
  VtkErrorLog& log = VtkErrorLog::Instance();
  // The reader reads from this array in place (no copy, no 2 GB limit).
  vtkNew<vtkCharArray> input;
  input->SetArray(const_cast<char*>(bytes.data()), static_cast<vtkIdType>(bytes.size()), 1);
  vtkNew<vtkPolyDataReader> reader;
  log.Watch(reader);
  reader->ReadFromInputStringOn();
  reader->SetInputArray(input);
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
  reader->Update();
  log.ThrowIfErrors("cannot read " + quotedFile + " (passing the mesh back)");
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput()); // the reader's own arrays, not views of `bytes`
  return mesh;
}

} // namespace

ReadLimits ReadLimits::ForFileOfSize(std::uint64_t fileBytes)
{
  ReadLimits limits;
  limits.MemoryBytes = 768 * MiB + 32 * fileBytes;
  limits.CpuSeconds = 10 + static_cast<unsigned>(fileBytes / (4 * MiB));
  limits.WallSeconds = 3.0 * limits.CpuSeconds + 10.0;
  limits.OutputBytes = limits.MemoryBytes;
  return limits;
}

vtkSmartPointer<vtkPolyData> ReadInSandbox(const std::string& quotedFile,
  const std::function<vtkSmartPointer<vtkPolyData>()>& read, const ReadLimits& limits)
{
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
  {
    throw RuntimeError("cannot read " + quotedFile + ": no pipe to a reading process (" +
      std::strerror(errno) + ")");
  }
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0)
  {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw RuntimeError(
      "cannot read " + quotedFile + ": no reading process (" + std::strerror(error) + ")");
  }
  if (child == 0)
  {
    ::close(fds[0]);
    RunChild(fds[1], quotedFile, read, limits);
  }
  ::close(fds[1]);
  const ChildAnswer answer = Collect(fds[0], child, limits);
  ::close(fds[0]);
  const ChildEnd end = WaitFor(child);
  const int status = end.Status;

  // Frames in order; a mesh frame is the last one of a good answer.
  VtkErrorLog& log = VtkErrorLog::Instance();
  std::size_t at = 0;
  while (!answer.TimedOut && !answer.TooLong && at + 9 <= answer.Bytes.size())
  {
    const Frame kind = static_cast<Frame>(answer.Bytes[at]);
    std::uint64_t length = 0;
    std::memcpy(&length, answer.Bytes.data() + at + 1, sizeof(length));
    at += 9;
    if (length > answer.Bytes.size() - at)
    {
      break; // cut short: the child died while writing
    }
    const std::string payload = answer.Bytes.substr(at, length);
    at += length;
    switch (kind)
    {
      case Frame::Warning:
        log.Record(VtkErrorLog::Kind::Warning, true, payload.c_str());
        break;
      case Frame::Error:
        throw RuntimeError(payload);
      case Frame::Mesh:
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        {
          return MeshFromLegacyVtk(payload, quotedFile);
        }
        break;
    }
  }
  throw RuntimeError("cannot read " + quotedFile + ": " + WhyTheChildFailed(end, answer, limits));
}

} // namespace cli
