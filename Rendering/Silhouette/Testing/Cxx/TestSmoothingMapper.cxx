// The render-time mapper (issue 15) draws what the filter's output draws:
// for the sphere, the torus and the coarse bunny, plain, with point scalars,
// with cell scalars and with a texture, over an orbit of views rendered by
// one mapper (so the hidden triangles of one frame are restored in the
// next), the image of vtkSilhouetteSmoothingMapper and that of
// vtkSilhouetteSmoothingFilter + vtkPolyDataMapper differ in at most
// MaximumDifferingPixels pixels (any channel). The mapper with smoothing
// off (the chord-only outline) must differ in more than that, or the check
// cannot fail. Hardware cell selection over every pixel reports the same
// input cell as the filter's output does (through its OriginalCellId).
// Zoomed in, part of the silhouette is outside the view: the mapper leaves
// it as it is (FrustumCulling, on in the mapper, off in the filter), and
// the images are still the same. (SkipSubpixelSmoothing, on in the mapper,
// is turned on in the filter too: it changes the outline by up to the
// tolerance, which pixels show.) So they are with a clipping plane across
// the mesh, and with the actor translucent (each case also shows that the
// mapper without the plane, or opaque, fails the check). Ghost cells (another piece's) are never
// re-meshed by the filter and never drawn by the mapper: its image is the
// filter's output with the ghost cells left out.

#include "MapperTestScene.h"
#include "SilhouetteTestSupport.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace mapper_test;

