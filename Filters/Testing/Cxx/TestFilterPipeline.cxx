// The filter as a pipeline citizen: when it re-executes (view changes that
// matter, and only those), the prop's matrix, attribute interpolation, the
// provenance arrays and counts, polygons/strips/verts/lines, and results that
// do not depend on the thread count.
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIcosphereSource.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSmartPointer.h"
#include "vtkStripper.h"
#include "vtkTorusSurfaceSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include "SilhouetteTestSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace
{

// Counts RequestData calls through the filter's StartEvent.
struct ExecutionCounter
{
  int Count = 0;
  vtkNew<vtkCallbackCommand> Command;
  explicit ExecutionCounter(vtkAlgorithm* algorithm)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
      ++static_cast<ExecutionCounter*>(self)->Count;
    });
    algorithm->AddObserver(vtkCommand::StartEvent, this->Command);
  }
};

long FieldCount(vtkPolyData* mesh, const char* name)
{
  vtkDataArray* a = mesh->GetFieldData()->GetArray(name);
  return a ? static_cast<long>(a->GetTuple1(0)) : -1;
}

bool ReExecutesOnlyWhenTheViewChanges()
{
  vtkNew<vtkIcosphereSource> sphere;
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 5);
  smoother->SetCamera(camera);
  ExecutionCounter runs(smoother);
  smoother->Update();
  CHECK(runs.Count == 1, "first update runs");
  smoother->Update();
  CHECK(runs.Count == 1, "a second update without changes does nothing");
  camera->SetClippingRange(0.1, 123.0);
  smoother->Update();
  CHECK(runs.Count == 1, "a clipping-range change (renderers do it every frame) does not re-run");
  camera->Azimuth(10);
  smoother->Update();
  CHECK(runs.Count == 2, "moving the camera re-runs");
  smoother->SetViewportSize(800, 600);
  smoother->Update();
  CHECK(runs.Count == 3, "a new viewport size re-runs");
  vtkNew<vtkTransform> userTransform; // applied after the projection
  userTransform->Translate(0.2, 0.0, 0.0);
  camera->SetUserTransform(userTransform);
  smoother->Update();
  CHECK(runs.Count == 4, "a camera user transform re-runs");
  userTransform->Translate(0.1, 0.0, 0.0); // the camera's MTime stays
  smoother->Update();
  CHECK(runs.Count == 5, "a change to the camera's user transform re-runs");
  camera->SetUserTransform(nullptr);

  vtkNew<vtkActor> actor;
  smoother->SetProp3D(actor);
  smoother->Update();
  CHECK(runs.Count == 6, "setting a prop re-runs");
  actor->GetProperty()->SetColor(1, 0, 0);
  smoother->Update();
  CHECK(runs.Count == 6, "a colour change does not re-run");
  actor->SetPosition(0.5, 0, 0);
  smoother->Update();
  CHECK(runs.Count == 7, "moving the prop re-runs");

  sphere->SetRadius(2.0);
  smoother->Update();
  CHECK(runs.Count == 8, "a new input re-runs");
  double bounds[6];
  smoother->GetOutput()->GetBounds(bounds);
  CHECK(bounds[1] > 1.9, "the cache follows the new input");

  // Through a renderer: camera and size come from it, no SetCamera needed.
  vtkNew<vtkSilhouetteSmoothingFilter> viaRenderer;
  viaRenderer->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(300, 200);
  window->AddRenderer(renderer);
  viaRenderer->SetRenderer(renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(viaRenderer->GetOutputPort());
  vtkNew<vtkActor> rendered;
  rendered->SetMapper(mapper);
  renderer->AddActor(rendered);
  renderer->ResetCamera();
  ExecutionCounter rendererRuns(viaRenderer);
  window->Render();
  window->Render();
  CHECK(rendererRuns.Count == 1, "two renders of an unchanged view run the filter once");
  renderer->GetActiveCamera()->Elevation(15);
  window->Render();
  CHECK(rendererRuns.Count == 2, "rendering after a camera move re-runs the filter");
  window->SetSize(400, 300);
  window->Render();
  CHECK(rendererRuns.Count == 3, "resizing the window re-runs the filter");
  CHECK(FieldCount(viaRenderer->GetOutput(), "SilhouetteTriangleCount") > 0,
    "renderer view has a silhouette");
  std::printf("re-execution: only on view, prop, size and input changes\n");
  return true;
}

