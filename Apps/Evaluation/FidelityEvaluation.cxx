#include "FidelityEvaluation.h"

#include "EvaluationModels.h"
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
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNTriangleFilter.h"
#include "vtkPhongTessellationFilter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace silhouette_eval
{
namespace
{

vtkSmartPointer<vtkPolyData> Triangulated(vtkPolyData* input)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputConnection(triangles->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(clean->GetOutput()->GetPoints());
  mesh->SetPolys(clean->GetOutput()->GetPolys());
  return mesh;
}

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

// New triangles whose geometric normal points against their corners' summed
// shading normals.
long FlippedNewTriangles(vtkPolyData* mesh)
{
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* kinds = mesh->GetCellData()->GetArray("NewGeometry");
  if (!normals || !kinds)
  {
    return 0;
  }
  long flipped = 0;
  const vtkIdType first = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  vtkIdType cell = first;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n != 3 || kinds->GetTuple1(cell) == 0)
    {
      continue;
    }
    double p[3][3];
    double sum[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
      double nk[3];
      normals->GetTuple(ids[k], nk);
      vtkMath::Add(sum, nk, sum);
    }
    double u[3], v[3], face[3];
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, face);
    flipped += vtkMath::Dot(face, sum) < 0.0 ? 1 : 0;
  }
  return flipped;
}

void Add(FidelityRow& row, const BoundaryDistance& toReference, const BoundaryDistance& toOriginal,
  int views)
{
  row.Mean += toReference.Mean / views;
  row.Max = std::max(row.Max, toReference.Max);
  row.MeanToOriginal += toOriginal.Mean / views;
  row.MaxToOriginal = std::max(row.MaxToOriginal, toOriginal.Max);
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
  vtkSmartPointer<vtkPolyData> original = Triangulated(input);
  if (original->GetNumberOfPolys() == 0 || CountBoundaryOrNonManifoldEdges(original) != 0)
  {
    throw std::runtime_error(
      name + " is not a closed manifold triangle mesh (the evaluation needs one)");
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
      Add(rows[r], OutlineDeviation(mask, truth), OutlineDeviation(mask, originalMask),
        options.Views);
      rows[r].Triangles += FieldCount(mesh, "OutputTriangleCount") / options.Views;
      if (r > 0)
      {
        rows[r].FlippedNewTriangles =
          std::max(rows[r].FlippedNewTriangles, 0L) + FlippedNewTriangles(mesh);
      }
    }
  }
  result.Rows = rows;
  const FidelityRow& ownRow = rows[1];

  // The view-independent peers, from the coarse mesh with its own normals
  // (the information ours has): nearest our count, and at the fixed level.
  const int nearest = NearestPNLevel(static_cast<double>(result.CoarseTriangles), ownRow.Triangles);
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> peers;
  for (const int level : { nearest, options.HighLevel })
  {
    vtkNew<vtkPNTriangleFilter> pn;
    pn->SetInputData(own);
    pn->SetLevel(level);
    pn->Update();
    peers.emplace_back("PN triangles, level " + std::to_string(level), pn->GetOutput());
    vtkNew<vtkPhongTessellationFilter> phong;
    phong->SetInputData(own);
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
        OutlineDeviation(mask, masks.Render(original, camera)), options.Views);
    }
    result.Rows.push_back(row);
  }
  return result;
}

} // namespace silhouette_eval
