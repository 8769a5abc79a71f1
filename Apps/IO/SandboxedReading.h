#ifndef SandboxedReading_h
#define SandboxedReading_h

#include <vtkSmartPointer.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

namespace cli
{

/**
 * What the child process that reads an untrusted file may use. VTK 9.1's
 * readers crash, loop or allocate without bound on some malformed files; the
 * limits turn each of those into an error of ours. They scale with the file's
 * size, so a large honest file still reads.
 */
struct ReadLimits
{
  /// Address space the child may add to what it has when it starts (not
  /// enforced under AddressSanitizer or ThreadSanitizer, which reserve
  /// terabytes of it).
  std::uint64_t MemoryBytes = 0;
  /// Processor time the child may use (RLIMIT_CPU).
  unsigned CpuSeconds = 0;
  /// Time the parent waits for the child's answer before it kills the child.
  double WallSeconds = 0.0;
  /// The most the child may send back (the mesh, its messages).
  std::uint64_t OutputBytes = 0;

  /// Limits for a file of `fileBytes` bytes: 768 MiB plus 32 times the file's
  /// size of memory and of output, 10 s plus 1 s per 4 MiB of processor time,
  /// and three times that plus 10 s of waiting.
  static ReadLimits ForFileOfSize(std::uint64_t fileBytes);
};

/**
 * Reads `path` in a child process under `limits` and returns the mesh it
 * produced, copied back through a pipe as binary legacy VTK (all points,
 * cells and point, cell and field data arrays, in their own types, with
 * their names whatever bytes they hold, and the active attributes).
 *
 * The child is a program of its own, `silhouette-read` (ReadingProcessMain),
 * found beside the running program or in ../libexec from it: the process
 * forks and at once executes it. Forking alone, and reading in the copy,
 * deadlocked: a copy of a process with other threads (a background index
 * build, Mesa's, a fuzzer's) may inherit a lock one of them held, and
 * wait for it forever (the allocator's, seen under AddressSanitizer).
 * Between fork and exec the child only makes system calls.
 *
 * Rules:
 * - the child writes no files (RLIMIT_FSIZE 0), dumps no core, and dies with
 *   the parent; its standard streams go to /dev/null, so a reader's own
 *   output or a C library abort message never reaches the terminal;
 * - the child's VTK warnings (VtkErrorLog) are recorded in the parent's log;
 * - a RuntimeError thrown by the child's reading becomes the same
 *   RuntimeError in the parent, prefixed by nothing; any other failure
 *   becomes a RuntimeError "cannot read <file>: <why>": the reader crashed
 *   (with the signal), ran out of memory, processor time or waiting time,
 *   sent too much, or the reading program could not be started.
 *
 * `quotedFile` names the file in those messages.
 */
vtkSmartPointer<vtkPolyData> ReadInSandbox(
  const std::string& quotedFile, const std::string& path, const ReadLimits& limits);

/**
 * The reading program's main: `silhouette-read FILE MEMORY_BYTES QUOTED_FILE`
 * (the name its messages give the file), its
 * standard output the pipe to the parent. Limits its address space to what
 * it has plus MEMORY_BYTES (not under a sanitizer), runs `read(FILE)`, and
 * sends back the warnings VtkErrorLog recorded and the mesh, or the error.
 * Returns the exit status.
 */
int ReadingProcessMain(int argc, char** argv,
  const std::function<vtkSmartPointer<vtkPolyData>(const std::string&)>& read);

/// Where ReadInSandbox looks for the reading program, in order.
std::vector<std::string> ReadingProgramCandidates();

} // namespace cli

#endif