// The same view through an actor's matrix must give the same world-space
// mesh as transforming the data first.
bool PropMatrixMatchesTransformedData()
{
  vtkNew<vtkTorusSurfaceSource> torus;
  torus->Update();
  vtkNew<vtkTransform> transform;
  transform->Translate(0.3, -0.2, 0.5);
  transform->RotateWXYZ(37, 0.2, 1.0, 0.4);
  transform->Scale(1.5, 1.5, 1.5);

  vtkNew<vtkCamera> camera;
  camera->SetPosition(1.0, 4.0, 6.0);
  camera->SetFocalPoint(0.3, -0.2, 0.5);

  vtkNew<vtkActor> actor;
  actor->SetUserTransform(transform);
  vtkNew<vtkSilhouetteSmoothingFilter> withProp;
  withProp->SetInputConnection(torus->GetOutputPort());
  withProp->SetProp3D(actor);
  withProp->SetCamera(camera);
  withProp->Update();

  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(torus->GetOutputPort());
  moved->SetTransform(transform);
  vtkNew<vtkSilhouetteSmoothingFilter> onMoved;
  onMoved->SetInputConnection(moved->GetOutputPort());
  onMoved->SetCamera(camera);
  onMoved->Update();

  vtkPolyData* a = withProp->GetOutput();
  vtkPolyData* b = onMoved->GetOutput();
  CHECK(FieldCount(a, "SilhouetteTriangleCount") > 0, "the view has a silhouette");
  CHECK(FieldCount(a, "SilhouetteTriangleCount") == FieldCount(b, "SilhouetteTriangleCount"),
    "same silhouette triangles");
  CHECK(a->GetNumberOfPoints() == b->GetNumberOfPoints(), "same number of points");
  double worst = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    transform->TransformPoint(p, p);
    b->GetPoint(i, q);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  CHECK(worst < 1e-5, "points agree in world space");
  std::printf("prop matrix: %ld silhouette triangles, largest world-space difference %.2e\n",
    FieldCount(a, "SilhouetteTriangleCount"), worst);
  return true;
}

