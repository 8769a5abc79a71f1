#include "vtkSilhouetteCompositeMapper.h"

#include "vtkActor.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkDataSetAttributes.h"
#include "vtkHardwareSelector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteSmoothingMapper.h"
#include "vtkUnsignedCharArray.h"

vtkStandardNewMacro(vtkSilhouetteCompositeMapper);

namespace
{

// Every parameter of the smoothing (the filter's own, not the view's: the
// mapper takes that from the renderer). Setters that get the value they hold
// leave the MTime alone, so an unchanged parameter costs nothing.
void CopySettings(vtkSilhouetteSmoothingFilter* from, vtkSilhouetteSmoothingFilter* to)
{
  to->SetTolerance(from->GetTolerance());
  to->SetMinimumSamples(from->GetMinimumSamples());
  to->SetMaximumSamples(from->GetMaximumSamples());
  to->SetNewPointBudget(from->GetNewPointBudget());
  to->SetSamplingRule(from->GetSamplingRule());
  to->SetPerturbVertices(from->GetPerturbVertices());
  to->SetFoldPrevention(from->GetFoldPrevention());
  to->SetFeatureLines(from->GetFeatureLines());
  to->SetFeatureEdgeDetection(from->GetFeatureEdgeDetection());
  to->SetFeatureAngle(from->GetFeatureAngle());
  to->SetFlatCreaseDetection(from->GetFlatCreaseDetection());
  to->SetFlatCreaseAngle(from->GetFlatCreaseAngle());
  to->SetNormalSeamFeatures(from->GetNormalSeamFeatures());
  to->SetWeldCoincidentPoints(from->GetWeldCoincidentPoints());
  to->SetWeldTolerance(from->GetWeldTolerance());
  to->SetConsistentOrientation(from->GetConsistentOrientation());
  to->SetNormalEstimation(from->GetNormalEstimation());
  to->SetVisibilityMethod(from->GetVisibilityMethod());
}

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
  vtkMTimeType CopiedMapperTime = 0;
  vtkMTimeType CopiedSettingsTime = 0;
  // The leaf's ghost cells, counted when it changes.
  vtkPolyData* Counted = nullptr;
  vtkMTimeType CountedTime = 0;
  vtkIdType GhostCells = 0;

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

vtkSilhouetteCompositeMapper::vtkSilhouetteCompositeMapper() = default;

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
  std::map<unsigned int, std::unique_ptr<Leaf>> used;
  unsigned int flatIndex = 0;
  this->RenderLeaf(ren, act, input, flatIndex, true, used);
  // Leaves gone or hidden: their buffers go.
  for (auto& leaf : this->Leaves)
  {
    leaf.second->Mapper->ReleaseGraphicsResources(ren->GetRenderWindow());
  }
  this->Leaves.swap(used);
}

// Walks the tree as vtkCompositePolyDataMapper2::BuildRenderValues does, so
// that the flat indices and the inherited block visibility are the same.
void vtkSilhouetteCompositeMapper::RenderLeaf(vtkRenderer* ren, vtkActor* act, vtkDataObject* dobj,
  unsigned int& flatIndex, bool visible, std::map<unsigned int, std::unique_ptr<Leaf>>& used)
{
  vtkCompositeDataDisplayAttributes* attributes = this->GetCompositeDataDisplayAttributes();
  if (attributes && attributes->HasBlockVisibility(dobj))
  {
    visible = attributes->GetBlockVisibility(dobj);
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
        this->RenderLeaf(ren, act, child, flatIndex, visible, used);
      }
    }
    return;
  }
  vtkPolyData* pd = vtkPolyData::SafeDownCast(dobj);
  if (!visible || !pd || !pd->GetPoints() || pd->GetNumberOfPoints() == 0)
  {
    return;
  }
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
    mapper->SetStatic(1);
    leaf->CopiedMapperTime = mapperTime;
  }
  const vtkMTimeType settingsTime = this->Settings->GetMTime();
  if (settingsTime != leaf->CopiedSettingsTime)
  {
    CopySettings(this->Settings, mapper->GetSmoothingFilter());
    leaf->CopiedSettingsTime = settingsTime;
  }
  mapper->SetSmoothing(this->Smoothing);
  // Ghost cells included: the leaf's mapper never draws them but smooths
  // with them (normals, adjacency), so pieces meet as the whole would.
  if (mapper->GetInput() != pd)
  {
    mapper->SetInputData(pd);
  }
  mapper->Render(ren, act); // Static: straight to RenderPiece
  this->ReplacedTriangleCount += mapper->GetReplacedTriangleCount();
  this->PatchTriangleCount += mapper->GetPatchTriangleCount();
  ++this->RenderedLeaves;
  const vtkIdType ghosts = leaf->Ghosts(pd);
  this->DrawnCells += pd->GetNumberOfCells() - ghosts;
  this->SkippedGhostCells += ghosts;
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
