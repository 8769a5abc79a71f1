// vtkOpenSubdivRefiner ("Fine references on OpenSubdiv", item 1): Loop limit
// positions against the closed form, level 1 against vtkLoopSubdivisionFilter,
// topology and normals, creases, point data, bad input, and the bunny's time.
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenSubdivRefiner.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"
#include "vtkTestErrorObserver.h"
#include "vtkTorusSurfaceSource.h"
#include "vtkUnsignedCharArray.h"

#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using Vec = std::array<double, 3>;
using Tri = std::array<vtkIdType, 3>;

int Failures = 0;

// Prints one line per check, "ok" or "FAIL", with the measured numbers.
void Expect(bool ok, const char* format, ...)
{
  std::printf("%s ", ok ? "  ok  " : "  FAIL");
  va_list args;
  va_start(args, format);
  std::vprintf(format, args);
  va_end(args);
  std::printf("\n");
  if (!ok)
  {
    ++Failures;
  }
}

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}

// The part of a VTK message from `word` on (the message itself without the
// file and line prefix), or "(none)".
const char* From(const std::string& message, const char* word)
{
  static std::string part;
  const std::size_t at = message.find(word);
  part = at == std::string::npos ? std::string("(none)") : message.substr(at);
  while (!part.empty() && (part.back() == '\n' || part.back() == ' '))
  {
    part.pop_back();
  }
  return part.c_str();
}

Vec PointOf(vtkPolyData* mesh, vtkIdType id)
{
  Vec p;
  mesh->GetPoint(id, p.data());
  return p;
}

double Diagonal(vtkPolyData* mesh)
{
  return mesh->GetLength();
}

vtkSmartPointer<vtkPolyData> MakeMesh(const std::vector<Vec>& points, const std::vector<Tri>& tris)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const Vec& p : points)
  {
    pts->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const Tri& t : tris)
  {
    polys->InsertNextCell(3, t.data());
  }
  mesh->SetPoints(pts);
  mesh->SetPolys(polys);
  return mesh;
}

// Orients the triangles of a convex solid around the origin outward.
std::vector<Tri> Outward(const std::vector<Vec>& points, std::vector<Tri> tris)
{
  for (Tri& t : tris)
  {
    const Vec& a = points[t[0]];
    const Vec& b = points[t[1]];
    const Vec& c = points[t[2]];
    const Vec centre{ a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2] };
    if (Dot(Cross(Sub(b, a), Sub(c, a)), centre) < 0.0)
    {
      std::swap(t[1], t[2]);
    }
  }
  return tris;
}

vtkSmartPointer<vtkPolyData> Tetrahedron()
{
  const std::vector<Vec> p = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
  return MakeMesh(p, Outward(p, { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } }));
}

vtkSmartPointer<vtkPolyData> Octahedron()
{
  const std::vector<Vec> p = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  std::vector<Tri> tris;
  for (vtkIdType x : { 0, 1 })
  {
    for (vtkIdType y : { 2, 3 })
    {
      for (vtkIdType z : { 4, 5 })
      {
        tris.push_back({ x, y, z });
      }
    }
  }
  return MakeMesh(p, Outward(p, tris));
}

// The cube [-1, 1]^3 as 8 points and 12 triangles (no split normals).
vtkSmartPointer<vtkPolyData> Cube()
{
  std::vector<Vec> p;
  for (int i = 0; i < 8; ++i)
  {
    p.push_back({ i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0 });
  }
  const std::vector<Tri> tris = { { 0, 1, 3 }, { 0, 3, 2 }, { 4, 5, 7 }, { 4, 7, 6 }, { 0, 1, 5 },
    { 0, 5, 4 }, { 2, 3, 7 }, { 2, 7, 6 }, { 0, 2, 6 }, { 0, 6, 4 }, { 1, 3, 7 }, { 1, 7, 5 } };
  return MakeMesh(p, Outward(p, tris));
}

// The 12 edges of Cube(): point ids differing in one bit.
std::vector<std::array<vtkIdType, 2>> CubeEdges()
{
  std::vector<std::array<vtkIdType, 2>> edges;
  for (vtkIdType a = 0; a < 8; ++a)
  {
    for (vtkIdType bit : { 1, 2, 4 })
    {
      if (!(a & bit))
      {
        edges.push_back({ a, a | bit });
      }
    }
  }
  return edges;
}

// A torus grid, nu x nv quads each split along the same diagonal: every vertex
// has valence 6.
vtkSmartPointer<vtkPolyData> TorusGrid(int nu, int nv)
{
  std::vector<Vec> p;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2.0 * vtkMath::Pi() * i / nu;
      const double v = 2.0 * vtkMath::Pi() * j / nv;
      p.push_back({ (1.0 + 0.4 * std::cos(v)) * std::cos(u),
        (1.0 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v) });
    }
  }
  auto id = [&](int i, int j) {
    return static_cast<vtkIdType>(((i + nu) % nu) * nv + (j + nv) % nv);
  };
  std::vector<Tri> tris;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      tris.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      tris.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return MakeMesh(p, tris);
}

