// The render-time mapper (issue 15) across changes: a deforming mesh (new
// points, the same cells) keeps the base mesh's cells and draws what the
// filter's output draws, frame after frame; and one mapper drawn in two
// views in turn keeps both views' patches (TestSmoothingMapper has the
// cases of one view); new values on a still mesh do not smooth again.
// Besides: the input's own lines, whose points get no normal, are lit as
// facing the viewer, not drawn black.

#include "MapperTestScene.h"
#include "SilhouetteTestSupport.h"
#include "vtkCommand.h"
#include "vtkIntArray.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace mapper_test;

namespace
{

// The values in which two meshes' points, attributes and cells differ (or
// -1 when their sizes or arrays do not match).
long ValuesDiffering(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return -1;
  }
  long differing = 0;
  auto compare = [&differing](vtkDataArray* x, vtkDataArray* y) {
    if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples() ||
      x->GetNumberOfComponents() != y->GetNumberOfComponents())
    {
      return false;
    }
    for (vtkIdType t = 0; t < x->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < x->GetNumberOfComponents(); ++c)
      {
        differing += x->GetComponent(t, c) != y->GetComponent(t, c) ? 1 : 0;
      }
    }
    return true;
  };
  bool matched = compare(a->GetPoints()->GetData(), b->GetPoints()->GetData());
  for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(a->GetPointData()),
         static_cast<vtkDataSetAttributes*>(a->GetCellData()) })
  {
    vtkDataSetAttributes* other = data == a->GetPointData()
      ? static_cast<vtkDataSetAttributes*>(b->GetPointData())
      : static_cast<vtkDataSetAttributes*>(b->GetCellData());
    matched = matched && data->GetNumberOfArrays() == other->GetNumberOfArrays();
    for (int i = 0; matched && i < data->GetNumberOfArrays(); ++i)
    {
      matched = compare(data->GetArray(i), other->GetArray(data->GetArrayName(i)));
    }
  }
  vtkNew<vtkIdList> x;
  vtkNew<vtkIdList> y;
  for (vtkIdType c = 0; matched && c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, x);
    b->GetCellPoints(c, y);
    matched = x->GetNumberOfIds() == y->GetNumberOfIds();
    for (vtkIdType k = 0; matched && k < x->GetNumberOfIds(); ++k)
    {
      differing += x->GetId(k) != y->GetId(k) ? 1 : 0;
    }
  }
  return matched ? differing : -1;
}

// A deforming mesh (new points, the same cells, as a time series gives; in
// the last move a triangle loses its area):
// the filter keeps the base mesh's cell arrays (WeldedSurface::movePoints)
// and makes only its points and attributes again (a cell scalar that changes
// every frame shows it does: the base mesh equals a fresh filter's), and the
// mapper's image still equals the filter's, frame after frame.
bool CheckDeformingMesh(vtkPolyData* bunny, vtkTexture* filterTexture, vtkTexture* mapperTexture)
{
  bool ok = true;
  vtkNew<vtkPolyData> deforming;
  deforming->DeepCopy(bunny);
  // The base mesh is built from the same points and triangles with a vertex
  // cell, a line and an empty line before them (passed through, and
  // dropped), an input OriginalCellId and a cell scalar that changes.
  vtkNew<vtkPolyData> built;
  built->SetPoints(deforming->GetPoints()); // moved with it
  built->SetPolys(deforming->GetPolys());
  vtkNew<vtkCellArray> verts;
  verts->InsertNextCell({ 0, 1 });
  built->SetVerts(verts);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell({ 2, 3, 4 });
  lines->InsertNextCell(0);
  built->SetLines(lines);
  vtkNew<vtkFloatArray> changing;
  changing->SetName("Changing");
  changing->SetNumberOfValues(built->GetNumberOfCells());
  changing->FillValue(0.0f);
  built->GetCellData()->AddArray(changing);
  vtkNew<vtkIdTypeArray> originalIds;
  originalIds->SetName("OriginalCellId");
  originalIds->SetNumberOfValues(built->GetNumberOfCells());
  for (vtkIdType c = 0; c < originalIds->GetNumberOfValues(); ++c)
  {
    originalIds->SetValue(c, 1000 + 2 * c);
  }
  built->GetCellData()->AddArray(originalIds);
  vtkNew<vtkSilhouetteSmoothingFilter> builder;
  vtkNew<vtkPolyData> base;
  builder->BuildBaseMesh(built, base);
  vtkCellArray* cellsBefore = base->GetPolys();
  Scene viaFilter;
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  filter->SetInputData(deforming);
  filter->SetRenderer(viaFilter.Renderer);
  filter->SetProp3D(viaFilter.Actor);
  filter->SkipSubpixelSmoothingOn(); // as in the mapper
  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputConnection(filter->GetOutputPort());
  Configure(plain, viaFilter.Actor, Colouring::Plain, filterTexture);
  viaFilter.Actor->SetMapper(plain);
  Scene viaMapper;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(deforming);
  Configure(mapper, viaMapper.Actor, Colouring::Plain, mapperTexture);
  viaMapper.Actor->SetMapper(mapper);
  viaFilter.Look(deforming, 0);
  viaMapper.Look(deforming, 0);
  long worst = 0;
  bool keptCells = true;
  long baseDiffering = 0;
  for (int step = 0; step < 3; ++step)
  {
    for (vtkIdType c = 0; c < changing->GetNumberOfValues(); ++c)
    {
      changing->SetValue(c, static_cast<float>(step + 1) + 0.25f * static_cast<float>(c % 7));
    }
    changing->Modified();
    vtkPoints* points = deforming->GetPoints();
    for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    {
      double x[3];
      points->GetPoint(p, x);
      points->SetPoint(p, x[0] * 1.03, x[1] + 0.02 * x[0], x[2]);
    }
    const bool collapse = step == 2;
    if (collapse)
    {
      // The first triangle loses its area (a corner onto another), and the
      // renderer's index buffer then leaves it out: every later triangle's
      // place in it moves, which the mapper must see to hide the right ones.
      // (A moved surface does not weld points that come together, where a
      // fresh filter would: the base meshes are compared before this.)
      vtkNew<vtkIdList> first;
      deforming->GetPolys()->GetCellAtId(0, first);
      points->SetPoint(first->GetId(1), points->GetPoint(first->GetId(0)));
    }
    points->Modified();
    builder->BuildBaseMesh(built, base);
    keptCells = keptCells && base->GetPolys() == cellsBefore;
    if (!collapse)
    {
      vtkNew<vtkSilhouetteSmoothingFilter> freshBuilder;
      vtkNew<vtkPolyData> fresh;
      freshBuilder->BuildBaseMesh(built, fresh);
      const long differing = ValuesDiffering(base, fresh);
      baseDiffering = differing < 0 || baseDiffering < 0 ? -1 : baseDiffering + differing;
    }
    worst = std::max(worst, Differing(viaMapper.Pixels(), viaFilter.Pixels()));
  }
  const bool passedThrough = base->GetNumberOfVerts() == 1 && base->GetNumberOfLines() == 1;
  std::printf("deforming bunny: at most %ld pixels differ over 3 moves (the last collapses a "
              "triangle); the base mesh %s its "
              "cell arrays, passed %lld vertex and %lld line cells through (1 and 1 expected), "
              "and differs from a fresh filter's in %ld values (-1: in its arrays)\n",
    worst, keptCells ? "kept" : "did not keep", static_cast<long long>(base->GetNumberOfVerts()),
    static_cast<long long>(base->GetNumberOfLines()), baseDiffering);
  if (worst > MaximumDifferingPixels || !keptCells || baseDiffering != 0 || !passedThrough)
  {
    std::printf("FAIL: deforming bunny\n");
    ok = false;
  }
  return ok;
}

} // namespace

