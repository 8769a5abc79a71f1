// Hostile meshes (issue 6, item 4; per-case expectations, issue 17):
// deterministic pseudo-random meshes of the awkward kinds real files contain
// (non-manifold fans, duplicate points, zero-area and repeated-id triangles,
// inconsistent orientation, coordinates at 1e30 and 1e-30 and both at once,
// NaN, infinite, zero and extreme normals, triangle soups) go through
// vtkSilhouetteSmoothingFilter for many random cameras (parallel and
// perspective, eye outside and inside, view-ups made parallel to the line of
// sight on purpose), with vertex perturbation on and off. Each case says
// what must happen:
// - smoothed: every request with a well-formed view succeeds, without an
//   error, with finite points and normals, ids in range on both outputs, and
//   at least as many triangles as the input has valid ones (three distinct
//   ids); a degenerate view may fail, and only with the view's error;
// - refused (non-finite coordinates, cells naming missing points): every
//   request fails, with the error that names the problem;
// - warned (no triangle at all): every request with a well-formed view
//   succeeds, and a warning says why nothing is smoothed.
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkTestErrorObserver.h"

#include "MeshValidation.h"
#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace
{

// SplitMix64: the same numbers on every platform and standard library.
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : State(seed)
  {
  }
  std::uint64_t next()
  {
    std::uint64_t z = (this->State += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform(double low = 0.0, double high = 1.0)
  {
    return low + (high - low) * static_cast<double>(this->next() >> 11) * 0x1.0p-53;
  }
  vtkIdType below(vtkIdType n) { return static_cast<vtkIdType>(this->next() % n); }
  bool chance(double p) { return this->uniform() < p; }

private:
  std::uint64_t State;
};

struct Triangle
{
  vtkIdType Ids[3];
};

// A mesh under construction: points, optional normals, triangles (and other polygons).
struct Soup
{
  std::vector<std::array<double, 3>> Points;
  std::vector<std::array<double, 3>> Normals; // empty: none
  std::vector<std::vector<vtkIdType>> Polygons;

  vtkIdType add(const std::array<double, 3>& p, const std::array<double, 3>& n = { 0, 0, 1 })
  {
    this->Points.push_back(p);
    if (!this->Normals.empty())
    {
      this->Normals.push_back(n);
    }
    return static_cast<vtkIdType>(this->Points.size() - 1);
  }

  vtkSmartPointer<vtkPolyData> polyData() const
  {
    auto mesh = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const auto& p : this->Points)
    {
      points->InsertNextPoint(p.data());
    }
    mesh->SetPoints(points);
    vtkNew<vtkCellArray> polys;
    for (const auto& polygon : this->Polygons)
    {
      polys->InsertNextCell(static_cast<vtkIdType>(polygon.size()), polygon.data());
    }
    mesh->SetPolys(polys);
    if (!this->Normals.empty())
    {
      vtkNew<vtkDoubleArray> normals;
      normals->SetName("Normals");
      normals->SetNumberOfComponents(3);
      for (const auto& n : this->Normals)
      {
        normals->InsertNextTuple(n.data());
      }
      mesh->GetPointData()->SetNormals(normals);
    }
    return mesh;
  }
};

// An icosphere with its exact normals, as a soup to corrupt.
Soup Sphere(int level)
{
  auto mesh = silhouette_test::Icosphere(level);
  Soup soup;
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  if (normals)
  {
    soup.Normals.reserve(static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  }
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p, n{ 0, 0, 1 };
    mesh->GetPoint(i, p.data());
    if (normals)
    {
      normals->GetTuple(i, n.data());
      soup.Normals.push_back(n);
    }
    soup.Points.push_back(p);
  }
  auto cell = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    cell->GetCurrentCell(size, ids);
    soup.Polygons.emplace_back(ids, ids + size);
  }
  return soup;
}

// --- The corruptions ------------------------------------------------------------

// Fans of 1 to 4 extra triangles on existing edges: 3 to 6 triangles per edge.
void AddNonManifoldFans(Soup& soup, Random& random, int fans)
{
  for (int f = 0; f < fans; ++f)
  {
    const auto& polygon = soup.Polygons[static_cast<std::size_t>(
      random.below(static_cast<vtkIdType>(soup.Polygons.size())))];
    const vtkIdType a = polygon[0], b = polygon[1];
    const int blades = 1 + static_cast<int>(random.below(4));
    for (int k = 0; k < blades; ++k)
    {
      std::array<double, 3> tip;
      for (int c = 0; c < 3; ++c)
      {
        tip[static_cast<std::size_t>(c)] =
          0.5 * (soup.Points[a][c] + soup.Points[b][c]) + random.uniform(-0.6, 0.6);
      }
      const vtkIdType t = soup.add(tip, { random.uniform(-1, 1), random.uniform(-1, 1), 1.0 });
      soup.Polygons.push_back(
        random.chance(0.5) ? std::vector<vtkIdType>{ a, b, t } : std::vector<vtkIdType>{ b, a, t });
    }
  }
}

