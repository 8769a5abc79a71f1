#include "Rendering.h"

#include "AtomicFile.h"
#include "CliErrors.h"
#include "MeshIO.h"
#include "RenderingBackend.h"
#include "Smoothing.h"
#include "VectorDrawing.h"
#include "VtkErrorLog.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCreaseAndBorderLines.h>
#include <vtkDataObject.h>
#include <vtkDataSetMapper.h>
#include <vtkFaceSilhouetteLines.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkSilhouetteLineVisibility.h>
#include <vtkSilhouetteSmoothingFilter.h>
#include <vtkSilhouetteSmoothingMapper.h>
#include <vtkStylizedStrokeFilter.h>
#include <vtkThreshold.h>
#include <vtkTrivialProducer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <unistd.h>

namespace cli
{
namespace
{

// The input as the smoothing sees it, with its shading normals (a point
// copy per smooth group at creases, as the filter's output has), so
// --no-smoothing differs from the smoothed mesh in its geometry only. The
// input's own points carry one normal each: across a crease that smeared
// the shading of flat faces.
vtkSmartPointer<vtkPolyData> InputWithShadingNormals(
  vtkPolyData* input, vtkSilhouetteSmoothingFilter* filter)
{
  auto base = vtkSmartPointer<vtkPolyData>::New();
  if (!filter->BuildBaseMesh(input, base))
  {
    throw RuntimeError("the filter could not prepare the input for drawing");
  }
  return base;
}

vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithmOutput* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkActor> MakeActor(vtkPolyData* mesh)
{
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(mesh);
  return MakeActor(producer->GetOutputPort());
}

// Lines in black, 2 px wide, unlit: the line styles' look.
void AddBlackLines(vtkRenderer* renderer, vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  property->SetColor(Black[0], Black[1], Black[2]);
  property->SetLineWidth(2.0);
  property->LightingOff();
  renderer->AddActor(actor);
}

// The hidden pieces (cell array Visible 0) of `lines` as dashes in the
// renderer's image: `on` pixels drawn, `off` left out, along each piece
// from its start (its points interpolated in model coordinates as in the
// image). For a PNG of a fixed view, as an SVG's stroke-dasharray does.
vtkSmartPointer<vtkPolyData> HiddenPiecesAsDashes(
  vtkPolyData* lines, vtkRenderer* renderer, double on, double off)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> dashes;
  auto* visible = vtkUnsignedCharArray::SafeDownCast(lines->GetCellData()->GetArray("Visible"));
  auto toPixels = [renderer](const double p[3], double pixel[2]) {
    renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
    renderer->WorldToDisplay();
    const double* display = renderer->GetDisplayPoint();
    pixel[0] = display[0];
    pixel[1] = display[1];
  };
  const double period = on + off;
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; visible && cell < lines->GetNumberOfCells(); ++cell)
  {
    const int type = lines->GetCellType(cell);
    if (visible->GetValue(cell) != 0 || (type != VTK_POLY_LINE && type != VTK_LINE))
    {
      continue;
    }
    lines->GetCellPoints(cell, ids);
    double along = 0.0; // pixels from the piece's start
    std::vector<vtkIdType> dash;
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      double a[3], b[3], pa[2], pb[2];
      lines->GetPoint(ids->GetId(k), a);
      lines->GetPoint(ids->GetId(k + 1), b);
      toPixels(a, pa);
      toPixels(b, pb);
      const double length = std::hypot(pb[0] - pa[0], pb[1] - pa[1]);
      if (!(length > 0.0) || !std::isfinite(length))
      {
        continue;
      }
      // The segment's stretches between changes of dash and gap.
      double at = 0.0;
      while (at < length)
      {
        const double phase = std::fmod(along + at, period);
        const bool drawn = phase < on;
        const double next = std::min(length, at + (drawn ? on - phase : period - phase));
        if (drawn)
        {
          double p[3];
          for (int i = 0; i < 3; ++i)
          {
            p[i] = a[i] + (at / length) * (b[i] - a[i]);
          }
          if (dash.empty())
          {
            dash.push_back(points->InsertNextPoint(p));
          }
          for (int i = 0; i < 3; ++i)
          {
            p[i] = a[i] + (next / length) * (b[i] - a[i]);
          }
          dash.push_back(points->InsertNextPoint(p));
        }
        else if (!dash.empty())
        {
          dashes->InsertNextCell(static_cast<vtkIdType>(dash.size()), dash.data());
          dash.clear();
        }
        at = next;
      }
      along += length;
    }
    if (dash.size() >= 2)
    {
      dashes->InsertNextCell(static_cast<vtkIdType>(dash.size()), dash.data());
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetLines(dashes);
  return result;
}

// The face-based silhouette of `input` (vtkFaceSilhouetteLines, Xing's Fig.
// 6b) for the renderer's camera, with the shading normals and visibility
// rule of the smoothing filter: what the silhouette is before smoothing.
vtkSmartPointer<vtkFaceSilhouetteLines> MakeFaceSilhouette(
  vtkPolyData* input, vtkRenderer* renderer)
{
  auto lines = vtkSmartPointer<vtkFaceSilhouetteLines>::New();
  VtkErrorLog::Instance().Watch(lines);
  lines->SetInputData(input);
  lines->SetRenderer(renderer);
  return lines;
}

} // namespace

