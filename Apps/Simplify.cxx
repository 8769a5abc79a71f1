#include "Simplify.h"

#include "CliErrors.h"
#include "EvaluationModels.h"
#include "Figures.h"
#include "MeshIO.h"
#include "ModelInput.h"
#include "Rendering.h"
#include "RenderingBackend.h"
#include "SilhouetteMasks.h"
#include "VtkErrorLog.h"

#include <vtkCamera.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSilhouetteProximity.h>
#include <vtkSilhouetteQuadricDecimation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

namespace cli
{

std::string SimplifyHelp()
{
  return R"(Usage: silhouette simplify INPUT -o OUTPUT --triangles N [--grid CELLS]
                          [--near-min D] [--near-max D] [--near-factor F]
                          [--plain] [--weld] [--measure] [--json]
                          [camera options]

Simplifies INPUT to at most N triangles by quadric edge collapse (Garland and
Heckbert), allowing less error near the external contour for the view of the
camera options (S. Mata, L. Pastor, A. Rodriguez, "Silhouette Detection for
Adaptive Polygonal Mesh Simplification Using Distance Transforms"):
vtkSilhouetteProximity projects the faces to a grid of CELLS cells along the
longer side of their projected bounding box, runs a two-pass 3-4 chamfer
distance transform on the occupancy image (enclosed holes filled, so only the
external contour counts) and labels every point with its distance in cells
to the contour (1 on it); vtkSilhouetteQuadricDecimation then takes collapses
cheapest first, a collapse touching a point labelled within [--near-min,
--near-max] ranked by its quadric cost divided by F, until at most N
triangles remain. If e is the largest rank taken, every point ends with
quadric error (sum of squared distances to the planes of the input triangles
merged into it, in squared model units) at most e, and at most F * e near
the contour. Collapses keep the link condition and never turn a triangle
over, so a closed manifold stays one; points on boundary edges stay. Reads
the formats and model names of 'silhouette smooth'; polygons and strips are
triangulated, vertices and lines dropped.

Options:
  -o, --output FILE   write the simplified mesh to FILE: .vtp or .ply
                      (required); point arrays QuadricError, NearContour,
                      OriginalPointId and the input's point arrays
  --triangles N       the triangle budget, at least 4 (required)
  --grid CELLS        proximity grid resolution, 1 to 16384 (default 128)
  --near-min D        the near interval's lower end, in cells (default 1)
  --near-max D        the near interval's upper end, in cells (default 3)
  --near-factor F     f >= 0: error allowed near the contour is f * e
                      (default 0.1; 1 is plain; 0 forbids collapses near the
                      contour, so N may not be reached: the figures say so)
  --plain             ignore the contour: plain quadric simplification, for
                      comparison (the camera options then play no part)
  --weld              join points at equal coordinates first: points on
                      borders stay, and a mesh whose triangles do not share
                      points (as OBJ files split at texture seams write them)
                      is borders everywhere; a joined point keeps the first
                      copy's arrays (texture seams are lost). Without it, a
                      target not reached on such a mesh draws a warning
  --measure           also render INPUT and the result as flat masks at
                      --size with the camera, and print the distance between
                      their outlines in pixels (every boundary pixel of each
                      mask to the other's boundary, Euclidean distance
                      transform; mean and max), as 'compare' measures; needs
                      a display or OSMesa, like 'render' (default: no
                      rendering)
  --json              print the figures as one JSON object instead of text
)" + RenderBackendHelp(22) +
    R"(  -h, --help          show this help and exit

Only --size and the camera of the camera options below matter here;
--tolerance and the smoothing options are accepted and ignored.

)" + CameraOptionsHelp() +
    R"(
Figures: input and output triangles, whether N was reached, output points
and how many of them are near the contour, e, the worst quadric error near
the contour and elsewhere, the grid's size in cells and a cell's side in
pixels, and the time of the proximity labelling and of the simplification
in milliseconds; with --measure the outline deviation. With --json the keys
are input, output, input_triangles, output_triangles, reached_target,
output_points, near_points, threshold, worst_near_error, worst_far_error,
near_factor, grid [w, h], cell_pixels, proximity_ms, simplify_ms, and with
--measure outline_mean_px and outline_max_px.
)";
}

namespace
{

double ParseNonNegative(const Option& option, const std::string& text)
{
  const double value = ParseNumber(option.Name, text);
  if (!(value >= 0.0) || !std::isfinite(value))
  {
    throw UsageError(
      "option '" + option.Name + "' needs a number of at least 0, got '" + text + "'");
  }
  return value;
}

long long ParseWhole(const Option& option, const std::string& text, long long low, long long high)
{
  const double value = ParseNumber(option.Name, text);
  if (value != std::floor(value) || value < static_cast<double>(low) ||
    value > static_cast<double>(high))
  {
    throw UsageError("option '" + option.Name + "' needs a whole number from " +
      std::to_string(low) + " to " + std::to_string(high) + ", got '" + text + "'");
  }
  return static_cast<long long>(value);
}

} // namespace