// The filter holds its prop weakly: actor -> mapper -> filter -> actor would
// otherwise keep the whole pipeline alive.
bool NoReferenceLoopThroughTheProp()
{
  vtkWeakPointer<vtkSilhouetteSmoothingFilter> filterLeft;
  vtkWeakPointer<vtkActor> actorLeft;
  {
    vtkNew<vtkIcosphereSource> sphere;
    vtkNew<vtkSilhouetteSmoothingFilter> smoother;
    smoother->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(smoother->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    smoother->SetProp3D(actor);
    filterLeft = smoother.Get();
    actorLeft = actor.Get();
  }
  CHECK(!filterLeft && !actorLeft, "the pipeline is freed when it goes out of scope");
  std::printf("prop reference: no loop, the pipeline is freed\n");
  return true;
}

// The camera's own model transform moves the eye like moving the data the
// other way.
bool CameraTransforms()
{
  vtkNew<vtkTorusSurfaceSource> torus;
  torus->Update();
  vtkNew<vtkTransform> turn;
  turn->RotateWXYZ(40, 0.3, 1.0, 0.2);
  vtkNew<vtkCamera> turned;
  turned->SetPosition(0.5, 2.0, 5.0);
  turned->SetModelTransformMatrix(turn->GetMatrix());
  vtkNew<vtkSilhouetteSmoothingFilter> withTransform;
  withTransform->SetInputConnection(torus->GetOutputPort());
  withTransform->SetCamera(turned);
  withTransform->Update();

  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(torus->GetOutputPort());
  moved->SetTransform(turn);
  vtkNew<vtkCamera> plain;
  plain->SetPosition(0.5, 2.0, 5.0);
  vtkNew<vtkSilhouetteSmoothingFilter> onMoved;
  onMoved->SetInputConnection(moved->GetOutputPort());
  onMoved->SetCamera(plain);
  onMoved->Update();
  CHECK(FieldCount(withTransform->GetOutput(), "SilhouetteTriangleCount") ==
      FieldCount(onMoved->GetOutput(), "SilhouetteTriangleCount"),
    "a camera model transform gives the silhouette of the transformed data");
  CHECK(
    withTransform->GetOutput()->GetNumberOfPoints() == onMoved->GetOutput()->GetNumberOfPoints(),
    "same points");
  ExecutionCounter runs(withTransform);
  vtkNew<vtkTransform> other;
  other->RotateY(10);
  turned->SetModelTransformMatrix(other->GetMatrix());
  withTransform->Update();
  CHECK(runs.Count == 1, "changing the camera's model transform re-runs the filter");
  std::printf("camera transforms: model transform honoured, %ld silhouette triangles\n",
    FieldCount(onMoved->GetOutput(), "SilhouetteTriangleCount"));
  return true;
}

bool ArraysAndCounts()
{
  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(2);
  sphere->Update();
  vtkNew<vtkPolyData> input;
  input->DeepCopy(sphere->GetOutput());
  const vtkIdType numPoints = input->GetNumberOfPoints();
  // A constant scalar (interpolation must keep it), texture coordinates, and
  // a cell array to be copied from the original cells.
  vtkNew<vtkDoubleArray> constant;
  constant->SetName("Constant");
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TextureCoordinates");
  tcoords->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    constant->InsertNextValue(7.25);
    double p[3];
    input->GetPoint(i, p);
    tcoords->InsertNextTuple2(0.5 + 0.5 * p[0], 0.5 + 0.5 * p[1]);
  }
  input->GetPointData()->AddArray(constant);
  input->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkIdTypeArray> cellTag;
  cellTag->SetName("CellTag");
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    cellTag->InsertNextValue(1000 + c);
  }
  input->GetCellData()->AddArray(cellTag);
  input->GetFieldData()->AddArray(constant); // passes through
  vtkNew<vtkIdTypeArray> globalIds;
  globalIds->SetName("GlobalIds");
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    globalIds->InsertNextValue(1000 + i);
  }
  input->GetPointData()->SetGlobalIds(globalIds);

  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(input);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(2.0, 1.0, 3.0);
  smoother->SetCamera(camera);
  smoother->Update();
  vtkPolyData* out = smoother->GetOutput();
  vtkPointData* pd = out->GetPointData();

  CHECK(pd->GetTCoords() && pd->GetTCoords()->GetNumberOfTuples() == out->GetNumberOfPoints(),
    "texture coordinates are carried and still active");
  CHECK(
    pd->GetNormals() && std::string(pd->GetNormals()->GetName()) == "Normals", "active Normals");
  vtkDataArray* outConstant = pd->GetArray("Constant");
  CHECK(outConstant, "other point arrays are carried");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    CHECK(std::abs(outConstant->GetTuple1(i) - 7.25) < 1e-12, "interpolation weights sum to one");
    double n[3];
    pd->GetNormals()->GetTuple(i, n);
    CHECK(std::abs(vtkMath::Norm(n) - 1.0) < 1e-6, "normals are unit");
    double t[2];
    pd->GetTCoords()->GetTuple(i, t);
    CHECK(t[0] >= -1e-6 && t[0] <= 1.0 + 1e-6 && t[1] >= -1e-6 && t[1] <= 1.0 + 1e-6,
      "texture coordinates stay in the convex hull of the input's");
  }
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double a[3], b[3];
    input->GetPoint(i, a);
    out->GetPoint(i, b);
    CHECK(
      a[0] == b[0] && a[1] == b[1] && a[2] == b[2], "input points keep their ids and positions");
  }

  vtkDataArray* newGeometry = out->GetCellData()->GetArray("NewGeometry");
  vtkDataArray* original = out->GetCellData()->GetArray("OriginalCellId");
  vtkDataArray* tag = out->GetCellData()->GetArray("CellTag");
  CHECK(
    newGeometry && vtkUnsignedCharArray::SafeDownCast(newGeometry), "NewGeometry is unsigned char");
  CHECK(original && vtkIdTypeArray::SafeDownCast(original), "OriginalCellId is vtkIdType");
  CHECK(tag, "cell arrays are carried");
  std::set<vtkIdType> remeshed;
  long newCells = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    CHECK(
      tag->GetTuple1(c) == 1000 + original->GetTuple1(c), "cell data come from the original cell");
    if (newGeometry->GetTuple1(c) == 1)
    {
      ++newCells;
      remeshed.insert(static_cast<vtkIdType>(original->GetTuple1(c)));
    }
  }
  CHECK(
    FieldCount(out, "NewTriangleCount") == newCells, "NewTriangleCount counts NewGeometry cells");
  CHECK(FieldCount(out, "SilhouetteTriangleCount") == static_cast<long>(remeshed.size()),
    "SilhouetteTriangleCount counts the re-meshed input cells");
  CHECK(FieldCount(out, "OutputTriangleCount") == out->GetNumberOfPolys(), "OutputTriangleCount");
  CHECK(FieldCount(out, "InputTriangleCount") == input->GetNumberOfPolys(), "InputTriangleCount");
  CHECK(FieldCount(out, "NewPointCount") == out->GetNumberOfPoints() - numPoints, "NewPointCount");
  CHECK(out->GetFieldData()->GetArray("Constant"), "input field data pass through");
  CHECK(!pd->GetGlobalIds(), "global ids are not interpolated into duplicates");
  std::printf("arrays: %ld silhouette triangles -> %ld new triangles, %ld new points\n",
    FieldCount(out, "SilhouetteTriangleCount"), newCells, FieldCount(out, "NewPointCount"));
  return true;
}

