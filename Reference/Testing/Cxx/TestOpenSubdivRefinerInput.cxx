// vtkOpenSubdivRefiner's input (the rest is TestOpenSubdivRefiner): point
// arrays carried through the refinement (interpolated, integer ones
// rounded, attributes kept), and bad input refused with an error or a
// warning that says why.
#include "OpenSubdivRefinerTestSupport.h"

namespace
{

using namespace refiner_test;

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

} // namespace

int TestOpenSubdivRefinerInput(int, char*[])
{
  TestPointData();
  TestBadInput();
  std::printf("%s: %d failed check(s)\n", Failures ? "FAILED" : "PASSED", Failures);
  return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