bool ParseSimplifyOption(const Option& option, ArgumentList& arguments, SimplifyOptions& options)
{
  if (option.Name == "-o" || option.Name == "--output")
  {
    options.Output = arguments.TakeValue(option);
  }
  else if (option.Name == "--triangles")
  {
    options.Triangles = ParseWhole(option, arguments.TakeValue(option), 4, 1000000000000LL);
  }
  else if (option.Name == "--grid")
  {
    options.Grid = static_cast<int>(ParseWhole(option, arguments.TakeValue(option), 1, 16384));
  }
  else if (option.Name == "--near-min")
  {
    options.NearMinimum = ParseNonNegative(option, arguments.TakeValue(option));
  }
  else if (option.Name == "--near-max")
  {
    options.NearMaximum = ParseNonNegative(option, arguments.TakeValue(option));
  }
  else if (option.Name == "--near-factor")
  {
    options.NearFactor = ParseNonNegative(option, arguments.TakeValue(option));
  }
  else if (option.Name == "--plain")
  {
    RejectInlineValue(option);
    options.Plain = true;
  }
  else if (option.Name == "--measure")
  {
    RejectInlineValue(option);
    options.Measure = true;
  }
  else if (option.Name == "--weld")
  {
    RejectInlineValue(option);
    options.Weld = true;
  }
  else
  {
    return false;
  }
  return true;
}

namespace
{

// The mesh with points at equal coordinates joined (vtkCleanPolyData,
// tolerance 0; cells kept as they are, the degenerate ones dropped).
vtkSmartPointer<vtkPolyData> Welded(vtkPolyData* mesh)
{
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(mesh);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  clean->Update();
  return clean->GetOutput();
}

} // namespace

void CheckSimplifyOptions(const SimplifyOptions& options)
{
  if (options.Output.empty())
  {
    throw UsageError("'simplify' needs '-o OUTPUT'");
  }
  if (options.Triangles == 0)
  {
    throw UsageError("'simplify' needs '--triangles N'");
  }
  if (options.NearMinimum > options.NearMaximum)
  {
    throw UsageError("'--near-min' must not be above '--near-max'");
  }
}