// Edges drawn over an unlit white fill, in one pass: the fill hides the
// edges behind the mesh without the z-fighting of a separate hidden-line pass.
void ShowEdges(vtkActor* actor, const double color[3])
{
  vtkProperty* property = actor->GetProperty();
  property->SetRepresentationToSurface();
  property->SetColor(White[0], White[1], White[2]);
  property->LightingOff();
  property->EdgeVisibilityOn();
  property->SetEdgeColor(color[0], color[1], color[2]);
  property->SetLineWidth(1.0);
}

void ShadeAsSurface(vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  property->SetColor(LightGrey[0], LightGrey[1], LightGrey[2]);
  property->SetInterpolationToPhong();
  property->SetSpecular(0.2);
  property->SetSpecularPower(20.0);
}

namespace
{

// Whether every pixel of the captured image is the background's colour
// (nothing drawn; a mesh filling the whole image is one colour too).
bool IsBackgroundOnly(vtkImageData* image, const double background[3])
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  auto* bytes = vtkUnsignedCharArray::SafeDownCast(scalars);
  if (!bytes || bytes->GetNumberOfTuples() == 0 || bytes->GetNumberOfComponents() < 3)
  {
    return false;
  }
  const int components = bytes->GetNumberOfComponents();
  const unsigned char* values = bytes->GetPointer(0);
  for (vtkIdType i = 0; i < bytes->GetNumberOfValues(); ++i)
  {
    const int c = static_cast<int>(i % components);
    if (c < 3 && std::abs(values[i] - 255.0 * background[c]) > 1.0)
    {
      return false;
    }
  }
  return true;
}

} // namespace

bool WriteWindowPng(vtkRenderWindow* window, const std::string& path, FileBatch* batch)
{
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  // An offscreen window keeps the frame just rendered; rendering it again
  // would count as a frame in a viewer's frame rate.
  capture->SetShouldRerender(!window->GetOffScreenRendering());
  capture->Update();
  vtkRenderer* first = window->GetRenderers()->GetFirstRenderer();
  const bool blank = first && IsBackgroundOnly(capture->GetOutput(), first->GetBackground());
  vtkNew<vtkPNGWriter> writer;
  errors.Watch(writer);
  writer->SetInputConnection(capture->GetOutputPort());
  writer->WriteToMemoryOn(); // our own file writing says why it fails, in one line
  writer->Write();
  errors.ThrowIfErrors("cannot write '" + path + "'");
  vtkUnsignedCharArray* png = writer->GetResult();
  if (!png || png->GetNumberOfValues() == 0)
  {
    throw RuntimeError("cannot write '" + path + "': VTK's PNG writer gave no image");
  }
  std::string bytes(reinterpret_cast<const char*>(png->GetPointer(0)),
    static_cast<std::size_t>(png->GetNumberOfValues()));
  if (batch)
  {
    batch->Add(path, bytes);
  }
  else
  {
    WriteFileAtomically(path, bytes);
  }
  return blank;
}