// Coincident copies of points, some triangles moved onto them (a seam of
// duplicates), and repeated copies of whole triangles.
void AddDuplicates(Soup& soup, Random& random, int count)
{
  const auto original = static_cast<vtkIdType>(soup.Points.size());
  for (int d = 0; d < count; ++d)
  {
    const vtkIdType source = random.below(original);
    const vtkIdType copy = soup.add(soup.Points[static_cast<std::size_t>(source)],
      soup.Normals.empty() ? std::array<double, 3>{ 0, 0, 1 }
                           : soup.Normals[static_cast<std::size_t>(source)]);
    for (auto& polygon : soup.Polygons)
    {
      for (vtkIdType& id : polygon)
      {
        if (id == source && random.chance(0.5))
        {
          id = copy;
        }
      }
    }
    const auto again = soup.Polygons[static_cast<std::size_t>(
      random.below(static_cast<vtkIdType>(soup.Polygons.size())))];
    soup.Polygons.push_back(again);
  }
}

// Repeated-id triangles, collinear triangles with distinct ids, triangles on
// three coincident points, and polygons that repeat ids.
void AddDegenerateTriangles(Soup& soup, Random& random, int count)
{
  const auto n = static_cast<vtkIdType>(soup.Points.size());
  for (int d = 0; d < count; ++d)
  {
    const vtkIdType a = random.below(n), b = random.below(n);
    soup.Polygons.push_back({ a, a, b });
    soup.Polygons.push_back({ a, a, a });
    std::array<double, 3> middle;
    for (int c = 0; c < 3; ++c)
    {
      middle[static_cast<std::size_t>(c)] = 0.5 * (soup.Points[a][c] + soup.Points[b][c]);
    }
    const vtkIdType m = soup.add(middle);
    soup.Polygons.push_back({ a, m, b }); // zero area, distinct ids
    const vtkIdType p = soup.add(soup.Points[a]), q = soup.add(soup.Points[a]);
    soup.Polygons.push_back({ a, p, q });       // three coincident points
    soup.Polygons.push_back({ a, b, a, m, b }); // a polygon repeating ids
    soup.Polygons.push_back({ a, b });          // a "polygon" of two points
  }
}

void FlipSome(Soup& soup, Random& random, double fraction)
{
  for (auto& polygon : soup.Polygons)
  {
    if (random.chance(fraction))
    {
      std::reverse(polygon.begin(), polygon.end());
    }
  }
}

void Scale(Soup& soup, double factor)
{
  for (auto& p : soup.Points)
  {
    for (double& x : p)
    {
      x *= factor;
    }
  }
}

// Some points pushed out to 1e30, some pulled in to 1e-30: both scales in one mesh.
void MixScales(Soup& soup, Random& random)
{
  for (auto& p : soup.Points)
  {
    const double r = random.uniform();
    const double factor = r < 0.1 ? 1e30 : (r < 0.2 ? 1e-30 : 1.0);
    for (double& x : p)
    {
      x *= factor;
    }
  }
}