void RunSimplify(const SimplifyOptions& options)
{
  using Clock = std::chrono::steady_clock;
  CheckMeshOutputPath(options.Output);
  RefuseOverwritingModelOrInput(options.Input, options.Output, "-o");
  if (options.Measure)
  {
    RequireDisplay();
  }
  vtkSmartPointer<vtkPolyData> mesh = ReadModelOrMesh(options.Input);
  if (options.Weld)
  {
    mesh = Welded(mesh);
  }
  const vtkIdType inputTriangles = CountTriangles(mesh);
  if (inputTriangles == 0)
  {
    throw RuntimeError(options.Input + " has no triangles");
  }
  // The camera exactly as 'render' would set it up for this mesh and size.
  const OffscreenView view = MakeOffscreenView(options.Camera.ViewportSize);
  SetUpCamera(view.Renderer, mesh->GetBounds(), options.Camera);

  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkNew<vtkSilhouetteProximity> proximity;
  errors.Watch(proximity);
  proximity->SetInputData(mesh);
  proximity->SetCamera(view.Renderer->GetActiveCamera());
  proximity->SetViewportSize(options.Camera.ViewportSize[0], options.Camera.ViewportSize[1]);
  proximity->SetResolution(options.Grid);
  const Clock::time_point start = Clock::now();
  proximity->Update();
  errors.ThrowIfErrors("cannot label " + options.Input);
  const Clock::time_point labelled = Clock::now();

  vtkNew<vtkSilhouetteQuadricDecimation> decimate;
  errors.Watch(decimate);
  decimate->SetInputData(proximity->GetOutput());
  decimate->SetTargetTriangles(options.Triangles);
  decimate->SetNearMinimum(options.NearMinimum);
  decimate->SetNearMaximum(options.NearMaximum);
  decimate->SetNearFactor(options.NearFactor);
  if (options.Plain)
  {
    decimate->SetDistanceArrayName("");
  }
  decimate->Update();
  errors.ThrowIfErrors("cannot simplify " + options.Input);
  const Clock::time_point simplified = Clock::now();
  vtkPolyData* out = decimate->GetOutput();
  WriteMesh(out, options.Output);

  vtkDataArray* error = out->GetPointData()->GetArray("QuadricError");
  vtkDataArray* near = out->GetPointData()->GetArray("NearContour");
  double worstNear = 0.0;
  double worstFar = 0.0;
  vtkIdType nearPoints = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const bool isNear = near->GetTuple1(i) != 0.0;
    nearPoints += isNear ? 1 : 0;
    double& worst = isNear ? worstNear : worstFar;
    worst = std::max(worst, error->GetTuple1(i));
  }
  vtkFieldData* fd = out->GetFieldData();
  const double threshold = fd->GetArray("ErrorThreshold")->GetTuple1(0);
  const bool reached = fd->GetArray("ReachedTarget")->GetTuple1(0) != 0.0;
  if (!reached && !options.Weld)
  {
    // Say why, where it is the input's borders (the points on them stay).
    const silhouette_eval::EdgeUses edges = silhouette_eval::CountEdgeUses(mesh);
    const vtkIdType joinable = mesh->GetNumberOfPoints() - Welded(mesh)->GetNumberOfPoints();
    if (edges.Borders > 0 && joinable > 0)
    {
      std::cerr << "silhouette: warning: " << edges.Borders << " of " << edges.Edges << " edges of "
                << options.Input << " are borders, whose points stay, and " << joinable
                << " of its points repeat another's coordinates (its triangles do not share "
                   "them): --weld joins them first\n";
    }
  }
  vtkDataArray* gridSize = proximity->GetOutput()->GetFieldData()->GetArray("ProximityGridSize");
  const double cellPixels =
    proximity->GetOutput()->GetFieldData()->GetArray("ProximityCellSize")->GetTuple1(0);
  const double labelMs = std::chrono::duration<double, std::milli>(labelled - start).count();
  const double simplifyMs =
    std::chrono::duration<double, std::milli>(simplified - labelled).count();
  const double factor = options.Plain ? 1.0 : options.NearFactor;
  silhouette_eval::BoundaryDistance outline;
  if (options.Measure)
  {
    errors.Clear();
    silhouette_eval::MaskRenderer masks(
      options.Camera.ViewportSize[0], options.Camera.ViewportSize[1]);
    vtkCamera* camera = view.Renderer->GetActiveCamera();
    const silhouette_eval::Mask before = masks.Render(mesh, camera);
    const silhouette_eval::Mask after = masks.Render(out, camera);
    errors.ThrowIfErrors("rendering failed");
    outline = silhouette_eval::OutlineDeviation(before, after);
  }

  std::ostringstream text;
  if (options.Json)
  {
    text << "{\"input\": " << JsonString(options.Input)
         << ", \"output\": " << JsonString(options.Output)
         << ", \"input_triangles\": " << inputTriangles
         << ", \"output_triangles\": " << out->GetNumberOfPolys()
         << ", \"reached_target\": " << (reached ? "true" : "false")
         << ", \"output_points\": " << out->GetNumberOfPoints()
         << ", \"near_points\": " << nearPoints << ", \"threshold\": " << threshold
         << ", \"worst_near_error\": " << worstNear << ", \"worst_far_error\": " << worstFar
         << ", \"near_factor\": " << factor << ", \"grid\": [" << gridSize->GetComponent(0, 0)
         << ", " << gridSize->GetComponent(0, 1) << "], \"cell_pixels\": " << cellPixels
         << ", \"proximity_ms\": " << labelMs << ", \"simplify_ms\": " << simplifyMs;
    if (options.Measure)
    {
      text << ", \"outline_mean_px\": " << outline.Mean << ", \"outline_max_px\": " << outline.Max;
    }
    text << "}\n";
  }
  else
  {
    text << "input:              " << options.Input << "\n"
         << "output:             " << options.Output << "\n"
         << "input triangles:    " << inputTriangles << "\n"
         << "output triangles:   " << out->GetNumberOfPolys() << " (target " << options.Triangles
         << (reached ? ", reached" : ", NOT reached") << ")\n"
         << "output points:      " << out->GetNumberOfPoints() << ", " << nearPoints
         << " near the contour\n"
         << "error threshold e:  " << threshold << " (quadric error, squared model units)\n"
         << "worst error near:   " << worstNear << " (at most f * e = " << factor * threshold
         << ")\n"
         << "worst error far:    " << worstFar << "\n"
         << "proximity grid:     " << gridSize->GetComponent(0, 0) << " x "
         << gridSize->GetComponent(0, 1) << " cells of " << cellPixels << " px\n"
         << "proximity labels:   " << labelMs << " ms\n"
         << "simplification:     " << simplifyMs << " ms\n";
    if (options.Measure)
    {
      text << "outline deviation:  " << outline.Mean << " px mean, " << outline.Max
           << " px max (from the input's outline, same camera)\n";
    }
  }
  std::cout << text.str();
  std::cout.flush();
}

} // namespace cli
