#include "vtkSilhouetteSmoothingMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteAttributeSources.h"
#include "vtkSilhouetteFittingArrays.h"
#include "vtkSilhouettePatchedMapper.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSilhouetteViewTracker.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSilhouetteSmoothingMapper);

namespace
{

// For each point of the patch, an input point whose process id it shares:
// its own input point, else one of a triangle it is on.
std::vector<vtkIdType> PointSources(vtkPolyData* patch)
{
  const vtkIdType n = patch->GetNumberOfPoints();
  std::vector<vtkIdType> sources(static_cast<std::size_t>(n), -1);
  vtkDataArray* original = patch->GetPointData()->GetArray("OriginalPointId");
  if (!original)
  {
    std::fill(sources.begin(), sources.end(), 0);
    return sources;
  }
  for (vtkIdType p = 0; p < n; ++p)
  {
    sources[static_cast<std::size_t>(p)] = static_cast<vtkIdType>(original->GetTuple1(p));
  }
  auto it = vtk::TakeSmartPointer(patch->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(size, ids);
    vtkIdType known = -1;
    for (vtkIdType k = 0; k < size && known < 0; ++k)
    {
      known = sources[static_cast<std::size_t>(ids[k])];
    }
    for (vtkIdType k = 0; k < size && known >= 0; ++k)
    {
      vtkIdType& s = sources[static_cast<std::size_t>(ids[k])];
      s = s >= 0 ? s : known;
    }
  }
  std::replace(sources.begin(), sources.end(), vtkIdType{ -1 }, vtkIdType{ 0 });
  return sources;
}

// Whether every cell of `mesh` names points it has: VTK's OpenGL mappers
// read the points a cell names unchecked, and crash on a missing one.
bool CellsNameTheirPoints(vtkPolyData* mesh)
{
  const vtkIdType points = mesh->GetNumberOfPoints();
  for (vtkCellArray* cells :
    { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType size = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(size, ids);
      if (std::any_of(ids, ids + size, [points](vtkIdType id) { return id < 0 || id >= points; }))
      {
        return false;
      }
    }
  }
  return true;
}

} // namespace

// One view's patch: what was smoothed for it, ready to hand to the drawing
// mapper again.
struct ViewPatch
{
  vtkNew<vtkPolyData> Changes;
  vtkNew<vtkIdTypeArray> Replaced;
  vtkSilhouetteFilterSupport::ViewTracker::Key View;
  bool Valid = false;
  bool Smoothed = false;
  // Whether the patch drawn is Changes (not the base mesh alone).
  bool DrawsChanges = false;
  std::vector<vtkIdType> Hidden;
  std::vector<vtkIdType> PointSources;
  // Where the patch's points and cells take their attributes from in the
  // input, and the smoothing's geometry time when it was made: while that
  // stays, an input whose other arrays change (new scalars on a still mesh)
  // refills the patch's arrays instead of smoothing again.
  vtkSilhouetteFilterSupport::AttributeSources Sources;
  vtkMTimeType GeometryTime = 0;
  // The figures the mapper reports for this view.
  vtkIdType ReplacedTriangles = 0;
  vtkIdType PatchTriangles = 0;
  vtkIdType CulledTriangles = 0;
  vtkIdType SubpixelTriangles = 0;
  vtkIdType SubpixelFeatureSegments = 0;
  vtkIdType FoldGuardRounds = 0;
  vtkIdType ReusedFallbacks = 0;
  vtkIdType SilhouetteTriangles = 0;
  vtkIdType NewTriangles = 0;
};

struct vtkSilhouetteSmoothingMapper::Internals
{
  vtkNew<vtkSilhouetteSmoothingFilter> Smoother;
  vtkNew<vtkSilhouettePatchedMapper> Drawn;
  vtkNew<vtkPolyData> Base;

  // The base mesh is of this input, at this time, with these settings.
  vtkPolyData* BaseInput = nullptr;
  vtkMTimeType BaseInputTime = 0;
  vtkMTimeType BaseSettingsTime = 0;
  bool BaseReady = false;
  // Whether the cells of this input, at this time, name their points: an
  // input that does not cannot even be drawn as it is.
  vtkPolyData* CheckedInput = nullptr;
  vtkMTimeType CheckedInputTime = 0;
  bool CheckedDrawable = true;