// NaN, infinite, zero, tiny and huge normals.
void SpoilNormals(Soup& soup, Random& random)
{
  if (soup.Normals.empty())
  {
    soup.Normals.assign(soup.Points.size(), { 0, 0, 1 });
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (auto& n : soup.Normals)
  {
    switch (random.below(8))
    {
      case 0:
        n = { nan, 0, 1 };
        break;
      case 1:
        n = { nan, nan, nan };
        break;
      case 2:
        n = { inf, -inf, 0 };
        break;
      case 3:
        n = { 0, 0, 0 };
        break;
      case 4:
        n = { 1e-300, -1e-300, 1e-310 };
        break;
      case 5:
        n = { 1e300, 1e300, -1e300 };
        break;
      default:
        break; // keep the good normal
    }
  }
}

// Random points (some coincident) and random triangles over them.
Soup TriangleSoup(Random& random, double scale)
{
  Soup soup;
  const int points = 4 + static_cast<int>(random.below(60));
  for (int i = 0; i < points; ++i)
  {
    if (i > 0 && random.chance(0.1))
    {
      soup.add(soup.Points[static_cast<std::size_t>(random.below(i))]);
      continue;
    }
    soup.add({ scale * random.uniform(-1, 1), scale * random.uniform(-1, 1),
      scale * random.uniform(-1, 1) });
  }
  const int triangles = 1 + static_cast<int>(random.below(150));
  for (int t = 0; t < triangles; ++t)
  {
    soup.Polygons.push_back({ random.below(points), random.below(points), random.below(points) });
  }
  return soup;
}

enum class Outcome
{
  Smoothed,
  Refused,
  Warned
};

struct Case
{
  std::string Name;
  Soup Mesh;
  Outcome Expected = Outcome::Smoothed;
  std::string Message = {}; ///< how the error or warning starts (Refused, Warned)
};

// Cases the filter cannot use: it must say so, by an error or a warning.
void AddUnusableMeshes(std::vector<Case>& cases)
{
  Soup nan = Sphere(1);
  nan.Points[3][1] = std::numeric_limits<double>::quiet_NaN();
  cases.push_back({ "a NaN coordinate", nan, Outcome::Refused, "Input has 1 points with NaN" });

  Soup infinite = Sphere(1);
  infinite.Normals.clear();
  infinite.Points[0][2] = -std::numeric_limits<double>::infinity();
  infinite.Points[7][0] = std::numeric_limits<double>::infinity();
  cases.push_back(
    { "two infinite coordinates", infinite, Outcome::Refused, "Input has 2 points with NaN" });

  Soup missing = Sphere(1);
  const auto count = static_cast<vtkIdType>(missing.Points.size());
  missing.Polygons.push_back({ 0, 1, count + 5 });
  cases.push_back({ "a triangle naming a missing point", missing, Outcome::Refused,
    "Input cells refer to points that do not exist" });

  Soup negative = Sphere(1);
  negative.Polygons.push_back({ 0, -1, 2 });
  cases.push_back({ "a triangle naming point -1", negative, Outcome::Refused,
    "Input cells refer to points that do not exist" });

  Soup none = Sphere(1);
  const std::size_t polygons = none.Polygons.size();
  none.Polygons.clear();
  for (std::size_t i = 0; i < polygons; ++i)
  {
    const auto a = static_cast<vtkIdType>(i % static_cast<std::size_t>(count));
    none.Polygons.push_back({ a, (a + 1) % count, a }); // a repeated id
    none.Polygons.push_back({ a, (a + 2) % count });    // two points
  }
  cases.push_back({ "no triangle, only repeated-id and two-point polygons", none, Outcome::Warned,
    "The input has no triangles" });
}

std::vector<Case> HostileMeshes()
{
  std::vector<Case> cases;
  Random random(20080306);
  auto sphere = [&](int level, bool normals) {
    Soup soup = Sphere(level);
    if (!normals)
    {
      soup.Normals.clear();
    }
    return soup;
  };
  for (bool normals : { true, false })
  {
    const std::string suffix = normals ? " (given normals)" : " (computed normals)";
    Soup fans = sphere(2, normals);
    AddNonManifoldFans(fans, random, 25);
    cases.push_back({ "non-manifold fans" + suffix, fans });

    Soup duplicates = sphere(2, normals);
    AddDuplicates(duplicates, random, 40);
    cases.push_back({ "duplicate points and triangles" + suffix, duplicates });

    Soup degenerate = sphere(2, normals);
    AddDegenerateTriangles(degenerate, random, 20);
    cases.push_back({ "zero-area and repeated-id triangles" + suffix, degenerate });

    Soup flipped = sphere(2, normals);
    FlipSome(flipped, random, 0.3);
    cases.push_back({ "inconsistent orientation" + suffix, flipped });

    for (double scale : { 1e30, 1e-30 })
    {
      Soup scaled = sphere(1, normals);
      AddNonManifoldFans(scaled, random, 5);
      AddDegenerateTriangles(scaled, random, 5);
      FlipSome(scaled, random, 0.2);
      Scale(scaled, scale);
      cases.push_back(
        { (scale > 1 ? "everything at 1e30" : "everything at 1e-30") + suffix, scaled });
    }

    Soup mixed = sphere(2, normals);
    MixScales(mixed, random);
    cases.push_back({ "mixed scales 1e-30 and 1e30" + suffix, mixed });
  }
  Soup spoiled = Sphere(2);
  SpoilNormals(spoiled, random);
  cases.push_back({ "NaN, infinite, zero and extreme normals", spoiled });

  Soup everything = Sphere(2);
  AddNonManifoldFans(everything, random, 10);
  AddDuplicates(everything, random, 10);
  AddDegenerateTriangles(everything, random, 10);
  FlipSome(everything, random, 0.25);
  SpoilNormals(everything, random);
  cases.push_back({ "all of it at once", everything });

  for (int s = 0; s < 6; ++s)
  {
    const double scale = std::pow(10.0, -30 + 12 * s);
    Soup soup = TriangleSoup(random, scale);
    if (s % 2 == 1)
    {
      SpoilNormals(soup, random);
    }
    cases.push_back({ "triangle soup at 1e" + std::to_string(-30 + 12 * s), soup });
  }
  AddUnusableMeshes(cases);
  return cases;
}

// --- The checks -----------------------------------------------------------------

bool Finite(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// What the program asks of any mesh it reads (cli::RequireConsistentMesh:
// finite points, cell ids in range, one tuple per point or cell in each
// array), and finite normals.
bool Valid(vtkPolyData* mesh, std::string& problem)
{
  try
  {
    cli::RequireConsistentMesh(mesh, "the output");
  }
  catch (const std::exception& error)
  {
    problem = error.what();
    return false;
  }
  if (vtkDataArray* normals = mesh->GetPointData()->GetNormals())
  {
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
    {
      double n[3];
      normals->GetTuple(i, n);
      if (!Finite(n))
      {
        problem = "normal " + std::to_string(i) + " is not finite";
        return false;
      }
    }
  }
  return true;
}

// Triangles with three distinct ids (the output's triangles, or the input's valid ones).
vtkIdType ValidTriangles(vtkPolyData* mesh)
{
  vtkIdType count = 0;
  auto cell = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    cell->GetCurrentCell(size, ids);
    count += size == 3 && ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2];
  }
  return count;
}

