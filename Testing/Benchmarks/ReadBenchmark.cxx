// read_benchmark FILE... [--runs N]: what reading in a child process costs.
// Each file is read N times (default 7) by the program's cli::ReadMesh (the
// pre-check, VTK's reader in the reading process, the VTP round trip, the
// validation) and by VTK's reader alone in this process, in turns; the
// medians and their ratio are printed side by side.
#include "MeshIO.h"
#include "VtkErrorLog.h"

#include <vtkAlgorithm.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace
{

vtkSmartPointer<vtkAlgorithm> PlainReader(const std::string& path)
{
  const std::string extension = cli::LowercaseExtension(path);
  if (extension == ".ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  if (extension == ".obj")
  {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  if (extension == ".stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  if (extension == ".vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  r->SetFileName(path.c_str());
  return r;
}

double Milliseconds(const std::function<void()>& work)
{
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

double Median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

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
    std::vector<double> sandboxed;
    std::vector<double> plain;
    vtkIdType cells = 0;
    for (int r = 0; r < runs; ++r)
    {
      sandboxed.push_back(Milliseconds([&] { cells = cli::ReadMesh(file)->GetNumberOfCells(); }));
      plain.push_back(Milliseconds([&] {
        vtkSmartPointer<vtkAlgorithm> reader = PlainReader(file);
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
