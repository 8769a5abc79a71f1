// vtkCreaseAndBorderLines with vtkSilhouetteLineVisibility (issue 16): the
// known answers of a line drawing.
// - A cube (vtkCubeSource: four points per face, each with the face's
//   normal) through the smoothing filter, seen in perspective from a generic
//   direction: 12 crease lines and no border; its 9 visible edges drawn
//   whole and the 3 that meet at the far corner hidden, with no visible stub
//   at their ends, with the automatic edge tolerance and with a mean edge's
//   (the faces that hide an edge are not its local sheet). The wrong
//   variant, a mean edge's tolerance on the surface without its normals
//   (one sheet), draws hidden edges.
// - A sphere in front of a plane: the plane's border is one loop, and the
//   part the sphere hides is hidden, its ends within 0.02 of the exact
//   sphere's shadow on the border line.
// - The same box smooth-shaded (one normal per corner): no crease.
// - A capped cylinder's silhouette lines end on its rims' crease points.
// - Two unit spheres overlapping (centres 1 apart, not joined), seen from
//   above: they meet along one intersection loop near the circle x = 0,
//   radius sqrt(0.75); its upper half is visible, its lower half hidden.
//   With Intersections off the drawing has no line there.
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCreaseAndBorderLines.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSilhouetteLineVisibility.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{

bool Fail(const char* what)
{
  std::printf("FAIL: %s\n", what);
  return false;
}

vtkIdType FieldValue(vtkPolyData* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? static_cast<vtkIdType>(array->GetTuple1(0)) : -1;
}

struct Piece
{
  bool Visible = true;
  int Kind = -1;
  double Length = 0.0;
  double Start[3] = { 0, 0, 0 };
  double End[3] = { 0, 0, 0 };
};

std::vector<Piece> Pieces(vtkPolyData* lines)
{
  std::vector<Piece> pieces;
  vtkDataArray* visible = lines->GetCellData()->GetArray("Visible");
  vtkDataArray* kind = lines->GetCellData()->GetArray("LineKind");
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  vtkIdType cell = lines->GetNumberOfVerts();
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    Piece piece;
    piece.Visible = visible && visible->GetTuple1(cell) != 0;
    piece.Kind = kind ? static_cast<int>(kind->GetTuple1(cell)) : -1;
    for (vtkIdType i = 1; i < n; ++i)
    {
      double a[3];
      double b[3];
      lines->GetPoint(ids[i - 1], a);
      lines->GetPoint(ids[i], b);
      piece.Length += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
    }
    lines->GetPoint(ids[0], piece.Start);
    lines->GetPoint(ids[n - 1], piece.End);
    pieces.push_back(piece);
  }
  return pieces;
}

// The cube from a generic direction: 9 visible edges of length 1, and the
// hidden ones hidden but for stubs shorter than `stub`. With `edgeTolerance`
// > 0 the creases are tested with it instead of the automatic one.
bool CheckCube(double edgeTolerance, bool withNormals, double& longestHiddenStub)
{
  vtkNew<vtkCubeSource> cube; // unit cube at the origin, 24 points, face normals
  vtkNew<vtkCamera> camera;
  camera->SetPosition(2.5, 1.85, 2.15);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  vtkNew<vtkSilhouetteSmoothingFilter> smoothing;
  smoothing->SetInputConnection(cube->GetOutputPort());
  smoothing->SetCamera(camera);
  vtkNew<vtkCreaseAndBorderLines> edges;
  edges->SetInputConnection(smoothing->GetOutputPort(0));
  vtkNew<vtkAppendPolyData> drawing; // silhouettes (none on a cube), creases, borders
  drawing->AddInputConnection(smoothing->GetOutputPort(1));
  drawing->AddInputConnection(edges->GetOutputPort());
  vtkNew<vtkSilhouetteLineVisibility> visibility;
  visibility->SetInputConnection(drawing->GetOutputPort());
  smoothing->Update();
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(smoothing->GetOutput(0));
  if (!withNormals)
  {
    // Without normals one vertex joins the faces' copies of a corner, so
    // every face is in the local sheet of every edge.
    vtkNew<vtkPointData> bare;
    surface->GetPointData()->ShallowCopy(bare);
  }
  visibility->SetSurfaceData(surface);
  visibility->SetCamera(camera);
  visibility->SetEdgeTolerance(edgeTolerance);
  visibility->Update();
  vtkPolyData* creases = edges->GetOutput();
  if (FieldValue(creases, "CreaseLineCount") != 12 || FieldValue(creases, "BorderLineCount") != 0)
  {
    std::printf("creases %lld, borders %lld\n",
      static_cast<long long>(FieldValue(creases, "CreaseLineCount")),
      static_cast<long long>(FieldValue(creases, "BorderLineCount")));
    return Fail("a cube has 12 creases and no border");
  }
  int visibleEdges = 0;
  longestHiddenStub = 0.0;
  for (const Piece& piece : Pieces(visibility->GetOutput()))
  {
    if (piece.Kind != 1)
    {
      return Fail("every line of a cube is a crease (LineKind 1)");
    }
    if (piece.Visible && std::abs(piece.Length - 1.0) < 1e-9)
    {
      ++visibleEdges;
    }
    else if (piece.Visible)
    {
      longestHiddenStub = std::max(longestHiddenStub, piece.Length);
    }
  }
  std::printf("edge tolerance %g, %s normals: %d whole visible edges, longest visible stub %g\n",
    edgeTolerance, withNormals ? "with" : "without", visibleEdges, longestHiddenStub);
  if (visibleEdges != 9)
  {
    return Fail("9 visible edges of a cube from a generic direction");
  }
  if (FieldValue(visibility->GetOutput(), "HiddenPieceCount") < 3)
  {
    return Fail("the 3 edges at the far corner are hidden");
  }
  return true;
}

