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
#include <filesystem>
#include <fstream>
#include <new>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

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

// In the forked child, before exec: system calls only (the copy of a
// process with threads may hold any lock; allocating could wait forever).
[[noreturn]] void ExecReadingProgram(
  int answerFd, int nullFd, const ReadLimits& limits, char* const* argv, char* const* envp)
{
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  ::dup2(nullFd, STDIN_FILENO);
  ::dup2(answerFd, STDOUT_FILENO); // dup2 clears close-on-exec
  ::dup2(nullFd, STDERR_FILENO);
  const rlimit none{ 0, 0 };
  ::setrlimit(RLIMIT_CORE, &none);
  ::setrlimit(RLIMIT_FSIZE, &none);
  // The soft limit sends SIGXCPU, the hard one a second later SIGKILL.
  const rlimit cpu{ limits.CpuSeconds, limits.CpuSeconds + 1 };
  ::setrlimit(RLIMIT_CPU, &cpu);
  ::execve(argv[0], argv, envp);
  ::_exit(127);
}

void SetLimit(int resource, rlim_t value)
{
  const rlimit limit{ value, value };
  ::setrlimit(resource, &limit);
}

// The parent's environment; under AddressSanitizer, with its signal
// handlers off, so that a reader's crash ends the child by its signal (as
// in a plain build) rather than by ASan's report and exit status.
std::vector<std::string> ChildEnvironment()
{
  std::vector<std::string> environment;
  std::string asanOptions;
  for (char** variable = environ; variable && *variable; ++variable)
  {
    const std::string entry = *variable;
    if (entry.rfind("ASAN_OPTIONS=", 0) == 0)
    {
      asanOptions = entry.substr(13);
      continue;
    }
    environment.push_back(entry);
  }
#ifdef SILHOUETTE_SANITIZED
  asanOptions += std::string(asanOptions.empty() ? "" : ":") +
    "handle_segv=0:handle_sigbus=0:handle_abort=0:handle_sigfpe=0:handle_sigill=0";
#endif
  if (!asanOptions.empty())
  {
    environment.push_back("ASAN_OPTIONS=" + asanOptions);
  }
  return environment;
}

std::vector<char*> Pointers(std::vector<std::string>& strings)
{
  std::vector<char*> pointers;
  for (std::string& text : strings)
  {
    pointers.push_back(text.data());
  }
  pointers.push_back(nullptr);
  return pointers;
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
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
  {
    return "the reading program could not be started";
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

std::vector<std::string> ReadingProgramCandidates()
{
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
  {
    return {};
  }
  const std::filesystem::path dir = self.parent_path();
  return { (dir / "silhouette-read").string(),
    (dir / ".." / SILHOUETTE_LIBEXEC_DIR / "silhouette-read").lexically_normal().string() };
}

vtkSmartPointer<vtkPolyData> ReadInSandbox(
  const std::string& quotedFile, const std::string& path, const ReadLimits& limits)
{
  const std::vector<std::string> places = ReadingProgramCandidates();
  std::string program;
  for (const std::string& candidate : places)
  {
    if (::access(candidate.c_str(), X_OK) == 0)
    {
      program = candidate;
      break;
    }
  }
  if (program.empty())
  {
    throw RuntimeError("cannot read " + quotedFile +
      ": the reading program silhouette-read is not installed " +
      (places.empty() ? std::string("beside this program")
                      : "(looked for " + places.front() + " and " + places.back() + ")"));
  }
  // Everything exec needs, made before the fork.
  std::vector<std::string> arguments{ program, path, std::to_string(limits.MemoryBytes),
    quotedFile };
  std::vector<std::string> environment = ChildEnvironment();
  std::vector<char*> argv = Pointers(arguments);
  std::vector<char*> envp = Pointers(environment);
  const int null = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  int fds[2];
  if (null < 0 || ::pipe2(fds, O_CLOEXEC) != 0)
  {
    const int error = errno;
    if (null >= 0)
    {
      ::close(null);
    }
    throw RuntimeError("cannot read " + quotedFile + ": no pipe to a reading process (" +
      std::strerror(error) + ")");
  }
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0)
  {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    ::close(null);
    throw RuntimeError(
      "cannot read " + quotedFile + ": no reading process (" + std::strerror(error) + ")");
  }
  if (child == 0)
  {
    ExecReadingProgram(fds[1], null, limits, argv.data(), envp.data());
  }
  ::close(null);
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

// ------------------------------------------------------ the reading program

int ReadingProcessMain(int argc, char** argv,
  const std::function<vtkSmartPointer<vtkPolyData>(const std::string&)>& read)
{
  constexpr int fd = STDOUT_FILENO;
  if (argc != 4)
  {
    return 2;
  }
  const std::string path = argv[1];
  const std::string quotedFile = argv[3];
  const std::uint64_t memory = std::strtoull(argv[2], nullptr, 10);
  // The parent dies: so does this process (set before exec too; checked
  // again in case the parent died in between).
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() == 1)
  {
    return 3;
  }
#ifndef SILHOUETTE_SANITIZED
  SetLimit(RLIMIT_AS, CurrentAddressSpace() + memory);
#endif
  VtkErrorLog& log = VtkErrorLog::Instance();
  try
  {
    vtkSmartPointer<vtkPolyData> mesh = read(path);
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
        std::to_string(memory / MiB) + " MiB of memory allowed for a file of its size");
  }
  catch (const std::exception& error)
  {
    SendFrame(fd, Frame::Error, "cannot read " + quotedFile + ": " + error.what());
  }
  return 0;
}

} // namespace cli
