// What the mapper tests share: a window with one actor, the colourings of
// the mesh, its pixels and the count of pixels two images differ in.
#pragma once

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSilhouetteSmoothingMapper.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace mapper_test
{

constexpr int Width = 400;
constexpr int Height = 400;
constexpr int Views = 4;
// Measured: 0 on every case and view (llvmpipe, X and OSMesa); the
// chord-only outline differs in 1,581 to 9,002 pixels.
constexpr long MaximumDifferingPixels = 20;

enum class Colouring
{
  Plain,
  PointScalars,
  CellScalars,
  Texture,
  /// One tuple of a field-data array colours every cell.
  FieldData,
  /// Two textures of the property, each on its own coordinates
  /// (MapDataArrayToMultiTextureAttribute).
  MultiTexture,
  /// Coordinates around the vertical axis, with the seam they jump across
  /// closed by SeamlessU.
  SeamlessTexture
};

// Renders `window` and returns its pixels.
inline std::vector<unsigned char> RenderedPixels(vtkRenderWindow* window)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  vtkDataArray* scalars = grab->GetOutput()->GetPointData()->GetScalars();
  const auto* data = static_cast<unsigned char*>(scalars->GetVoidPointer(0));
  return std::vector<unsigned char>(
    data, data + scalars->GetNumberOfTuples() * scalars->GetNumberOfComponents());
}

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;

  Scene()
  {
    this->Window->SetSize(Width, Height);
    this->Window->SetMultiSamples(0);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->AddActor(this->Actor);
  }

  double Zoom = 1.3;

  void Look(vtkPolyData* mesh, int view)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0, 0, 1);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    this->Renderer->ResetCamera(mesh->GetBounds());
    camera->Azimuth(20.0 + 25.0 * view);
    camera->Elevation(15.0 + 5.0 * view);
    camera->OrthogonalizeViewUp();
    camera->Zoom(this->Zoom);
    this->Renderer->ResetCameraClippingRange(mesh->GetBounds());
  }

  std::vector<unsigned char> Pixels() { return RenderedPixels(this->Window); }

  // The input cell under every pixel (-1 for none): the selected cell id,
  // through `original` when given (the filter's OriginalCellId).
  std::vector<vtkIdType> CellUnderPixels(vtkIdTypeArray* original)
  {
    vtkNew<vtkHardwareSelector> selector;
    selector->SetRenderer(this->Renderer);
    selector->SetArea(0, 0, Width - 1, Height - 1);
    selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
    std::vector<vtkIdType> cells(static_cast<std::size_t>(Width * Height), -1);
    if (!selector->CaptureBuffers())
    {
      return cells;
    }
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        unsigned int position[2] = { static_cast<unsigned int>(x), static_cast<unsigned int>(y) };
        const vtkHardwareSelector::PixelInformation info = selector->GetPixelInformation(position);
        if (info.Valid)
        {
          const vtkIdType id = info.AttributeID;
          cells[static_cast<std::size_t>(y * Width + x)] =
            original && id >= 0 && id < original->GetNumberOfValues() ? original->GetValue(id) : id;
        }
      }
    }
    selector->ClearBuffers();
    return cells;
  }
};

inline long Differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  long count = 0;
  for (std::size_t p = 0; p + 2 < a.size() && p + 2 < b.size(); p += 3)
  {
    count += a[p] != b[p] || a[p + 1] != b[p + 1] || a[p + 2] != b[p + 2] ? 1 : 0;
  }
  return count + static_cast<long>(a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

inline vtkSmartPointer<vtkPolyData> Coloured(vtkPolyData* mesh, Colouring colouring)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(mesh);
  double bounds[6];
  mesh->GetBounds(bounds);
  if (colouring == Colouring::FieldData)
  {
    vtkNew<vtkFloatArray> tint;
    tint->SetName("Tint");
    for (const float value : { 0.0f, 5.0f, 2.0f })
    {
      tint->InsertNextValue(value);
    }
    out->GetFieldData()->AddArray(tint);
  }
  if (colouring == Colouring::MultiTexture || colouring == Colouring::SeamlessTexture)
  {
    vtkNew<vtkFloatArray> around; // the active coordinates
    around->SetName("TextureCoordinates");
    around->SetNumberOfComponents(2);
    vtkNew<vtkFloatArray> plane;
    plane->SetName("PlaneCoordinates");
    plane->SetNumberOfComponents(2);
    const double* centre = mesh->GetCenter();
    for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    {
      double x[3];
      mesh->GetPoint(p, x);
      const double u = 0.5 + std::atan2(x[2] - centre[2], x[0] - centre[0]) / (2.0 * vtkMath::Pi());
      const double v = (x[1] - bounds[2]) / (bounds[3] - bounds[2] + 1e-30);
      around->InsertNextTuple2(u, v);
      plane->InsertNextTuple2(2.0 * (x[0] - bounds[0]) / (bounds[1] - bounds[0] + 1e-30), 2.0 * v);
    }
    out->GetPointData()->SetTCoords(around);
    out->GetPointData()->AddArray(plane);
  }
  if (colouring == Colouring::PointScalars || colouring == Colouring::Texture)
  {
    vtkNew<vtkFloatArray> values;
    values->SetName(colouring == Colouring::Texture ? "TextureCoordinates" : "Height");
    values->SetNumberOfComponents(colouring == Colouring::Texture ? 2 : 1);
    values->SetNumberOfTuples(mesh->GetNumberOfPoints());
    for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    {
      double x[3];
      mesh->GetPoint(p, x);
      const double u = (x[0] - bounds[0]) / (bounds[1] - bounds[0] + 1e-30);
      const double v = (x[2] - bounds[4]) / (bounds[5] - bounds[4] + 1e-30);
      if (colouring == Colouring::Texture)
      {
        values->SetTuple2(p, 3.0 * u, 3.0 * v);
      }
      else
      {
        values->SetValue(p, static_cast<float>(x[1]));
      }
    }
    if (colouring == Colouring::Texture)
    {
      out->GetPointData()->SetTCoords(values);
    }
    else
    {
      out->GetPointData()->SetScalars(values);
    }
  }
  if (colouring == Colouring::CellScalars)
  {
    vtkNew<vtkFloatArray> values;
    values->SetName("Band");
    values->SetNumberOfTuples(mesh->GetNumberOfCells());
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
    {
      values->SetValue(c, static_cast<float>(c % 7));
    }
    out->GetCellData()->SetScalars(values);
  }
  return out;
}