namespace
{

// The visible pieces of a line drawing's lines: the smoothed silhouette and
// the creases and borders of the smoothed surface, against that surface; or
// (unsmoothed) the face-based silhouette and the input's creases and
// borders, against the input (vtkSilhouetteLineVisibility).
vtkSmartPointer<vtkSilhouetteLineVisibility> MakeVisibleLines(
  vtkRenderer* renderer, vtkSilhouetteSmoothingFilter* filter, vtkPolyData* input, bool smoothed)
{
  auto edges = vtkSmartPointer<vtkCreaseAndBorderLines>::New();
  VtkErrorLog::Instance().Watch(edges);
  auto drawing = vtkSmartPointer<vtkAppendPolyData>::New();
  auto visible = vtkSmartPointer<vtkSilhouetteLineVisibility>::New();
  VtkErrorLog::Instance().Watch(visible);
  // A silhouette within a pixel of the surface's outline is drawn: a
  // smoothed surface's flat triangles can stand a pixel or two beyond the
  // curve and cut gaps into a drawing's outline (the Wuson's back).
  visible->SetOutlinePixels(1.0);
  // Where the outline is concave, the surface's front facets can stand
  // beyond the curve and hide it: their edge is drawn where no line covers
  // it (within 1.5 px, or alongside within 4).
  visible->SetOutlineGapPixels(4.0);
  // One vertex where the filter made one: with --weld-tolerance, the near
  // copies an exporter left would otherwise cut the surface, and the sliver
  // triangles between them would draw creases.
  edges->SetWeldTolerance(filter->GetWeldCoincidentPoints() ? filter->GetWeldTolerance() : 0.0);
  if (smoothed)
  {
    // The smoothed surface marks its creases by a normal per side.
    edges->SetInputConnection(filter->GetOutputPort(0));
    drawing->AddInputConnection(filter->GetOutputPort(1));
    visible->SetSurfaceConnection(filter->GetOutputPort(0));
  }
  else
  {
    // The input's creases: by its own point normals, or without them by the
    // angle the filter finds creases at.
    edges->SetInputData(input);
    edges->SetFeatureAngle(
      filter->GetFeatureEdgeDetection() ? filter->GetFeatureAngle() : filter->GetFlatCreaseAngle());
    // The face-based silhouette lines, already chained into polylines, so
    // the brushes run along whole strokes.
    drawing->AddInputConnection(MakeFaceSilhouette(input, renderer)->GetOutputPort());
    visible->SetSurfaceData(input);
  }
  drawing->AddInputConnection(edges->GetOutputPort());
  visible->SetInputConnection(drawing->GetOutputPort());
  visible->SetRenderer(renderer);
  visible->PassHiddenLinesOff();
  return visible;
}

vtkSmartPointer<vtkPolyDataAlgorithm> MakeStrokes(vtkRenderer* renderer,
  vtkSilhouetteSmoothingFilter* filter, vtkPolyData* input, RenderStyle style, bool smoothed)
{
  auto strokes = vtkSmartPointer<vtkStylizedStrokeFilter>::New();
  VtkErrorLog::Instance().Watch(strokes);
  // Brushes run along the visible pieces only.
  strokes->SetInputConnection(MakeVisibleLines(renderer, filter, input, smoothed)->GetOutputPort());
  strokes->SetCamera(renderer->GetActiveCamera());
  // Per brush, as fractions of the silhouette's size: high frequency for
  // charcoal, low frequency for lazy, low magnitude for hand, high for rough
  // (the paper's Table 1).
  switch (style)
  {
    case RenderStyle::Lazy:
      strokes->SetBrushToLazy();
      strokes->SetAmplitude(0.012);
      strokes->SetWavelength(0.1);
      break;
    case RenderStyle::Hand:
      strokes->SetBrushToHand();
      strokes->SetAmplitude(0.004);
      strokes->SetWavelength(0.03);
      break;
    case RenderStyle::Rough:
      strokes->SetBrushToRough();
      strokes->SetAmplitude(0.025);
      strokes->SetSpacing(0.004);
      break;
    case RenderStyle::Charcoal:
    default:
      strokes->SetBrushToCharcoal();
      strokes->SetAmplitude(0.004);
      strokes->SetWavelength(0.006);
      break;
  }
  return strokes;
}

} // namespace