  // Reports an undrawable input once per input change.
  bool CellsDrawable(vtkSilhouetteSmoothingMapper* self, vtkPolyData* input)
  {
    if (input != this->CheckedInput || input->GetMTime() != this->CheckedInputTime)
    {
      this->CheckedInput = input;
      this->CheckedInputTime = input->GetMTime();
      this->CheckedDrawable = CellsNameTheirPoints(input);
      if (!this->CheckedDrawable)
      {
        vtkErrorWithObjectMacro(
          self, "The input's cells name points it does not have: it is not drawn.");
      }
    }
    return this->CheckedDrawable;
  }
  // The input without its arrays of the wrong length (the input itself when
  // they all fit): what is smoothed and drawn.
  vtkSilhouetteFilterSupport::FittingArrays Fitting;
  vtkPolyData* Usable = nullptr;
  // The base mesh's ghost triangles (indices among its polygons): another
  // piece's to draw, so hidden in every frame.
  std::vector<vtkIdType> Ghosts;
  // The patches of the last four views drawn (views compared by value, as
  // the filters compare them): stereo's two eyes, a shadow map's light and
  // the camera, renderers showing one actor, actors sharing this mapper
  // (each with its own matrix, drawn in turn in every pass of depth
  // peeling) each render without smoothing again while their views stay.
  // Patches[Current] is drawn; a new view replaces the one drawn longest
  // ago (LastDrawn: when each was last drawn, counted in patch updates).
  std::array<ViewPatch, 4> Patches;
  std::array<std::uint64_t, 4> LastDrawn{};
  std::uint64_t Updates = 0;
  std::size_t Current = 0;
  vtkMTimeType CopiedSettingsTime = 0;

  enum class PatchUpdate
  {
    Kept,     // the view drawn last
    Switched, // the other cached view
    Made      // smoothed anew
  };

  void Forget()
  {
    for (ViewPatch& patch : this->Patches)
    {
      patch.Valid = false;
    }
  }