bool CellTypes()
{
  // Strips give the same mesh as their triangles; verts and lines pass.
  vtkNew<vtkTorusSurfaceSource> torus;
  vtkNew<vtkStripper> stripper;
  stripper->SetInputConnection(torus->GetOutputPort());
  stripper->Update();
  vtkNew<vtkPolyData> mixed;
  mixed->DeepCopy(stripper->GetOutput());
  CHECK(mixed->GetNumberOfStrips() > 0, "the stripper made strips");
  vtkNew<vtkCellArray> verts;
  const vtkIdType vertex = 3;
  verts->InsertNextCell(1, &vertex);
  mixed->SetVerts(verts);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[3] = { 0, 5, 9 };
  lines->InsertNextCell(3, line);
  mixed->SetLines(lines);

  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.5, 3.0, 4.0);
  vtkNew<vtkSilhouetteSmoothingFilter> fromStrips;
  fromStrips->SetInputData(mixed);
  fromStrips->SetCamera(camera);
  fromStrips->Update();
  vtkNew<vtkSilhouetteSmoothingFilter> fromTriangles;
  fromTriangles->SetInputConnection(torus->GetOutputPort());
  fromTriangles->SetCamera(camera);
  fromTriangles->Update();
  vtkPolyData* a = fromStrips->GetOutput();
  vtkPolyData* b = fromTriangles->GetOutput();
  CHECK(a->GetNumberOfVerts() == 1 && a->GetNumberOfLines() == 1, "verts and lines pass through");
  CHECK(a->GetNumberOfStrips() == 0, "strips are triangulated");
  CHECK(a->GetNumberOfPolys() == b->GetNumberOfPolys(), "strips give the same triangle count");
  CHECK(FieldCount(a, "SilhouetteTriangleCount") == FieldCount(b, "SilhouetteTriangleCount"),
    "strips give the same silhouette");
  vtkDataArray* original = a->GetCellData()->GetArray("OriginalCellId");
  CHECK(
    original->GetTuple1(0) == 0 && original->GetTuple1(1) == 1, "verts and lines keep their ids");
  CHECK(original->GetTuple1(2) >= 2, "triangles point to the strips they came from");
  const auto report = silhouette_test::AnalyzeTopology(a);
  CHECK(report.closedManifold(), "triangulated strips stay a closed manifold");
  std::printf("cell types: strips -> %lld triangles, verts and lines kept\n",
    static_cast<long long>(a->GetNumberOfPolys()));
  return true;
}