void AddStyleActors(vtkRenderer* renderer, vtkSilhouetteSmoothingFilter* filter, vtkPolyData* input,
  RenderStyle style, bool smoothed, bool hiddenLines, vtkSilhouetteSmoothingMapper* mapper)
{
  switch (style)
  {
    case RenderStyle::Shaded:
    {
      if (smoothed && mapper)
      {
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        ShadeAsSurface(actor);
        renderer->AddActor(actor);
        break;
      }
      vtkSmartPointer<vtkActor> actor = smoothed
        ? MakeActor(filter->GetOutputPort(0))
        : MakeActor(InputWithShadingNormals(input, filter));
      ShadeAsSurface(actor);
      renderer->AddActor(actor);
      break;
    }
    case RenderStyle::Wireframe:
    {
      vtkSmartPointer<vtkActor> actor =
        smoothed ? MakeActor(filter->GetOutputPort(0)) : MakeActor(input);
      ShowEdges(actor, Black);
      renderer->AddActor(actor);
      break;
    }
    case RenderStyle::NewGeometry:
    {
      if (!smoothed)
      {
        vtkSmartPointer<vtkActor> actor = MakeActor(input);
        ShowEdges(actor, DarkGrey);
        renderer->AddActor(actor);
        break;
      }
      // Two actors, so each can have its edge colour; the red one is drawn
      // last and wins the edges both share. The kept and the made triangles
      // are selected in the pipeline, so a viewer's follow its camera.
      for (const bool made : { false, true })
      {
        vtkNew<vtkThreshold> select;
        select->SetInputConnection(filter->GetOutputPort(0));
        select->SetInputArrayToProcess(
          0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "NewGeometry");
        select->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
        select->SetLowerThreshold(made ? 0.5 : -0.5);
        select->SetUpperThreshold(made ? 255.0 : 0.5);
        vtkNew<vtkDataSetMapper> mapper;
        mapper->SetInputConnection(select->GetOutputPort());
        mapper->ScalarVisibilityOff();
        vtkNew<vtkActor> actor;
        actor->SetMapper(mapper);
        ShowEdges(actor, made ? Red : DarkGrey);
        renderer->AddActor(actor);
      }
      break;
    }
    case RenderStyle::Lines:
    {
      vtkSmartPointer<vtkSilhouetteLineVisibility> lines =
        MakeVisibleLines(renderer, filter, input, smoothed);
      if (!hiddenLines)
      {
        AddBlackLines(renderer, MakeActor(lines->GetOutputPort()));
        break;
      }
      // The hidden pieces too, light grey and dashed (4 px drawn, 3 left
      // out) for the camera as it is now (render's view is fixed), under
      // the visible ones.
      lines->PassHiddenLinesOn();
      lines->Update();
      vtkNew<vtkPolyDataMapper> dashMapper;
      dashMapper->SetInputData(HiddenPiecesAsDashes(lines->GetOutput(), renderer, 4.0, 3.0));
      vtkNew<vtkActor> dashes;
      dashes->SetMapper(dashMapper);
      dashes->GetProperty()->SetColor(0.6, 0.6, 0.6);
      dashes->GetProperty()->SetLineWidth(1.5);
      dashes->GetProperty()->LightingOff();
      renderer->AddActor(dashes);
      vtkNew<vtkThreshold> visibleOnly;
      visibleOnly->SetInputConnection(lines->GetOutputPort());
      visibleOnly->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Visible");
      visibleOnly->SetLowerThreshold(1.0);
      visibleOnly->SetUpperThreshold(1.0);
      visibleOnly->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
      vtkNew<vtkDataSetMapper> visibleMapper;
      visibleMapper->SetInputConnection(visibleOnly->GetOutputPort());
      visibleMapper->ScalarVisibilityOff();
      vtkNew<vtkActor> actor;
      actor->SetMapper(visibleMapper);
      AddBlackLines(renderer, actor);
      break;
    }
    case RenderStyle::Charcoal:
    case RenderStyle::Lazy:
    case RenderStyle::Hand:
    case RenderStyle::Rough:
    {
      vtkSmartPointer<vtkPolyDataAlgorithm> strokes =
        MakeStrokes(renderer, filter, input, style, smoothed);
      AddBlackLines(renderer, MakeActor(strokes->GetOutputPort()));
      break;
    }
  }
}