using silhouette_test::Icosphere;

vtkSmartPointer<vtkPolyData> TorusSource()
{
  vtkNew<vtkTorusSurfaceSource> source;
  source->SetRingResolution(12);
  source->SetTubeResolution(8);
  source->Update();
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(source->GetOutput());
  return copy;
}

std::vector<Tri> Triangles(vtkPolyData* mesh)
{
  std::vector<Tri> tris;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType npts;
  const vtkIdType* pts;
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    if (npts == 3)
    {
      tris.push_back({ pts[0], pts[1], pts[2] });
    }
  }
  return tris;
}

// Runs the refiner; records errors and warnings of the filter and its executive.
struct Run
{
  vtkNew<vtkOpenSubdivRefiner> Filter;
  vtkNew<vtkTest::ErrorObserver> Errors;
  vtkNew<vtkTest::ErrorObserver> ExecutiveErrors;
  bool Ok = false;
  double Milliseconds = 0.0;

  Run(vtkPolyData* input, int level, bool limit, double featureAngle = 0.0)
  {
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->Errors);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->Errors);
    this->Filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->ExecutiveErrors);
    this->Filter->SetInputData(input);
    this->Filter->SetLevel(level);
    this->Filter->SetProjectToLimit(limit);
    this->Filter->SetFeatureAngle(featureAngle);
    const auto start = std::chrono::steady_clock::now();
    this->Ok = this->Filter->GetExecutive()->Update() != 0;
    this->Milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  vtkPolyData* Output() { return this->Filter->GetOutput(); }
  std::string Error() { return this->Errors->GetError() ? this->Errors->GetErrorMessage() : ""; }
  std::string Warning()
  {
    return this->Errors->GetWarning() ? this->Errors->GetWarningMessage() : "";
  }
  bool Clean() { return this->Ok && !this->Errors->GetError() && !this->Errors->GetWarning(); }
};

// Loop's limit position of vertex `v` of `mesh` in closed form (interior vertex).
Vec LoopLimit(vtkPolyData* mesh, vtkIdType v, int* valence)
{
  std::set<vtkIdType> neighbours;
  for (const Tri& t : Triangles(mesh))
  {
    for (int k = 0; k < 3; ++k)
    {
      if (t[k] == v)
      {
        neighbours.insert(t[(k + 1) % 3]);
        neighbours.insert(t[(k + 2) % 3]);
      }
    }
  }
  const double n = static_cast<double>(neighbours.size());
  const double c = 3.0 / 8.0 + std::cos(2.0 * vtkMath::Pi() / n) / 4.0;
  const double beta = (5.0 / 8.0 - c * c) / n;
  const double chi = 1.0 / (n + 3.0 / (8.0 * beta));
  const Vec p = PointOf(mesh, v);
  Vec limit{ (1.0 - n * chi) * p[0], (1.0 - n * chi) * p[1], (1.0 - n * chi) * p[2] };
  for (vtkIdType w : neighbours)
  {
    const Vec q = PointOf(mesh, w);
    for (int k = 0; k < 3; ++k)
    {
      limit[k] += chi * q[k];
    }
  }
  *valence = static_cast<int>(neighbours.size());
  return limit;
}

// Distance from `p` to the nearest point of `mesh`.
struct Nearest
{
  vtkNew<vtkStaticPointLocator> Locator;
  vtkPolyData* Mesh;
  explicit Nearest(vtkPolyData* mesh)
    : Mesh(mesh)
  {
    this->Locator->SetDataSet(mesh);
    this->Locator->BuildLocator();
  }
  double Distance(const Vec& p)
  {
    const vtkIdType id = this->Locator->FindClosestPoint(p.data());
    return id < 0 ? std::numeric_limits<double>::infinity() : Norm(Sub(PointOf(this->Mesh, id), p));
  }
};

// Largest distance from a point of one mesh to the nearest point of the other.
double SymmetricPointDistance(vtkPolyData* a, vtkPolyData* b)
{
  double worst = 0.0;
  Nearest inA(a);
  Nearest inB(b);
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst, inB.Distance(PointOf(a, i)));
  }
  for (vtkIdType i = 0; i < b->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst, inA.Distance(PointOf(b, i)));
  }
  return worst;
}

long Power4(int level)
{
  return 1L << (2 * level);
}