bool IndependentOfThreadCount()
{
  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(4);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(1.0, 2.0, 2.5);
  auto run = [&](int threads) {
    vtkSMPTools::Initialize(threads);
    vtkNew<vtkSilhouetteSmoothingFilter> smoother;
    smoother->SetInputConnection(sphere->GetOutputPort());
    smoother->SetCamera(camera);
    smoother->Update();
    std::array<vtkSmartPointer<vtkPolyData>, 2> copies;
    for (int port = 0; port < 2; ++port)
    {
      copies[port] = vtkSmartPointer<vtkPolyData>::New();
      copies[port]->DeepCopy(smoother->GetOutput(port));
    }
    return copies;
  };
  const auto one = run(1);
  const auto two = run(2);
  vtkSMPTools::Initialize(0);
  for (int port = 0; port < 2; ++port)
  {
    vtkPolyData* a = one[port];
    vtkPolyData* b = two[port];
    CHECK(a->GetNumberOfPoints() == b->GetNumberOfPoints(), "same points");
    CHECK(a->GetNumberOfCells() == b->GetNumberOfCells(), "same cells");
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3];
      a->GetPoint(i, p);
      b->GetPoint(i, q);
      CHECK(p[0] == q[0] && p[1] == q[1] && p[2] == q[2], "bit-identical points");
    }
    // The connectivity too: the same cells over the same point ids, in order.
    vtkNew<vtkIdList> cellA;
    vtkNew<vtkIdList> cellB;
    for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
    {
      a->GetCellPoints(c, cellA);
      b->GetCellPoints(c, cellB);
      CHECK(a->GetCellType(c) == b->GetCellType(c) &&
          cellA->GetNumberOfIds() == cellB->GetNumberOfIds() &&
          std::equal(cellA->begin(), cellA->end(), cellB->begin()),
        "the same cells over the same point ids");
    }
    // And the cell arrays (NewGeometry, OriginalCellId, LineKind).
    for (int k = 0; k < a->GetCellData()->GetNumberOfArrays(); ++k)
    {
      vtkDataArray* x = a->GetCellData()->GetArray(k);
      vtkDataArray* y = x ? b->GetCellData()->GetArray(x->GetName()) : nullptr;
      CHECK(x && y && x->GetNumberOfValues() == y->GetNumberOfValues(), "the same cell arrays");
      for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
      {
        CHECK(x->GetVariantValue(v) == y->GetVariantValue(v), "identical cell array values");
      }
    }
  }
  std::printf("threads: 1 and 2 threads give identical output: %lld points, %lld triangles, "
              "%lld silhouette polylines, their connectivity and cell arrays\n",
    static_cast<long long>(one[0]->GetNumberOfPoints()),
    static_cast<long long>(one[0]->GetNumberOfPolys()),
    static_cast<long long>(one[1]->GetNumberOfLines()));
  return true;
}

bool ParallelProjection()
{
  // In parallel projection the silhouette points of a sphere have
  // interpolated normals perpendicular to the view, and so do the samples
  // between them. (The view is tilted: straight along z it would pass through
  // the icosahedron's vertices on the equator, where every silhouette point
  // sits on a vertex.) A silhouette point kept 1% away from an edge end (the edge-margin
  // clamp) is off by at most 1% of the normal's turn along its edge.
  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(2);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.7, 0.3, 10);
  camera->ParallelProjectionOn();
  camera->SetParallelScale(1.2);
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputConnection(sphere->GetOutputPort());
  smoother->SetCamera(camera);
  smoother->Update();
  double view[3];
  camera->GetDirectionOfProjection(view);
  vtkPolyData* lines = smoother->GetSilhouetteOutput();
  CHECK(lines->GetNumberOfLines() == 1, "one loop");
  const double edgeTurn = 0.33; // largest angle between the normals of an edge, level 2
  double worst = 0.0;
  vtkIdType exact = 0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    double n[3];
    lines->GetPointData()->GetNormals()->GetTuple(i, n);
    const double off = std::abs(vtkMath::Dot(n, view));
    worst = std::max(worst, off);
    exact += off < 1e-6 ? 1 : 0; // normals are stored as floats
  }
  CHECK(worst <= 0.01 * edgeTurn, "silhouette normals are perpendicular to the view");
  CHECK(
    exact * 2 > lines->GetNumberOfPoints(), "most silhouette points are exactly on the contour");
  std::printf(
    "parallel: %lld silhouette points, %lld exact, worst normal %.1e off the view plane\n",
    static_cast<long long>(lines->GetNumberOfPoints()), static_cast<long long>(exact), worst);
  return true;
}

} // namespace

