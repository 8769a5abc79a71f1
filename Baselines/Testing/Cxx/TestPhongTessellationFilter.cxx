// vtkPhongTessellationFilter (Boubekeur and Alexa 2008): triangle count =
// input x (k+1)^2, input points kept, watertight output for a closed input,
// the output arrays (Normals, NewGeometry, OriginalCellId), point data
// interpolated at the flat point and cell data copied, a flat mesh with face
// normals stays flat, on a sphere with exact normals the patches are nearer
// the sphere than flat subdivision (ShapeFactor 0), the options, and bad
// input (NaN points, cells naming missing points) failing the request.
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPhongTessellationFilter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "SilhouetteTestSupport.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{

double LargestRadialError(vtkPolyData* mesh)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    worst = std::max(worst, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0));
  }
  return worst;
}

// Counts, topology, kept points, the three output arrays, and the distance to
// the sphere against the flat tessellation, on the 20- and 80-triangle
// icospheres with their exact normals.
bool CheckSphere()
{
  for (int sphereLevel = 0; sphereLevel <= 1; ++sphereLevel)
  {
    auto sphere = silhouette_test::Icosphere(sphereLevel);
    const vtkIdType inputTriangles = sphere->GetNumberOfPolys();
    vtkNew<vtkPhongTessellationFilter> phong;
    phong->SetInputData(sphere);
    vtkNew<vtkPhongTessellationFilter> flat;
    flat->SetInputData(sphere);
    flat->SetShapeFactor(0.0);
    for (int level = 0; level <= 4; ++level)
    {
      phong->SetLevel(level);
      phong->Update();
      vtkPolyData* out = phong->GetOutput();
      const vtkIdType perTriangle = (level + 1) * (level + 1);
      CHECK(
        silhouette_test::IsUniformTessellationOf(sphere, out, level), "the tessellation's layout");

      auto* newGeometry =
        vtkUnsignedCharArray::SafeDownCast(out->GetCellData()->GetArray("NewGeometry"));
      auto* originalCell =
        vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("OriginalCellId"));
      vtkDataArray* normals = out->GetPointData()->GetNormals();
      CHECK(newGeometry && originalCell && normals, "NewGeometry, OriginalCellId and Normals");
      CHECK(normals == out->GetPointData()->GetArray("Normals") &&
          normals->GetNumberOfComponents() == 3 &&
          normals->GetNumberOfTuples() == out->GetNumberOfPoints(),
        "Normals: the active point normals, one per point");
      std::vector<vtkIdType> perInput(static_cast<std::size_t>(inputTriangles), 0);
      for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
      {
        CHECK(newGeometry->GetValue(c) == (level > 0 ? 1 : 0), "NewGeometry 1, or 0 at level 0");
        const vtkIdType source = originalCell->GetValue(c);
        CHECK(source >= 0 && source < inputTriangles, "OriginalCellId names an input cell");
        ++perInput[static_cast<std::size_t>(source)];
        // With radial normals the patch of a triangle stays inside the cone
        // of its corners, so each output triangle's centre is seen through
        // the cell OriginalCellId names (and no other).
        vtkIdType count = 0;
        const vtkIdType* made = nullptr;
        const vtkIdType* corners = nullptr;
        out->GetCellPoints(c, count, made);
        sphere->GetCellPoints(source, count, corners);
        double centre[3] = { 0, 0, 0 };
        for (int k = 0; k < 3; ++k)
        {
          double q[3];
          out->GetPoint(made[k], q);
          for (int d = 0; d < 3; ++d)
          {
            centre[d] += q[d] / 3.0;
          }
        }
        for (int k = 0; k < 3; ++k)
        {
          double a[3];
          double b[3];
          double side[3];
          sphere->GetPoint(corners[k], a);
          sphere->GetPoint(corners[(k + 1) % 3], b);
          vtkMath::Cross(a, b, side);
          CHECK(vtkMath::Dot(side, centre) > 0.0, "output triangles inside their OriginalCellId");
        }
      }
      for (const vtkIdType count : perInput)
      {
        CHECK(count == perTriangle, "(k+1)^2 triangles from every input triangle");
      }
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double n[3];
        double p[3];
        normals->GetTuple(i, n);
        out->GetPoint(i, p);
        CHECK(std::abs(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) < 1e-6,
          "unit normals");
        CHECK(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] > 0.9, "normals near the sphere's");
      }

      flat->SetLevel(level);
      flat->Update();
      const double phongError = LargestRadialError(out);
      const double flatError = LargestRadialError(flat->GetOutput());
      std::printf("Phong on %lld triangles, level %d: %lld triangles, largest |r - 1| %.5f, "
                  "flat %.5f\n",
        static_cast<long long>(inputTriangles), level,
        static_cast<long long>(out->GetNumberOfPolys()), phongError, flatError);
      if (level >= 1)
      {
        CHECK(phongError < 0.5 * flatError, "Phong patches nearer the sphere than flat");
      }
    }
  }
  return true;
}