// A window of `views` renderers side by side, each looking at the bunny from
// its own side; `shared` puts one actor (one mapper) in all of them, else
// each renderer has an actor and a mapper of its own.
struct SideBySide
{
  vtkNew<vtkRenderWindow> Window;
  std::vector<vtkSmartPointer<vtkSilhouetteSmoothingMapper>> Mappers;

  SideBySide(vtkPolyData* mesh, int views, bool shared)
  {
    this->Window->SetSize(Width / 2 * views, Height / 2);
    this->Window->SetMultiSamples(0);
    this->Window->SetOffScreenRendering(1);
    vtkNew<vtkActor> sharedActor;
    for (int v = 0; v < views; ++v)
    {
      vtkNew<vtkRenderer> renderer;
      renderer->SetViewport(double(v) / views, 0.0, double(v + 1) / views, 1.0);
      this->Window->AddRenderer(renderer);
      vtkSmartPointer<vtkActor> actor = sharedActor;
      if (!shared || v == 0)
      {
        this->Mappers.push_back(vtkSmartPointer<vtkSilhouetteSmoothingMapper>::New());
        this->Mappers.back()->SetInputData(mesh);
        actor =
          shared ? vtkSmartPointer<vtkActor>(sharedActor.Get()) : vtkSmartPointer<vtkActor>::New();
        actor->SetMapper(this->Mappers.back());
      }
      renderer->AddActor(actor);
      vtkCamera* camera = renderer->GetActiveCamera();
      renderer->ResetCamera(mesh->GetBounds());
      camera->Azimuth(30.0 + 70.0 * v);
      camera->Elevation(10.0);
      camera->OrthogonalizeViewUp();
      renderer->ResetCameraClippingRange(mesh->GetBounds());
    }
  }

  std::vector<unsigned char> Pixels() { return RenderedPixels(this->Window); }
};

// One mapper drawn in two views in turn (stereo's eyes, a shadow map's
// light and the camera, one actor in two renderers) keeps both views'
// patches: rendering them again smooths nothing, and each renderer draws
// its own view's patch (the image equals one mapper per renderer's). Four
// views are kept too (since 2026-12-05: three actors sharing a mapper under
// depth peeling smoothed 18 times a render, a user's trial); a fifth view
// exceeds the four kept: every render smooths all five again, so the
// counter counts (the wrong variant: a cache of one view would give two
// views the same count).
bool CheckViewsInTurn(vtkPolyData* bunny)
{
  bool ok = true;
  SideBySide shared(bunny, 2, true);
  SideBySide separate(bunny, 2, false);
  vtkSilhouetteSmoothingMapper* mapper = shared.Mappers[0];
  const std::vector<unsigned char> expected = separate.Pixels();
  const long first = Differing(shared.Pixels(), expected);
  const vtkIdType afterFirst = mapper->GetSmoothingRunCount();
  const long again = Differing(shared.Pixels(), expected);
  const vtkIdType afterAgain = mapper->GetSmoothingRunCount();
  mapper->SmoothingOff();
  const long unsmoothed = Differing(shared.Pixels(), expected);
  mapper->SmoothingOn();
  SideBySide four(bunny, 4, true);
  four.Pixels();
  const vtkIdType fourFirst = four.Mappers[0]->GetSmoothingRunCount();
  four.Pixels();
  const vtkIdType fourAgain = four.Mappers[0]->GetSmoothingRunCount();
  SideBySide five(bunny, 5, true);
  five.Pixels();
  const vtkIdType fiveFirst = five.Mappers[0]->GetSmoothingRunCount();
  five.Pixels();
  const vtkIdType fiveAgain = five.Mappers[0]->GetSmoothingRunCount();
  std::printf("one mapper in two views: %lld smoothings for the first render, %lld more for the "
              "second; %ld and %ld pixels differ from a mapper per view (unsmoothed %ld); four "
              "views: %lld, then %lld more; five: %lld, then %lld more\n",
    static_cast<long long>(afterFirst), static_cast<long long>(afterAgain - afterFirst), first,
    again, unsmoothed, static_cast<long long>(fourFirst),
    static_cast<long long>(fourAgain - fourFirst), static_cast<long long>(fiveFirst),
    static_cast<long long>(fiveAgain - fiveFirst));
  if (afterFirst != 2 || afterAgain != afterFirst)
  {
    std::printf("FAIL: two views drawn again were smoothed again\n");
    ok = false;
  }
  if (first > MaximumDifferingPixels || again > MaximumDifferingPixels)
  {
    std::printf("FAIL: a view drew another view's patch\n");
    ok = false;
  }
  if (unsmoothed <= MaximumDifferingPixels)
  {
    std::printf("FAIL: the unsmoothed views pass the check, which cannot fail\n");
    ok = false;
  }
  // Pixels() renders twice (Render, then the grab's own render): four
  // views are smoothed once, five (more than the mapper keeps) every render.
  if (fourFirst != 4 || fourAgain != 4)
  {
    std::printf("FAIL: four views drawn again were smoothed again\n");
    ok = false;
  }
  if (fiveFirst != 10 || fiveAgain != 20)
  {
    std::printf("FAIL: five views in turn should each be smoothed every render\n");
    ok = false;
  }
  return ok;
}