namespace
{

// The cells of `mesh` not flagged as ghosts, over its points, with the
// cells' data.
vtkSmartPointer<vtkPolyData> WithoutGhosts(vtkPolyData* mesh)
{
  auto kept = vtkSmartPointer<vtkPolyData>::New();
  kept->SetPoints(mesh->GetPoints());
  kept->GetPointData()->ShallowCopy(mesh->GetPointData());
  vtkNew<vtkCellArray> polys;
  vtkDataArray* ghosts = mesh->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  const vtkIdType first = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  vtkNew<vtkIdList> ids;
  for (vtkIdType p = 0; p < mesh->GetNumberOfPolys(); ++p)
  {
    if (!ghosts || ghosts->GetTuple1(first + p) == 0.0)
    {
      mesh->GetCellPoints(first + p, ids);
      polys->InsertNextCell(ids);
    }
  }
  kept->SetPolys(polys);
  return kept;
}

struct MapperCase
{
  const char* Name;
  vtkPolyData* Mesh;
  Colouring How;
  double Zoom = 1.3;
  /// A clipping plane through the mesh's centre, on both mappers.
  bool Clipped = false;
  /// The actors' opacity (below 1: the translucent pass).
  double Opacity = 1.0;
  /// Both smoothings' OutputPointsPrecision (the bunny's points are float:
  /// DOUBLE_PRECISION makes the output's another type than the input's).
  int Precision = vtkAlgorithm::DEFAULT_PRECISION;
};

// One case: the mapper's image against filter + mapper's over the views,
// the wrong variants that must fail, and selection.
// A redraw of the same view reuses the patch: the prepare time drops to next
// to nothing, and the smoothing time stays the last real work's (the
// viewer's overlay once showed 0.01 ms, its own redraw's). So does a
// window-to-image grab, though vtkWindowToImageFilter renders with a copy of
// the camera whose view angle went through a float: a view compared bit for
// bit smoothed twice per screenshot.
bool SmoothingTimeOutlivesARedraw(
  vtkSilhouetteSmoothingMapper* mapper, vtkRenderWindow* window, const char* name)
{
  window->Render();
  const double smoothing = mapper->GetLastSmoothingSeconds();
  const auto reused = [&](const char* how) {
    if (smoothing > 0.0 && mapper->GetLastSmoothingSeconds() == smoothing &&
      mapper->GetLastPrepareSeconds() < smoothing)
    {
      return true;
    }
    std::printf("FAIL: %s: after a %s, the smoothing time is not the last view change's (%g s, "
                "then %g s; prepare %g s)\n",
      name, how, smoothing, mapper->GetLastSmoothingSeconds(), mapper->GetLastPrepareSeconds());
    return false;
  };
  window->Render();
  if (!reused("redraw"))
  {
    return false;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  return reused("window-to-image grab");
}

bool CheckCase(const MapperCase& c, vtkTexture* filterTexture, vtkTexture* mapperTexture)
{
  bool ok = true;
  vtkSmartPointer<vtkPolyData> mesh = Coloured(c.Mesh, c.How);
  Scene viaFilter;
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  filter->SetInputData(mesh);
  filter->SetRenderer(viaFilter.Renderer);
  filter->SetProp3D(viaFilter.Actor);
  filter->SkipSubpixelSmoothingOn(); // as in the mapper
  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputConnection(filter->GetOutputPort());
  // Colouring::MultiTexture's second textures: one per window.
  vtkSmartPointer<vtkTexture> filterSecond = Stripes();
  vtkSmartPointer<vtkTexture> mapperSecond = Stripes();
  Configure(plain, viaFilter.Actor, c.How, filterTexture, filterSecond);
  viaFilter.Actor->SetMapper(plain);

  Scene viaMapper;
  viaFilter.Zoom = viaMapper.Zoom = c.Zoom;
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(mesh);
  filter->SetOutputPointsPrecision(c.Precision);
  mapper->GetSmoothingFilter()->SetOutputPointsPrecision(c.Precision);
  // The filter's requests reuse no fold fallbacks from frame to frame; the
  // mapper's reuse is tested in core.SilhouetteSmoother and
  // module.TestNoFolds.
  mapper->GetSmoothingFilter()->ReuseFoldFallbacksOff();
  Configure(mapper, viaMapper.Actor, c.How, mapperTexture, mapperSecond);
  viaMapper.Actor->SetMapper(mapper);
  for (Scene* scene : { &viaFilter, &viaMapper })
  {
    scene->Actor->GetProperty()->SetOpacity(c.Opacity);
  }
  if (c.Clipped)
  {
    // Oblique, through the centre: it cuts across silhouette triangles.
    const double* centre = mesh->GetCenter();
    for (vtkMapper* m : { static_cast<vtkMapper*>(plain), static_cast<vtkMapper*>(mapper) })
    {
      vtkNew<vtkPlane> plane;
      plane->SetOrigin(centre[0], centre[1], centre[2]);
      plane->SetNormal(0.6, -0.3, 0.74);
      m->AddClippingPlane(plane);
    }
  }

  long worst = 0;
  long leastUnsmoothed = -1;
  vtkIdType culled = 0;
  for (int view = 0; view < Views; ++view)
  {
    viaFilter.Look(mesh, view);
    viaMapper.Look(mesh, view);
    const std::vector<unsigned char> expected = viaFilter.Pixels();
    mapper->SmoothingOff();
    const long unsmoothed = Differing(viaMapper.Pixels(), expected);
    mapper->SmoothingOn();
    const long differing = Differing(viaMapper.Pixels(), expected);
    worst = std::max(worst, differing);
    culled += mapper->GetCulledTriangleCount();
    leastUnsmoothed = leastUnsmoothed < 0 ? unsmoothed : std::min(leastUnsmoothed, unsmoothed);
    if (view == 0 && mapper->GetReplacedTriangleCount() == 0)
    {
      std::printf("FAIL: %s: the mapper replaced no triangle\n", c.Name);
      ok = false;
    }
    if (view == 0 && !SmoothingTimeOutlivesARedraw(mapper, viaMapper.Window, c.Name))
    {
      ok = false;
    }
    if (view == 0 && !(mapper->GetTimeToDraw() > 0.0))
    {
      // vtkLODActor weighs it; the drawing mapper's, as vtkPolyDataMapper's.
      std::printf("FAIL: %s: the mapper's TimeToDraw is %g\n", c.Name, mapper->GetTimeToDraw());
      ok = false;
    }
    if (view == 0 && (c.Clipped || c.Opacity < 1.0))
    {
      // The wrong variant: the mapper without the plane, or opaque, must
      // fail the check, or the case does not test what it names.
      vtkSmartPointer<vtkPlaneCollection> planes = mapper->GetClippingPlanes();
      mapper->SetClippingPlanes(static_cast<vtkPlaneCollection*>(nullptr));
      viaMapper.Actor->GetProperty()->SetOpacity(1.0);
      const long without = Differing(viaMapper.Pixels(), expected);
      mapper->SetClippingPlanes(planes);
      viaMapper.Actor->GetProperty()->SetOpacity(c.Opacity);
      std::printf("%s: %s, %ld pixels differ\n", c.Name,
        c.Clipped ? "without the clipping plane" : "opaque", without);
      if (without <= MaximumDifferingPixels)
      {
        std::printf("FAIL: %s: the check cannot tell\n", c.Name);
        ok = false;
      }
    }
  }
  std::printf("%s: at most %ld pixels differ from the filter's image over %d views "
              "(limit %ld); with smoothing off at least %ld\n",
    c.Name, worst, Views, MaximumDifferingPixels, leastUnsmoothed);
  if (c.Zoom > 2.0)
  {
    std::printf("%s: %lld silhouette triangles outside the view left as they are\n", c.Name,
      static_cast<long long>(culled));
    if (culled == 0)
    {
      std::printf("FAIL: %s: nothing was outside the view, the case is not tested\n", c.Name);
      ok = false;
    }
  }
  if (worst > MaximumDifferingPixels)
  {
    std::printf("FAIL: %s: the mapper's image is not the filter's\n", c.Name);
    ok = false;
  }
  if (leastUnsmoothed <= MaximumDifferingPixels)
  {
    std::printf("FAIL: %s: the chord-only outline passes the check, which cannot fail\n", c.Name);
    ok = false;
  }

  if (c.How == Colouring::Plain)
  {
    // Selection: the input cell under every pixel, as the filter's output
    // says (through OriginalCellId).
    viaFilter.Look(mesh, 1);
    viaMapper.Look(mesh, 1);
    viaFilter.Window->Render();
    viaMapper.Window->Render();
    vtkIdTypeArray* original =
      vtkIdTypeArray::SafeDownCast(filter->GetOutput()->GetCellData()->GetArray("OriginalCellId"));
    const std::vector<vtkIdType> expected = viaFilter.CellUnderPixels(original);
    const std::vector<vtkIdType> picked = viaMapper.CellUnderPixels(nullptr);
    long mismatches = 0;
    long covered = 0;
    long outOfRange = 0;
    for (std::size_t p = 0; p < expected.size(); ++p)
    {
      mismatches += expected[p] != picked[p] ? 1 : 0;
      covered += expected[p] >= 0 ? 1 : 0;
      outOfRange += picked[p] >= mesh->GetNumberOfCells() ? 1 : 0;
    }
    std::printf("%s: selection: %ld of %ld covered pixels report another cell than the "
                "filter's; %ld ids beyond the input's cells\n",
      c.Name, mismatches, covered, outOfRange);
    if (covered == 0 || mismatches > MaximumDifferingPixels || outOfRange > 0)
    {
      std::printf("FAIL: %s: selection does not report the input's cells\n", c.Name);
      ok = false;
    }
  }
  return ok;
}

// Ghost cells: the cells of one side of the sphere are another piece's.
bool CheckGhostCells(vtkPolyData* sphere, vtkTexture* filterTexture, vtkTexture* mapperTexture)
{
  bool ok = true;
  vtkNew<vtkPolyData> piece;
  piece->DeepCopy(sphere);
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(piece->GetNumberOfCells());
  long ghostCells = 0;
  for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c)
  {
    double bounds[6];
    piece->GetCellBounds(c, bounds);
    const bool ghost = bounds[0] + bounds[1] > 0.3;
    ghosts->SetValue(c, ghost ? vtkDataSetAttributes::DUPLICATECELL : 0);
    ghostCells += ghost ? 1 : 0;
  }
  piece->GetCellData()->AddArray(ghosts);
  Scene viaFilter;
  Scene viaMapper;
  viaFilter.Look(piece, 0);
  viaMapper.Look(piece, 0);
  // The filter: ghost cells pass through as they are.
  auto count = [&](const char* ghostName) {
    vtkNew<vtkPolyData> named;
    named->DeepCopy(piece);
    named->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName())->SetName(ghostName);
    vtkNew<vtkSilhouetteSmoothingFilter> filter;
    filter->SetInputData(named);
    filter->SetRenderer(viaFilter.Renderer);
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    vtkDataArray* made = out->GetCellData()->GetArray("NewGeometry");
    vtkDataArray* from = out->GetCellData()->GetArray("OriginalCellId");
    long remeshedGhosts = 0;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      remeshedGhosts +=
        made->GetTuple1(c) > 0 && ghosts->GetValue(static_cast<vtkIdType>(from->GetTuple1(c))) ? 1
                                                                                               : 0;
    }
    return remeshedGhosts;
  };
  const long remeshed = count(vtkDataSetAttributes::GhostArrayName());
  const long remeshedIfNotGhosts = count("NotGhosts");
  std::printf("ghost cells: %ld of %lld; new triangles from them %ld (%ld were they not "
              "ghosts)\n",
    ghostCells, static_cast<long long>(piece->GetNumberOfCells()), remeshed, remeshedIfNotGhosts);
  if (remeshed != 0 || remeshedIfNotGhosts == 0)
  {
    std::printf("FAIL: ghost cells are re-meshed, or the case has none to re-mesh\n");
    ok = false;
  }
  // The mapper: the filter's output without its ghost cells, drawn.
  vtkNew<vtkSilhouetteSmoothingFilter> filter;
  filter->SetInputData(piece);
  filter->SetRenderer(viaFilter.Renderer);
  filter->Update();
  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputData(WithoutGhosts(filter->GetOutput()));
  Configure(plain, viaFilter.Actor, Colouring::Plain, filterTexture);
  viaFilter.Actor->SetMapper(plain);
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  mapper->SetInputData(piece);
  Configure(mapper, viaMapper.Actor, Colouring::Plain, mapperTexture);
  viaMapper.Actor->SetMapper(mapper);
  const std::vector<unsigned char> expected = viaFilter.Pixels();
  const long differing = Differing(viaMapper.Pixels(), expected);
  vtkNew<vtkPolyDataMapper> withGhosts;
  withGhosts->SetInputData(filter->GetOutput());
  Configure(withGhosts, viaFilter.Actor, Colouring::Plain, filterTexture);
  viaFilter.Actor->SetMapper(withGhosts);
  const long ghostsDrawn = Differing(viaFilter.Pixels(), expected);
  std::printf("ghost cells: the mapper's image differs from the filter's without ghosts in "
              "%ld pixels; drawing the ghosts too differs in %ld\n",
    differing, ghostsDrawn);
  if (differing > MaximumDifferingPixels || ghostsDrawn <= MaximumDifferingPixels)
  {
    std::printf("FAIL: ghost cells drawn, or the check cannot fail\n");
    ok = false;
  }
  return ok;
}

} // namespace

