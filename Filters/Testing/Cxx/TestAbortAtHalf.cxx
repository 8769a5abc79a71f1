// Progress and abort inside the long loops (issue 17): each filter with a
// long loop reports progress from inside it, and a ProgressEvent observer
// that sets AbortExecute once the progress reaches 0.5 stops it there: the
// run ends without reaching 1, and the output is empty (or, for the line
// visibility, holds only the lines done before the abort). The same filter
// without the abort is the wrong variant: it reaches 1 with the full output.
// The filters: the quadric decimation (the bunny to 300 triangles), the
// progressive mesh's build (the bunny), OpenSubdiv refinement (the coarse
// bunny to level 3), the line visibility (2,000 short lines over a sphere),
// the smoothing filter (the coarse bunny), whose core pass runs between two
// checks, the view-dependent level of detail's build (the bunny's
// simplification and vertex hierarchy), PN triangles and Phong
// tessellation (the bunny at level 3). The filters whose work is a few
// steps check between them: the face and crease lines (the bunny, the
// bracket), the 2003 method (the coarse bunny) and the silhouette proximity
// (the bunny).
#include "vtkAlgorithm.h"
#include "vtkBoundaryCurveSmoothingFilter.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCreaseAndBorderLines.h"
#include "vtkDataObject.h"
#include "vtkFaceSilhouetteLines.h"
#include "vtkNew.h"
#include "vtkOpenSubdivRefiner.h"
#include "vtkPNTriangleFilter.h"
#include "vtkPhongTessellationFilter.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProgressiveMeshFilter.h"
#include "vtkSilhouetteLineVisibility.h"
#include "vtkSilhouetteProximity.h"
#include "vtkSilhouetteQuadricDecimation.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSmartPointer.h"
#include "vtkViewDependentLevelOfDetail.h"

#include "SilhouetteTestSupport.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{

// Records every progress value; with `abortAt` set, asks the filter to
// abort once the progress reaches it.
class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    const double progress = *static_cast<double*>(data);
    this->Values.push_back(progress);
    if (this->AbortAt > 0.0 && progress >= this->AbortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  }
  std::vector<double> Values;
  double AbortAt = 0.0;
};

struct Run
{
  double Highest = 0.0;
  std::size_t Reports = 0;
  bool Inside = false; ///< a report strictly between 0 and 1 other than the abort's
  vtkIdType Cells = 0;
};

Run Execute(vtkAlgorithm* filter, double abortAt)
{
  vtkNew<ProgressRecorder> recorder;
  recorder->AbortAt = abortAt;
  const unsigned long tag = filter->AddObserver(vtkCommand::ProgressEvent, recorder);
  // A new input, as far as the filters' caches know: the whole work again.
  filter->GetInputDataObject(0, 0)->Modified();
  filter->Update();
  filter->RemoveObserver(tag);
  Run run;
  for (const double value : recorder->Values)
  {
    run.Highest = std::max(run.Highest, value);
    run.Inside = run.Inside || (value > 0.0 && value < 1.0);
  }
  run.Reports = recorder->Values.size();
  run.Cells = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0))->GetNumberOfCells();
  return run;
}

// The abort at half stops `filter`; `partial`: its output may keep what was
// done before the abort, less than the whole.
bool Check(const char* name, vtkAlgorithm* filter, bool partial)
{
  const Run whole = Execute(filter, 0.0);
  const Run stopped = Execute(filter, 0.5);
  std::printf("%s: whole run %zu reports up to %.3f, %lld cells; aborted at 0.5: %zu reports up "
              "to %.3f, %lld cells\n",
    name, whole.Reports, whole.Highest, static_cast<long long>(whole.Cells), stopped.Reports,
    stopped.Highest, static_cast<long long>(stopped.Cells));
  bool ok = true;
  if (!(whole.Highest == 1.0 && whole.Inside && whole.Cells > 0))
  {
    std::printf("FAIL: %s: the whole run reports progress inside its work and reaches 1 with an "
                "output (the wrong variant must pass this)\n",
      name);
    ok = false;
  }
  if (!(stopped.Highest >= 0.5 && stopped.Highest < 1.0))
  {
    std::printf("FAIL: %s: the aborted run stops between 0.5 and 1\n", name);
    ok = false;
  }
  if (partial ? !(stopped.Cells < whole.Cells) : stopped.Cells != 0)
  {
    std::printf("FAIL: %s: the aborted run's output is %s\n", name,
      partial ? "not smaller than the whole" : "not empty");
    ok = false;
  }
  return ok;
}