// (1) Limit positions of the base vertices against the closed form.
void TestLimitPositions()
{
  std::printf("(1) limit positions against v_inf = (1 - n chi) v + chi sum(neighbours)\n");
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes = {
    { "tetrahedron", Tetrahedron() }, { "octahedron", Octahedron() },
    { "icosahedron", Icosphere(0) }, { "torus grid 8x6", TorusGrid(8, 6) },
    { "icosphere level 1", Icosphere(1) }, { "cube", Cube() }
  };
  for (const auto& named : meshes)
  {
    vtkPolyData* mesh = named.second;
    std::vector<Vec> expected;
    std::set<int> valences;
    for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
    {
      int valence = 0;
      expected.push_back(LoopLimit(mesh, v, &valence));
      valences.insert(valence);
    }
    std::string valenceText;
    for (int n : valences)
    {
      valenceText += (valenceText.empty() ? "" : ",") + std::to_string(n);
    }
    for (int level = 0; level <= 3; ++level)
    {
      Run run(mesh, level, true);
      Nearest nearest(run.Output());
      double worst = 0.0;
      for (const Vec& p : expected)
      {
        worst = std::max(worst, nearest.Distance(p) / Diagonal(mesh));
      }
      Expect(run.Clean() && worst < 1e-9,
        "%-18s valence %-5s level %d: max |p - v_inf| / diagonal = %.2e over %zu vertices",
        named.first.c_str(), valenceText.c_str(), level, worst, expected.size());
    }
  }

  // An open, curved 3 x 3 grid of fanned quads. Boundary rule (edge and
  // corner): a boundary vertex in one triangle is a corner and stays; any other
  // boundary vertex goes to the cubic B-spline limit of the boundary polygon,
  // (previous + 4 v + next) / 6, whatever the interior; interior vertices as above.
  std::vector<Vec> p;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      p.push_back({ double(i), double(j),
        0.25 * (i - 1.5) * (i - 1.5) - 0.2 * (j - 1.5) * (j - 1.5) + 0.1 * i * j });
    }
  }
  std::vector<Tri> tris;
  for (vtkIdType j = 0; j < 3; ++j)
  {
    for (vtkIdType i = 0; i < 3; ++i)
    {
      const vtkIdType a = j * 4 + i;
      tris.push_back({ a, a + 1, a + 5 });
      tris.push_back({ a, a + 5, a + 4 });
    }
  }
  vtkSmartPointer<vtkPolyData> grid = MakeMesh(p, tris);
  std::map<std::pair<vtkIdType, vtkIdType>, int> edgeUses;
  std::vector<int> trianglesAt(p.size(), 0);
  for (const Tri& t : tris)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++edgeUses[std::minmax(t[k], t[(k + 1) % 3])];
      ++trianglesAt[t[k]];
    }
  }
  std::vector<std::vector<vtkIdType>> boundaryNeighbours(p.size());
  for (const auto& entry : edgeUses)
  {
    if (entry.second == 1)
    {
      boundaryNeighbours[entry.first.first].push_back(entry.first.second);
      boundaryNeighbours[entry.first.second].push_back(entry.first.first);
    }
  }
  std::vector<Vec> expected;
  int corners = 0;
  int boundary = 0;
  for (vtkIdType v = 0; v < static_cast<vtkIdType>(p.size()); ++v)
  {
    const std::vector<vtkIdType>& b = boundaryNeighbours[v];
    if (b.empty())
    {
      int valence = 0;
      expected.push_back(LoopLimit(grid, v, &valence));
    }
    else if (trianglesAt[v] == 1)
    {
      expected.push_back(p[v]);
      ++corners;
    }
    else
    {
      const Vec& a = p[b[0]];
      const Vec& c = p[b[1]];
      expected.push_back({ (a[0] + 4 * p[v][0] + c[0]) / 6, (a[1] + 4 * p[v][1] + c[1]) / 6,
        (a[2] + 4 * p[v][2] + c[2]) / 6 });
      ++boundary;
    }
  }
  for (int level = 0; level <= 3; ++level)
  {
    Run run(grid, level, true);
    Nearest nearest(run.Output());
    double worst = 0.0;
    for (const Vec& q : expected)
    {
      worst = std::max(worst, nearest.Distance(q) / Diagonal(grid));
    }
    Expect(run.Clean() && worst < 1e-9,
      "open curved grid level %d: %d corners (one triangle), %d other boundary and %d interior "
      "vertices: max |p - expected| / diagonal = %.2e",
      level, corners, boundary, static_cast<int>(p.size()) - corners - boundary, worst);
  }
}