int TestSmoothingMapper(int argc, char* argv[])
{
  const vtkSmartPointer<vtkRenderWindow> keeper = KeepTheDisplayOpen();
  const silhouette_test::SphereTorusBunny meshes =
    silhouette_test::MakeSphereTorusBunny(argc, argv);
  if (!meshes.Bunny)
  {
    return EXIT_FAILURE;
  }
  vtkPolyData* sphere = meshes.Sphere;
  vtkPolyData* torus = meshes.Torus;
  vtkPolyData* bunny = meshes.Bunny;
  // One texture per window: a vtkTexture's OpenGL object belongs to one
  // context.
  vtkSmartPointer<vtkTexture> filterTexture = Checkers();
  vtkSmartPointer<vtkTexture> mapperTexture = Checkers();
  const MapperCase cases[] = { { "sphere", sphere, Colouring::Plain },
    { "torus", torus, Colouring::Plain }, { "bunny", bunny, Colouring::Plain },
    { "bunny, point scalars", bunny, Colouring::PointScalars },
    { "torus, cell scalars", torus, Colouring::CellScalars },
    { "sphere, texture", sphere, Colouring::Texture },
    { "bunny, texture", bunny, Colouring::Texture },
    { "bunny, field data", bunny, Colouring::FieldData },
    { "bunny, two textures", bunny, Colouring::MultiTexture },
    { "torus, seamless texture", torus, Colouring::SeamlessTexture },
    { "torus, zoomed in", torus, Colouring::Plain, 3.0 },
    { "bunny, clipped", bunny, Colouring::Plain, 1.3, true },
    { "torus, clipped", torus, Colouring::Plain, 1.3, true },
    { "bunny, translucent", bunny, Colouring::Plain, 1.3, false, 0.5 },
    { "torus, translucent, point scalars", torus, Colouring::PointScalars, 1.3, false, 0.5 },
    { "bunny, double-precision output", bunny, Colouring::Plain, 1.3, false, 1.0,
      vtkAlgorithm::DOUBLE_PRECISION } };

  bool ok = true;
  for (const MapperCase& c : cases)
  {
    ok = CheckCase(c, filterTexture, mapperTexture) && ok;
  }
  ok = CheckGhostCells(sphere, filterTexture, mapperTexture) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