// Whether two meshes have the same points (bit for bit) and polygons.
bool SameMesh(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfPolys() != b->GetNumberOfPolys())
  {
    return false;
  }
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3];
    double y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    if (x[0] != y[0] || x[1] != y[1] || x[2] != y[2])
    {
      return false;
    }
  }
  vtkNew<vtkIdList> ca;
  vtkNew<vtkIdList> cb;
  vtkCellArray* pa = a->GetPolys();
  vtkCellArray* pb = b->GetPolys();
  for (vtkIdType c = 0; c < pa->GetNumberOfCells(); ++c)
  {
    pa->GetCellAtId(c, ca);
    pb->GetCellAtId(c, cb);
    if (ca->GetNumberOfIds() != cb->GetNumberOfIds())
    {
      return false;
    }
    for (vtkIdType k = 0; k < ca->GetNumberOfIds(); ++k)
    {
      if (ca->GetId(k) != cb->GetId(k))
      {
        return false;
      }
    }
  }
  return true;
}

// Cells edited in place: VTK 9.1's vtkCellArray::ReplaceCellAtId leaves the
// cell array's MTime alone, and the user marks the mesh Modified(). The
// filter must re-read the cells, not take the change for a move of the
// points (a deforming mesh keeps its topology): its output equals a fresh
// filter's on a copy of the edited mesh, and differs from the output before
// the edit.
// A level-2 icosphere of its own, for a test to edit.
vtkSmartPointer<vtkPolyData> EditableSphere()
{
  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(2);
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  return mesh;
}

// What a new filter with `settings`' tolerance makes of a copy of `mesh`
// from `camera`: what an edited input must give.
vtkSmartPointer<vtkPolyData> FreshOutput(
  vtkPolyData* mesh, vtkCamera* camera, vtkSilhouetteSmoothingFilter* settings)
{
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(mesh);
  vtkNew<vtkSilhouetteSmoothingFilter> fresh;
  fresh->SetInputData(copy);
  fresh->SetCamera(camera);
  fresh->SetTolerance(settings->GetTolerance());
  fresh->Update();
  return fresh->GetOutput();
}

bool CellsEditedInPlace()
{
  vtkSmartPointer<vtkPolyData> mesh = EditableSphere();
  vtkNew<vtkCamera> camera;
  camera->SetPosition(1.0, 2.0, 4.0);
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(mesh);
  smoother->SetCamera(camera);
  smoother->Update();
  vtkNew<vtkPolyData> before;
  before->DeepCopy(smoother->GetOutput());

  // Flip the shared edge of disjoint pairs of neighbouring triangles:
  // (a, b, c) and (c, b, d) become (a, b, d) and (a, d, c).
  mesh->BuildLinks();
  vtkCellArray* polys = mesh->GetPolys();
  const vtkMTimeType polysTime = polys->GetMTime();
  std::vector<bool> used(static_cast<std::size_t>(mesh->GetNumberOfCells()), false);
  vtkNew<vtkIdList> ids;
  vtkNew<vtkIdList> edge;
  vtkNew<vtkIdList> neighbours;
  vtkNew<vtkIdList> other;
  int flipped = 0;
  for (vtkIdType t = 0; t < mesh->GetNumberOfCells(); ++t)
  {
    if (used[static_cast<std::size_t>(t)])
    {
      continue;
    }
    mesh->GetCellPoints(t, ids);
    const vtkIdType a = ids->GetId(0);
    const vtkIdType b = ids->GetId(1);
    const vtkIdType c = ids->GetId(2);
    edge->SetNumberOfIds(2);
    edge->SetId(0, b);
    edge->SetId(1, c);
    mesh->GetCellNeighbors(t, edge, neighbours);
    if (neighbours->GetNumberOfIds() != 1 || used[static_cast<std::size_t>(neighbours->GetId(0))])
    {
      continue;
    }
    const vtkIdType n = neighbours->GetId(0);
    mesh->GetCellPoints(n, other);
    vtkIdType d = -1;
    for (vtkIdType k = 0; k < 3; ++k)
    {
      d = other->GetId(k) != b && other->GetId(k) != c ? other->GetId(k) : d;
    }
    const vtkIdType first[3] = { a, b, d };
    const vtkIdType second[3] = { a, d, c };
    polys->ReplaceCellAtId(t, 3, first);
    polys->ReplaceCellAtId(n, 3, second);
    used[static_cast<std::size_t>(t)] = used[static_cast<std::size_t>(n)] = true;
    ++flipped;
  }
  mesh->Modified(); // as a user would; the cell array's time stays
  smoother->Update();

  vtkSmartPointer<vtkPolyData> fresh = FreshOutput(mesh, camera, smoother);
  std::printf("cells edited in place: %d edges flipped (the polygons' MTime %s)\n", flipped,
    polys->GetMTime() == polysTime ? "unchanged" : "changed");
  CHECK(flipped > 20, "the edit flips many edges");
  CHECK(!SameMesh(before, fresh), "the edit changes the output");
  CHECK(
    SameMesh(smoother->GetOutput(), fresh), "cells edited in place give a fresh filter's output");
  return true;
}