// (2) Level 1 without limit projection against VTK's own Loop filter.
void TestAgainstVtkLoop()
{
  std::printf("(2) level 1 without projection against vtkLoopSubdivisionFilter\n");
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes = {
    { "icosphere level 1", Icosphere(1) }, { "torus 12x8", TorusSource() }
  };
  for (const auto& named : meshes)
  {
    vtkPolyData* mesh = named.second;
    Run ours(mesh, 1, false);

    // VTK 9.1's filter misreads 32-bit cell storage as non-manifold.
    vtkNew<vtkPolyData> input;
    input->DeepCopy(mesh);
    input->GetPolys()->ConvertTo64BitStorage();
    vtkNew<vtkLoopSubdivisionFilter> loop;
    loop->SetNumberOfSubdivisions(1);
    loop->SetInputData(input);
    loop->Update();
    vtkPolyData* theirs = loop->GetOutput();

    const double distance = SymmetricPointDistance(ours.Output(), theirs) / Diagonal(mesh);
    Expect(ours.Clean() && distance < 1e-6 &&
        ours.Output()->GetNumberOfPoints() == theirs->GetNumberOfPoints() &&
        ours.Output()->GetNumberOfPolys() == theirs->GetNumberOfPolys(),
      "%-18s: %lld / %lld points, %lld / %lld triangles (ours / VTK), max nearest-point "
      "distance / diagonal = %.2e",
      named.first.c_str(), static_cast<long long>(ours.Output()->GetNumberOfPoints()),
      static_cast<long long>(theirs->GetNumberOfPoints()),
      static_cast<long long>(ours.Output()->GetNumberOfPolys()),
      static_cast<long long>(theirs->GetNumberOfPolys()), distance);
  }
}

// (3) Closed manifold in, closed manifold out; normals; original cell ids.
void TestTopologyAndNormals()
{
  std::printf("(3) topology, limit normals, OriginalCellId\n");
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes = {
    { "icosphere level 1", Icosphere(1) }, { "torus 12x8", TorusSource() },
    { "torus grid 8x6", TorusGrid(8, 6) }, { "tetrahedron", Tetrahedron() }
  };
  for (const auto& named : meshes)
  {
    vtkPolyData* mesh = named.second;
    const long inputTriangles = static_cast<long>(mesh->GetNumberOfPolys());
    for (int level = 1; level <= 3; ++level)
    {
      Run run(mesh, level, true);
      vtkPolyData* out = run.Output();
      const silhouette_test::TopologyReport report = silhouette_test::AnalyzeTopology(out);
      vtkDataArray* normals = out->GetPointData()->GetNormals();
      double worstLength = normals ? 0.0 : 1.0;
      for (vtkIdType i = 0; normals && i < normals->GetNumberOfTuples(); ++i)
      {
        const double* n = normals->GetTuple3(i);
        worstLength = std::max(worstLength, std::abs(Norm({ n[0], n[1], n[2] }) - 1.0));
      }
      Expect(run.Clean() && report.closedManifold() && report.DegenerateTriangles == 0 &&
          report.NonFinitePoints == 0 && report.FlippedTriangles == 0 &&
          report.Triangles == Power4(level) * inputTriangles && worstLength < 1e-12,
        "%-18s level %d: %ld triangles (4^%d x %ld), %s; max ||n| - 1| = %.1e", named.first.c_str(),
        level, report.Triangles, level, inputTriangles, report.summary().c_str(), worstLength);
    }
  }

  // Outward normals on the sphere.
  {
    Run run(Icosphere(1), 3, true);
    vtkPolyData* out = run.Output();
    vtkDataArray* normals = out->GetPointData()->GetNormals();
    double worstDot = 1.0;
    for (vtkIdType i = 0; normals && i < out->GetNumberOfPoints(); ++i)
    {
      const Vec p = PointOf(out, i);
      const double* n = normals->GetTuple3(i);
      worstDot = std::min(worstDot, Dot({ n[0], n[1], n[2] }, p) / Norm(p));
    }
    Expect(normals && worstDot > 0.99,
      "icosphere level 1 -> level 3: min normal . p/|p| = %.6f (> 0.99)", worstDot);
  }

  // OriginalCellId: 4^N children per input triangle, each in its parent's patch
  // (on the icosahedron, the patch of a face is its central projection: the
  // region nearest to the face centre's direction), input cell data copied.
  vtkSmartPointer<vtkPolyData> icosahedron = Icosphere(0);
  vtkNew<vtkIntArray> tags;
  tags->SetName("Tag");
  for (vtkIdType c = 0; c < icosahedron->GetNumberOfCells(); ++c)
  {
    tags->InsertNextValue(static_cast<int>(10 * c));
  }
  icosahedron->GetCellData()->AddArray(tags);
  std::vector<Vec> centres;
  for (const Tri& t : Triangles(icosahedron))
  {
    Vec c{ 0, 0, 0 };
    for (vtkIdType id : t)
    {
      const Vec p = PointOf(icosahedron, id);
      c = { c[0] + p[0], c[1] + p[1], c[2] + p[2] };
    }
    centres.push_back(c);
  }
  for (int level = 1; level <= 3; ++level)
  {
    for (bool limit : { false, true })
    {
      Run run(icosahedron, level, limit);
      vtkPolyData* out = run.Output();
      vtkIdTypeArray* ids =
        vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("OriginalCellId"));
      vtkIntArray* outTags = vtkIntArray::SafeDownCast(out->GetCellData()->GetArray("Tag"));
      std::map<vtkIdType, long> children;
      long wrongPatch = 0;
      long wrongTag = 0;
      const std::vector<Tri> tris = Triangles(out);
      for (std::size_t f = 0; ids && outTags && f < tris.size(); ++f)
      {
        const vtkIdType id = ids->GetValue(static_cast<vtkIdType>(f));
        ++children[id];
        Vec c{ 0, 0, 0 };
        for (vtkIdType p : tris[f])
        {
          const Vec q = PointOf(out, p);
          c = { c[0] + q[0], c[1] + q[1], c[2] + q[2] };
        }
        std::size_t best = 0;
        for (std::size_t k = 1; k < centres.size(); ++k)
        {
          if (Dot(c, centres[k]) > Dot(c, centres[best]))
          {
            best = k;
          }
        }
        wrongPatch += static_cast<vtkIdType>(best) != id;
        wrongTag += outTags->GetValue(static_cast<vtkIdType>(f)) != 10 * id;
      }
      bool counts = children.size() == 20;
      for (const auto& entry : children)
      {
        counts = counts && entry.first >= 0 && entry.first < 20 && entry.second == Power4(level);
      }
      Expect(run.Clean() && ids && outTags && counts && wrongPatch == 0 && wrongTag == 0,
        "icosahedron level %d%s: OriginalCellId gives %zu parents with 4^%d children each: %s; "
        "children outside their parent's patch: %ld; wrong copied cell data: %ld",
        level, limit ? " (limit)" : "", children.size(), level, counts ? "yes" : "no", wrongPatch,
        wrongTag);
    }
  }
}

