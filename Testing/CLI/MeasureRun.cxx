// MeasureRun REPORT COMMAND [ARGS...]: runs COMMAND, passes its output and
// exit status through (128 + N for a death by signal N), and writes to
// REPORT the wall-clock seconds it took and the largest resident set of it
// and of every process it started and waited for (getrusage's
// RUSAGE_CHILDREN), in MiB:
//   seconds=0.042
//   max_rss_mib=35.1
// RunCli.cmake uses it to hold every failing run to its time and memory
// limits.
#include <chrono>
#include <cstdio>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: MeasureRun REPORT COMMAND [ARGS...]\n");
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child < 0)
  {
    std::perror("MeasureRun: fork");
    return 2;
  }
  if (child == 0)
  {
    execvp(argv[2], argv + 2);
    std::perror("MeasureRun: exec");
    _exit(127);
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
  {
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  std::FILE* report = std::fopen(argv[1], "w");
  if (!report)
  {
    std::perror("MeasureRun: report");
    return 2;
  }
  std::fprintf(report, "seconds=%.3f\nmax_rss_mib=%.1f\n", seconds, usage.ru_maxrss / 1024.0);
  std::fclose(report);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
