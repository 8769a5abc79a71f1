// The viewer's overlay: the status text and figures, the key help and the
// tolerance slider (Viewer.h).
#include "Viewer.h"

#include "CliErrors.h"
#include "Figures.h"
#include "MeshIO.h"
#include "Rendering.h"
#include "RenderingBackend.h"
#include "Smoothing.h"
#include "TextFormat.h"
#include "VtkErrorLog.h"

#include "EvaluationModels.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkPolyData.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSilhouetteSmoothingFilter.h>
#include <vtkSilhouetteSmoothingMapper.h>
#include <vtkSliderRepresentation2D.h>
#include <vtkSliderWidget.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkViewDependentLevelOfDetail.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace cli
{

void Viewer::BuildOverlay(bool withWidget)
{
  const int fontSize = std::max(11, this->Options.Camera.ViewportSize[1] / 48);
  this->Status = vtkSmartPointer<vtkTextActor>::New();
  vtkTextProperty* status = this->Status->GetTextProperty();
  status->SetFontSize(fontSize);
  status->SetColor(0, 0, 0);
  status->SetVerticalJustificationToTop();
  status->SetBackgroundColor(1, 1, 1);
  status->SetBackgroundOpacity(0.75);
  this->Status->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Status->SetPosition(0.01, 0.99);
  this->OverlayRenderer->AddViewProp(this->Status);

  this->Help = vtkSmartPointer<vtkTextActor>::New();
  std::string help = ViewerKeysHelp();
  help.pop_back(); // no empty last line
  this->Help->SetInput(help.c_str());
  vtkTextProperty* helpText = this->Help->GetTextProperty();
  helpText->SetFontSize(fontSize);
  helpText->SetFontFamilyToCourier(); // the columns line up
  helpText->SetColor(0, 0, 0);
  helpText->SetVerticalJustificationToBottom();
  helpText->SetBackgroundColor(1.0, 1.0, 0.9);
  helpText->SetBackgroundOpacity(0.9);
  helpText->SetFrame(1);
  helpText->SetFrameColor(0.5, 0.5, 0.5);
  this->Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Help->SetPosition(0.01, 0.02);
  this->Help->SetVisibility(this->ShowHelp);
  this->OverlayRenderer->AddViewProp(this->Help);

  this->FineLabel = vtkSmartPointer<vtkTextActor>::New();
  vtkTextProperty* label = this->FineLabel->GetTextProperty();
  label->SetFontSize(fontSize);
  label->SetColor(0, 0, 0);
  label->SetJustificationToRight();
  label->SetVerticalJustificationToTop();
  this->FineLabel->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->FineLabel->SetPosition(0.99, 0.99);

  auto slider = vtkSmartPointer<vtkSliderRepresentation2D>::New();
  slider->SetMinimumValue(MinimumSliderTolerance);
  slider->SetMaximumValue(MaximumSliderTolerance);
  slider->SetValue(this->Filter->GetTolerance());
  slider->SetTitleText("tolerance (px)");
  slider->SetLabelFormat("%.2f");
  slider->GetPoint1Coordinate()->SetCoordinateSystemToNormalizedDisplay();
  slider->GetPoint1Coordinate()->SetValue(0.70, 0.07);
  slider->GetPoint2Coordinate()->SetCoordinateSystemToNormalizedDisplay();
  slider->GetPoint2Coordinate()->SetValue(0.96, 0.07);
  slider->SetSliderLength(0.02);
  slider->SetSliderWidth(0.03);
  slider->SetTubeWidth(0.006);
  slider->SetEndCapLength(0.008);
  slider->SetEndCapWidth(0.03);
  slider->SetTitleHeight(0.03);
  slider->SetLabelHeight(0.025);
  // VTK's defaults are white, for dark backgrounds.
  slider->GetTitleProperty()->SetColor(0, 0, 0);
  slider->GetTitleProperty()->ShadowOff();
  slider->GetTitleProperty()->BoldOff();
  slider->GetLabelProperty()->SetColor(0, 0, 0);
  slider->GetLabelProperty()->ShadowOff();
  slider->GetTubeProperty()->SetColor(0.55, 0.55, 0.55);
  slider->GetCapProperty()->SetColor(0.35, 0.35, 0.35);
  slider->GetSliderProperty()->SetColor(0.15, 0.35, 0.75);
  slider->GetSelectedProperty()->SetColor(0.9, 0.1, 0.1);
  this->SliderRepresentation = slider;

  if (withWidget)
  {
    this->Slider = vtkSmartPointer<vtkSliderWidget>::New();
    this->Slider->SetInteractor(this->Interactor);
    this->Slider->SetRepresentation(slider);
    this->Slider->SetDefaultRenderer(this->OverlayRenderer);
    this->Slider->SetCurrentRenderer(this->OverlayRenderer);
    this->Slider->SetAnimationModeToJump();
    this->Slider->KeyPressActivationOff(); // 'i' would switch it off
    this->Slider->AddObserver(vtkCommand::InteractionEvent, this, &Viewer::OnSliderMoved);
    this->Slider->AddObserver(vtkCommand::EndInteractionEvent, this, &Viewer::OnSliderReleased);
  }
  else
  {
    // No interactor to drive a widget: draw the representation alone.
    slider->SetRenderer(this->OverlayRenderer);
    slider->BuildRepresentation();
    this->OverlayRenderer->AddViewProp(slider);
  }
}

void Viewer::OnOverlayRenderStart()
{
  // The overlay layer renders after the views, so the figures are this frame's.
  if (this->Status)
  {
    this->Status->SetInput(this->StatusText().c_str());
  }
}

void Viewer::OnSliderMoved()
{
  this->Filter->SetTolerance(this->SliderRepresentation->GetValue());
  this->SmoothMapper->GetSmoothingFilter()->SetTolerance(this->SliderRepresentation->GetValue());
}

void Viewer::OnSliderReleased()
{
  if (this->RunMode == Mode::Playback)
  {
    this->Window->Render();
    this->ReportStep("slider");
  }
}

double Viewer::FramesPerSecond() const
{
  if (this->FrameEnds.size() < 2)
  {
    return 0.0;
  }
  const double seconds =
    std::chrono::duration<double>(this->FrameEnds.back() - this->FrameEnds.front()).count();
  return seconds > 0.0 ? (this->FrameEnds.size() - 1) / seconds : 0.0;
}

ViewerFigures Viewer::CurrentFigures() const
{
  ViewerFigures figures;
  figures.InputTriangles = this->Lod ? this->Mesh->GetNumberOfPolys() : this->InputTriangles;
  if (this->UsesMapper())
  {
    const vtkSilhouetteSmoothingMapper* mapper = this->SmoothMapper;
    figures.OutputTriangles =
      figures.InputTriangles - mapper->GetReplacedTriangleCount() + mapper->GetPatchTriangleCount();
    figures.SilhouetteTriangles = mapper->GetSilhouetteTriangleCount();
    figures.NewTriangles = mapper->GetNewTriangleCount();
    figures.SubpixelTriangles = mapper->GetSubpixelTriangleCount();
    figures.SubpixelFeatureSegments = mapper->GetSubpixelFeatureSegmentCount();
    figures.FilterMilliseconds = 1000.0 * mapper->GetLastPrepareSeconds();
    figures.RenderMilliseconds = 1000.0 * this->MainRenderer->GetLastRenderTimeInSeconds();
    return figures;
  }
  if (this->Smoothing)
  {
    vtkPolyData* output = this->Filter->GetOutput();
    figures.OutputTriangles = FieldCount(output, "OutputTriangleCount");
    figures.SilhouetteTriangles = FieldCount(output, "SilhouetteTriangleCount");
    figures.NewTriangles = FieldCount(output, "NewTriangleCount");
  }
  else
  {
    figures.OutputTriangles = figures.InputTriangles;
  }
  figures.FilterMilliseconds = this->FilterRanInLastFrame ? this->LastFilterMilliseconds : 0.0;
  figures.RenderMilliseconds = 1000.0 * this->MainRenderer->GetLastRenderTimeInSeconds();
  return figures;
}

std::string Viewer::StyleName() const
{
  return NameOf(this->CurrentStyle);
}

std::string Viewer::StatusText() const
{
  // Short lines: in the side-by-side view the status has half the window.
  const ViewerFigures figures = this->CurrentFigures();
  const bool parallel = this->MainRenderer->GetActiveCamera()->GetParallelProjection() != 0;
  std::ostringstream text;
  text << this->MeshName << "\n"
       << "smoothing " << OnOff(this->Smoothing) << "; " << this->StyleName() << "; "
       << (parallel ? "parallel" : "perspective") << "\n";
  text << "triangles in " << Grouped(figures.InputTriangles) << ", out "
       << Grouped(figures.OutputTriangles) << "\n";
  if (this->Lod)
  {
    text << "level of detail of " << Grouped(this->InputTriangles) << "\n";
  }
  if (this->Smoothing)
  {
    text << "silhouette " << Grouped(figures.SilhouetteTriangles) << ", new "
         << Grouped(figures.NewTriangles);
    if (figures.SubpixelTriangles > 0)
    {
      // A fine mesh's silhouette can be all of it: "silhouette 0" alone
      // would read as none found.
      text << "; " << Grouped(figures.SubpixelTriangles) << " below the tolerance, kept";
    }
    if (figures.SubpixelFeatureSegments > 0)
    {
      text << "; " << Grouped(figures.SubpixelFeatureSegments) << " crease segments straight";
    }
    text << "\n";
  }
  else
  {
    text << "(the filter is off)\n";
  }
  text << "tolerance " << Fixed(this->Filter->GetTolerance(), 2) << " px (+ -, slider)";
  if (!this->Options.NoTimes)
  {
    // Wall time between frames, so it counts everything a frame costs.
    const double fps = this->FramesPerSecond();
    text << "\n"
         << (fps > 0.0 ? Fixed(fps, 1) : std::string("-")) << " frames/s (wall time, "
         << (this->FrameEnds.empty() ? 0 : this->FrameEnds.size() - 1) << " frames)";
    text << "\nrender " << Fixed(1000.0 * this->MainRenderer->GetLastRenderTimeInSeconds(), 1)
         << " ms (renderer's own)";
    if (this->UsesMapper())
    {
      // The last render that smoothed: a redraw of the same view (the
      // overlay's own, say) reuses the patch and costs next to nothing.
      text << "\nsmoothing " << Fixed(1000.0 * this->SmoothMapper->GetLastSmoothingSeconds(), 2)
           << " ms (mapper, last view change)";
    }
    else if (this->Smoothing)
    {
      text << "\nfilter " << Fixed(this->LastFilterMilliseconds, 2) << " ms (last run)";
    }
  }
  if (!this->Message.empty())
  {
    text << "\n" << this->Message;
  }
  if (!this->ShowHelp)
  {
    text << "\nh: help";
  }
  return text.str();
}

} // namespace cli