// A request for the same view, settings and geometry takes the last
// smoothing again (the input's other arrays changed: a time series of
// values), and only then: after each change below the output equals a fresh
// filter's on a copy of the input, points, polygons and values. Wrong
// variants (the last smoothing taken whatever changed in the view, the
// settings or the points) give the old outline at the step that changes
// them.
bool SmoothingTakenAgainOnlyWhileItHolds()
{
  vtkSmartPointer<vtkPolyData> mesh = EditableSphere();
  vtkNew<vtkFloatArray> values;
  values->SetName("Values");
  values->SetNumberOfValues(mesh->GetNumberOfPoints());
  mesh->GetPointData()->AddArray(values);
  auto paint = [&](float shift) {
    for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    {
      values->SetValue(p, static_cast<float>(mesh->GetPoint(p)[0]) + shift);
    }
    values->Modified();
  };
  paint(0.0f);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(1.0, 2.0, 4.0);
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(mesh);
  smoother->SetCamera(camera);
  smoother->Update();
  const char* steps[] = { "new values", "the camera moved", "a finer tolerance",
    "points moved in place", "new values again" };
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkPolyData> before;
    before->DeepCopy(smoother->GetOutput());
    if (k == 0 || k == 4)
    {
      paint(1.0f + static_cast<float>(k));
    }
    else if (k == 1)
    {
      camera->Azimuth(10.0);
    }
    else if (k == 2)
    {
      smoother->SetTolerance(0.1);
    }
    else
    {
      vtkDataArray* xyz = mesh->GetPoints()->GetData();
      for (vtkIdType p = 0; p < xyz->GetNumberOfTuples(); ++p)
      {
        xyz->SetComponent(p, 1, 1.2 * xyz->GetComponent(p, 1)); // no Modified() of the points
      }
      mesh->Modified();
    }
    smoother->Update();
    vtkSmartPointer<vtkPolyData> fresh = FreshOutput(mesh, camera, smoother);
    vtkDataArray* mine = smoother->GetOutput()->GetPointData()->GetArray("Values");
    vtkDataArray* theirs = fresh->GetPointData()->GetArray("Values");
    bool sameValues = mine && theirs && mine->GetNumberOfTuples() == theirs->GetNumberOfTuples();
    for (vtkIdType t = 0; sameValues && t < mine->GetNumberOfTuples(); ++t)
    {
      sameValues = mine->GetTuple1(t) == theirs->GetTuple1(t);
    }
    const bool same = SameMesh(smoother->GetOutput(), fresh) && sameValues;
    const bool geometryChanged = !SameMesh(before, smoother->GetOutput());
    std::printf("smoothing taken again: %s: the output %s a fresh filter's; its geometry %s\n",
      steps[k], same ? "equals" : "differs from", geometryChanged ? "changed" : "stayed");
    CHECK(same, "the output equals a fresh filter's");
    CHECK(geometryChanged == (k >= 1 && k <= 3), "only view, settings and points change the mesh");
  }
  return true;
}

