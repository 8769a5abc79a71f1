// Concurrent filters (issue 14): four C++ threads each run their own
// vtkSilhouetteSmoothingFilter (and a PN triangle filter) on their own copy
// of the coarse bunny through a series of views, and every output must equal
// the one a single thread computed for that view, point for point and cell
// for cell. The filters share no state; ThreadSanitizer (scripts/tsan.sh)
// runs this test to look for any they do. VTK's SMP back-end is set to
// sequential here, so the only threads are ours.
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPNTriangleFilter.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include "SilhouetteTestSupport.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace
{

constexpr int Threads = 4;
constexpr int Views = 12;

// Everything that makes two outputs the same mesh.
struct Fingerprint
{
  std::vector<double> Points;
  std::vector<vtkIdType> Offsets;
  std::vector<vtkIdType> Connectivity;
  bool operator==(const Fingerprint& o) const
  {
    return Points == o.Points && Offsets == o.Offsets && Connectivity == o.Connectivity;
  }
};

Fingerprint FingerprintOf(vtkPolyData* mesh)
{
  Fingerprint f;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    f.Points.insert(f.Points.end(), p, p + 3);
  }
  vtkCellArray* polys = mesh->GetPolys();
  for (vtkIdType i = 0; i < polys->GetOffsetsArray()->GetNumberOfTuples(); ++i)
  {
    f.Offsets.push_back(static_cast<vtkIdType>(polys->GetOffsetsArray()->GetTuple1(i)));
  }
  for (vtkIdType i = 0; i < polys->GetConnectivityArray()->GetNumberOfTuples(); ++i)
  {
    f.Connectivity.push_back(static_cast<vtkIdType>(polys->GetConnectivityArray()->GetTuple1(i)));
  }
  return f;
}

std::array<double, 3> Direction(int view)
{
  const auto directions = silhouette_test::SphereDirections(Views);
  return directions[static_cast<std::size_t>(view)];
}

// One thread's work: its own input copy and filters, every view in turn
// (starting at `first`, so the threads are at different views at any time).
std::vector<Fingerprint> RunViews(vtkPolyData* source, int first)
{
  vtkNew<vtkPolyData> input;
  input->DeepCopy(source);
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  filter->SetInputData(input);
  filter->SetViewportSize(640, 480);
  vtkNew<vtkPNTriangleFilter> pn;
  pn->SetInputConnection(filter->GetOutputPort());
  pn->SetLevel(1);
  std::vector<Fingerprint> out(static_cast<std::size_t>(Views));
  for (int k = 0; k < Views; ++k)
  {
    const int view = (first + k) % Views;
    filter->SetCamera(silhouette_test::CameraAroundMesh(input, Direction(view), 3.0, false));
    pn->Update();
    Fingerprint f = FingerprintOf(filter->GetOutput());
    const Fingerprint tessellated = FingerprintOf(pn->GetOutput());
    f.Points.insert(f.Points.end(), tessellated.Points.begin(), tessellated.Points.end());
    out[static_cast<std::size_t>(view)] = std::move(f);
  }
  return out;
}

} // namespace

int TestConcurrentFilters(int argc, char* argv[])
{
  vtkSMPTools::SetBackend("Sequential");
  auto bunny = silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bunny_coarse.ply"));
  const std::vector<Fingerprint> expected = RunViews(bunny, 0);

  std::vector<std::vector<Fingerprint>> results(Threads);
  std::vector<std::thread> threads;
  for (int t = 0; t < Threads; ++t)
  {
    threads.emplace_back([&, t] { results[static_cast<std::size_t>(t)] = RunViews(bunny, 3 * t); });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  int mismatches = 0;
  for (int t = 0; t < Threads; ++t)
  {
    for (int v = 0; v < Views; ++v)
    {
      if (!(results[static_cast<std::size_t>(t)][static_cast<std::size_t>(v)] ==
            expected[static_cast<std::size_t>(v)]))
      {
        std::printf("FAIL: thread %d, view %d differs from the single-threaded output\n", t, v);
        ++mismatches;
      }
    }
  }
  std::printf("%d threads x %d views: %d outputs differ from one thread's (%zu points in view "
              "0)\n",
    Threads, Views, mismatches, expected[0].Points.size() / 3);
  return mismatches == 0 && !expected[0].Points.empty() ? EXIT_SUCCESS : EXIT_FAILURE;
}