// A sphere of radius R centred over the border x = 2 of the plane
// [-2, 2]^2 at z = 0, seen from high above: the sphere hides the border
// where the ray to the eye passes through it.
bool CheckSphereHidesBorder()
{
  const double eye[3] = { 0.0, 0.0, 20.0 };
  const double centre[3] = { 2.0, 0.0, 1.5 };
  const double radius = 0.8;
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2.0, -2.0, 0.0);
  plane->SetPoint1(2.0, -2.0, 0.0);
  plane->SetPoint2(-2.0, 2.0, 0.0);
  plane->SetResolution(40, 40);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(centre);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  vtkNew<vtkAppendPolyData> scene;
  scene->AddInputConnection(plane->GetOutputPort());
  scene->AddInputConnection(sphere->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(scene->GetOutputPort());
  vtkNew<vtkCreaseAndBorderLines> edges;
  edges->SetInputConnection(triangles->GetOutputPort());
  vtkNew<vtkCamera> camera;
  camera->SetPosition(eye);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  vtkNew<vtkSilhouetteLineVisibility> visibility;
  visibility->SetInputConnection(edges->GetOutputPort());
  visibility->SetSurfaceConnection(triangles->GetOutputPort());
  visibility->SetCamera(camera);
  visibility->Update();
  if (FieldValue(edges->GetOutput(), "BorderLineCount") != 1 ||
    FieldValue(edges->GetOutput(), "CreaseLineCount") != 0)
  {
    return Fail("the plane's border is one loop; the sphere and plane have no crease");
  }
  // Exact: the border point (2, y, 0) is hidden when its ray to the eye
  // passes within `radius` of the centre.
  auto hidden = [&](double y) {
    const double p[3] = { 2.0, y, 0.0 };
    double d[3] = { eye[0] - p[0], eye[1] - p[1], eye[2] - p[2] };
    const double length = vtkMath::Normalize(d);
    double c[3] = { centre[0] - p[0], centre[1] - p[1], centre[2] - p[2] };
    const double along = vtkMath::Dot(c, d);
    const double miss2 = vtkMath::Dot(c, c) - along * along;
    return along > 0.0 && along < length && miss2 < radius * radius;
  };
  double low = 0.0; // the exact hidden interval is [-h, h]: find h by bisection
  double high = 2.0;
  for (int i = 0; i < 60; ++i)
  {
    const double middle = 0.5 * (low + high);
    (hidden(middle) ? low : high) = middle;
  }
  const double exact = low;
  int hiddenPieces = 0;
  for (const Piece& piece : Pieces(visibility->GetOutput()))
  {
    if (piece.Kind != 2)
    {
      return Fail("the plane's border is LineKind 2");
    }
    if (piece.Visible)
    {
      continue;
    }
    ++hiddenPieces;
    const double ends[2] = { std::min(piece.Start[1], piece.End[1]),
      std::max(piece.Start[1], piece.End[1]) };
    std::printf("hidden border piece at x = %.6f from y = %.4f to %.4f; exact +-%.4f\n",
      piece.Start[0], ends[0], ends[1], exact);
    // The sphere's 96 x 48 facets lie inside it by up to 0.0005 of the
    // radius: the facets' shadow ends within 0.02 of the exact one.
    if (std::abs(piece.Start[0] - 2.0) > 1e-9 || std::abs(ends[0] + exact) > 0.02 ||
      std::abs(ends[1] - exact) > 0.02)
    {
      return Fail("the hidden part of the border is where the sphere covers it");
    }
  }
  if (hiddenPieces != 1)
  {
    return Fail("one hidden piece of the border");
  }
  return true;
}

