// What the vtkOpenSubdivRefiner tests share (TestOpenSubdivRefiner,
// TestOpenSubdivRefinerInput): checks that count failures and go on, small
// vector helpers, hand-made meshes (tetrahedron, octahedron, cube, torus
// grids), a filter run that records its errors and warnings, and Loop's limit
// position in closed form.
#ifndef OpenSubdivRefinerTestSupport_h
#define OpenSubdivRefinerTestSupport_h

#include "SilhouetteTestSupport.h"
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

namespace refiner_test
{

using Vec = std::array<double, 3>;
using Tri = std::array<vtkIdType, 3>;

inline int Failures = 0; ///< failed Expect()s of the running test

// Prints one line per check, "ok" or "FAIL", with the measured numbers.
inline void Expect(bool ok, const char* format, ...)
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

inline Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

inline double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

inline double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}

// The part of a VTK message from `word` on (the message itself without the
// file and line prefix), or "(none)".
inline const char* From(const std::string& message, const char* word)
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

inline Vec PointOf(vtkPolyData* mesh, vtkIdType id)
{
  Vec p;
  mesh->GetPoint(id, p.data());
  return p;
}

inline double Diagonal(vtkPolyData* mesh)
{
  return mesh->GetLength();
}

inline vtkSmartPointer<vtkPolyData> MakeMesh(
  const std::vector<Vec>& points, const std::vector<Tri>& tris)
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
inline std::vector<Tri> Outward(const std::vector<Vec>& points, std::vector<Tri> tris)
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

inline vtkSmartPointer<vtkPolyData> Tetrahedron()
{
  const std::vector<Vec> p = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
  return MakeMesh(p, Outward(p, { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } }));
}

inline vtkSmartPointer<vtkPolyData> Octahedron()
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
inline vtkSmartPointer<vtkPolyData> Cube()
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
inline std::vector<std::array<vtkIdType, 2>> CubeEdges()
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
inline vtkSmartPointer<vtkPolyData> TorusGrid(int nu, int nv)
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

inline vtkSmartPointer<vtkPolyData> TorusSource()
{
  vtkNew<vtkTorusSurfaceSource> source;
  source->SetRingResolution(12);
  source->SetTubeResolution(8);
  source->Update();
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(source->GetOutput());
  return copy;
}

inline std::vector<Tri> Triangles(vtkPolyData* mesh)
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
inline Vec LoopLimit(vtkPolyData* mesh, vtkIdType v, int* valence)
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
inline double SymmetricPointDistance(vtkPolyData* a, vtkPolyData* b)
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

inline long Power4(int level)
{
  return 1L << (2 * level);
}

} // namespace refiner_test

#endif