// (4) Creases on the cube, by FeatureAngle and by line cells.
void TestCreases()
{
  std::printf("(4) creases\n");
  const std::vector<std::array<vtkIdType, 2>> edges = CubeEdges();
  vtkSmartPointer<vtkPolyData> cube = Cube();

  // Distance of p from the union of the cube's 12 edges.
  auto edgeDistance = [&](const Vec& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& e : edges)
    {
      const Vec a = PointOf(cube, e[0]);
      const Vec d = Sub(PointOf(cube, e[1]), a);
      const double t = std::min(1.0, std::max(0.0, Dot(Sub(p, a), d) / Dot(d, d)));
      best = std::min(best, Norm(Sub(p, { a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2] })));
    }
    return best;
  };
  // At level 3 each creased edge holds 2^3 - 1 refined points, plus the corners.
  const long creasePoints = 12 * 7 + 8;
  auto checkCreased = [&](vtkPolyData* out, const char* how) {
    long onEdges = 0;
    long nearEdges = 0;
    double worstOnEdge = 0.0;
    double worstOnSurface = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const Vec p = PointOf(out, i);
      const double d = edgeDistance(p);
      if (d < 1e-3)
      {
        ++nearEdges;
        worstOnEdge = std::max(worstOnEdge, d);
        onEdges += d < 1e-9;
      }
      const double maxNorm = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
      worstOnSurface = std::max(worstOnSurface, std::abs(maxNorm - 1.0));
    }
    Nearest nearest(out);
    double worstCorner = 0.0;
    for (vtkIdType c = 0; c < 8; ++c)
    {
      worstCorner = std::max(worstCorner, nearest.Distance(PointOf(cube, c)));
    }
    Expect(onEdges == creasePoints && nearEdges == creasePoints && worstOnEdge < 1e-9 &&
        worstCorner < 1e-9 && worstOnSurface < 1e-9,
      "cube, %s, level 3, limit: %ld points on the 12 edges (expected %ld), max distance to "
      "the edges %.1e; corners moved by at most %.1e; max distance to the cube's faces %.1e",
      how, onEdges, creasePoints, worstOnEdge, worstCorner, worstOnSurface);
  };

  Run byAngle(cube, 3, true, 30.0);
  Expect(byAngle.Clean(), "cube, FeatureAngle 30: no error or warning");
  checkCreased(byAngle.Output(), "FeatureAngle 30");

  // Without creases the cube rounds off.
  {
    Run smooth(cube, 3, true, 0.0);
    Nearest nearest(smooth.Output());
    const double moved = nearest.Distance({ 1, 1, 1 });
    double maxNorm = 0.0;
    for (vtkIdType i = 0; i < smooth.Output()->GetNumberOfPoints(); ++i)
    {
      const Vec p = PointOf(smooth.Output(), i);
      maxNorm = std::max({ maxNorm, std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
    }
    Expect(smooth.Clean() && moved > 0.1 && maxNorm < 0.95,
      "cube, no creases, level 3, limit: corner (1,1,1) is %.3f from the nearest output point, "
      "max |coordinate| %.3f",
      moved, maxNorm);
  }
  // The threshold: the cube's edges are 90 degrees, its face diagonals 0.
  for (double angle : { 80.0, 100.0 })
  {
    Run run(cube, 2, true, angle);
    Nearest nearest(run.Output());
    const double moved = nearest.Distance({ 1, 1, 1 });
    Expect(run.Clean() && (angle < 90.0 ? moved < 1e-12 : moved > 0.1),
      "cube, FeatureAngle %g, level 2: corner (1,1,1) moved by %.3f (%s)", angle, moved,
      angle < 90.0 ? "edges creased" : "edges smooth");
  }

  // Line cells: 8 edges as 2-point lines, the 4 edges of the face z = +1 as one
  // closed polyline, and a segment between opposite corners that is no edge.
  vtkNew<vtkPolyData> marked;
  marked->DeepCopy(cube);
  vtkNew<vtkCellArray> lines;
  long twoPointLines = 0;
  for (const auto& e : edges)
  {
    if (!((e[0] & 4) && (e[1] & 4)))
    {
      lines->InsertNextCell(2, e.data());
      ++twoPointLines;
    }
  }
  const vtkIdType top[5] = { 4, 5, 7, 6, 4 };
  lines->InsertNextCell(5, top);
  const vtkIdType bogus[2] = { 0, 7 };
  lines->InsertNextCell(2, bogus);
  marked->SetLines(lines);
  const vtkIdType numLines = marked->GetNumberOfLines();

  Run byLines(marked, 3, true, 0.0);
  const std::string warning = byLines.Warning();
  Expect(byLines.Ok && !byLines.Errors->GetError() &&
      warning.find("Ignored 1 crease segment") != std::string::npos,
    "cube, %ld 2-point lines + a 5-point polyline + 1 segment that is no edge: warning \"%s\"",
    twoPointLines, From(warning, "Ignored"));
  checkCreased(byLines.Output(), "crease lines");
  const double apart = SymmetricPointDistance(byLines.Output(), byAngle.Output());
  Expect(
    apart < 1e-12, "crease lines and FeatureAngle 30 give the same points (%.1e apart)", apart);
  vtkDataArray* ids = byLines.Output()->GetCellData()->GetArray("OriginalCellId");
  double range[2] = { -1, -1 };
  if (ids)
  {
    ids->GetRange(range);
  }
  Expect(ids && range[0] == numLines && range[1] == numLines + 11 &&
      byLines.Output()->GetNumberOfLines() == 0,
    "with %lld line cells first, OriginalCellId spans %g..%g (the polygons' cell ids); no lines "
    "in the output",
    static_cast<long long>(numLines), range[0], range[1]);
}

// (5) Point data carried through the refinement.
void TestPointData()
{
  std::printf("(5) point data\n");
  vtkSmartPointer<vtkPolyData> mesh = TorusSource();
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> x;
  x->SetName("X");
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("UV");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkIntArray> seven;
  seven->SetName("Seven");
  vtkNew<vtkUnsignedCharArray> colour;
  colour->SetName("Colour");
  colour->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Vec p = PointOf(mesh, i);
    x->InsertNextValue(p[0]);
    tcoords->InsertNextTuple2(p[0], p[1]);
    seven->InsertNextValue(7);
    colour->InsertNextTuple3(10, 120, 250);
  }
  mesh->GetPointData()->SetScalars(x);
  mesh->GetPointData()->SetTCoords(tcoords);
  mesh->GetPointData()->AddArray(seven);
  mesh->GetPointData()->AddArray(colour);

  for (int level : { 1, 2 })
  {
    for (bool limit : { false, true })
    {
      Run run(mesh, level, limit);
      vtkPolyData* out = run.Output();
      vtkPointData* pd = out->GetPointData();
      auto* outX = vtkDoubleArray::SafeDownCast(pd->GetScalars());
      auto* outUV = vtkFloatArray::SafeDownCast(pd->GetTCoords());
      auto* outSeven = vtkIntArray::SafeDownCast(pd->GetArray("Seven"));
      auto* outColour = vtkUnsignedCharArray::SafeDownCast(pd->GetArray("Colour"));
      const bool types = outX && outUV && outSeven && outColour &&
        outUV->GetNumberOfComponents() == 2 && outColour->GetNumberOfComponents() == 3 &&
        std::string(outX->GetName()) == "X" && std::string(outUV->GetName()) == "UV";
      double worstX = 0.0;
      double worstUV = 0.0;
      long wrongInts = 0;
      for (vtkIdType i = 0; types && i < out->GetNumberOfPoints(); ++i)
      {
        const Vec p = PointOf(out, i);
        worstX = std::max(worstX, std::abs(outX->GetValue(i) - p[0]));
        worstUV = std::max(worstUV,
          std::max(std::abs(outUV->GetComponent(i, 0) - p[0]),
            std::abs(outUV->GetComponent(i, 1) - p[1])));
        wrongInts += outSeven->GetValue(i) != 7;
        wrongInts += outColour->GetValue(3 * i) != 10 || outColour->GetValue(3 * i + 1) != 120 ||
          outColour->GetValue(3 * i + 2) != 250;
      }
      Expect(run.Clean() && types && worstX < 1e-9 && worstUV < 1e-6 && wrongInts == 0,
        "torus level %d%s: scalar X (double, active scalars) max |X - x| = %.1e; UV (float, 2 "
        "components, active tcoords) max |UV - (x, y)| = %.1e; int and 3 x uchar constants "
        "kept: %s",
        level, limit ? " (limit)" : "", worstX, worstUV, wrongInts == 0 ? "yes" : "no");
    }
  }

  // The input's normals: replaced by limit normals, or dropped without projection.
  {
    vtkSmartPointer<vtkPolyData> sphere = Icosphere(1); // has exact point Normals
    Run without(sphere, 1, false);
    Run with(sphere, 1, true);
    Expect(without.Clean() && !without.Output()->GetPointData()->GetNormals() &&
        !without.Output()->GetPointData()->GetArray("Normals") &&
        with.Output()->GetPointData()->GetNormals() &&
        with.Output()->GetPointData()->GetNumberOfArrays() == 1,
      "input Normals: dropped without projection, replaced by the limit normals with it");
  }
}