bool CheckSmoothShadedBoxHasNoCrease()
{
  // One normal per corner: the copies merged, then the faces' normals
  // averaged. Without the normals, the faces' 90 degrees make 12 creases.
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(merged->GetOutputPort());
  normals->SplittingOff();
  vtkNew<vtkCreaseAndBorderLines> edges;
  edges->SetInputConnection(normals->GetOutputPort());
  edges->Update();
  const vtkIdType smooth = FieldValue(edges->GetOutput(), "CreaseLineCount");
  merged->Update();
  merged->GetOutput()->GetPointData()->SetNormals(nullptr);
  edges->SetInputConnection(merged->GetOutputPort());
  edges->Update();
  const vtkIdType bare = FieldValue(edges->GetOutput(), "CreaseLineCount");
  std::printf("box: %lld creases smooth-shaded, %lld without normals\n",
    static_cast<long long>(smooth), static_cast<long long>(bare));
  return (smooth == 0 && bare == 12) ||
    Fail("a box with one normal per corner has no crease; without normals, 12");
}

// A cylinder with flat caps (24 sides) seen obliquely: its two silhouette
// lines end on the rims, which are creases; each end is a point of a crease
// line, so the drawing connects (distance 0).
bool CheckSilhouettesEndOnCreases()
{
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetResolution(24);
  cylinder->SetHeight(2.0);
  cylinder->SetRadius(0.6);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cylinder->GetOutputPort());
  vtkNew<vtkCamera> camera;
  camera->SetPosition(3.0, 1.5, 2.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  vtkNew<vtkSilhouetteSmoothingFilter> smoothing;
  smoothing->SetInputConnection(triangles->GetOutputPort());
  smoothing->SetCamera(camera);
  vtkNew<vtkCreaseAndBorderLines> edges;
  edges->SetInputConnection(smoothing->GetOutputPort(0));
  edges->Update();
  vtkPolyData* silhouettes = smoothing->GetOutput(1);
  vtkPolyData* creases = edges->GetOutput();
  if (silhouettes->GetNumberOfLines() != 2 || FieldValue(creases, "CreaseLineCount") != 2)
  {
    return Fail("a capped cylinder: two silhouette lines, two rim creases");
  }
  double farthest = 0.0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < silhouettes->GetNumberOfCells(); ++c)
  {
    silhouettes->GetCellPoints(c, ids);
    for (const vtkIdType end : { ids->GetId(0), ids->GetId(ids->GetNumberOfIds() - 1) })
    {
      double p[3];
      silhouettes->GetPoint(end, p);
      double nearest = VTK_DOUBLE_MAX;
      for (vtkIdType q = 0; q < creases->GetNumberOfPoints(); ++q)
      {
        double x[3];
        creases->GetPoint(q, x);
        nearest = std::min(nearest, vtkMath::Distance2BetweenPoints(p, x));
      }
      farthest = std::max(farthest, std::sqrt(nearest));
    }
  }
  std::printf("cylinder: the silhouettes' ends lie %g from the rims' crease points\n", farthest);
  return farthest == 0.0 || Fail("the silhouettes end on the creases' points");
}