// A random camera: around the mesh's bounding sphere (outside or inside it),
// parallel or perspective; now and then a view-up along the view direction.
// Aims the camera at the mesh from a random place; true when its view-up is
// made parallel to the line of sight on purpose (a degenerate view).
bool AimCamera(vtkCamera* camera, vtkPolyData* mesh, Random& random)
{
  // The bounds of the finite points (vtkPolyData's take infinite ones in).
  double bounds[6] = { 0, -1, 0, -1, 0, -1 };
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
    {
      for (int a = 0; a < 3; ++a)
      {
        const bool first = bounds[2 * a] > bounds[2 * a + 1];
        bounds[2 * a] = first ? p[a] : std::min(bounds[2 * a], p[a]);
        bounds[2 * a + 1] = first ? p[a] : std::max(bounds[2 * a + 1], p[a]);
      }
    }
  }
  double center[3], radius = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    center[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    radius = std::max(radius, 0.5 * (bounds[2 * a + 1] - bounds[2 * a]));
  }
  if (!(radius > 0.0))
  {
    radius = 1.0;
  }
  double direction[3];
  double length = 0.0;
  do
  {
    for (double& d : direction)
    {
      d = random.uniform(-1, 1);
    }
    length = std::sqrt(
      direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  } while (length < 0.1 || length > 1.0);
  const bool inside = random.chance(0.25);
  const double distance = radius * (inside ? random.uniform(0.05, 0.9) : random.uniform(1.2, 30));
  double focal[3], position[3];
  for (int a = 0; a < 3; ++a)
  {
    focal[a] = center[a] + 0.3 * radius * random.uniform(-1, 1);
    position[a] = focal[a] + distance * direction[a] / length;
  }
  camera->SetFocalPoint(focal);
  camera->SetPosition(position);
  const bool degenerate = random.chance(0.05);
  if (degenerate)
  {
    camera->SetViewUp(direction[0], direction[1], direction[2]);
  }
  else
  {
    camera->SetViewUp(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
  }
  camera->SetViewAngle(random.uniform(5, 120));
  camera->SetParallelProjection(random.chance(0.4));
  camera->SetParallelScale(radius * random.uniform(0.2, 3));
  return degenerate;
}

// The first sentence of a VTK error or warning's text:
// "ERROR: In file, line N\nvtkSilhouetteSmoothingFilter (0x...): Text. More".
std::string FirstSentence(std::string message)
{
  const std::size_t text = message.find("): ");
  message = message.substr(text == std::string::npos ? 0 : text + 3);
  return message.substr(0, message.find_first_of(".\n"));
}

bool StartsWith(const std::string& text, const std::string& start)
{
  return text.compare(0, start.size(), start) == 0;
}

const char* NameOf(Outcome outcome)
{
  return outcome == Outcome::Smoothed ? "smoothed"
                                      : (outcome == Outcome::Refused ? "refused" : "warned");
}

// What the requests of one case did.
struct Tally
{
  int Succeeded = 0;
  int Failed = 0;
  bool Warned = false; ///< the expected warning was seen
};

} // namespace

