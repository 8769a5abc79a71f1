#ifndef SandboxedReading_h
#define SandboxedReading_h

#include <vtkSmartPointer.h>

#include <cstdint>
#include <functional>
#include <string>

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
 * Runs `read` in a child process (fork) under `limits` and returns the mesh
 * it produced, copied back through a pipe as binary legacy VTK (all points,
 * cells and point, cell and field data arrays, in their own types, with
 * their names whatever bytes they hold, and the active attributes).
 *
 * Rules:
 * - the child writes no files (RLIMIT_FSIZE 0), dumps no core, and dies with
 *   the parent; its standard streams go to /dev/null, so a reader's own
 *   output or a C library abort message never reaches the terminal;
 * - the child's VTK warnings (VtkErrorLog) are recorded in the parent's log;
 * - a RuntimeError thrown by `read` becomes the same RuntimeError in the
 *   parent, prefixed by nothing; any other failure becomes a RuntimeError
 *   "cannot read <file>: <why>": the reader crashed (with the signal), ran
 *   out of memory, processor time or waiting time, or sent too much.
 *
 * `quotedFile` names the file in those messages.
 */
vtkSmartPointer<vtkPolyData> ReadInSandbox(const std::string& quotedFile,
  const std::function<vtkSmartPointer<vtkPolyData>()>& read, const ReadLimits& limits);

} // namespace cli

#endif
