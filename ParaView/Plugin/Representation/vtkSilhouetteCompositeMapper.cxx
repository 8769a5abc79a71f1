#include "vtkSilhouetteCompositeMapper.h"

#include "vtkActor.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkDataSetAttributes.h"
#include "vtkHardwareSelector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingMapper.h"
#include "vtkUnsignedCharArray.h"

vtkStandardNewMacro(vtkSilhouetteCompositeMapper);

namespace
{

// Cells flagged as ghosts not to be drawn: copies owned by another piece
// (DUPLICATECELL) or hidden ones (HIDDENCELL).
vtkIdType CountGhostCells(vtkPolyData* pd)
{
  vtkUnsignedCharArray* ghosts = pd->GetCellGhostArray();
  if (!ghosts)
  {
    return 0;
  }
  const unsigned char skip = vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
  const vtkIdType n = ghosts->GetNumberOfValues();
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    count += (ghosts->GetValue(i) & skip) != 0 ? 1 : 0;
  }
  return count;
}

} // namespace

struct vtkSilhouetteCompositeMapper::Leaf
{
  vtkNew<vtkSilhouetteSmoothingMapper> Mapper;
  // For a leaf with a colour or opacity of its own: the actor it is drawn
  // with (the real one's matrix, texture and pass) and its property (the
  // real one's, copied when that changes, with the block's look).
  vtkNew<vtkActor> Actor;
  vtkNew<vtkProperty> Property;
  vtkProperty* CopiedProperty = nullptr;
  vtkMTimeType CopiedPropertyTime = 0;
  vtkMTimeType CopiedMapperTime = 0;
  vtkMTimeType CopiedSettingsTime = 0;
  // The leaf's ghost cells, counted when it changes.
  vtkPolyData* Counted = nullptr;
  vtkMTimeType CountedTime = 0;
  vtkIdType GhostCells = 0;
  // Its cells drawn at its last render (ghost cells not counted).
  vtkIdType DrawnCells = 0;

  vtkIdType Ghosts(vtkPolyData* pd)
  {
    if (pd != this->Counted || pd->GetMTime() != this->CountedTime)
    {
      this->Counted = pd;
      this->CountedTime = pd->GetMTime();
      this->GhostCells = CountGhostCells(pd);
    }
    return this->GhostCells;
  }
};

vtkSilhouetteCompositeMapper::vtkSilhouetteCompositeMapper()
{
  // The leaf mappers' own defaults: what the view cannot show, or would
  // show moved by less than the tolerance, is not smoothed.
  this->Settings->FrustumCullingOn();
  this->Settings->SkipSubpixelSmoothingOn();
}

vtkSilhouetteCompositeMapper::~vtkSilhouetteCompositeMapper() = default;

vtkSilhouetteSmoothingFilter* vtkSilhouetteCompositeMapper::GetSmoothingFilter()
{
  return this->Settings;
}

void vtkSilhouetteCompositeMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  // Selection passes: the superclass, with ParaView's id arrays and the
  // blocks' flat indices (see the class documentation).
  if (ren->GetSelector())
  {
    this->Superclass::Render(ren, act);
    return;
  }
  this->ReplacedTriangleCount = 0;
  this->PatchTriangleCount = 0;
  this->RenderedLeaves = 0;
  this->DrawnCells = 0;
  this->SkippedGhostCells = 0;
  this->SmoothingRunCount = 0;
  if (ren->GetRenderWindow()->CheckAbortStatus() || !this->GetInputAlgorithm())
  {
    return;
  }
  if (!this->Static)
  {
    this->InvokeEvent(vtkCommand::StartEvent, nullptr);
    this->GetInputAlgorithm()->Update();
    this->InvokeEvent(vtkCommand::EndEvent, nullptr);
  }
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  if (!input)
  {
    return;
  }
  // Each leaf in its pass: translucent ones in the translucent pass, the
  // others in the opaque one. The actor asks for a pass only when the
  // superclass says it has geometry for it (block opacities counted); an
  // actor that skips one (its property translucent, ForceOpaque, ...) has
  // every leaf drawn in the other.
  this->TranslucentPass = act->IsRenderingTranslucentPolygonalGeometry();
  this->OtherPassDrawn = this->TranslucentPass ? act->HasOpaqueGeometry() != 0
                                               : act->HasTranslucentPolygonalGeometry() != 0;
  std::map<unsigned int, std::unique_ptr<Leaf>> used;
  unsigned int flatIndex = 0;
  this->RenderLeaf(ren, act, input, flatIndex, BlockLook(), used);
  // Leaves gone or hidden: their buffers go.
  for (auto& leaf : this->Leaves)
  {
    leaf.second->Mapper->ReleaseGraphicsResources(ren->GetRenderWindow());
  }
  this->Leaves.swap(used);
  // The figures of every leaf's last render, in whichever pass it was drawn.
  for (const auto& entry : this->Leaves)
  {
    const Leaf& leaf = *entry.second;
    this->ReplacedTriangleCount += leaf.Mapper->GetReplacedTriangleCount();
    this->PatchTriangleCount += leaf.Mapper->GetPatchTriangleCount();
    ++this->RenderedLeaves;
    this->DrawnCells += leaf.DrawnCells;
    this->SkippedGhostCells += leaf.GhostCells;
    this->SmoothingRunCount += leaf.Mapper->GetSmoothingRunCount();
  }
}

// Walks the tree as vtkCompositePolyDataMapper2::BuildRenderValues does, so
// that the flat indices and the inherited block visibility, colour and
// opacity are the same.
void vtkSilhouetteCompositeMapper::RenderLeaf(vtkRenderer* ren, vtkActor* act, vtkDataObject* dobj,
  unsigned int& flatIndex, BlockLook look, std::map<unsigned int, std::unique_ptr<Leaf>>& used)
{
  vtkCompositeDataDisplayAttributes* attributes = this->GetCompositeDataDisplayAttributes();
  if (attributes && attributes->HasBlockVisibility(dobj))
  {
    look.Visible = attributes->GetBlockVisibility(dobj);
  }
  if (attributes && attributes->HasBlockColor(dobj))
  {
    look.HasColor = true;
    attributes->GetBlockColor(dobj, look.Color);
  }
  if (attributes && attributes->HasBlockOpacity(dobj))
  {
    look.HasOpacity = true;
    look.Opacity = attributes->GetBlockOpacity(dobj);
  }
  const unsigned int index = flatIndex++;
  if (auto tree = vtkDataObjectTree::SafeDownCast(dobj))
  {
    for (vtkDataObject* child : vtk::Range(tree, vtk::DataObjectTreeOptions::None))
    {
      if (!child)
      {
        ++flatIndex;
      }
      else
      {
        this->RenderLeaf(ren, act, child, flatIndex, look, used);
      }
    }
    return;
  }
  vtkPolyData* pd = vtkPolyData::SafeDownCast(dobj);
  if (!look.Visible || !pd || !pd->GetPoints() || pd->GetNumberOfPoints() == 0)
  {
    return;
  }
  const double opacity = look.HasOpacity ? look.Opacity : act->GetProperty()->GetOpacity();
  std::unique_ptr<Leaf>& leaf = used[index];
  auto known = this->Leaves.find(index);
  if (known != this->Leaves.end())
  {
    leaf = std::move(known->second);
    this->Leaves.erase(known);
  }
  else
  {
    leaf.reset(new Leaf);
  }
  vtkSilhouetteSmoothingMapper* mapper = leaf->Mapper;
  // Colouring and clipping as this mapper's (as CopyMapperValuesToHelper
  // does; vtkMapper's settings only, not the input).
  const vtkMTimeType mapperTime = this->GetMTime();
  if (mapperTime != leaf->CopiedMapperTime)
  {
    mapper->vtkMapper::ShallowCopy(this);
    // vtkPolyDataMapper's own, which vtkMapper::ShallowCopy leaves out (the
    // display's Seamless U and V).
    mapper->SetSeamlessU(this->GetSeamlessU());
    mapper->SetSeamlessV(this->GetSeamlessV());
    mapper->SetStatic(1);
    leaf->CopiedMapperTime = mapperTime;
  }
  // A block's own colour wins over scalar colouring, as on Surface.
  mapper->SetScalarVisibility(this->GetScalarVisibility() && !look.HasColor);
  const vtkMTimeType settingsTime = this->Settings->GetMTime();
  if (settingsTime != leaf->CopiedSettingsTime)
  {
    mapper->GetSmoothingFilter()->CopySmoothingSettings(this->Settings);
    leaf->CopiedSettingsTime = settingsTime;
  }
  mapper->SetSmoothing(this->Smoothing);
  // Ghost cells included: the leaf's mapper never draws them but smooths
  // with them (normals, adjacency), so pieces meet as the whole would.
  if (mapper->GetInput() != pd)
  {
    mapper->SetInputData(pd);
  }
  // Translucent: by the block's or the actor's opacity, or by its colours'
  // (a colour map with opacity mapping).
  const bool translucent =
    opacity < 1.0 || (mapper->GetScalarVisibility() && mapper->HasTranslucentPolygonalGeometry());
  if (translucent != this->TranslucentPass && this->OtherPassDrawn)
  {
    return; // the other pass's leaf: kept as it is (its buffers, its patch)
  }
  mapper->Render(ren, this->ActorForLeaf(act, *leaf, look)); // Static: straight to RenderPiece
  const vtkIdType ghosts = leaf->Ghosts(pd);
  leaf->DrawnCells = pd->GetNumberOfCells() - ghosts;
}

