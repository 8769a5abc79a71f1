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
#include "vtkRenderer.h"
#include "vtkSilhouettePatchedMapper.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSilhouetteViewTracker.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <iterator>
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

} // namespace

struct vtkSilhouetteSmoothingMapper::Internals
{
  vtkNew<vtkSilhouetteSmoothingFilter> Smoother;
  vtkNew<vtkSilhouettePatchedMapper> Drawn;
  vtkNew<vtkPolyData> Base;
  vtkNew<vtkPolyData> Changes;
  vtkNew<vtkIdTypeArray> Replaced;

  // The base mesh is of this input, at this time, with these settings.
  vtkPolyData* BaseInput = nullptr;
  vtkMTimeType BaseInputTime = 0;
  vtkMTimeType BaseSettingsTime = 0;
  bool BaseReady = false;
  // The base mesh's ghost triangles (indices among its polygons): another
  // piece's to draw, so hidden in every frame.
  std::vector<vtkIdType> Ghosts;
  // The patch is for the view of this time (and this base mesh, and
  // Smoothing); the view is compared by value, as the filters compare it.
  vtkSilhouetteFilterSupport::ViewTracker View;
  vtkMTimeType PatchViewTime = 0;
  bool HavePatch = false;
  bool PatchSmoothed = false;
  // Whether the patch drawn is Changes (not the base mesh alone).
  bool PatchDrawsChanges = false;
  vtkMTimeType CopiedSettingsTime = 0;

  void UpdateBase(vtkSilhouetteSmoothingMapper* self, vtkPolyData* input)
  {
    const vtkMTimeType settings = this->Smoother->GetMTime();
    if (input == this->BaseInput && input->GetMTime() == this->BaseInputTime &&
      settings == this->BaseSettingsTime)
    {
      return;
    }
    this->BaseInput = input;
    this->BaseInputTime = input->GetMTime();
    this->BaseSettingsTime = settings;
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
    this->HavePatch = false;
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
  }

  // False when the view (and the smoothing switch) are the last patch's:
  // the patch is kept as it is.
  bool UpdatePatch(
    vtkSilhouetteSmoothingMapper* self, vtkPolyData* input, vtkRenderer* ren, vtkActor* act)
  {
    const bool smooth = self->Smoothing && this->BaseReady;
    vtkCamera* camera = ren->GetActiveCamera();
    double model[16];
    vtkMatrix4x4::DeepCopy(model, act->GetMatrix());
    int width = 0, height = 0, x = 0, y = 0;
    ren->GetTiledSizeAndOrigin(&width, &height, &x, &y);
    const vtkMTimeType viewTime = this->View.Update(camera, model, { { width, height } });
    if (this->HavePatch && this->PatchSmoothed == smooth && viewTime == this->PatchViewTime)
    {
      return false;
    }
    this->PatchViewTime = viewTime;
    this->HavePatch = true;
    this->PatchSmoothed = smooth;
    this->PatchDrawsChanges = false;
    self->ReplacedTriangleCount = 0;
    self->PatchTriangleCount = 0;
    self->CulledTriangleCount = 0;
    self->SilhouetteTriangleCount = 0;
    self->NewTriangleCount = 0;
    if (!smooth || width <= 0 || height <= 0 ||
      !this->Smoother->BuildChanges(
        input, camera, model, width, height, this->Changes, this->Replaced))
    {
      this->Drawn->SetPatch(this->Ghosts, nullptr, nullptr, {});
      return true;
    }
    const vtkIdType* replaced = this->Replaced->GetPointer(0);
    std::vector<vtkIdType> hidden;
    std::set_union(replaced, replaced + this->Replaced->GetNumberOfValues(), this->Ghosts.begin(),
      this->Ghosts.end(), std::back_inserter(hidden));
    this->Drawn->SetPatch(hidden, this->Changes,
      vtkIdTypeArray::SafeDownCast(this->Changes->GetCellData()->GetArray("OriginalCellId")),
      PointSources(this->Changes));
    this->PatchDrawsChanges = true;
    self->ReplacedTriangleCount = this->Replaced->GetNumberOfValues();
    self->PatchTriangleCount = this->Changes->GetNumberOfPolys();
    vtkFieldData* figures = this->Changes->GetFieldData();
    if (vtkDataArray* culled = figures->GetArray("CulledTriangleCount"))
    {
      self->CulledTriangleCount = static_cast<vtkIdType>(culled->GetTuple1(0));
    }
    if (vtkDataArray* silhouette = figures->GetArray("SilhouetteTriangleCount"))
    {
      self->SilhouetteTriangleCount = static_cast<vtkIdType>(silhouette->GetTuple1(0));
    }
    if (vtkDataArray* made = this->Changes->GetCellData()->GetArray("NewGeometry"))
    {
      for (vtkIdType c = 0; c < made->GetNumberOfTuples(); ++c)
      {
        self->NewTriangleCount += made->GetTuple1(c) != 0.0 ? 1 : 0;
      }
    }
    return true;
  }
};

vtkSilhouetteSmoothingMapper::vtkSilhouetteSmoothingMapper()
  : Internal(new Internals)
{
  // What the view cannot show is not smoothed.
  this->Internal->Smoother->FrustumCullingOn();
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
  double* bounds = this->Superclass::GetBounds(); // the input's
  const Internals& internal = *this->Internal;
  vtkPolyData* input = this->GetInput();
  // The patch counts while smoothing is on and it was made for this input as
  // it is now (UpdateBase keeps the base mesh's input and time).
  const bool current = this->Smoothing && internal.HavePatch && internal.PatchDrawsChanges &&
    input && input == internal.BaseInput && input->GetMTime() == internal.BaseInputTime;
  if (!bounds || !current || internal.Changes->GetNumberOfPolys() == 0 ||
    !vtkMath::AreBoundsInitialized(bounds))
  {
    return bounds;
  }
  double patch[6];
  internal.Changes->GetBounds(patch);
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
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  Internals& internal = *this->Internal;
  internal.UpdateBase(this, input);
  // Colouring and clipping as this mapper's (vtkMapper's settings, not the
  // input).
  const vtkMTimeType settings = this->Superclass::GetMTime();
  if (settings != internal.CopiedSettingsTime)
  {
    internal.Drawn->vtkMapper::ShallowCopy(this);
    internal.Drawn->SetStatic(1);
    internal.CopiedSettingsTime = settings;
  }
  const bool smoothed = internal.UpdatePatch(this, input, ren, act);
  this->LastPrepareSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (smoothed)
  {
    this->LastSmoothingSeconds = this->LastPrepareSeconds;
  }
  internal.Drawn->RenderPiece(ren, act);
}

void vtkSilhouetteSmoothingMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Internal->Drawn->ReleaseGraphicsResources(win);
  this->Internal->HavePatch = false;
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
  os << indent << "SmoothingFilter:\n";
  this->Internal->Smoother->PrintSelf(os, indent.GetNextIndent());
}