// The bunny with a polyline of points of its own beside it (a marker line,
// as a ParaView user's feature lines): the smoothing gives those points a
// zero normal, as vtkPolyDataNormals does. Drawn by the mapper, the line's
// pixels (those that differ from the bunny drawn without it) must be lit:
// their mean grey at least MinimumLineGrey. The wrong variant, the filter's
// output through vtkPolyDataMapper, draws them black.
bool CheckLinesAreLit(vtkPolyData* bunny)
{
  // Measured: 253 (the mapper), 0 (filter + vtkPolyDataMapper).
  constexpr double MinimumLineGrey = 60.0;
  auto withLine = vtkSmartPointer<vtkPolyData>::New();
  withLine->DeepCopy(bunny);
  double bounds[6];
  bunny->GetBounds(bounds);
  vtkPoints* points = withLine->GetPoints();
  const double x = bounds[1] + 0.1 * (bounds[1] - bounds[0]);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(4);
  for (int k = 0; k < 4; ++k)
  {
    const double t = k / 3.0;
    lines->InsertCellPoint(points->InsertNextPoint(
      x, bounds[2] + t * (bounds[3] - bounds[2]), 0.5 * (bounds[4] + bounds[5])));
  }
  withLine->SetLines(lines);
  if (withLine->GetPointData()->GetNormals())
  {
    withLine->GetPointData()->SetNormals(nullptr); // the bunny's are per its points only
  }
  // The mesh's cell data (if any) would be a value short: none is kept.
  withLine->GetCellData()->Initialize();
  vtkNew<vtkPolyData> frame; // frames both images alike: the mesh with the line
  frame->ShallowCopy(withLine);

  auto linePixelsGrey = [&](bool viaMapper, double& grey) {
    std::vector<unsigned char> images[2];
    for (int withTheLine = 0; withTheLine < 2; ++withTheLine)
    {
      Scene scene;
      scene.Actor->GetProperty()->SetLineWidth(6);
      scene.Renderer->SetBackground(0.3, 0.3, 0.3); // a black line shows
      vtkNew<vtkSilhouetteSmoothingMapper> mapper;
      vtkNew<vtkSilhouetteSmoothingFilter> filter;
      vtkNew<vtkPolyDataMapper> plain;
      vtkPolyData* input = withTheLine ? withLine.Get() : bunny;
      if (viaMapper)
      {
        mapper->SetInputData(input);
        scene.Actor->SetMapper(mapper);
      }
      else
      {
        filter->SetInputData(input);
        filter->SetRenderer(scene.Renderer);
        filter->SkipSubpixelSmoothingOn(); // as in the mapper
        plain->SetInputConnection(filter->GetOutputPort());
        scene.Actor->SetMapper(plain);
      }
      Configure(scene.Actor->GetMapper(), scene.Actor, Colouring::Plain, nullptr);
      scene.Look(frame, 0);
      images[withTheLine] = scene.Pixels();
    }
    double sum = 0.0;
    long count = 0;
    for (std::size_t p = 0; p + 2 < images[0].size(); p += 3)
    {
      const unsigned char* a = &images[0][p];
      const unsigned char* b = &images[1][p];
      if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2])
      {
        sum += (b[0] + b[1] + b[2]) / 3.0;
        ++count;
      }
    }
    grey = count > 0 ? sum / count : 0.0;
    return count;
  };
  double mapperGrey = 0.0;
  double plainGrey = 0.0;
  const long mapperPixels = linePixelsGrey(true, mapperGrey);
  const long plainPixels = linePixelsGrey(false, plainGrey);
  std::printf("the input's own line: %ld pixels of mean grey %.0f through the mapper (at least "
              "%.0f), %ld of %.0f through filter + vtkPolyDataMapper (must be less)\n",
    mapperPixels, mapperGrey, MinimumLineGrey, plainPixels, plainGrey);
  if (mapperPixels < 100 || !(mapperGrey >= MinimumLineGrey) || !(plainGrey < MinimumLineGrey))
  {
    std::printf("FAIL: the input's lines should be lit through the mapper\n");
    return false;
  }
  return true;
}