  // Updates the base mesh for `input` and returns what is smoothed and
  // drawn: `input` without its arrays of the wrong length.
  vtkPolyData* UpdateBase(vtkSilhouetteSmoothingMapper* self, vtkPolyData* input)
  {
    const vtkMTimeType settings = this->Smoother->GetMTime();
    if (input == this->BaseInput && input->GetMTime() == this->BaseInputTime &&
      settings == this->BaseSettingsTime)
    {
      return this->Usable;
    }
    // With the same settings the patches may be kept (RefreshPatches), also
    // for another input object: a pipeline that makes its output anew each
    // update (a reader's time steps) gives new objects of the same geometry.
    const bool mayKeepPatches = settings == this->BaseSettingsTime && this->BaseReady;
    this->BaseInput = input;
    this->BaseInputTime = input->GetMTime();
    this->BaseSettingsTime = settings;
    std::string leftOut;
    this->Usable = this->Fitting.Of(input, leftOut);
    if (!leftOut.empty())
    {
      vtkWarningWithObjectMacro(self, << leftOut);
    }
    input = this->Usable;
    this->BaseReady = this->Smoother->BuildBaseMesh(input, this->Base) != 0;
    if (!this->BaseReady)
    {
      vtkWarningWithObjectMacro(
        self, "The input cannot be smoothed (see the error above): it is drawn as it is.");
    }
    this->Drawn->SetInputData(this->BaseReady ? this->Base.Get() : input);
    this->Base->Modified(); // refilled in place: the buffers are built again
    // Selection reports the input's cell ids for the base mesh's cells.
    this->Drawn->SetCellIdArrayName(this->BaseReady ? "OriginalCellId" : nullptr);
    this->Ghosts.clear();
    vtkPolyData* drawn = this->BaseReady ? this->Base.Get() : input;
    vtkUnsignedCharArray* ghosts = vtkArrayDownCast<vtkUnsignedCharArray>(
      drawn->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
    if (ghosts && ghosts->GetNumberOfValues() == drawn->GetNumberOfCells())
    {
      const unsigned char skip =
        vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
      const vtkIdType first = drawn->GetNumberOfVerts() + drawn->GetNumberOfLines();
      for (vtkIdType p = 0; p < drawn->GetNumberOfPolys(); ++p)
      {
        if ((ghosts->GetValue(first + p) & skip) != 0)
        {
          this->Ghosts.push_back(p);
        }
      }
    }
    if (mayKeepPatches && this->BaseReady)
    {
      this->RefreshPatches(self, input);
    }
    else
    {
      this->Forget();
    }
    return input;
  }

  // After a change of the input's arrays alone, the patches of the same
  // geometry take the new arrays; the others are forgotten. The patch drawn
  // is handed to the drawing mapper again.
  void RefreshPatches(vtkSilhouetteSmoothingMapper* self, vtkPolyData* input)
  {
    const vtkMTimeType geometry = this->Smoother->GetGeometryTime();
    for (ViewPatch& patch : this->Patches)
    {
      patch.Valid = patch.Valid && patch.GeometryTime == geometry &&
        (!patch.DrawsChanges ||
          vtkSilhouetteFilterSupport::RefillAttributes(input, patch.Sources, patch.Changes));
    }
    if (this->Patches[this->Current].Valid)
    {
      this->Show(self, this->Patches[this->Current]);
    }
  }

  // Hands `patch` to the drawing mapper and its figures to `self`.
  void Show(vtkSilhouetteSmoothingMapper* self, const ViewPatch& patch)
  {
    if (patch.DrawsChanges)
    {
      this->Drawn->SetPatch(patch.Hidden, patch.Changes,
        vtkIdTypeArray::SafeDownCast(patch.Changes->GetCellData()->GetArray("OriginalCellId")),
        patch.PointSources);
    }
    else
    {
      this->Drawn->SetPatch(this->Ghosts, nullptr, nullptr, {});
    }
    this->ReportFigures(self, patch);
  }

  // The frame's figures, those of the patch drawn.
  static void ReportFigures(vtkSilhouetteSmoothingMapper* self, const ViewPatch& patch)
  {
    self->ReplacedTriangleCount = patch.ReplacedTriangles;
    self->PatchTriangleCount = patch.PatchTriangles;
    self->CulledTriangleCount = patch.CulledTriangles;
    self->SubpixelTriangleCount = patch.SubpixelTriangles;
    self->SubpixelFeatureSegmentCount = patch.SubpixelFeatureSegments;
    self->FoldGuardRoundCount = patch.FoldGuardRounds;
    self->ReusedFallbackCount = patch.ReusedFallbacks;
    self->SilhouetteTriangleCount = patch.SilhouetteTriangles;
    self->NewTriangleCount = patch.NewTriangles;
  }

  // Smooths `input` for the view into `patch`.
  // `ren` and `prop` name the viewer whose frames follow one another.
  void Make(vtkSilhouetteSmoothingMapper* self, vtkPolyData* input, vtkRenderer* ren, vtkProp* prop,
    vtkCamera* camera, const double model[16], int width, int height, bool smooth, ViewPatch& patch)
  {
    patch.Valid = true;
    patch.Smoothed = smooth;
    patch.DrawsChanges = false;
    patch.ReplacedTriangles = patch.PatchTriangles = patch.CulledTriangles = 0;
    patch.SubpixelTriangles = patch.SubpixelFeatureSegments = 0;
    patch.FoldGuardRounds = patch.ReusedFallbacks = 0;
    patch.SilhouetteTriangles = patch.NewTriangles = 0;
    patch.GeometryTime = this->Smoother->GetGeometryTime();
    if (!smooth || width <= 0 || height <= 0)
    {
      return;
    }
    ++self->SmoothingRunCount;
    // The history of sub-pixel decisions is the renderer's and the prop's:
    // two renderers taking turns must not read each other's frames.
    if (!this->Smoother->BuildChanges(input, camera, model, width, height, patch.Changes,
          patch.Replaced, &patch.Sources, { { ren, prop } }))
    {
      return;
    }
    patch.GeometryTime = this->Smoother->GetGeometryTime();
    const vtkIdType* replaced = patch.Replaced->GetPointer(0);
    patch.Hidden.clear();
    std::set_union(replaced, replaced + patch.Replaced->GetNumberOfValues(), this->Ghosts.begin(),
      this->Ghosts.end(), std::back_inserter(patch.Hidden));
    patch.PointSources = PointSources(patch.Changes);
    patch.DrawsChanges = true;
    patch.ReplacedTriangles = patch.Replaced->GetNumberOfValues();
    patch.PatchTriangles = patch.Changes->GetNumberOfPolys();
    vtkFieldData* figures = patch.Changes->GetFieldData();
    if (vtkDataArray* culled = figures->GetArray("CulledTriangleCount"))
    {
      patch.CulledTriangles = static_cast<vtkIdType>(culled->GetTuple1(0));
    }
    if (vtkDataArray* subpixel = figures->GetArray("SubpixelTriangleCount"))
    {
      patch.SubpixelTriangles = static_cast<vtkIdType>(subpixel->GetTuple1(0));
    }
    if (vtkDataArray* straight = figures->GetArray("SubpixelFeatureSegmentCount"))
    {
      patch.SubpixelFeatureSegments = static_cast<vtkIdType>(straight->GetTuple1(0));
    }
    if (vtkDataArray* rounds = figures->GetArray("FoldGuardRoundCount"))
    {
      patch.FoldGuardRounds = static_cast<vtkIdType>(rounds->GetTuple1(0));
    }
    if (vtkDataArray* reused = figures->GetArray("ReusedFallbackCount"))
    {
      patch.ReusedFallbacks = static_cast<vtkIdType>(reused->GetTuple1(0));
    }
    if (vtkDataArray* silhouette = figures->GetArray("SilhouetteTriangleCount"))
    {
      patch.SilhouetteTriangles = static_cast<vtkIdType>(silhouette->GetTuple1(0));
    }
    if (vtkDataArray* made = patch.Changes->GetCellData()->GetArray("NewGeometry"))
    {
      for (vtkIdType c = 0; c < made->GetNumberOfTuples(); ++c)
      {
        patch.NewTriangles += made->GetTuple1(c) != 0.0 ? 1 : 0;
      }
    }
  }

  PatchUpdate UpdatePatch(
    vtkSilhouetteSmoothingMapper* self, vtkPolyData* input, vtkRenderer* ren, vtkActor* act)
  {
    // Points and wireframe draw the mesh as it is (the patched mapper
    // patches surfaces only): smoothing for them was work thrown away every
    // frame (a user's trial).
    const bool smooth =
      self->Smoothing && this->BaseReady && act->GetProperty()->GetRepresentation() == VTK_SURFACE;
    vtkCamera* camera = ren->GetActiveCamera();
    double model[16];
    vtkMatrix4x4::DeepCopy(model, act->GetMatrix());
    int width = 0, height = 0, x = 0, y = 0;
    ren->GetTiledSizeAndOrigin(&width, &height, &x, &y);
    using Tracker = vtkSilhouetteFilterSupport::ViewTracker;
    const Tracker::Key view = Tracker::KeyOf(camera, model, { { width, height } });
    ++this->Updates;
    for (std::size_t k = 0; k < this->Patches.size(); ++k)
    {
      // The drawn patch first: of two equal views, it is the one to keep.
      const std::size_t i = (this->Current + k) % this->Patches.size();
      const ViewPatch& patch = this->Patches[i];
      if (patch.Valid && patch.Smoothed == smooth && Tracker::SameView(patch.View, view))
      {
        this->LastDrawn[i] = this->Updates;
        if (i == this->Current)
        {
          // The figures again: a frame that drew nothing (an empty input
          // in between) cleared them.
          ReportFigures(self, patch);
          return PatchUpdate::Kept;
        }
        this->Current = i;
        this->Show(self, patch);
        return PatchUpdate::Switched;
      }
    }
    // A new view replaces the one drawn longest ago (an invalid one first).
    std::size_t oldest = 0;
    for (std::size_t i = 1; i < this->Patches.size(); ++i)
    {
      const bool older = this->Patches[oldest].Valid &&
        (!this->Patches[i].Valid || this->LastDrawn[i] < this->LastDrawn[oldest]);
      oldest = older ? i : oldest;
    }
    this->Current = oldest;
    this->LastDrawn[oldest] = this->Updates;
    ViewPatch& patch = this->Patches[this->Current];
    patch.View = view;
    this->Make(self, input, ren, act, camera, model, width, height, smooth, patch);
    this->Show(self, patch);
    return PatchUpdate::Made;
  }
};

vtkSilhouetteSmoothingMapper::vtkSilhouetteSmoothingMapper()
  : Internal(new Internals)
{
  // What the view cannot show is not smoothed, nor what it would show
  // moved by less than the tolerance.
  this->Internal->Smoother->FrustumCullingOn();
  this->Internal->Smoother->SkipSubpixelSmoothingOn();
}

vtkSilhouetteSmoothingMapper::~vtkSilhouetteSmoothingMapper() = default;

vtkSilhouetteSmoothingFilter* vtkSilhouetteSmoothingMapper::GetSmoothingFilter()
{
  return this->Internal->Smoother;
}

vtkMTimeType vtkSilhouetteSmoothingMapper::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Internal->Smoother->GetMTime());
}