// `second`: the other texture of Colouring::MultiTexture (one per window).
inline void Configure(vtkMapper* mapper, vtkActor* actor, Colouring colouring, vtkTexture* texture,
  vtkTexture* second = nullptr)
{
  actor->GetProperty()->SetColor(0.75, 0.78, 0.85);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(30);
  actor->SetTexture(
    colouring == Colouring::Texture || colouring == Colouring::SeamlessTexture ? texture : nullptr);
  auto* polyMapper = vtkPolyDataMapper::SafeDownCast(mapper);
  if (colouring == Colouring::MultiTexture && polyMapper && second)
  {
    actor->GetProperty()->SetTexture("checkers", texture);
    actor->GetProperty()->SetTexture("stripes", second);
    polyMapper->MapDataArrayToMultiTextureAttribute(
      "checkers", "TextureCoordinates", vtkDataObject::FIELD_ASSOCIATION_POINTS);
    polyMapper->MapDataArrayToMultiTextureAttribute(
      "stripes", "PlaneCoordinates", vtkDataObject::FIELD_ASSOCIATION_POINTS);
  }
  if (colouring == Colouring::SeamlessTexture && polyMapper)
  {
    polyMapper->SetSeamlessU(true);
  }
  mapper->SetScalarVisibility(
    colouring == Colouring::PointScalars || colouring == Colouring::CellScalars);
  if (colouring == Colouring::PointScalars)
  {
    mapper->SetScalarModeToUsePointData();
    mapper->SetScalarRange(-1.0, 1.0);
  }
  if (colouring == Colouring::CellScalars)
  {
    mapper->SetScalarModeToUseCellData();
    mapper->SetScalarRange(0.0, 6.0);
  }
  if (colouring == Colouring::FieldData)
  {
    mapper->SetScalarVisibility(true);
    mapper->SetScalarModeToUseFieldData();
    mapper->SelectColorArray("Tint");
    mapper->SetFieldDataTupleId(1);
    mapper->SetScalarRange(0.0, 6.0);
  }
}

// A window kept open for the whole test: each case closes its own, and an X
// server whose last client leaves resets, refusing the next connection while
// it does (xvfb-run starts Xvfb without -noreset).
inline vtkSmartPointer<vtkRenderWindow> KeepTheDisplayOpen()
{
  auto keeper = vtkSmartPointer<vtkRenderWindow>::New();
  keeper->SetOffScreenRendering(1);
  keeper->SetSize(8, 8);
  keeper->Render();
  return keeper;
}

// A texture of size x size RGB pixels, each painted by paint(x, y, rgb);
// unfiltered and repeated.
inline vtkSmartPointer<vtkTexture> PaintedTexture(
  int size, const std::function<void(int, int, unsigned char*)>& paint)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int y = 0; y < size; ++y)
  {
    for (int x = 0; x < size; ++x)
    {
      paint(x, y, pixels + 3 * (y * size + x));
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOff();
  texture->RepeatOn();
  return texture;
}

// Stripes added to the first texture (Colouring::MultiTexture's second).
inline vtkSmartPointer<vtkTexture> Stripes()
{
  auto texture = PaintedTexture(32, [](int x, int, unsigned char* p) {
    p[0] = (x / 4) % 2 ? 90 : 0;
    p[1] = 0;
    p[2] = (x / 4) % 2 ? 0 : 60;
  });
  texture->SetBlendingMode(vtkTexture::VTK_TEXTURE_BLENDING_MODE_ADD);
  return texture;
}

inline vtkSmartPointer<vtkTexture> Checkers()
{
  return PaintedTexture(64, [](int x, int y, unsigned char* p) {
    const bool dark = ((x / 8) + (y / 8)) % 2 == 0;
    p[0] = dark ? 40 : 230;
    p[1] = dark ? 60 : 200;
    p[2] = dark ? 160 : 90;
  });
}

} // namespace mapper_test
