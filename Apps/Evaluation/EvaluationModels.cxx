#include "EvaluationModels.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkGenericCell.h"
#include "vtkIcosphereSource.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenSubdivRefiner.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSilhouetteFilterSupport.h"
#include "vtkSilhouetteQuadricDecimation.h"
#include "vtkStaticCellLocator.h"
#include "vtkTorusSurfaceSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace silhouette_eval
{
namespace
{

// How an analytic model's surface is sampled: the (u, v) grid of the
// torus-like ones, or the icosphere subdivision level (in U) of the sphere
// and the ellipsoid. The original and the exact stand-in differ only in this.
struct Sampling
{
  int U = 0;
  int V = 0;
};

struct ModelInfo
{
  const char* Name;
  const char* Description;
  int CoarseTriangles;
  ExactShape Exact;
  Sampling Original; ///< of MakeOriginal (analytic models)
  Sampling StandIn;  ///< of ExactSurface (ExactShape::Surface only)
};

// Coarse sizes where the raw outline is visibly polygonal at 1024 x 768
// (about 1.5 px or more from the fine reference on average). The exact
// stand-ins' samplings are chosen and measured in EvaluationModels.h.
const ModelInfo Models[] = {
  { "bunny", "the Stanford bunny (Data/bunny.ply, 3,674 triangles)", 500, ExactShape::None, {},
    {} },
  { "sphere", "unit icosphere, 1,280 triangles, points on the sphere", 80, ExactShape::UnitSphere,
    { 3 }, {} },
  { "torus", "torus R = 1, r = 0.4, 48 x 24 grid", 300, ExactShape::Surface, { 48, 24 },
    { 720, 360 } },
  { "ellipsoid", "ellipsoid 2 : 1.2 : 0.7, from a 1,280-triangle icosphere", 200,
    ExactShape::Surface, { 3 }, { 7 } },
  { "supertoroid", "super-toroid with a rounded-square tube, 64 x 32 grid", 300,
    ExactShape::Surface, { 64, 32 }, { 720, 360 } },
  { "knot", "trefoil knot tube, 192 x 16 grid", 600, ExactShape::Surface, { 192, 16 },
    { 1440, 180 } },
};

const ModelInfo& InfoOf(const std::string& name)
{
  for (const ModelInfo& info : Models)
  {
    if (name == info.Name)
    {
      return info;
    }
  }
  throw std::runtime_error("no model named '" + name + "'");
}

// Signed power: keeps the sign, raises the magnitude (super-quadrics).
double SignedPower(double x, double e)
{
  return std::copysign(std::pow(std::abs(x), e), x);
}

void SuperToroid(double u, double v, double p[3])
{
  const double ring = 1.0 + 0.45 * SignedPower(std::cos(v), 0.5);
  p[0] = ring * std::cos(u);
  p[1] = ring * std::sin(u);
  p[2] = 0.45 * SignedPower(std::sin(v), 0.5);
}

// Trefoil (2, 3) torus knot with a circular tube around it, in the curve's
// Frenet frame (its curvature never vanishes, so the frame is smooth and
// periodic).
void TrefoilTube(double u, double v, double p[3])
{
  auto curve = [](double t, double c[3]) {
    c[0] = (2.0 + std::cos(3.0 * t)) * std::cos(2.0 * t);
    c[1] = (2.0 + std::cos(3.0 * t)) * std::sin(2.0 * t);
    c[2] = std::sin(3.0 * t);
  };
  const double h = 1e-4;
  double c[3], a[3], b[3];
  curve(u, c);
  curve(u - h, a);
  curve(u + h, b);
  double tangent[3], second[3];
  for (int k = 0; k < 3; ++k)
  {
    tangent[k] = (b[k] - a[k]) / (2.0 * h);
    second[k] = (b[k] - 2.0 * c[k] + a[k]) / (h * h);
  }
  vtkMath::Normalize(tangent);
  double normal[3];
  const double along = vtkMath::Dot(second, tangent);
  for (int k = 0; k < 3; ++k)
  {
    normal[k] = second[k] - along * tangent[k];
  }
  vtkMath::Normalize(normal);
  double binormal[3];
  vtkMath::Cross(tangent, normal, binormal);
  const double radius = 0.45;
  for (int k = 0; k < 3; ++k)
  {
    p[k] = c[k] + radius * (std::cos(v) * normal[k] + std::sin(v) * binormal[k]);
  }
}

} // namespace

// Silhouette smoothing assumes the coarse mesh samples the smooth surface,
// which quadric decimation's optimal placement does not (on a convex shape it
// puts the points outside, and the smoothing then overshoots).
void ProjectOntoSurface(vtkPolyData* coarse, vtkPolyData* surface)
{
  vtkSmartPointer<vtkDataArray> normals = surface->GetPointData()->GetNormals();
  if (!normals)
  {
    vtkNew<vtkPolyDataNormals> compute;
    compute->SetInputData(surface);
    compute->SplittingOff();
    compute->ConsistencyOff();
    compute->ComputePointNormalsOn();
    compute->ComputeCellNormalsOff();
    compute->Update();
    normals = compute->GetOutput()->GetPointData()->GetNormals();
  }
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkPoints> onSurface;
  onSurface->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> coarseNormals;
  coarseNormals->SetName("Normals");
  coarseNormals->SetNumberOfComponents(3);
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < coarse->GetNumberOfPoints(); ++i)
  {
    double p[3], closest[3], distance2, pcoords[3], weights[3];
    vtkIdType cellId = -1;
    int subId = 0;
    coarse->GetPoint(i, p);
    locator->FindClosestPoint(p, closest, cell, cellId, subId, distance2);
    onSurface->InsertNextPoint(closest);
    double n[3] = { 0, 0, 0 };
    if (cellId >= 0 && cell->GetNumberOfPoints() == 3)
    {
      double ignored[3], d2;
      cell->EvaluatePosition(closest, ignored, subId, pcoords, d2, weights);
      for (int k = 0; k < 3; ++k)
      {
        double nk[3];
        normals->GetTuple(cell->GetPointId(k), nk);
        for (int c = 0; c < 3; ++c)
        {
          n[c] += weights[k] * nk[c];
        }
      }
    }
    vtkMath::Normalize(n);
    coarseNormals->InsertNextTuple(n);
  }
  coarse->SetPoints(onSurface);
  coarse->GetPointData()->SetNormals(coarseNormals);
}