OffscreenView MakeOffscreenView(const std::array<int, 2>& size)
{
  OffscreenView view;
  view.Window = vtkSmartPointer<vtkRenderWindow>::New();
  view.Window->SetOffScreenRendering(1);
  view.Window->SetMultiSamples(0); // deterministic images
  view.Window->SetSize(size[0], size[1]);
  view.Renderer = vtkSmartPointer<vtkRenderer>::New();
  view.Renderer->SetBackground(White[0], White[1], White[2]);
  view.Window->AddRenderer(view.Renderer);
  return view;
}

void CheckImageOutputPath(const std::string& path)
{
  if (LowercaseExtension(path) != ".png")
  {
    throw UsageError("cannot write '" + path + "': the image must be a .png file");
  }
  RequireOutputDirectory(path);
}

bool IsLineStyle(RenderStyle style)
{
  return style != RenderStyle::Shaded && style != RenderStyle::Wireframe &&
    style != RenderStyle::NewGeometry;
}

void CheckPdfPageSize(const std::array<int, 2>& size)
{
  // PDF's smallest page is 3 by 3 units (points); a pixel is 0.75 pt.
  if (size[0] < 4 || size[1] < 4)
  {
    throw UsageError("a PDF drawing's page is at least 3 pt on each side: --size 4x4 or more, "
                     "not " +
      std::to_string(size[0]) + "x" + std::to_string(size[1]));
  }
}

void CheckRenderOutputPath(const RenderOptions& options)
{
  const bool lineStyle = IsLineStyle(options.Style);
  if (LowercaseExtension(options.Output) == ".pdf")
  {
    CheckPdfPageSize(options.Camera.ViewportSize);
  }
  if (!IsVectorDrawingPath(options.Output))
  {
    if (LowercaseExtension(options.Output) != ".png")
    {
      throw UsageError("cannot write '" + options.Output +
        "': the image must be a .png file, or an .svg or .pdf drawing with a line style");
    }
    if (options.WidthByDepth)
    {
      throw UsageError("--width-by-depth needs an .svg or .pdf drawing; '" + options.Output +
        "' is a PNG image, whose lines have one width");
    }
    if (options.JoinLines)
    {
      throw UsageError("--join-lines needs an .svg or .pdf drawing; '" + options.Output +
        "' is a PNG image, which has no paths to join");
    }
    if (options.HiddenLines && options.Style != RenderStyle::Lines)
    {
      throw UsageError("--hidden dashed draws the hidden lines of '--style lines' in a PNG "
                       "image (of any line style in an .svg or .pdf drawing), not of '" +
        std::string(NameOf(options.Style)) + "'");
    }
  }
  else if (!lineStyle)
  {
    throw UsageError("cannot write '" + options.Output +
      "': a drawing (.svg or .pdf) needs a line style "
      "(lines, charcoal, lazy, hand or rough), not '" +
      NameOf(options.Style) + "'");
  }
  RequireOutputDirectory(options.Output);
}