namespace
{

// The point a camera's projection sees from, found apart from the filter:
// the solution of clip x = y = w = 0 (a 3 x 3 system), or for a parallel
// projection the direction along which x and y stay (x = y = w = 0 with
// z = 1). In model coordinates (the model matrix is the identity here).
void TrueCentre(vtkCamera* camera, double aspect, double centre[4])
{
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
  const int rows[3] = { 0, 1, 3 };
  double a[3][3];
  double b[3];
  const bool parallel = camera->GetParallelProjection() != 0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      a[i][j] = parallel && j == 2 ? m->GetElement(rows[i], 3) : m->GetElement(rows[i], j);
    }
    b[i] = -m->GetElement(rows[i], parallel ? 2 : 3);
  }
  double* matrix[3] = { a[0], a[1], a[2] };
  vtkMath::SolveLinearSystem(matrix, b, 3);
  if (parallel)
  {
    double d[3] = { b[0], b[1], 1.0 };
    double projection[3];
    camera->GetDirectionOfProjection(projection);
    const double sign = vtkMath::Dot(d, projection) > 0.0 ? -1.0 : 1.0; // towards the viewer
    vtkMath::Normalize(d);
    for (int k = 0; k < 3; ++k)
    {
      centre[k] = sign * d[k];
    }
    centre[3] = 0.0;
  }
  else
  {
    for (int k = 0; k < 3; ++k)
    {
      centre[k] = b[k];
    }
    centre[3] = 1.0;
  }
}

// The largest |n . v| over the silhouette points, v the unit direction from
// the point towards `centre` (a point, or a direction when w = 0).
double WorstContourCosine(vtkPolyData* lines, const double centre[4])
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    double n[3];
    double p[3];
    lines->GetPointData()->GetNormals()->GetTuple(i, n);
    lines->GetPoint(i, p);
    double v[3];
    for (int k = 0; k < 3; ++k)
    {
      v[k] = centre[3] == 0.0 ? centre[k] : centre[k] - p[k];
    }
    vtkMath::Normalize(v);
    worst = std::max(worst, std::abs(vtkMath::Dot(n, v)));
  }
  return worst;
}

bool ShearedProjections()
{
  // A sheared projection (SetViewShear, an oblique parallel view, a stereo
  // eye) sees from a point off the camera's axis: the silhouette must turn
  // away from that point, not from the camera's position. The filter's
  // silhouette normals are within a few degrees of perpendicular to the
  // true line of sight, and far from it for the camera's position and axis
  // (the deliberately wrong view, which the filter used until 2026-12-06).
  vtkNew<vtkIcosphereSource> sphere;
  sphere->SetSubdivisionLevel(3);
  for (const bool parallel : { false, true })
  {
    vtkNew<vtkCamera> camera;
    camera->SetPosition(0.4, 0.3, 5.0);
    camera->SetClippingRange(0.5, 20.0);
    camera->SetParallelProjection(parallel);
    camera->SetParallelScale(1.5);
    camera->SetViewShear(0.5, 0.3, 1.0);
    vtkNew<vtkSilhouetteSmoothingFilter> smoother;
    smoother->SetInputConnection(sphere->GetOutputPort());
    smoother->SetCamera(camera);
    smoother->SetViewportSize(640, 480);
    smoother->Update();
    double centre[4];
    TrueCentre(camera, 640.0 / 480.0, centre);
    double unsheared[4] = { 0.4, 0.3, 5.0, 1.0 };
    if (parallel)
    {
      camera->GetDirectionOfProjection(unsheared);
      vtkMath::MultiplyScalar(unsheared, -1.0);
      unsheared[3] = 0.0;
    }
    vtkPolyData* lines = smoother->GetSilhouetteOutput();
    CHECK(lines->GetNumberOfPoints() > 0, "a silhouette");
    const double right = WorstContourCosine(lines, centre);
    const double wrong = WorstContourCosine(lines, unsheared);
    std::printf("%s, sheared: silhouette normals at most %.4f (cosine) off square to the true "
                "line of sight, %.4f to the camera's\n",
      parallel ? "parallel" : "perspective", right, wrong);
    CHECK(right < 0.03, "the silhouette turns away from the sheared projection's centre");
    CHECK(wrong > 0.2, "the view is sheared enough to tell the two apart");
  }
  return true;
}

} // namespace

int TestFilterPipeline(int, char*[])
{
  bool ok = ReExecutesOnlyWhenTheViewChanges();
  ok = NoReferenceLoopThroughTheProp() && ok;
  ok = CameraTransforms() && ok;
  ok = PropMatrixMatchesTransformedData() && ok;
  ok = ArraysAndCounts() && ok;
  ok = CellTypes() && ok;
  ok = IndependentOfThreadCount() && ok;
  ok = ParallelProjection() && ok;
  ok = ShearedProjections() && ok;
  ok = CellsEditedInPlace() && ok;
  ok = SmoothingTakenAgainOnlyWhileItHolds() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