std::vector<std::string> ModelNames()
{
  std::vector<std::string> names;
  for (const ModelInfo& info : Models)
  {
    names.emplace_back(info.Name);
  }
  return names;
}

bool IsModelName(const std::string& name)
{
  for (const ModelInfo& info : Models)
  {
    if (name == info.Name)
    {
      return true;
    }
  }
  return false;
}

std::string ModelDescription(const std::string& name)
{
  return InfoOf(name).Description;
}

int DefaultCoarseTriangles(const std::string& name)
{
  return InfoOf(name).CoarseTriangles;
}

ExactShape ExactShapeOf(const std::string& name)
{
  return IsModelName(name) ? InfoOf(name).Exact : ExactShape::None;
}

vtkSmartPointer<vtkPolyData> PeriodicGridSurface(
  int uResolution, int vResolution, void (*surface)(double u, double v, double point[3]))
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto index = [=](int i, int j) {
    return static_cast<vtkIdType>((i % uResolution) * vResolution + (j % vResolution));
  };
  for (int i = 0; i < uResolution; ++i)
  {
    for (int j = 0; j < vResolution; ++j)
    {
      double p[3];
      surface(2.0 * vtkMath::Pi() * i / uResolution, 2.0 * vtkMath::Pi() * j / vResolution, p);
      points->InsertNextPoint(p);
    }
  }
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < uResolution; ++i)
  {
    for (int j = 0; j < vResolution; ++j)
    {
      const vtkIdType first[3] = { index(i, j), index(i + 1, j), index(i + 1, j + 1) };
      const vtkIdType second[3] = { index(i, j), index(i + 1, j + 1), index(i, j + 1) };
      polys->InsertNextCell(3, first);
      polys->InsertNextCell(3, second);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

namespace
{

// The analytic surface of model `name` (not the bunny) sampled as `sampling`
// says: every point on the surface.
vtkSmartPointer<vtkPolyData> SampleAnalytic(const std::string& name, const Sampling& sampling)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  if (name == "sphere" || name == "ellipsoid")
  {
    vtkNew<vtkIcosphereSource> sphere;
    sphere->SetSubdivisionLevel(sampling.U);
    sphere->Update();
    mesh->ShallowCopy(sphere->GetOutput());
    if (name == "ellipsoid")
    {
      vtkNew<vtkTransform> scale;
      scale->Scale(2.0, 1.2, 0.7);
      vtkNew<vtkTransformPolyDataFilter> stretch;
      stretch->SetInputData(mesh);
      stretch->SetTransform(scale); // transforms the normals too
      stretch->Update();
      mesh = vtkSmartPointer<vtkPolyData>::New();
      mesh->ShallowCopy(stretch->GetOutput());
    }
  }
  else if (name == "torus")
  {
    vtkNew<vtkTorusSurfaceSource> torus;
    torus->SetRingResolution(sampling.U);
    torus->SetTubeResolution(sampling.V);
    torus->Update();
    mesh->ShallowCopy(torus->GetOutput());
  }
  else if (name == "supertoroid")
  {
    mesh = PeriodicGridSurface(sampling.U, sampling.V, SuperToroid);
  }
  else if (name == "knot")
  {
    mesh = PeriodicGridSurface(sampling.U, sampling.V, TrefoilTube);
  }
  else
  {
    throw std::runtime_error("'" + name + "' has no analytic surface");
  }
  return mesh;
}

} // namespace

std::string ModelFile(const std::string& name, const std::string& dataDir)
{
  return name == "bunny" ? dataDir + "/bunny.ply" : std::string();
}

vtkSmartPointer<vtkPolyData> MakeOriginal(const std::string& name, const std::string& dataDir)
{
  const std::string path = ModelFile(name, dataDir);
  if (path.empty())
  {
    return SampleAnalytic(name, InfoOf(name).Original); // InfoOf throws for an unknown name
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfPolys() == 0)
  {
    throw std::runtime_error("cannot read the bunny from " + path);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  return mesh;
}

vtkSmartPointer<vtkPolyData> ExactSurface(const std::string& name, int finer)
{
  if (ExactShapeOf(name) != ExactShape::Surface)
  {
    return nullptr;
  }
  Sampling sampling = InfoOf(name).StandIn;
  for (int k = 0; k < finer; ++k)
  {
    // A level more halves an icosphere's edges, as twice the grid does.
    sampling =
      sampling.V == 0 ? Sampling{ sampling.U + 1, 0 } : Sampling{ 2 * sampling.U, 2 * sampling.V };
  }
  return SampleAnalytic(name, sampling);
}

EdgeUses CountEdgeUses(vtkPolyData* mesh)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids[k];
      const vtkIdType b = ids[(k + 1) % n];
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  EdgeUses counts;
  counts.Edges = static_cast<long>(uses.size());
  for (const auto& entry : uses)
  {
    counts.Borders += entry.second == 1 ? 1 : 0;
    counts.NotTwo += entry.second != 2 ? 1 : 0;
  }
  return counts;
}

long CountBoundaryOrNonManifoldEdges(vtkPolyData* mesh)
{
  return CountEdgeUses(mesh).NotTwo;
}

double EnclosedVolume(vtkPolyData* mesh)
{
  double volume = 0.0;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n < 3)
    {
      continue;
    }
    double a[3], b[3], c[3], bc[3];
    mesh->GetPoint(ids[0], a);
    mesh->GetPoint(ids[1], b);
    mesh->GetPoint(ids[2], c);
    vtkMath::Cross(b, c, bc);
    volume += vtkMath::Dot(a, bc) / 6.0;
  }
  return volume;
}