// Drawn as wireframe (or points), the mesh is drawn as it is: the mapper
// makes no new triangles and its image is that of the mapper with
// smoothing off, pixel for pixel. It smoothed every frame all the same (a
// user's trial: 149 new triangles drawn nowhere). Back to surface, it
// smooths (the wrong variant).
bool CheckWireframeIsNotSmoothed(vtkPolyData* bunny)
{
  bool ok = true;
  Scene smoothing;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(bunny);
  smoothing.Actor->SetMapper(mapper);
  smoothing.Actor->GetProperty()->SetRepresentationToWireframe();
  smoothing.Look(bunny, 0);
  Scene plain; // the mesh as it is, with the same shading normals
  vtkNew<vtkSilhouetteSmoothingMapper> plainMapper;
  plainMapper->SmoothingOff();
  plainMapper->SetInputData(bunny);
  plain.Actor->SetMapper(plainMapper);
  plain.Actor->GetProperty()->SetRepresentationToWireframe();
  plain.Look(bunny, 0);
  const long differing = Differing(smoothing.Pixels(), plain.Pixels());
  const vtkIdType wireframeNew = mapper->GetNewTriangleCount();
  // Neither the wireframe nor smoothing off counts as a smoothing run (a
  // user's trial, 2026-12-06: both counted one, though nothing was smoothed).
  const vtkIdType wireframeRuns = mapper->GetSmoothingRunCount();
  const vtkIdType offRuns = plainMapper->GetSmoothingRunCount();
  smoothing.Actor->GetProperty()->SetRepresentationToSurface();
  smoothing.Pixels();
  const vtkIdType surfaceNew = mapper->GetNewTriangleCount();
  const vtkIdType surfaceRuns = mapper->GetSmoothingRunCount();
  std::printf("wireframe: %lld new triangles in %lld runs, %ld pixels differ from the unsmoothed "
              "mapper's (its runs: %lld); surface: %lld new triangles, %lld runs\n",
    static_cast<long long>(wireframeNew), static_cast<long long>(wireframeRuns), differing,
    static_cast<long long>(offRuns), static_cast<long long>(surfaceNew),
    static_cast<long long>(surfaceRuns));
  if (wireframeNew != 0 || differing != 0 || wireframeRuns != 0 || offRuns != 0)
  {
    std::printf("FAIL: the wireframe was smoothed, counted a run, or was drawn otherwise than as "
                "it is\n");
    ok = false;
  }
  if (surfaceNew == 0 || surfaceRuns != 1)
  {
    std::printf("FAIL: the surface was not smoothed once, so the check cannot fail\n");
    ok = false;
  }
  return ok;
}

// A reader's cell array shorter than the cells (VTK 9.1's OBJ readers give
// a file of faces and lines group ids for its faces only) is left out with a
// warning, and the mesh is smoothed: pixel for pixel as without the array.
// Until 2026-12-05 the mapper refused the whole input and drew it faceted (a
// ParaView user's trial); a mapper that refuses it draws no new triangles,
// which fails the check.
bool CheckShortArraysAreLeftOut(vtkPolyData* bunny)
{
  bool ok = true;
  vtkNew<vtkPolyData> withShortArray;
  withShortArray->ShallowCopy(bunny);
  vtkNew<vtkIntArray> groups;
  groups->SetName("GroupIds");
  groups->SetNumberOfValues(bunny->GetNumberOfCells() - 1);
  groups->Fill(0);
  withShortArray->GetCellData()->AddArray(groups);
  Scene smoothing;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  vtkNew<vtkTest::ErrorObserver> messages;
  mapper->AddObserver(vtkCommand::WarningEvent, messages);
  mapper->AddObserver(vtkCommand::ErrorEvent, messages);
  mapper->SetInputData(withShortArray);
  smoothing.Actor->SetMapper(mapper);
  smoothing.Look(bunny, 1);
  Scene reference;
  vtkNew<vtkSilhouetteSmoothingMapper> referenceMapper;
  referenceMapper->SetInputData(bunny);
  reference.Actor->SetMapper(referenceMapper);
  reference.Look(bunny, 1);
  const long differing = Differing(smoothing.Pixels(), reference.Pixels());
  const bool warned = messages->GetWarning() &&
    messages->GetWarningMessage().find("'GroupIds' (") != std::string::npos;
  std::printf("a cell array one short: %lld new triangles, %ld pixels differ from the bunny's "
              "without it, warned: %s\n",
    static_cast<long long>(mapper->GetNewTriangleCount()), differing, warned ? "yes" : "no");
  if (mapper->GetNewTriangleCount() == 0 || differing != 0 || !warned || messages->GetError())
  {
    std::printf("FAIL: the input was not smoothed as without the array, or not with one warning\n");
    ok = false;
  }
  return ok;
}

// Two actors side by side share one mapper: hardware selection reports, for
// each actor's pixels, the cells that the actor drawn alone reports. The
// selector converts every prop's pixels after a pass has drawn them all, so
// the mapper keeps what it drew for each prop. Until 2026-12-05 it converted
// every prop's pixels through the patch of the prop drawn last (a user's
// trial: 1,000 of 12,721 pixels wrong along the first actor's outline).
bool CheckSharedMapperSelection(vtkPolyData* bunny)
{
  double bounds[6];
  bunny->GetBounds(bounds);
  const double shift = 1.2 * (bounds[1] - bounds[0]);
  const double both[6] = { bounds[0], bounds[1] + shift, bounds[2], bounds[3], bounds[4],
    bounds[5] };
  const auto look = [&](Scene& scene) {
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetPosition(0, 0, 1);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    scene.Renderer->ResetCamera(both);
    camera->Elevation(20.0);
    camera->OrthogonalizeViewUp();
    scene.Renderer->ResetCameraClippingRange(both);
    scene.Window->Render();
  };
  // Each actor alone, with a mapper of its own.
  std::vector<vtkIdType> alone[2];
  for (int a = 0; a < 2; ++a)
  {
    Scene scene;
    vtkNew<vtkSilhouetteSmoothingMapper> mapper;
    mapper->SetInputData(bunny);
    scene.Actor->SetMapper(mapper);
    scene.Actor->SetPosition(a * shift, 0, 0);
    look(scene);
    alone[a] = scene.CellUnderPixels(nullptr);
  }
  Scene shared;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(bunny);
  shared.Actor->SetMapper(mapper);
  vtkNew<vtkActor> second;
  second->SetMapper(mapper);
  second->SetPosition(shift, 0, 0);
  shared.Renderer->AddActor(second);
  look(shared);
  const std::vector<vtkIdType> picked = shared.CellUnderPixels(nullptr);
  long covered[2] = { 0, 0 };
  long wrong[2] = { 0, 0 };
  for (std::size_t p = 0; p < picked.size(); ++p)
  {
    for (int a = 0; a < 2; ++a)
    {
      if (alone[a][p] >= 0)
      {
        ++covered[a];
        wrong[a] += picked[p] != alone[a][p] ? 1 : 0;
      }
    }
  }
  std::printf("two actors sharing a mapper: selection differs from each actor's alone in %ld of "
              "%ld and %ld of %ld pixels\n",
    wrong[0], covered[0], wrong[1], covered[1]);
  if (covered[0] == 0 || covered[1] == 0 || wrong[0] > MaximumDifferingPixels ||
    wrong[1] > MaximumDifferingPixels)
  {
    std::printf("FAIL: selection through a shared mapper reports other cells than each actor's\n");
    return false;
  }
  return true;
}