// (6) Bad and unusual input.
void TestBadInput()
{
  std::printf("(6) bad and unusual input\n");
  {
    // Three triangles on the edge (0, 1).
    auto mesh = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } },
      { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } });
    Run run(mesh, 2, true);
    const std::string error = run.Error();
    Expect(!run.Ok && error.find("Non-manifold input") != std::string::npos &&
        run.ExecutiveErrors->GetError() && run.Output()->GetNumberOfCells() == 0,
      "three triangles on one edge: request failed with \"%s\"", From(error, "Non-manifold"));
  }
  {
    auto mesh = MakeMesh(
      { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 } }, { { 0, 1, 2 }, { 0, 1, 3 } });
    Run run(mesh, 2, true);
    const std::string error = run.Error();
    Expect(!run.Ok && error.find("Inconsistent orientation") != std::string::npos &&
        run.ExecutiveErrors->GetError(),
      "inconsistent orientation: request failed with \"%s\"", From(error, "Inconsistent"));
  }
  {
    auto mesh = Tetrahedron();
    mesh->GetPoints()->SetPoint(2, std::nan(""), 0, 0);
    Run run(mesh, 2, true);
    const std::string error = run.Error();
    Expect(!run.Ok && error.find("NaN") != std::string::npos && run.ExecutiveErrors->GetError(),
      "NaN coordinate: request failed with \"%s\"", From(error, "Point"));
  }
  {
    auto mesh = Tetrahedron();
    const vtkIdType missing[3] = { 0, 1, 99 };
    mesh->GetPolys()->InsertNextCell(3, missing);
    Run run(mesh, 1, true);
    const std::string error = run.Error();
    Expect(!run.Ok && error.find("refers to point 99") != std::string::npos,
      "cell naming a missing point: request failed with \"%s\"", From(error, "Cell"));
  }
  {
    vtkNew<vtkPolyData> empty;
    Run run(empty, 3, true);
    vtkNew<vtkPolyData> pointsOnly;
    pointsOnly->SetPoints(Tetrahedron()->GetPoints());
    Run run2(pointsOnly, 3, true);
    Expect(run.Clean() && run.Output()->GetNumberOfPoints() == 0 && run2.Clean() &&
        run2.Output()->GetNumberOfPoints() == 0,
      "empty input and points without cells: empty output, no error");
  }
  {
    // A 3 x 3 grid of quads in the plane z = 0, and a triangle strip of 6 points.
    std::vector<Vec> p;
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        p.push_back({ double(i), double(j), 0.0 });
      }
    }
    vtkNew<vtkPolyData> grid;
    grid->SetPoints(MakeMesh(p, {})->GetPoints());
    vtkNew<vtkCellArray> quads;
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        const vtkIdType q[4] = { j * 4 + i, j * 4 + i + 1, (j + 1) * 4 + i + 1, (j + 1) * 4 + i };
        quads->InsertNextCell(4, q);
      }
    }
    grid->SetPolys(quads);
    for (bool limit : { false, true })
    {
      Run run(grid, 2, limit);
      vtkPolyData* out = run.Output();
      const silhouette_test::TopologyReport report = silhouette_test::AnalyzeTopology(out);
      double worstZ = 0.0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        worstZ = std::max(worstZ, std::abs(PointOf(out, i)[2]));
      }
      Expect(run.Clean() && report.Triangles == 9 * 2 * 16 && report.OtherCells == 0 &&
          report.NonManifoldEdges == 0 && report.OrientationConflicts == 0 &&
          report.BoundaryEdges == 12 * 4 && worstZ < 1e-12,
        "3x3 quads, level 2%s: %ld triangles (expected 288), %s, max |z| %.1e",
        limit ? " (limit)" : "", report.Triangles, report.summary().c_str(), worstZ);
    }

    vtkNew<vtkPolyData> strip;
    strip->SetPoints(grid->GetPoints());
    vtkNew<vtkCellArray> strips;
    const vtkIdType s[6] = { 0, 4, 1, 5, 2, 6 };
    strips->InsertNextCell(6, s);
    strip->SetStrips(strips);
    Run run(strip, 2, false);
    vtkPolyData* out = run.Output();
    const silhouette_test::TopologyReport report = silhouette_test::AnalyzeTopology(out);
    long facingDown = 0;
    for (const Tri& t : Triangles(out))
    {
      const Vec n = Cross(
        Sub(PointOf(out, t[1]), PointOf(out, t[0])), Sub(PointOf(out, t[2]), PointOf(out, t[0])));
      facingDown += n[2] > 0.0; // the strip starts clockwise seen from +z
    }
    Expect(run.Clean() && report.Triangles == 4 * 16 && report.OrientationConflicts == 0 &&
        facingDown == 0,
      "triangle strip of 6 points, level 2: %ld triangles (expected 64), %ld facing the other "
      "way",
      report.Triangles, facingDown);
  }
  {
    // Two fans of three triangles sharing only their centre (a bowtie vertex),
    // and a degenerate triangle.
    auto mesh = MakeMesh({ { 0, 0, 0 }, { 1, -1, 0.5 }, { 1, 0, 1 }, { 1, 1, 0.5 }, { 0.5, 1.5, 0 },
                           { -1, 1, 0.5 }, { -1, 0, 1 }, { -1, -1, 0.5 }, { -0.5, -1.5, 0 } },
      { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 5, 6 }, { 0, 6, 7 }, { 0, 7, 8 },
        { 1, 1, 2 } });
    Run run(mesh, 2, true);
    const std::string warning = run.Warning();
    Nearest nearest(run.Output());
    const double moved = nearest.Distance({ 0, 0, 0 });
    Expect(run.Ok && !run.Errors->GetError() && run.Output()->GetNumberOfPolys() == 6 * 16 &&
        warning.find("Dropped 1 degenerate") != std::string::npos && moved < 1e-12,
      "bowtie vertex and a degenerate triangle, level 2 (limit): %lld triangles (expected 96), "
      "the bowtie vertex moved by %.1e (a corner), warning \"%s\"",
      static_cast<long long>(run.Output()->GetNumberOfPolys()), moved, From(warning, "Dropped"));
  }
  {
    vtkNew<vtkOpenSubdivRefiner> filter;
    filter->SetLevel(12);
    filter->SetFeatureAngle(-5);
    std::ostringstream printed;
    filter->Print(printed);
    Expect(filter->GetLevel() == 8 && filter->GetFeatureAngle() == 0.0 &&
        printed.str().find("ProjectToLimit: On") != std::string::npos,
      "SetLevel(12) clamps to %d, SetFeatureAngle(-5) to %g, PrintSelf prints the settings",
      filter->GetLevel(), filter->GetFeatureAngle());
  }
}

