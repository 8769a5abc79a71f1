// Image regression for real asset files (issue 12), compared with
// Testing/Data/Baseline/TestAssetImages.png:
//   top:    Debian's assimp-testmodels spider OBJ, textured with its own
//           JPEG textures per material, as read (left) and smoothed with
//           default settings (right): the texture coordinates are carried
//           onto the added points, each texture chart from its own points;
//   bottom: with default settings, a vtkCubeSource box (flat-shaded normals,
//           24 points) stays a box (left) and the OpenSCAD bracket
//           (Data/bracket.stl) keeps its edges while its cylinders are
//           smoothed (right).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkGeometryFilter.h"
#include "vtkJPEGReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkStringArray.h"
#include "vtkTexture.h"
#include "vtkThreshold.h"

#include "SilhouetteTestSupport.h"

#include <cstdio>
#include <string>

namespace
{

vtkSmartPointer<vtkRenderer> AddRenderer(vtkRenderWindow* window, int row, int column)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(0.5 * column, 0.5 * (1 - row), 0.5 * (column + 1), 0.5 * (2 - row));
  renderer->SetBackground(1, 1, 1);
  window->AddRenderer(renderer);
  return renderer;
}

void Frame(vtkRenderer* renderer, vtkPolyData* mesh, double azimuth, double elevation, double zoom)
{
  renderer->ResetCamera(mesh->GetBounds());
  renderer->GetActiveCamera()->Azimuth(azimuth);
  renderer->GetActiveCamera()->Elevation(elevation);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->GetActiveCamera()->Zoom(zoom);
  renderer->ResetCameraClippingRange();
}

// One textured actor per material of a mesh read by vtkOBJReader: the cells
// of material m, with the point array named after the material as their
// texture coordinates, and the material's JPEG.
bool AddTextured(vtkRenderer* renderer, vtkPolyData* mesh, const std::string& folder)
{
  vtkStringArray* materials =
    vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("MaterialNames"));
  if (!materials)
  {
    return false;
  }
  // The spider's .mtl names these images for its materials.
  const std::pair<const char*, const char*> images[] = { { "Skin", "wal67ar_small.jpg" },
    { "Brusttex", "wal69ar_small.jpg" }, { "HLeibTex", "SpiderTex.jpg" },
    { "BeinTex", "drkwood2.jpg" }, { "Augentex", "engineflare1.jpg" } };
  for (vtkIdType m = 0; m < materials->GetNumberOfValues(); ++m)
  {
    const std::string name = materials->GetValue(m);
    const char* image = nullptr;
    for (const auto& entry : images)
    {
      image = name == entry.first ? entry.second : image;
    }
    if (!image || !mesh->GetPointData()->GetArray(name.c_str()))
    {
      continue;
    }
    vtkNew<vtkThreshold> part;
    part->SetInputData(mesh);
    part->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "MaterialIds");
    part->SetLowerThreshold(static_cast<double>(m));
    part->SetUpperThreshold(static_cast<double>(m));
    vtkNew<vtkGeometryFilter> surface;
    surface->SetInputConnection(part->GetOutputPort());
    surface->Update();
    vtkNew<vtkPolyData> piece;
    piece->ShallowCopy(surface->GetOutput());
    piece->GetPointData()->SetTCoords(piece->GetPointData()->GetArray(name.c_str()));
    vtkNew<vtkJPEGReader> jpeg;
    jpeg->SetFileName((folder + "/OBJ/" + image).c_str());
    vtkNew<vtkTexture> texture;
    texture->SetInputConnection(jpeg->GetOutputPort());
    texture->InterpolateOn();
    texture->RepeatOn();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(piece);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(texture);
    renderer->AddActor(actor);
  }
  return true;
}

vtkSmartPointer<vtkPolyData> SmoothedFor(vtkPolyData* mesh, vtkRenderer* renderer)
{
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(mesh);
  smoother->SetCamera(renderer->GetActiveCamera());
  smoother->SetViewportSize(renderer->GetSize()[0], renderer->GetSize()[1]);
  smoother->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(smoother->GetOutput());
  return out;
}

void AddShaded(vtkRenderer* renderer, vtkPolyData* mesh)
{
  vtkNew<vtkSilhouetteSmoothingFilter> smoother;
  smoother->SetInputData(mesh);
  smoother->SetRenderer(renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(smoother->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.75, 0.78, 0.85);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(30);
  renderer->AddActor(actor);
}

} // namespace

int TestAssetImages(int argc, char* argv[])
{
  const std::string folder = silhouette_test::AssetModelsFolder();
  if (folder.empty())
  {
    std::printf(
      "FAIL: Debian's assimp-testmodels is not installed (scripts/setup.sh installs it)\n");
    return EXIT_FAILURE;
  }
  auto spider = silhouette_test::ReadMesh(folder + "/OBJ/spider.obj");
  auto bracket = silhouette_test::ReadMesh(silhouette_test::DataFile(argc, argv, "bracket.stl"));
  if (!spider || !bracket)
  {
    std::printf("FAIL: cannot read spider.obj or bracket.stl\n");
    return EXIT_FAILURE;
  }
  vtkNew<vtkCubeSource> cube;
  cube->Update();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(1000, 800);
  window->SetMultiSamples(0);
  window->SetOffScreenRendering(1);

  // Spider: both panels from one camera; the smoothed mesh for that view.
  auto raw = AddRenderer(window, 0, 0);
  auto smoothed = AddRenderer(window, 0, 1);
  Frame(raw, spider, 35, 30, 1.5);
  smoothed->SetActiveCamera(raw->GetActiveCamera());
  window->Render(); // sizes the renderers
  if (!AddTextured(raw, spider, folder) ||
    !AddTextured(smoothed, SmoothedFor(spider, smoothed), folder))
  {
    std::printf("FAIL: the spider has no materials\n");
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkPolyData> spiderOut = SmoothedFor(spider, smoothed);
  std::printf("spider: %lld silhouette triangles, %lld normal-seam edges, %lld welded points\n",
    static_cast<long long>(
      spiderOut->GetFieldData()->GetArray("SilhouetteTriangleCount")->GetTuple1(0)),
    static_cast<long long>(
      spiderOut->GetFieldData()->GetArray("NormalSeamEdgeCount")->GetTuple1(0)),
    static_cast<long long>(spiderOut->GetFieldData()->GetArray("WeldedPointCount")->GetTuple1(0)));

  auto box = AddRenderer(window, 1, 0);
  AddShaded(box, cube->GetOutput());
  Frame(box, cube->GetOutput(), 30, 25, 0.85);
  auto part = AddRenderer(window, 1, 1);
  AddShaded(part, bracket);
  Frame(part, bracket, 30, 30, 1.3);
  window->Render();
  const int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