// A cell that names a point the input does not have cannot be smoothed, nor
// drawn as it is: VTK's OpenGL mapper reads the point unchecked (it crashed
// there after the mapper's warning, a user's trial). The mapper reports an
// error and draws nothing; the same input with the cell's ids in range is
// drawn (the wrong variant: the check would pass a mapper that drew nothing
// at all).
bool CheckMissingPointsAreNotDrawn(vtkPolyData* bunny)
{
  const auto drawnPixels = [&](vtkIdType id, bool& error) {
    vtkNew<vtkPolyData> mesh;
    mesh->DeepCopy(bunny);
    vtkNew<vtkCellArray> polys;
    polys->DeepCopy(mesh->GetPolys());
    const vtkIdType triangle[3] = { 0, 1, id };
    polys->InsertNextCell(3, triangle);
    mesh->SetPolys(polys);
    Scene scene;
    vtkNew<vtkSilhouetteSmoothingMapper> mapper;
    vtkNew<vtkTest::ErrorObserver> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    mapper->SetInputData(mesh);
    scene.Actor->SetMapper(mapper);
    scene.Look(bunny, 0);
    const std::vector<unsigned char> pixels = scene.Pixels();
    error = messages->GetError();
    long lit = 0;
    for (std::size_t p = 0; p + 2 < pixels.size(); p += 3)
    {
      lit += pixels[p] != 0 || pixels[p + 1] != 0 || pixels[p + 2] != 0 ? 1 : 0;
    }
    return lit;
  };
  bool missingError = false, presentError = false;
  const long missing = drawnPixels(100000000, missingError);
  const long present = drawnPixels(2, presentError);
  std::printf("a cell naming a missing point: %ld pixels drawn, error: %s; in range: %ld pixels\n",
    missing, missingError ? "yes" : "no", present);
  if (missing != 0 || !missingError || present == 0 || presentError)
  {
    std::printf("FAIL: a cell naming a missing point was drawn or not reported\n");
    return false;
  }
  return true;
}

// A change of the input's arrays alone (new scalars on a still mesh, each
// frame of a time series of values) does not smooth again: the patch takes
// the new values (vtkSilhouetteFilterSupport::RefillAttributes), and the
// image equals a fresh mapper's. Points written in place with only the
// mesh marked modified, and new ghost flags, are geometry: they smooth
// again. So does a new mesh object (a reader's next time step) with the same
// cells only when its points moved. Until 2026-12-06 every such change smoothed again (a user's
// trial: a frame 1.6 to 2 times a plain mapper's); the wrong variants are a
// patch kept with its old values (the image differs along the outline) and
// a change told by the points' modification time (step 4 keeps the old
// outline).
bool CheckArraysAloneDoNotSmoothAgain(vtkPolyData* bunny)
{
  vtkNew<vtkPolyData> still;
  still->DeepCopy(bunny);
  vtkNew<vtkFloatArray> wave;
  wave->SetName("Wave");
  wave->SetNumberOfValues(still->GetNumberOfPoints());
  vtkNew<vtkFloatArray> band;
  band->SetName("Band");
  band->SetNumberOfValues(still->GetNumberOfCells());
  auto paint = [&](int step) {
    for (vtkIdType p = 0; p < still->GetNumberOfPoints(); ++p)
    {
      double x[3];
      still->GetPoint(p, x);
      wave->SetValue(p, static_cast<float>(std::sin(20.0 * x[0] + 2.0 * step)));
    }
    for (vtkIdType c = 0; c < still->GetNumberOfCells(); ++c)
    {
      band->SetValue(c, static_cast<float>((c + 3 * step) % 7));
    }
    wave->Modified();
    band->Modified();
  };
  paint(0);
  still->GetPointData()->SetScalars(wave);
  still->GetCellData()->SetScalars(band);

  Scene viaMapper;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(still);
  viaMapper.Actor->SetMapper(mapper);
  Scene fresh;
  viaMapper.Look(still, 1);
  fresh.Look(still, 1);
  auto colour = [](vtkMapper* m, bool cells) {
    m->ScalarVisibilityOn();
    if (cells)
    {
      m->SetScalarModeToUseCellData();
      m->SetScalarRange(0.0, 6.0);
    }
    else
    {
      m->SetScalarModeToUsePointData();
      m->SetScalarRange(-1.0, 1.0);
    }
  };
  // Each step: what changes, whether it smooths again, and the pixels that
  // differ from a fresh mapper's.
  struct Step
  {
    const char* What;
    bool Smooths;
  };
  const Step steps[] = { { "new point values", false }, { "new cell values", false },
    { "points written in place, the mesh alone marked modified", true },
    { "triangles flagged as hidden ghosts", true },
    { "a new mesh object with the same cells and points, new values", false },
    { "a new mesh object with the same cells, points moved", true } };
  colour(mapper, false);
  viaMapper.Pixels();
  bool ok = true;
  vtkSmartPointer<vtkPolyData> input = still.Get();
  for (int k = 0; k < 6; ++k)
  {
    const bool cells = k == 1;
    if (k < 2 || k == 4)
    {
      paint(k + 1);
    }
    else if (k == 2)
    {
      vtkDataArray* xyz = still->GetPoints()->GetData();
      for (vtkIdType p = 0; p < xyz->GetNumberOfTuples(); ++p)
      {
        xyz->SetComponent(p, 0, 1.05 * xyz->GetComponent(p, 0)); // no Modified() of the points
      }
      still->Modified();
    }
    else if (k == 3)
    {
      vtkNew<vtkUnsignedCharArray> ghosts;
      ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
      ghosts->SetNumberOfValues(still->GetNumberOfCells());
      ghosts->FillValue(0);
      // Every 97th triangle, some of them on the silhouette: neither
      // re-meshed nor drawn.
      for (vtkIdType c = 0; c < still->GetNumberOfCells(); c += 97)
      {
        ghosts->SetValue(c, vtkDataSetAttributes::HIDDENCELL);
      }
      still->GetCellData()->AddArray(ghosts);
    }
    if (k >= 4)
    {
      // A reader's next time step: a new object, new cell arrays of the
      // same cells.
      input = vtkSmartPointer<vtkPolyData>::New();
      input->DeepCopy(still);
      if (k == 5)
      {
        vtkPoints* points = input->GetPoints();
        for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
        {
          double x[3];
          points->GetPoint(p, x);
          points->SetPoint(p, x[0], 1.04 * x[1], x[2]);
        }
      }
      mapper->SetInputData(input);
    }
    colour(mapper, cells);
    const vtkIdType runsBefore = mapper->GetSmoothingRunCount();
    const std::vector<unsigned char> pixels = viaMapper.Pixels();
    const vtkIdType runs = mapper->GetSmoothingRunCount() - runsBefore;
    vtkNew<vtkPolyData> snapshot;
    snapshot->DeepCopy(input);
    vtkNew<vtkSilhouetteSmoothingMapper> freshMapper;
    freshMapper->SetInputData(snapshot);
    colour(freshMapper, cells);
    fresh.Actor->SetMapper(freshMapper);
    const long differing = Differing(pixels, fresh.Pixels());
    std::printf("arrays alone: %s: smoothed %lld times (%s expected), %ld pixels differ from a "
                "fresh mapper's\n",
      steps[k].What, static_cast<long long>(runs), steps[k].Smooths ? "1 or more" : "0", differing);
    if ((runs > 0) != steps[k].Smooths || differing > MaximumDifferingPixels)
    {
      std::printf("FAIL: arrays alone: %s\n", steps[k].What);
      ok = false;
    }
  }
  // The filter's side of a new object with the same cells: the surface built
  // for the last one moves its points, and the base mesh keeps its cell
  // arrays (a renderer, its index buffers), and its points too where none
  // moved. (Until 2026-12-06 a new object built everything anew, the wrong
  // variant.)
  vtkNew<vtkSilhouetteSmoothingFilter> builder;
  vtkNew<vtkPolyData> base;
  builder->BuildBaseMesh(still, base);
  vtkCellArray* polys = base->GetPolys();
  vtkPoints* points = base->GetPoints();
  vtkNew<vtkPolyData> same;
  same->DeepCopy(still);
  builder->BuildBaseMesh(same, base);
  const bool keptAll = base->GetPolys() == polys && base->GetPoints() == points;
  builder->BuildBaseMesh(input, base); // the points moved
  const bool keptCells = base->GetPolys() == polys && base->GetPoints() != points;
  std::printf("arrays alone: the base mesh of a new object %s its cells and points, and of one "
              "with moved points %s its cells\n",
    keptAll ? "kept" : "did not keep", keptCells ? "kept" : "did not keep");
  if (!keptAll || !keptCells)
  {
    std::printf("FAIL: arrays alone: the base mesh of a new object of the same cells\n");
    ok = false;
  }
  return ok;
}