// The bunny (3,674 triangles, with holes) to level 3 with limit projection.
void TestBunny(int argc, char* argv[])
{
  std::printf("bunny\n");
  vtkSmartPointer<vtkPolyData> bunny =
    silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bunny.ply"));
  if (!bunny)
  {
    Expect(false, "could not read bunny.ply");
    return;
  }
  Run run(bunny, 3, true);
  double best = run.Milliseconds;
  for (int i = 0; i < 2; ++i)
  {
    Run again(bunny, 3, true);
    best = std::min(best, again.Milliseconds);
  }
  const silhouette_test::TopologyReport in = silhouette_test::AnalyzeTopology(bunny);
  const silhouette_test::TopologyReport out = silhouette_test::AnalyzeTopology(run.Output());
  Expect(run.Clean() && out.Triangles == 64 * in.Triangles && out.NonManifoldEdges == 0 &&
      out.OrientationConflicts == 0 && out.FlippedTriangles == 0 &&
      out.BoundaryEdges == 8 * in.BoundaryEdges,
    "bunny %ld triangles (%ld boundary edges) -> level 3, limit: %ld triangles, %lld points, %ld "
    "boundary edges, %ld flipped; %.1f ms (best of 3)",
    in.Triangles, in.BoundaryEdges, out.Triangles,
    static_cast<long long>(run.Output()->GetNumberOfPoints()), out.BoundaryEdges,
    out.FlippedTriangles, best);
}

} // namespace

int TestOpenSubdivRefiner(int argc, char* argv[])
{
  TestLimitPositions();
  TestAgainstVtkLoop();
  TestTopologyAndNormals();
  TestCreases();
  TestPointData();
  TestBadInput();
  TestBunny(argc, argv);
  std::printf("%s: %d failed check(s)\n", Failures ? "FAILED" : "PASSED", Failures);
  return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