// `count` short lines on the unit sphere, the sphere's points as the surface.
vtkSmartPointer<vtkPolyData> ShortLinesOnSphere(int count)
{
  auto lines = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  const std::vector<std::array<double, 3>> directions = silhouette_test::SphereDirections(count);
  for (const auto& d : directions)
  {
    // A short arc from d towards +z.
    const vtkIdType first = points->GetNumberOfPoints();
    for (int k = 0; k < 3; ++k)
    {
      double p[3] = { d[0], d[1], d[2] + 0.01 * k };
      const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      points->InsertNextPoint(p[0] / length, p[1] / length, p[2] / length);
    }
    const vtkIdType ids[3] = { first, first + 1, first + 2 };
    cells->InsertNextCell(3, ids);
  }
  lines->SetPoints(points);
  lines->SetLines(cells);
  return lines;
}

} // namespace

int TestAbortAtHalf(int argc, char* argv[])
{
  bool ok = true;
  const auto bunny = silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bunny.ply"));
  const auto coarse =
    silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bunny_coarse.ply"));
  if (!bunny || !coarse)
  {
    std::printf("FAIL: the bunnies read\n");
    return EXIT_FAILURE;
  }

  vtkNew<vtkSilhouetteQuadricDecimation> decimation;
  decimation->SetInputData(bunny);
  decimation->SetTargetTriangles(300);
  ok = Check("quadric decimation", decimation, false) && ok;

  vtkNew<vtkProgressiveMeshFilter> progressive;
  progressive->SetInputData(bunny);
  ok = Check("progressive mesh", progressive, false) && ok;

  vtkNew<vtkOpenSubdivRefiner> refiner;
  refiner->SetInputData(coarse);
  refiner->SetLevel(3);
  ok = Check("OpenSubdiv refinement", refiner, false) && ok;

  vtkSmartPointer<vtkCamera> camera =
    silhouette_test::CameraAroundMesh(coarse, { 0.3, 0.2, 1.0 }, 3.0, false);
  vtkNew<vtkSilhouetteSmoothingFilter> smoothing;
  smoothing->SetInputData(coarse);
  smoothing->SetCamera(camera);
  ok = Check("smoothing", smoothing, false) && ok;

  vtkNew<vtkViewDependentLevelOfDetail> lod;
  lod->SetInputData(bunny);
  lod->SetCamera(silhouette_test::CameraAroundMesh(bunny, { 0.3, 0.2, 1.0 }, 3.0, false));
  ok = Check("level of detail", lod, false) && ok;

  vtkNew<vtkPNTriangleFilter> pn;
  pn->SetInputData(bunny);
  pn->SetLevel(3);
  ok = Check("PN triangles", pn, false) && ok;

  vtkNew<vtkPhongTessellationFilter> phong;
  phong->SetInputData(bunny);
  phong->SetLevel(3);
  ok = Check("Phong tessellation", phong, false) && ok;

  const auto bracket =
    silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bracket.stl"));
  if (!bracket)
  {
    std::printf("FAIL: the bracket reads\n");
    return EXIT_FAILURE;
  }
  vtkNew<vtkCreaseAndBorderLines> creases;
  creases->SetInputData(bracket);
  ok = Check("crease and border lines", creases, false) && ok;

  vtkSmartPointer<vtkCamera> bunnyCamera =
    silhouette_test::CameraAroundMesh(bunny, { 0.3, 0.2, 1.0 }, 3.0, false);
  vtkNew<vtkFaceSilhouetteLines> faceLines;
  faceLines->SetInputData(bunny);
  faceLines->SetCamera(bunnyCamera);
  ok = Check("face silhouette lines", faceLines, false) && ok;

  vtkNew<vtkBoundaryCurveSmoothingFilter> boundaryCurves;
  boundaryCurves->SetInputData(coarse);
  boundaryCurves->SetCamera(camera);
  ok = Check("2003 boundary curves", boundaryCurves, false) && ok;

  vtkNew<vtkSilhouetteProximity> proximity;
  proximity->SetInputData(bunny);
  proximity->SetCamera(bunnyCamera);
  ok = Check("silhouette proximity", proximity, false) && ok;

  vtkNew<vtkSilhouetteLineVisibility> visibility;
  visibility->SetInputData(ShortLinesOnSphere(2000));
  visibility->SetSurfaceData(silhouette_test::Icosphere(3));
  vtkSmartPointer<vtkCamera> sphereCamera =
    silhouette_test::CameraLookingAtOrigin({ 0.0, 0.0, 1.0 }, 5.0);
  visibility->SetCamera(sphereCamera);
  ok = Check("line visibility", visibility, true) && ok;

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