// ShallowCopy takes the smoothing mapper's own settings, not only
// vtkPolyDataMapper's; and a frame that draws nothing (empty input) leaves
// the frame's figures at 0, not at the last smoothed frame's. Both found in
// a user's trial (2026-12-06): the copy kept Smoothing on and the tolerance
// at 0.5, and the figures read 22 silhouette triangles after the mesh went.
bool CheckCopiesAndEmptyFrames(vtkPolyData* bunny)
{
  bool ok = true;
  vtkNew<vtkSilhouetteSmoothingMapper> original;
  original->SmoothingOff();
  original->ScalarVisibilityOff();
  original->GetSmoothingFilter()->SetTolerance(5.0);
  original->GetSmoothingFilter()->SkipSubpixelSmoothingOff();
  original->GetSmoothingFilter()->FrustumCullingOff();
  original->GetSmoothingFilter()->SetFeatureAngle(30.0);
  original->GetSmoothingFilter()->FoldPreventionOff();
  auto same = [&](vtkSilhouetteSmoothingMapper* copy) {
    vtkSilhouetteSmoothingFilter* a = original->GetSmoothingFilter();
    vtkSilhouetteSmoothingFilter* b = copy->GetSmoothingFilter();
    return copy->GetSmoothing() == original->GetSmoothing() &&
      copy->GetScalarVisibility() == original->GetScalarVisibility() &&
      b->GetTolerance() == a->GetTolerance() &&
      b->GetSkipSubpixelSmoothing() == a->GetSkipSubpixelSmoothing() &&
      b->GetFrustumCulling() == a->GetFrustumCulling() &&
      b->GetFeatureAngle() == a->GetFeatureAngle() &&
      b->GetFoldPrevention() == a->GetFoldPrevention();
  };
  vtkNew<vtkSilhouetteSmoothingMapper> copy;
  copy->ShallowCopy(original);
  // The deliberately wrong variant: vtkPolyDataMapper's copy alone.
  vtkNew<vtkSilhouetteSmoothingMapper> partial;
  partial->vtkPolyDataMapper::ShallowCopy(original);
  std::printf("ShallowCopy: smoothing settings %s; vtkPolyDataMapper's copy alone: %s\n",
    same(copy) ? "copied" : "NOT copied", same(partial) ? "copied" : "not copied");
  if (!same(copy) || same(partial))
  {
    std::printf(
      "FAIL: ShallowCopy does not copy the smoothing settings, or the check cannot fail\n");
    ok = false;
  }

  Scene scene;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(bunny);
  scene.Actor->SetMapper(mapper);
  scene.Look(bunny, 0);
  scene.Pixels();
  const vtkIdType before = mapper->GetSilhouetteTriangleCount() + mapper->GetNewTriangleCount() +
    mapper->GetReplacedTriangleCount() + mapper->GetPatchTriangleCount();
  vtkNew<vtkPolyData> empty;
  mapper->SetInputData(empty);
  scene.Pixels();
  const vtkIdType after = mapper->GetSilhouetteTriangleCount() + mapper->GetNewTriangleCount() +
    mapper->GetReplacedTriangleCount() + mapper->GetPatchTriangleCount() +
    mapper->GetCulledTriangleCount() + mapper->GetSubpixelTriangleCount() +
    mapper->GetSubpixelFeatureSegmentCount();
  // The bunny back, the same view: the patch kept, its figures again (a
  // trial found them left at 0).
  mapper->SetInputData(bunny);
  scene.Pixels();
  const vtkIdType again = mapper->GetSilhouetteTriangleCount() + mapper->GetNewTriangleCount() +
    mapper->GetReplacedTriangleCount() + mapper->GetPatchTriangleCount();
  std::printf("figures: %lld with the bunny, %lld after a frame of an empty input, %lld with the "
              "bunny again\n",
    static_cast<long long>(before), static_cast<long long>(after), static_cast<long long>(again));
  if (before == 0 || after != 0 || again != before)
  {
    std::printf(
      "FAIL: a frame that draws nothing keeps the last frame's figures, a kept patch does "
      "not report its own again (or the bunny's "
      "frame had none, and the check cannot fail)\n");
    ok = false;
  }
  return ok;
}

