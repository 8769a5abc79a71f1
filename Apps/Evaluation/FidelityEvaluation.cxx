#include "FidelityEvaluation.h"

#include "EvaluationModels.h"
#include "FoldCounting.h"
#include "ShadingNormals.h"
#include "SilhouetteComparison.h"
#include "SilhouetteMasks.h"

#include "vtkButterflySubdivisionFilter.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImplicitPolyDataDistance.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNTriangleFilter.h"
#include "vtkPhongTessellationFilter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace silhouette_eval
{
namespace
{

vtkSmartPointer<vtkPolyData> WithoutNormals(vtkPolyData* mesh)
{
  auto bare = vtkSmartPointer<vtkPolyData>::New();
  bare->SetPoints(mesh->GetPoints());
  bare->SetPolys(mesh->GetPolys());
  return bare;
}

double FieldCount(vtkPolyData* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  return array ? array->GetTuple1(0) : static_cast<double>(mesh->GetNumberOfPolys());
}

// The coarse mesh with the normals ours computes by default, for the peers.
vtkSmartPointer<vtkPolyData> WithAreaNormals(vtkPolyData* mesh)
{
  std::vector<glm::dvec3> points(static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double x[3];
    mesh->GetPoint(p, x);
    points[static_cast<std::size_t>(p)] = glm::dvec3(x[0], x[1], x[2]);
  }
  std::vector<silsmooth::Triangle> triangles;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n == 3)
    {
      triangles.push_back({ { ids[0], ids[1], ids[2] } });
    }
  }
  const std::vector<glm::dvec3> normals =
    silsmooth::vertexNormals(points, triangles, silsmooth::NormalWeighting::Area);
  vtkNew<vtkFloatArray> array;
  array->SetName("Normals");
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (std::size_t p = 0; p < normals.size(); ++p)
  {
    array->SetTuple3(static_cast<vtkIdType>(p), normals[p].x, normals[p].y, normals[p].z);
  }
  auto withNormals = vtkSmartPointer<vtkPolyData>::New();
  withNormals->ShallowCopy(mesh);
  withNormals->GetPointData()->SetNormals(array);
  return withNormals;
}

void Add(FidelityRow& row, const BoundaryDistance& toReference, const BoundaryDistance& toOriginal,
  int view, int views)
{
  if (row.WorstView < 0 || toReference.Max > row.Max)
  {
    row.WorstView = view;
    row.WorstOutside = toReference.FarthestOutside;
  }
  row.Mean += toReference.Mean / views;
  row.Max = std::max(row.Max, toReference.Max);
  row.MeanToOriginal += toOriginal.Mean / views;
  row.MaxToOriginal = std::max(row.MaxToOriginal, toOriginal.Max);
}

// The signed distances of `mesh`'s points from `surface` (positive
// outside), largest outside and inside, over `surface`'s bounding-box diagonal.
std::pair<double, double> SignedDistanceRange(vtkPolyData* mesh, vtkPolyData* surface)
{
  vtkNew<vtkImplicitPolyDataDistance> distance;
  distance->SetInput(surface);
  double outside = 0.0;
  double inside = 0.0;
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double x[3];
    mesh->GetPoint(p, x);
    const double d = distance->EvaluateFunction(x);
    outside = std::max(outside, d);
    inside = std::min(inside, d);
  }
  const double diagonal = surface->GetLength();
  return diagonal > 0.0 ? std::make_pair(outside / diagonal, inside / diagonal)
                        : std::make_pair(0.0, 0.0);
}

} // namespace

vtkSmartPointer<vtkPolyData> InterpolatingRefinement(vtkPolyData* original, int levels)
{
  auto input = vtkSmartPointer<vtkPolyData>::New();
  input->DeepCopy(original);
  input->GetPolys()->ConvertTo64BitStorage();
  vtkNew<vtkButterflySubdivisionFilter> butterfly;
  butterfly->SetInputData(input);
  butterfly->SetNumberOfSubdivisions(levels);
  butterfly->Update();
  auto fine = vtkSmartPointer<vtkPolyData>::New();
  fine->SetPoints(butterfly->GetOutput()->GetPoints());
  fine->SetPolys(butterfly->GetOutput()->GetPolys());
  if (fine->GetNumberOfPolys() == 0)
  {
    throw std::runtime_error("Butterfly subdivision failed");
  }
  return fine;
}