void RequireDisplay()
{
  if (ActiveRenderBackend() != RenderBackend::X)
  {
    return; // OSMesa, or VTK's own offscreen window: no display needed
  }
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    throw RuntimeError("render needs an X display and DISPLAY is not set; run it under "
                       "'xvfb-run -a'");
  }
}

bool RenderToPng(const OffscreenView& view, vtkSilhouetteSmoothingFilter* filter,
  vtkPolyData* input, const RenderOptions& options, FileBatch* batch)
{
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkNew<vtkSilhouetteSmoothingMapper> mapper;
  vtkSilhouetteSmoothingMapper* drawnBy = nullptr;
  if (options.Style == RenderStyle::Shaded && !options.NoSmoothing)
  {
    drawnBy = mapper;
    // Smoothed while it renders, with the same settings (the filter's run
    // gives the figures): the image is the filter's output's, pixel for
    // pixel (module.TestSmoothingMapper). So the mapper smooths sub-pixel
    // silhouettes too, as the filter does; a still image has no frame rate
    // to keep.
    mapper->SetInputData(input);
    mapper->ScalarVisibilityOff();
    ApplySmoothingOptions(mapper->GetSmoothingFilter(), options.Camera);
    mapper->GetSmoothingFilter()->SkipSubpixelSmoothingOff();
    errors.Watch(mapper->GetSmoothingFilter());
  }
  AddStyleActors(view.Renderer, filter, input, options.Style, !options.NoSmoothing,
    options.HiddenLines, drawnBy);
  // Clip on what is drawn: the smoothed silhouette bulges past the input's bounds.
  view.Renderer->ResetCameraClippingRange();

  view.Window->Render();
  errors.ThrowIfErrors("rendering failed");

  return WriteWindowPng(view.Window, options.Output, batch);
}

bool RenderToDrawing(const OffscreenView& view, vtkSilhouetteSmoothingFilter* filter,
  vtkPolyData* input, const RenderOptions& options, FileBatch* batch)
{
  VtkErrorLog& errors = VtkErrorLog::Instance();
  errors.Clear();
  vtkRenderer* renderer = view.Renderer;
  const bool smoothed = !options.NoSmoothing;
  vtkSmartPointer<vtkPolyDataAlgorithm> drawn;
  if (options.Style == RenderStyle::Lines)
  {
    drawn = MakeVisibleLines(renderer, filter, input, smoothed);
  }
  else
  {
    drawn = MakeStrokes(renderer, filter, input, options.Style, smoothed);
  }
  drawn->Update();
  errors.ThrowIfErrors("drawing failed");
  std::vector<DrawnLine> lines = ProjectLines(drawn->GetOutput(), renderer, false);
  if (options.HiddenLines)
  {
    vtkSmartPointer<vtkSilhouetteLineVisibility> all =
      MakeVisibleLines(renderer, filter, input, smoothed);
    all->PassHiddenLinesOn();
    all->Update();
    errors.ThrowIfErrors("drawing failed");
    for (DrawnLine& line : ProjectLines(all->GetOutput(), renderer, true))
    {
      lines.push_back(std::move(line));
    }
  }
  DrawingStyle style;
  style.Width = options.Camera.ViewportSize[0];
  style.Height = options.Camera.ViewportSize[1];
  style.WidthByDepth = options.WidthByDepth;
  style.JoinLines = options.JoinLines;
  style.ReferenceDepth = renderer->GetActiveCamera()->GetDistance();
  // The whole command line, every option that shaped the drawing with it
  // (the input and style alone left out --hidden, --width-by-depth, --size...).
  style.Title = options.CommandText;
  // Blank: no visible line crosses the image (a line through it may have
  // no point in it).
  std::size_t visiblePaths = 0;
  const std::string document = VectorDocument(options.Output, lines, style, &visiblePaths);
  const bool blank = visiblePaths == 0;
  if (batch)
  {
    batch->Add(options.Output, document);
  }
  else
  {
    WriteFileAtomically(options.Output, document);
  }
  return blank;
}

} // namespace cli