// A CAD-like part: a capped cylinder, its rims found as creases (flat
// faces' outlines). Divided finely (192 sides), its rims' curves lie within
// the tolerance of their chords at this size: the mapper draws them
// straight and re-meshes only where the silhouette crosses a rim, not the
// 768 triangles beside the rims, and the image differs from the mapper's
// with the option off in a few pixels. Divided coarsely (16 sides), the
// curves show and are smoothed as before: the same image. The check can
// fail: the coarse part's rims drawn straight (a tolerance of 20 px) differ
// in hundreds of pixels.
vtkSmartPointer<vtkPolyData> CappedCylinder(int sides)
{
  vtkNew<vtkPoints> points;
  for (const double z : { -1.0, 1.0 })
  {
    for (int i = 0; i < sides; ++i)
    {
      const double a = 2.0 * vtkMath::Pi() * i / sides;
      points->InsertNextPoint(std::cos(a), std::sin(a), z);
    }
  }
  const vtkIdType bottom = points->InsertNextPoint(0, 0, -1);
  const vtkIdType top = points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkCellArray> polys;
  for (vtkIdType i = 0; i < sides; ++i)
  {
    const vtkIdType j = (i + 1) % sides;
    const vtkIdType n = sides;
    const vtkIdType cells[4][3] = { { i, j, n + j }, { i, n + j, n + i }, { top, n + i, n + j },
      { bottom, j, i } };
    for (const auto& cell : cells)
    {
      polys->InsertNextCell(3, cell);
    }
  }
  auto cylinder = vtkSmartPointer<vtkPolyData>::New();
  cylinder->SetPoints(points);
  cylinder->SetPolys(polys);
  return cylinder;
}

bool CheckFineCreasesAreDrawnStraight()
{
  bool ok = true;
  struct Frame
  {
    std::vector<unsigned char> Pixels;
    vtkIdType Replaced = 0;
    vtkIdType Straight = 0;
  };
  auto render = [](vtkPolyData* cylinder, bool skip, double tolerance) {
    Scene scene;
    scene.Zoom = 1.1;
    vtkNew<vtkSilhouetteSmoothingMapper> mapper;
    mapper->SetInputData(cylinder);
    mapper->GetSmoothingFilter()->SetSkipSubpixelSmoothing(skip);
    mapper->GetSmoothingFilter()->SetTolerance(tolerance);
    scene.Actor->SetMapper(mapper);
    scene.Look(cylinder, 1);
    Frame frame;
    frame.Pixels = scene.Pixels();
    frame.Replaced = mapper->GetReplacedTriangleCount();
    frame.Straight = mapper->GetSubpixelFeatureSegmentCount();
    return frame;
  };
  const vtkSmartPointer<vtkPolyData> fine = CappedCylinder(192);
  const Frame fineAll = render(fine, false, 0.5);
  const Frame fineSkipped = render(fine, true, 0.5);
  const vtkSmartPointer<vtkPolyData> coarse = CappedCylinder(16);
  const Frame coarseAll = render(coarse, false, 0.5);
  const Frame coarseSkipped = render(coarse, true, 0.5);
  const Frame coarseStraight = render(coarse, true, 20.0);
  const long fineDiffering = Differing(fineAll.Pixels, fineSkipped.Pixels);
  const long coarseDiffering = Differing(coarseAll.Pixels, coarseSkipped.Pixels);
  const long straightDiffering = Differing(coarseAll.Pixels, coarseStraight.Pixels);
  std::printf("capped cylinder of 192 sides: %lld crease segments straight, %lld triangles "
              "replaced (all smoothed: %lld), %ld pixels differ; of 16 sides: %lld straight, %ld "
              "pixels differ (%lld straight at 20 px: %ld)\n",
    static_cast<long long>(fineSkipped.Straight), static_cast<long long>(fineSkipped.Replaced),
    static_cast<long long>(fineAll.Replaced), fineDiffering,
    static_cast<long long>(coarseSkipped.Straight), coarseDiffering,
    static_cast<long long>(coarseStraight.Straight), straightDiffering);
  if (fineSkipped.Straight != 2 * 192 || fineAll.Straight != 0 ||
    fineSkipped.Replaced * 10 > fineAll.Replaced || coarseSkipped.Straight != 0)
  {
    std::printf("FAIL: the fine rims' segments were not all drawn straight, their triangles were "
                "still re-meshed, or the coarse rims were drawn straight\n");
    ok = false;
  }
  if (fineDiffering > 40 || coarseDiffering != 0 || straightDiffering <= 200)
  {
    std::printf("FAIL: drawing the rims straight changed the image, or the check cannot fail\n");
    ok = false;
  }
  return ok;
}