double* vtkSilhouetteSmoothingMapper::GetBounds()
{
  // vtkPolyDataMapper's bounds are its cells', read unchecked: a cell that
  // names a missing point is read past the points' end.
  vtkPolyData* in = this->GetInput();
  if (in && !this->Static && this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  if (in && !this->Internal->CellsDrawable(this, in))
  {
    this->ClearFrameCounts();
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  double* bounds = this->Superclass::GetBounds(); // the input's
  if (!bounds || !vtkMath::AreBoundsInitialized(bounds))
  {
    // The renderer draws no prop without bounds, so RenderPiece never sees
    // this frame: the figures of the last one would stay.
    this->ClearFrameCounts();
    return bounds;
  }
  const Internals& internal = *this->Internal;
  vtkPolyData* input = this->GetInput();
  // The patch counts while smoothing is on and it was made for this input as
  // it is now (UpdateBase keeps the base mesh's input and time).
  const ViewPatch& drawn = internal.Patches[internal.Current];
  const bool current = this->Smoothing && drawn.Valid && drawn.DrawsChanges && input &&
    input == internal.BaseInput && input->GetMTime() == internal.BaseInputTime;
  if (!bounds || !current || drawn.Changes->GetNumberOfPolys() == 0 ||
    !vtkMath::AreBoundsInitialized(bounds))
  {
    return bounds;
  }
  double patch[6];
  drawn.Changes->GetBounds(patch);
  for (int axis = 0; axis < 3; ++axis)
  {
    bounds[2 * axis] = std::min(bounds[2 * axis], patch[2 * axis]);
    bounds[2 * axis + 1] = std::max(bounds[2 * axis + 1], patch[2 * axis + 1]);
  }
  return bounds;
}

void vtkSilhouetteSmoothingMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  vtkPolyData* input = this->GetInput();
  if (!input || input->GetNumberOfPoints() == 0 || !ren || !act)
  {
    this->ClearFrameCounts(); // nothing drawn, nothing smoothed
    return;
  }
  Internals& internal = *this->Internal;
  if (!internal.CellsDrawable(this, input))
  {
    this->ClearFrameCounts();
    return; // neither smoothed nor drawn as it is
  }
  const auto start = std::chrono::steady_clock::now();
  vtkPolyData* usable = internal.UpdateBase(this, input);
  // Colouring and clipping as this mapper's (vtkMapper's settings, not the
  // input).
  const vtkMTimeType settings = this->Superclass::GetMTime();
  if (settings != internal.CopiedSettingsTime)
  {
    internal.Drawn->vtkMapper::ShallowCopy(this);
    internal.Drawn->SetSeamlessU(this->SeamlessU); // vtkPolyDataMapper's, not vtkMapper's
    internal.Drawn->SetSeamlessV(this->SeamlessV);
    internal.Drawn->SetStatic(1);
    internal.CopiedSettingsTime = settings;
  }
  const bool smoothed =
    internal.UpdatePatch(this, usable, ren, act) == Internals::PatchUpdate::Made;
  this->LastPrepareSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (smoothed)
  {
    this->LastSmoothingSeconds = this->LastPrepareSeconds;
  }
  internal.Drawn->RenderPiece(ren, act);
  this->TimeToDraw = internal.Drawn->GetTimeToDraw(); // what vtkLODActor weighs
}

void vtkSilhouetteSmoothingMapper::ShallowCopy(vtkAbstractMapper* other)
{
  this->Superclass::ShallowCopy(other);
  if (auto* smoothing = vtkSilhouetteSmoothingMapper::SafeDownCast(other))
  {
    this->SetSmoothing(smoothing->GetSmoothing());
    this->Internal->Smoother->CopySmoothingSettings(smoothing->GetSmoothingFilter());
  }
}

void vtkSilhouetteSmoothingMapper::ClearFrameCounts()
{
  this->ReplacedTriangleCount = this->PatchTriangleCount = this->CulledTriangleCount = 0;
  this->SubpixelTriangleCount = this->SilhouetteTriangleCount = this->NewTriangleCount = 0;
  this->SubpixelFeatureSegmentCount = 0;
  this->FoldGuardRoundCount = 0;
  this->ReusedFallbackCount = 0;
}

void vtkSilhouetteSmoothingMapper::MapDataArrayToVertexAttribute(
  const char* vertexAttributeName, const char* dataArrayName, int fieldAssociation, int componentno)
{
  this->Internal->Drawn->MapDataArrayToVertexAttribute(
    vertexAttributeName, dataArrayName, fieldAssociation, componentno);
  this->Modified();
}

void vtkSilhouetteSmoothingMapper::MapDataArrayToMultiTextureAttribute(
  const char* textureName, const char* dataArrayName, int fieldAssociation, int componentno)
{
  this->Internal->Drawn->MapDataArrayToMultiTextureAttribute(
    textureName, dataArrayName, fieldAssociation, componentno);
  this->Modified();
}

void vtkSilhouetteSmoothingMapper::RemoveVertexAttributeMapping(const char* vertexAttributeName)
{
  this->Internal->Drawn->RemoveVertexAttributeMapping(vertexAttributeName);
  this->Modified();
}

void vtkSilhouetteSmoothingMapper::RemoveAllVertexAttributeMappings()
{
  this->Internal->Drawn->RemoveAllVertexAttributeMappings();
  this->Modified();
}

void vtkSilhouetteSmoothingMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Internal->Drawn->ReleaseGraphicsResources(win);
  this->Internal->Forget();
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkSilhouetteSmoothingMapper::ProcessSelectorPixelBuffers(
  vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop)
{
  this->Internal->Drawn->ProcessSelectorPixelBuffers(sel, pixeloffsets, prop);
}

void vtkSilhouetteSmoothingMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Smoothing: " << (this->Smoothing ? "On" : "Off") << "\n";
  os << indent << "ReplacedTriangleCount: " << this->ReplacedTriangleCount << "\n";
  os << indent << "PatchTriangleCount: " << this->PatchTriangleCount << "\n";
  os << indent << "CulledTriangleCount: " << this->CulledTriangleCount << "\n";
  os << indent << "SubpixelTriangleCount: " << this->SubpixelTriangleCount << "\n";
  os << indent << "SubpixelFeatureSegmentCount: " << this->SubpixelFeatureSegmentCount << "\n";
  os << indent << "SilhouetteTriangleCount: " << this->SilhouetteTriangleCount << "\n";
  os << indent << "NewTriangleCount: " << this->NewTriangleCount << "\n";
  os << indent << "FoldGuardRoundCount: " << this->FoldGuardRoundCount << "\n";
  os << indent << "ReusedFallbackCount: " << this->ReusedFallbackCount << "\n";
  os << indent << "SmoothingRunCount: " << this->SmoothingRunCount << "\n";
  os << indent << "LastPrepareSeconds: " << this->LastPrepareSeconds << "\n";
  os << indent << "LastSmoothingSeconds: " << this->LastSmoothingSeconds << "\n";
  os << indent << "SmoothingFilter:\n";
  this->Internal->Smoother->PrintSelf(os, indent.GetNextIndent());
}