FidelityResult EvaluateFidelity(
  const std::string& name, vtkPolyData* input, const FidelityOptions& options)
{
  auto progress = [&](const std::string& what) {
    if (options.Progress)
    {
      options.Progress(name + ": " + what);
    }
  };
  vtkSmartPointer<vtkPolyData> original = WeldedTriangles(input);
  if (original->GetNumberOfPolys() == 0 || CountBoundaryOrNonManifoldEdges(original) != 0)
  {
    throw std::runtime_error(
      "it is not a closed manifold triangle mesh (the evaluation needs one)");
  }
  FidelityResult result;
  result.Name = name;
  result.OriginalTriangles = static_cast<long>(original->GetNumberOfPolys());

  progress("decimating to " + std::to_string(options.CoarseTriangles) +
    " triangles and refining the original by Butterfly subdivision");
  // Decimate moves the points onto the original and carries its normals.
  vtkSmartPointer<vtkPolyData> carried = Decimate(original, options.CoarseTriangles);
  vtkSmartPointer<vtkPolyData> own = WithoutNormals(carried);
  result.CoarseTriangles = static_cast<long>(own->GetNumberOfPolys());
  vtkSmartPointer<vtkPolyData> reference =
    InterpolatingRefinement(original, options.ReferenceLevels);
  result.ReferenceTriangles = static_cast<long>(reference->GetNumberOfPolys());
  std::tie(result.ReferenceOutside, result.ReferenceInside) =
    SignedDistanceRange(reference, original);
  result.CoarsePointsOnReference = options.CoarsePointsOnReference;
  if (options.CoarsePointsOnReference)
  {
    ProjectOntoSurface(carried, reference);
    own = WithoutNormals(carried);
  }

  MaskRenderer masks(options.Width, options.Height);
  vtkNew<vtkRenderer> framing;
  vtkNew<vtkRenderWindow> framingWindow;
  framingWindow->SetOffScreenRendering(1);
  framingWindow->SetSize(options.Width, options.Height);
  framingWindow->AddRenderer(framing);

  auto smootherFor = [&](vtkPolyData* mesh, int estimation) {
    auto smoother = vtkSmartPointer<vtkSilhouetteSmoothingFilter>::New();
    smoother->SetInputData(mesh);
    smoother->SetCamera(framing->GetActiveCamera());
    smoother->SetViewportSize(options.Width, options.Height);
    smoother->SetTolerance(options.Tolerance);
    smoother->SetNormalEstimation(estimation);
    return smoother;
  };
  // Ours with each estimate of the coarse mesh's own normals, and with the
  // original's normals carried over; rows in this order after "coarse".
  const std::pair<const char*, int> estimations[] = {
    { "ours, angle-weighted normals", vtkSilhouetteSmoothingFilter::ANGLE_WEIGHTED },
    { "ours, area-weighted normals", vtkSilhouetteSmoothingFilter::AREA_WEIGHTED },
    { "ours, Max normals", vtkSilhouetteSmoothingFilter::MAX_WEIGHTED },
    { "ours, quadric-fit normals", vtkSilhouetteSmoothingFilter::QUADRIC_FIT }
  };
  std::vector<FidelityRow> rows{ FidelityRow{ "coarse" } };
  std::vector<vtkSmartPointer<vtkSilhouetteSmoothingFilter>> smoothers;
  for (const auto& [label, estimation] : estimations)
  {
    rows.push_back(FidelityRow{ label });
    smoothers.push_back(smootherFor(own, estimation));
  }
  rows.push_back(FidelityRow{ "ours, carried normals" });
  smoothers.push_back(smootherFor(carried, vtkSilhouetteSmoothingFilter::ANGLE_WEIGHTED));
  rows.push_back(FidelityRow{ "ours, area, no fold guard" });
  smoothers.push_back(smootherFor(own, vtkSilhouetteSmoothingFilter::AREA_WEIGHTED));
  smoothers.back()->FoldPreventionOff();
  const std::size_t carriedRow = 1 + std::size(estimations);
  progress("measuring outlines from " + std::to_string(options.Views) + " views");
  for (int view = 0; view < options.Views; ++view)
  {
    PlaceCamera(framing, original, view, options.Views);
    vtkCamera* camera = framing->GetActiveCamera();
    const Mask truth = masks.Render(reference, camera);
    const Mask originalMask = masks.Render(original, camera);
    for (std::size_t r = 0; r < rows.size(); ++r)
    {
      vtkPolyData* mesh = own;
      if (r > 0)
      {
        smoothers[r - 1]->Update();
        mesh = smoothers[r - 1]->GetOutput();
      }
      const Mask mask = masks.Render(mesh, camera);
      Add(rows[r], OutlineDeviation(mask, truth), OutlineDeviation(mask, originalMask), view,
        options.Views);
      rows[r].Triangles += FieldCount(mesh, "OutputTriangleCount") / options.Views;
      if (r > 0)
      {
        const FoldCount folds = CountFolds(r == carriedRow ? carried.Get() : own.Get(), mesh);
        rows[r].TurnedOver = std::max(rows[r].TurnedOver, 0L) + folds.Flipped;
        rows[r].Cutting = std::max(rows[r].Cutting, 0L) + folds.Intersecting;
        rows[r].ChordFallbacks = std::max(rows[r].ChordFallbacks, 0L) +
          static_cast<long>(FieldCount(mesh, "ChordFallbackCount"));
      }
    }
  }
  result.Rows = rows;
  const FidelityRow& ownRow = rows[1];

  // The view-independent peers, from the coarse mesh with the normals ours
  // uses by default (the same information): nearest our count, and at the
  // fixed level.
  vtkSmartPointer<vtkPolyData> peerInput = WithAreaNormals(own);
  const int nearest = NearestPNLevel(static_cast<double>(result.CoarseTriangles), ownRow.Triangles);
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> peers;
  for (const int level : { nearest, options.HighLevel })
  {
    vtkNew<vtkPNTriangleFilter> pn;
    pn->SetInputData(peerInput);
    pn->SetLevel(level);
    pn->Update();
    peers.emplace_back("PN triangles, level " + std::to_string(level), pn->GetOutput());
    vtkNew<vtkPhongTessellationFilter> phong;
    phong->SetInputData(peerInput);
    phong->SetLevel(level);
    phong->Update();
    peers.emplace_back("Phong tessellation, level " + std::to_string(level), phong->GetOutput());
    if (nearest == options.HighLevel)
    {
      break;
    }
  }
  progress("measuring the PN triangles and Phong tessellation");
  for (const auto& [label, mesh] : peers)
  {
    FidelityRow row{ label };
    row.Triangles = static_cast<double>(mesh->GetNumberOfPolys());
    for (int view = 0; view < options.Views; ++view)
    {
      PlaceCamera(framing, original, view, options.Views);
      vtkCamera* camera = framing->GetActiveCamera();
      const Mask mask = masks.Render(mesh, camera);
      Add(row, OutlineDeviation(mask, masks.Render(reference, camera)),
        OutlineDeviation(mask, masks.Render(original, camera)), view, options.Views);
    }
    result.Rows.push_back(row);
  }
  return result;
}

} // namespace silhouette_eval