// The sub-pixel skip's margin against blinking reads the frame before of
// the same viewer. One actor in two renderers of one window: B, far away,
// leaves the sphere's outline whole; A, close, smooths it. When the
// tolerance then rises just past A's largest bound (but not past it over
// three quarters), A, which smoothed the outline in its frame before, keeps
// smoothing the strip with that bound (strips whose bounds lie within three
// quarters go whole), although B, drawn just before A, left its own whole.
// With one history for the mapper (the wrong variant, as before
// 2026-12-06) A read B's and left the whole outline whole. A fresh mapper, with no frame
// before, leaves it whole at that tolerance, so the check can tell.
bool CheckEachRendererHasItsOwnHistory()
{
  const vtkSmartPointer<vtkPolyData> sphere = silhouette_test::Icosphere(4);
  auto placeCameras = [](vtkRenderer* near, vtkRenderer* far) {
    near->GetActiveCamera()->SetPosition(0.3, 0.4, 3.2);
    near->GetActiveCamera()->SetFocalPoint(0, 0, 0);
    near->ResetCameraClippingRange();
    if (far)
    {
      far->GetActiveCamera()->SetPosition(0.3, 0.4, 60.0);
      far->GetActiveCamera()->SetFocalPoint(0, 0, 0);
      far->ResetCameraClippingRange();
    }
  };
  // A's largest bound: the tolerance from which a first frame leaves the
  // outline whole.
  auto firstFrameLeavesWhole = [&](double tolerance) {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(Width, Height);
    window->SetMultiSamples(0);
    window->SetOffScreenRendering(1);
    vtkNew<vtkRenderer> near;
    window->AddRenderer(near);
    vtkNew<vtkActor> actor;
    vtkNew<vtkSilhouetteSmoothingMapper> mapper;
    mapper->SetInputData(sphere);
    mapper->GetSmoothingFilter()->SetTolerance(tolerance);
    actor->SetMapper(mapper);
    near->AddActor(actor);
    placeCameras(near, nullptr);
    window->Render();
    return mapper->GetSubpixelTriangleCount() > 0 && mapper->GetSilhouetteTriangleCount() == 0;
  };
  double low = 0.001;
  double high = 5.0;
  if (firstFrameLeavesWhole(low) || !firstFrameLeavesWhole(high))
  {
    std::printf("FAIL: the sphere's outline is not smoothed at %g px or not left whole at %g px\n",
      low, high);
    return false;
  }
  for (int step = 0; step < 24; ++step)
  {
    const double middle = std::sqrt(low * high);
    (firstFrameLeavesWhole(middle) ? high : low) = middle;
  }
  const double bound = high;

  vtkNew<vtkRenderWindow> window;
  window->SetSize(2 * Width, Height);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);
  vtkNew<vtkRenderer> far; // drawn first: the figures read after a render are A's
  vtkNew<vtkRenderer> near;
  far->SetViewport(0.5, 0.0, 1.0, 1.0);
  near->SetViewport(0.0, 0.0, 0.5, 1.0);
  window->AddRenderer(far);
  window->AddRenderer(near);
  vtkNew<vtkActor> actor;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(sphere);
  actor->SetMapper(mapper);
  far->AddActor(actor);
  near->AddActor(actor);
  placeCameras(near, far);
  mapper->GetSmoothingFilter()->SetTolerance(0.9 * bound);
  window->Render();
  const vtkIdType smoothedBefore = mapper->GetSilhouetteTriangleCount();
  mapper->GetSmoothingFilter()->SetTolerance(1.1 * bound);
  window->Render();
  const vtkIdType whole = mapper->GetSubpixelTriangleCount();
  const vtkIdType smoothed = mapper->GetSilhouetteTriangleCount();
  std::printf("own history: A's largest bound %.4f px; at 0.9 of it A smoothed %lld silhouette "
              "triangles; at 1.1 of it, after B left its outline whole, A smoothed %lld and left "
              "%lld whole (a first frame there leaves it whole: %s)\n",
    bound, static_cast<long long>(smoothedBefore), static_cast<long long>(smoothed),
    static_cast<long long>(whole), firstFrameLeavesWhole(1.1 * bound) ? "yes" : "no");
  if (smoothedBefore == 0 || smoothed == 0 || !firstFrameLeavesWhole(1.1 * bound))
  {
    std::printf("FAIL: a renderer read another renderer's frame as its frame before\n");
    return false;
  }
  return true;
}

int TestSmoothingMapperUpdates(int argc, char* argv[])
{
  const vtkSmartPointer<vtkRenderWindow> keeper = KeepTheDisplayOpen();
  const silhouette_test::SphereTorusBunny meshes =
    silhouette_test::MakeSphereTorusBunny(argc, argv);
  if (!meshes.Bunny)
  {
    return EXIT_FAILURE;
  }
  // One texture per window: a vtkTexture's OpenGL object belongs to one
  // context.
  vtkSmartPointer<vtkTexture> filterTexture = Checkers();
  vtkSmartPointer<vtkTexture> mapperTexture = Checkers();
  bool ok = CheckDeformingMesh(meshes.Bunny, filterTexture, mapperTexture);
  ok = CheckViewsInTurn(meshes.Bunny) && ok;
  ok = CheckLinesAreLit(meshes.Bunny) && ok;
  ok = CheckWireframeIsNotSmoothed(meshes.Bunny) && ok;
  ok = CheckShortArraysAreLeftOut(meshes.Bunny) && ok;
  ok = CheckSharedMapperSelection(meshes.Bunny) && ok;
  ok = CheckMissingPointsAreNotDrawn(meshes.Bunny) && ok;
  ok = CheckArraysAloneDoNotSmoothAgain(meshes.Bunny) && ok;
  ok = CheckCopiesAndEmptyFrames(meshes.Bunny) && ok;
  ok = CheckFineCreasesAreDrawnStraight() && ok;
  ok = CheckEachRendererHasItsOwnHistory() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
