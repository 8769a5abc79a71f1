// vtkOpenSubdivRefiner ("Fine references on OpenSubdiv", item 1): Loop limit
// positions against the closed form, level 1 against vtkLoopSubdivisionFilter,
// topology and normals, creases, and the bunny's time. Point data and bad
// input: TestOpenSubdivRefinerInput.
#include "OpenSubdivRefinerTestSupport.h"

namespace
{

using namespace refiner_test;

// The largest distance from an expected point to `refined`, in diagonals
// of the base `mesh`.
double WorstDistanceInDiagonals(
  vtkPolyData* refined, const std::vector<Vec>& expected, vtkPolyData* mesh)
{
  Nearest nearest(refined);
  double worst = 0.0;
  for (const Vec& p : expected)
  {
    worst = std::max(worst, nearest.Distance(p) / Diagonal(mesh));
  }
  return worst;
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
      const double worst = WorstDistanceInDiagonals(run.Output(), expected, mesh);
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
    const double worst = WorstDistanceInDiagonals(run.Output(), expected, grid);
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
  TestBunny(argc, argv);
  std::printf("%s: %d failed check(s)\n", Failures ? "FAILED" : "PASSED", Failures);
  return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