// Point data is interpolated with the flat point's barycentric weights (so a
// coordinate carried as data gives the flat tessellation's point, not the
// moved one), a constant stays constant, and cell data is copied from the
// original cell.
bool CheckAttributes()
{
  auto sphere = silhouette_test::Icosphere(1);
  vtkNew<vtkDoubleArray> x;
  x->SetName("X");
  vtkNew<vtkDoubleArray> constant;
  constant->SetName("Constant");
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    x->InsertNextValue(sphere->GetPoint(i)[0]);
    constant->InsertNextValue(7.25);
  }
  sphere->GetPointData()->AddArray(x);
  sphere->GetPointData()->AddArray(constant);
  vtkNew<vtkDoubleArray> cellValue;
  cellValue->SetName("CellValue");
  for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
  {
    cellValue->InsertNextValue(10.0 * static_cast<double>(c) + 0.5);
  }
  sphere->GetCellData()->AddArray(cellValue);

  vtkNew<vtkPhongTessellationFilter> phong;
  phong->SetInputData(sphere);
  phong->SetLevel(3);
  phong->Update();
  vtkNew<vtkPhongTessellationFilter> flat;
  flat->SetInputData(sphere);
  flat->SetLevel(3);
  flat->SetShapeFactor(0.0);
  flat->Update();
  vtkPolyData* out = phong->GetOutput();
  vtkPolyData* flatOut = flat->GetOutput();
  CHECK(out->GetNumberOfPoints() == flatOut->GetNumberOfPoints(), "same points either way");
  vtkDataArray* outX = out->GetPointData()->GetArray("X");
  vtkDataArray* outConstant = out->GetPointData()->GetArray("Constant");
  vtkDataArray* outCell = out->GetCellData()->GetArray("CellValue");
  vtkDataArray* originalCell = out->GetCellData()->GetArray("OriginalCellId");
  CHECK(outX && outConstant && outCell && originalCell, "input arrays carried over");
  double moved = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    CHECK(std::abs(outX->GetTuple1(i) - flatOut->GetPoint(i)[0]) < 1e-12,
      "point data interpolated at the flat point");
    CHECK(std::abs(outConstant->GetTuple1(i) - 7.25) < 1e-12, "interpolation weights sum to one");
    moved = std::max(moved, std::abs(outX->GetTuple1(i) - out->GetPoint(i)[0]));
  }
  // The wrong case: the data is not the moved point's coordinate.
  CHECK(moved > 0.01, "the check above tells the flat point from the moved one");
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    const double expected = 10.0 * originalCell->GetTuple1(c) + 0.5;
    CHECK(outCell->GetTuple1(c) == expected, "cell data copied from the original cell");
  }
  return true;
}

// A flat mesh with the plane's normal everywhere stays in the plane, and a
// linear field carried as point data matches the output points.
bool CheckFlat()
{
  vtkSmartPointer<vtkPolyData> flat = silhouette_test::FlatGrid();
  vtkNew<vtkDoubleArray> field;
  field->SetName("Linear");
  for (vtkIdType i = 0; i < flat->GetNumberOfPoints(); ++i)
  {
    const double* p = flat->GetPoint(i);
    field->InsertNextValue(2.0 * p[0] - 3.0 * p[1] + 0.5);
  }
  flat->GetPointData()->AddArray(field);
  vtkNew<vtkPhongTessellationFilter> phong;
  phong->SetInputData(flat);
  phong->SetLevel(3);
  phong->Update();
  vtkPolyData* out = phong->GetOutput();
  CHECK(
    silhouette_test::IsUniformTessellationOfFlatGrid(flat, out, 3), "the flat grid's tessellation");
  vtkDataArray* outField = out->GetPointData()->GetArray("Linear");
  CHECK(outField, "the linear field is carried over");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    CHECK(std::abs(outField->GetTuple1(i) - (2.0 * p[0] - 3.0 * p[1] + 0.5)) < 1e-5,
      "a linear field is interpolated exactly");
  }
  return true;
}

bool CheckOptions()
{
  vtkNew<vtkPhongTessellationFilter> phong;
  CHECK(phong->GetLevel() == 2 && phong->GetShapeFactor() == 0.75, "defaults 2 and 0.75");
  std::ostringstream printed;
  phong->Print(printed);
  CHECK(printed.str().find("Level: 2") != std::string::npos &&
      printed.str().find("ShapeFactor: 0.75") != std::string::npos,
    "PrintSelf shows the options");
  phong->SetShapeFactor(1.5);
  CHECK(phong->GetShapeFactor() == 1.0, "ShapeFactor clamped to 1");
  phong->SetShapeFactor(-0.5);
  CHECK(phong->GetShapeFactor() == 0.0, "ShapeFactor clamped to 0");
  phong->SetLevel(-3);
  CHECK(phong->GetLevel() == 0, "Level clamped to 0");
  return true;
}

// Bad input fails the request with an error; the same mesh without the fault
// (the wrong case) passes, so the check is the fault's.
bool CheckBadInput()
{
  auto run = [](vtkPolyData* input, std::string& message) {
    vtkNew<vtkPhongTessellationFilter> phong;
    phong->SetInputData(input);
    return silhouette_test::UpdateReportingError(phong, message);
  };
  std::string message;
  auto sphere = silhouette_test::Icosphere(1);
  CHECK(run(sphere, message) == 1 && message.empty(), "a good sphere passes");

  auto nan = silhouette_test::Icosphere(1);
  nan->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  CHECK(run(nan, message) == 0, "NaN points fail the request");
  CHECK(message.find("1 points with NaN or infinite coordinates") != std::string::npos,
    "the NaN points are named");

  CHECK(run(silhouette_test::MeshNamingAMissingPoint(), message) == 0 &&
      message.find("points that do not exist") != std::string::npos,
    "cells naming missing points are an error");

  vtkNew<vtkPolyData> empty;
  vtkNew<vtkPhongTessellationFilter> phong;
  phong->SetInputData(empty);
  phong->Update();
  CHECK(phong->GetOutput()->GetNumberOfPoints() == 0 && phong->GetOutput()->GetNumberOfCells() == 0,
    "empty in, empty out");
  return true;
}

} // namespace

int TestPhongTessellationFilter(int, char*[])
{
  bool ok = CheckSphere();
  ok = CheckAttributes() && ok;
  ok = CheckFlat() && ok;
  ok = CheckOptions() && ok;
  ok = CheckBadInput() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
