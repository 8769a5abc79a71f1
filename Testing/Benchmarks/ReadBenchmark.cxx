// read_benchmark FILE... [--runs N]: what reading in a child process costs.
// Each file is read N times (default 7) by the program's cli::ReadMesh (the
// pre-check, VTK's reader in the reading process, the VTP round trip, the
// validation) and by VTK's reader alone in this process, in turns; the
// medians and their ratio are printed side by side.
#include "BenchmarkTiming.h"
#include "CliErrors.h"
#include "MeshIO.h"
#include "VtkErrorLog.h"

#include <vtkAlgorithm.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using benchmark_timing::Median;
using benchmark_timing::Milliseconds;

namespace
{

} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::string> files;
  int runs = 7;
  for (int i = 1; i < argc; ++i)
  {
    const std::string word = argv[i];
    if (word == "--runs" && i + 1 < argc)
    {
      runs = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      files.push_back(word);
    }
  }
  if (files.empty())
  {
    std::fprintf(stderr, "usage: read_benchmark FILE... [--runs N]\n");
    return 2;
  }
  cli::VtkErrorLog::Instance().InstallMessageCapture();
  std::printf("%-28s %10s %12s %12s %7s\n", "file", "cells", "sandbox ms", "VTK alone ms", "ratio");
  for (const std::string& file : files)
  {
    try
    {
      cli::ReadMesh(file); // a file the program refuses has nothing to time
    }
    catch (const cli::RuntimeError& error)
    {
      std::fprintf(stderr, "read_benchmark: %s\n", error.what());
      return 1;
    }
    std::vector<double> sandboxed;
    std::vector<double> plain;
    vtkIdType cells = 0;
    for (int r = 0; r < runs; ++r)
    {
      sandboxed.push_back(Milliseconds([&] { cells = cli::ReadMesh(file)->GetNumberOfCells(); }));
      plain.push_back(Milliseconds([&] {
        vtkSmartPointer<vtkAlgorithm> reader = cli::NewVtkReader(file);
        reader->Update();
      }));
    }
    const double s = Median(sandboxed);
    const double p = Median(plain);
    const std::string name = file.substr(file.find_last_of('/') + 1);
    std::printf("%-28s %10lld %12.2f %12.2f %7.2f\n", name.c_str(), static_cast<long long>(cells),
      s, p, s / p);
  }
  return 0;
}