// The actor itself, or for a leaf with a colour or opacity of its own, the
// leaf's actor: the real one's state (matrix, texture, pass) with a copy of
// its property that has the block's look. Setters leave the MTime alone when
// the value is the same, so an unchanged look rebuilds nothing.
vtkActor* vtkSilhouetteCompositeMapper::ActorForLeaf(
  vtkActor* act, Leaf& leaf, const BlockLook& look)
{
  if (!look.HasColor && !look.HasOpacity)
  {
    return act;
  }
  vtkProperty* property = act->GetProperty();
  if (property != leaf.CopiedProperty || property->GetMTime() != leaf.CopiedPropertyTime)
  {
    leaf.Property->DeepCopy(property);
    leaf.CopiedProperty = property;
    leaf.CopiedPropertyTime = property->GetMTime();
  }
  // The block's colour, or the actor's again when the block lost its own.
  const double* ambient = look.HasColor ? look.Color : property->GetAmbientColor();
  const double* diffuse = look.HasColor ? look.Color : property->GetDiffuseColor();
  leaf.Property->SetAmbientColor(ambient[0], ambient[1], ambient[2]);
  leaf.Property->SetDiffuseColor(diffuse[0], diffuse[1], diffuse[2]);
  leaf.Property->SetOpacity(look.HasOpacity ? look.Opacity : property->GetOpacity());
  leaf.Actor->ShallowCopy(act);
  leaf.Actor->SetMapper(nullptr); // this mapper holds the leaf: no cycle
  leaf.Actor->SetProperty(leaf.Property);
  leaf.Actor->SetIsRenderingTranslucentPolygonalGeometry(
    act->IsRenderingTranslucentPolygonalGeometry());
  return leaf.Actor;
}

void vtkSilhouetteCompositeMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  for (auto& leaf : this->Leaves)
  {
    leaf.second->Mapper->ReleaseGraphicsResources(win);
  }
  this->Superclass::ReleaseGraphicsResources(win);
}

void vtkSilhouetteCompositeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Smoothing: " << (this->Smoothing ? "On" : "Off") << "\n";
  os << indent << "Leaves: " << this->Leaves.size() << "\n";
  os << indent << "SmoothingFilter:\n";
  this->Settings->PrintSelf(os, indent.GetNextIndent());
}