namespace
{

// The input's triangles as the filters read them (vtkTriangleFilter cuts
// some concave polygons into fewer triangles than they take: assimp's
// concave_polygon.obj, 17 of 64).
vtkSmartPointer<vtkPolyData> FiltersTriangles(vtkPolyData* input)
{
  auto triangles = vtkSmartPointer<vtkPolyData>::New();
  const std::string error = vtkSilhouetteFilterSupport::Triangulate(input, triangles);
  if (!error.empty())
  {
    throw std::runtime_error(error);
  }
  return triangles;
}

} // namespace

vtkSmartPointer<vtkPolyData> WeldedTriangles(vtkPolyData* input, vtkIdType* merged)
{
  vtkSmartPointer<vtkPolyData> triangles = FiltersTriangles(input);
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(triangles);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  // Merged, pieces of one surface may still disagree on their winding (the
  // spider's do), which the Loop refinement refuses: made consistent, each
  // connected part as its first triangle winds (no cell flips on a mesh
  // that agrees already), then the whole turned outward below.
  vtkNew<vtkPolyDataNormals> orient;
  orient->SetInputConnection(clean->GetOutputPort());
  orient->ConsistencyOn();
  orient->SplittingOff();
  orient->AutoOrientNormalsOff();
  orient->ComputeCellNormalsOff();
  orient->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(orient->GetOutput()->GetPoints());
  mesh->SetPolys(orient->GetOutput()->GetPolys());
  // A part winds as its first triangle did: when that one was the odd one
  // out, the whole came out inside out. A negative enclosed volume turns
  // it back (the truth evaluation tells outside from inside by it).
  if (EnclosedVolume(mesh) < 0.0)
  {
    for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
    {
      mesh->GetPolys()->ReverseCellAtId(c);
    }
  }
  if (merged)
  {
    // Points no triangle uses go too; only those sharing a position count.
    vtkNew<vtkCleanPolyData> unused;
    unused->SetInputData(triangles);
    unused->PointMergingOff();
    unused->Update();
    *merged = unused->GetOutput()->GetNumberOfPoints() - mesh->GetNumberOfPoints();
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> Decimate(vtkPolyData* original, int triangles)
{
  vtkSmartPointer<vtkPolyData> input = FiltersTriangles(original);
  const vtkIdType have = input->GetNumberOfPolys();
  auto coarse = vtkSmartPointer<vtkPolyData>::New();
  if (have <= triangles)
  {
    coarse->SetPoints(input->GetPoints());
    coarse->SetPolys(input->GetPolys());
    return coarse;
  }
  // Our quadric simplifier, not vtkQuadricDecimation: it collapses an edge
  // only when the link condition holds, so a closed surface stays closed (VTK's
  // broke a 5,800-triangle cow at 500 and 1,000 triangles).
  vtkNew<vtkSilhouetteQuadricDecimation> decimate;
  decimate->SetInputData(input);
  decimate->SetTargetTriangles(triangles);
  decimate->Update();
  // Only geometry: normals of the original do not belong to the moved points.
  coarse->SetPoints(decimate->GetOutput()->GetPoints());
  coarse->SetPolys(decimate->GetOutput()->GetPolys());
  ProjectOntoSurface(coarse, input);
  if (CountBoundaryOrNonManifoldEdges(input) == 0 && CountBoundaryOrNonManifoldEdges(coarse) != 0)
  {
    throw std::runtime_error("quadric decimation to " + std::to_string(triangles) +
      " triangles broke the closed surface; ask for more triangles");
  }
  return coarse;
}

vtkSmartPointer<vtkPolyData> Refine(vtkPolyData* original, int level)
{
  vtkNew<vtkOpenSubdivRefiner> refiner;
  refiner->SetInputData(original);
  refiner->SetLevel(level);
  refiner->ProjectToLimitOn();
  refiner->Update();
  if (refiner->GetOutput()->GetNumberOfPolys() == 0)
  {
    throw std::runtime_error("Loop refinement failed");
  }
  auto fine = vtkSmartPointer<vtkPolyData>::New();
  fine->ShallowCopy(refiner->GetOutput());
  return fine;
}

ModelVersions MakeVersions(const std::string& name, vtkSmartPointer<vtkPolyData> original,
  int coarseTriangles, int fineLevel)
{
  ModelVersions versions;
  versions.Name = name;
  versions.Description = IsModelName(name) ? ModelDescription(name) : name;
  versions.Exact = ExactShapeOf(name);
  versions.Original = original;
  versions.Coarse = Decimate(original, coarseTriangles);
  versions.Fine = Refine(original, fineLevel);
  return versions;
}

} // namespace silhouette_eval