bool CheckOverlappingSpheresMeetAlongAVisibleArc()
{
  // Different resolutions, so that no vertex of one lies on the other.
  vtkNew<vtkSphereSource> left;
  left->SetCenter(-0.5, 0.0, 0.0);
  left->SetThetaResolution(96);
  left->SetPhiResolution(48);
  left->SetRadius(1.0);
  vtkNew<vtkSphereSource> right;
  right->SetCenter(0.5, 0.0, 0.0);
  right->SetThetaResolution(90);
  right->SetPhiResolution(45);
  right->SetRadius(1.0);
  vtkNew<vtkAppendPolyData> scene;
  scene->AddInputConnection(left->GetOutputPort());
  scene->AddInputConnection(right->GetOutputPort());
  vtkNew<vtkCreaseAndBorderLines> edges;
  edges->SetInputConnection(scene->GetOutputPort());
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, 0.0, 20.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  vtkNew<vtkSilhouetteLineVisibility> visibility;
  visibility->SetInputConnection(edges->GetOutputPort());
  visibility->SetSurfaceConnection(scene->GetOutputPort());
  visibility->SetCamera(camera);
  visibility->Update();
  std::printf("spheres: %lld intersection, %lld crease, %lld border lines\n",
    static_cast<long long>(FieldValue(edges->GetOutput(), "IntersectionLineCount")),
    static_cast<long long>(FieldValue(edges->GetOutput(), "CreaseLineCount")),
    static_cast<long long>(FieldValue(edges->GetOutput(), "BorderLineCount")));
  if (FieldValue(edges->GetOutput(), "IntersectionLineCount") != 1 ||
    FieldValue(edges->GetOutput(), "CreaseLineCount") != 0 ||
    FieldValue(edges->GetOutput(), "BorderLineCount") != 0)
  {
    return Fail("two overlapping spheres meet along one loop, with no crease or border");
  }
  double visibleLength = 0.0;
  double hiddenLength = 0.0;
  double lowestVisible = VTK_DOUBLE_MAX;
  for (const Piece& piece : Pieces(visibility->GetOutput()))
  {
    if (piece.Kind != 3)
    {
      return Fail("the spheres' meeting curve is LineKind 3");
    }
    (piece.Visible ? visibleLength : hiddenLength) += piece.Length;
    if (piece.Visible)
    {
      lowestVisible = std::min({ lowestVisible, piece.Start[2], piece.End[2] });
    }
  }
  // The circle's halves are pi sqrt(0.75) = 2.7207 long. Where the curve
  // meets the outline (z = 0), the rays from it graze the facets beside it,
  // which hide it within about a facet (0.07 of arc) of the outline.
  const double half = vtkMath::Pi() * std::sqrt(0.75);
  std::printf("spheres: intersection %.4f visible, %.4f hidden (half the circle %.4f); lowest "
              "visible end z = %.4f\n",
    visibleLength, hiddenLength, half, lowestVisible);
  if (std::abs(visibleLength - half) > 0.2 || std::abs(hiddenLength - half) > 0.2 ||
    lowestVisible < -0.05)
  {
    return Fail("the upper half of the spheres' meeting curve is visible, the lower half hidden");
  }
  // The wrong variant: without the intersection curves nothing is drawn
  // where the spheres meet.
  edges->IntersectionsOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfLines() == 0 ||
    Fail("with Intersections off, two overlapping spheres draw no line");
}

} // namespace

int TestCreaseAndBorderLines(int, char*[])
{
  bool ok = true;
  double stub = 0.0;
  ok = CheckCube(0.0, true, stub) && ok;
  if (stub > 1e-3)
  {
    ok = Fail("hidden edges are hidden to within 1e-3 of their ends");
  }
  // The tolerance alone decides nothing for the surface's own edges: with a
  // tolerance of 1.1 (a mean edge), the faces that hide an edge are another
  // sheet (their copies of the corners have other normals).
  ok = CheckCube(1.1, true, stub) && ok;
  // The wrong variant: the same without normals, where one sheet holds the
  // whole cube, draws hidden edges as visible.
  double wrongStub = 0.0;
  std::printf("the wrong variant, expected to fail:\n");
  if (CheckCube(1.1, false, wrongStub))
  {
    ok = Fail("the wrong variant (tolerance 1.1, no normals) passes the cube's check");
  }
  ok = CheckSphereHidesBorder() && ok;
  ok = CheckSmoothShadedBoxHasNoCrease() && ok;
  ok = CheckSilhouettesEndOnCreases() && ok;
  ok = CheckOverlappingSpheresMeetAlongAVisibleArc() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