int TestHostileMeshes(int, char*[])
{
  const auto start = std::chrono::steady_clock::now();
  Random random(7);
  constexpr int CamerasPerMesh = 40;
  int succeeded = 0, failed = 0;
  std::map<std::string, int> errorMessages; // the first sentence of each, counted
  bool ok = true;
  for (const Case& hostile : HostileMeshes())
  {
    vtkSmartPointer<vtkPolyData> input = hostile.Mesh.polyData();
    const vtkIdType inputTriangles = ValidTriangles(input);
    Tally tally;
    for (bool perturb : { true, false })
    {
      // One filter per mesh: the prepared cache serves all the cameras.
      vtkNew<vtkSilhouetteSmoothingFilter> filter;
      vtkNew<vtkTest::ErrorObserver> errors;
      vtkNew<vtkTest::ErrorObserver> executiveErrors;
      filter->AddObserver(vtkCommand::ErrorEvent, errors);
      filter->AddObserver(vtkCommand::WarningEvent, errors);
      filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
      filter->SetInputData(input);
      filter->SetPerturbVertices(perturb);
      vtkNew<vtkCamera> camera;
      filter->SetCamera(camera);
      for (int view = 0; view < CamerasPerMesh; ++view)
      {
        const bool degenerateView = AimCamera(camera, input, random);
        filter->SetViewportSize(
          1 + static_cast<int>(random.below(2000)), 1 + static_cast<int>(random.below(2000)));
        filter->SetTolerance(random.uniform(0.1, 3.0));
        errors->Clear();
        executiveErrors->Clear();
        const int result = filter->GetExecutive()->Update();
        const std::string where = hostile.Name + (perturb ? ", perturbation on" : ", off") +
          ", view " + std::to_string(view);
        const std::string error =
          errors->GetError() ? FirstSentence(errors->GetErrorMessage()) : "";
        // Warnings are said once per input, on the first request.
        if (errors->GetWarning() && !hostile.Message.empty() &&
          errors->GetWarningMessage().find(hostile.Message) != std::string::npos)
        {
          tally.Warned = true;
        }
        if (!result)
        {
          ++failed;
          ++tally.Failed;
          if (!errors->GetError())
          {
            std::printf("FAIL: %s: the request failed without an error\n", where.c_str());
            ok = false;
            continue;
          }
          ++errorMessages[error];
          // The view is checked before the input.
          const bool expected =
            (hostile.Expected == Outcome::Refused && StartsWith(error, hostile.Message)) ||
            (degenerateView && StartsWith(error, "The view is degenerate"));
          if (!expected)
          {
            std::printf("FAIL: %s: expected %s, failed with \"%s\"\n", where.c_str(),
              NameOf(hostile.Expected), error.c_str());
            ok = false;
          }
          continue;
        }
        ++succeeded;
        ++tally.Succeeded;
        if (hostile.Expected == Outcome::Refused)
        {
          std::printf("FAIL: %s: expected an error \"%s...\", the request succeeded\n",
            where.c_str(), hostile.Message.c_str());
          ok = false;
          continue;
        }
        std::string problem;
        if (!Valid(filter->GetOutput(), problem) || !Valid(filter->GetSilhouetteOutput(), problem))
        {
          std::printf("FAIL: %s: %s\n", where.c_str(), problem.c_str());
          ok = false;
          continue;
        }
        const vtkIdType outputTriangles = ValidTriangles(filter->GetOutput());
        if (outputTriangles < inputTriangles)
        {
          std::printf("FAIL: %s: %lld output triangles, fewer than the %lld valid input ones\n",
            where.c_str(), static_cast<long long>(outputTriangles),
            static_cast<long long>(inputTriangles));
          ok = false;
        }
      }
    }
    if (hostile.Expected == Outcome::Warned && !tally.Warned)
    {
      std::printf(
        "FAIL: %s: no warning \"%s...\"\n", hostile.Name.c_str(), hostile.Message.c_str());
      ok = false;
    }
    std::printf("%-52s %6lld points %6lld valid triangles: %-8s (%d succeeded, %d failed)\n",
      hostile.Name.c_str(), static_cast<long long>(input->GetNumberOfPoints()),
      static_cast<long long>(inputTriangles), NameOf(hostile.Expected), tally.Succeeded,
      tally.Failed);
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
    "%d requests succeeded, %d failed with an error, in %.2f s\n", succeeded, failed, seconds);
  for (const auto& message : errorMessages)
  {
    std::printf("  %4d x \"%s\"\n", message.second, message.first.c_str());
  }
  CHECK(succeeded > 0, "some requests succeed");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
