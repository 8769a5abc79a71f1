#include "vtkSilhouetteSmoothingRepresentation.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkSelection.h"
#include "vtkSilhouetteCompositeMapper.h"
#include "vtkSilhouetteSmoothingFilter.h"

vtkStandardNewMacro(vtkSilhouetteSmoothingRepresentation);

vtkSilhouetteSmoothingRepresentation::vtkSilhouetteSmoothingRepresentation()
{
  // The superclasses' mappers are replaced (as vtkSurfaceLICRepresentation
  // and the Representation plugin example do), with what
  // vtkGeometryRepresentation's constructor set up on its own: the
  // selection's id arrays, the block attributes (one set for the full
  // resolution, one for LOD, which UpdateBlockAttributes fills) and the
  // selection of the full-resolution mapper.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->BackfaceMapper->Delete();
  this->LODBackfaceMapper->Delete();

  vtkSilhouetteCompositeMapper* mapper = vtkSilhouetteCompositeMapper::New();
  mapper->SetProcessIdArrayName("vtkProcessId");
  mapper->SetCompositeIdArrayName("vtkCompositeIndex");
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  mapper->SetCompositeDataDisplayAttributes(attributes);
  vtkNew<vtkSelection> selection;
  mapper->SetSelection(selection);
  this->Mapper = mapper;
  this->SetArrayIdNames(nullptr, nullptr); // vtkOriginalPointIds, vtkOriginalCellIds

  vtkSilhouetteCompositeMapper* lodMapper = vtkSilhouetteCompositeMapper::New();
  vtkNew<vtkCompositeDataDisplayAttributes> lodAttributes;
  lodMapper->SetCompositeDataDisplayAttributes(lodAttributes);
  this->LODMapper = lodMapper;

  // The back faces, when drawn apart (BackfaceRepresentation), get the same
  // outline as the front faces.
  this->BackfaceMapper = vtkSilhouetteCompositeMapper::New();
  this->LODBackfaceMapper = vtkSilhouetteCompositeMapper::New();

  // Actor->SetMapper / SetLODMapper, BackfaceActor's too.
  this->SetupDefaults();
}

vtkSilhouetteSmoothingRepresentation::~vtkSilhouetteSmoothingRepresentation() = default;

vtkSilhouetteCompositeMapper* vtkSilhouetteSmoothingRepresentation::FullMapper()
{
  return vtkSilhouetteCompositeMapper::SafeDownCast(this->Mapper);
}

template<typename F>
void vtkSilhouetteSmoothingRepresentation::ForEachMapper(F&& f)
{
  for (vtkMapper* m :
    { this->Mapper, this->LODMapper, this->BackfaceMapper, this->LODBackfaceMapper })
  {
    if (auto mapper = vtkSilhouetteCompositeMapper::SafeDownCast(m))
    {
      f(mapper->GetSmoothingFilter());
    }
  }
}

void vtkSilhouetteSmoothingRepresentation::UpdateSmoothingSwitches()
{
  const bool full = this->SilhouetteSmoothing;
  const bool lod = this->SilhouetteSmoothing && this->SmoothLOD;
  if (auto m = vtkSilhouetteCompositeMapper::SafeDownCast(this->Mapper))
  {
    m->SetSmoothing(full);
  }
  if (auto m = vtkSilhouetteCompositeMapper::SafeDownCast(this->BackfaceMapper))
  {
    m->SetSmoothing(full);
  }
  if (auto m = vtkSilhouetteCompositeMapper::SafeDownCast(this->LODMapper))
  {
    m->SetSmoothing(lod);
  }
  if (auto m = vtkSilhouetteCompositeMapper::SafeDownCast(this->LODBackfaceMapper))
  {
    m->SetSmoothing(lod);
  }
}

void vtkSilhouetteSmoothingRepresentation::SetSilhouetteSmoothing(bool smoothing)
{
  this->SilhouetteSmoothing = smoothing;
  this->UpdateSmoothingSwitches();
}

void vtkSilhouetteSmoothingRepresentation::SetSilhouetteSmoothLOD(bool smoothLOD)
{
  this->SmoothLOD = smoothLOD;
  this->UpdateSmoothingSwitches();
}

// The first mapper's filter takes the value (and warns, once, when it
// clamps it); the others take what it kept.
#define SILHOUETTE_FORWARD(name, type)                                                             \
  void vtkSilhouetteSmoothingRepresentation::SetSilhouette##name(type value)                       \
  {                                                                                                \
    vtkSilhouetteSmoothingFilter* first = nullptr;                                                 \
    this->ForEachMapper([value, &first](vtkSilhouetteSmoothingFilter* f) {                         \
      if (!first)                                                                                  \
      {                                                                                            \
        first = f;                                                                                 \
        f->Set##name(value);                                                                       \
      }                                                                                            \
      else                                                                                         \
      {                                                                                            \
        f->Set##name(first->Get##name());                                                          \
      }                                                                                            \
    });                                                                                            \
  }

SILHOUETTE_FORWARD(Tolerance, double)
SILHOUETTE_FORWARD(MinimumSamples, int)
SILHOUETTE_FORWARD(MaximumSamples, int)
SILHOUETTE_FORWARD(NewPointBudget, double)
SILHOUETTE_FORWARD(SamplingRule, int)
SILHOUETTE_FORWARD(PerturbVertices, bool)
SILHOUETTE_FORWARD(FoldPrevention, bool)
SILHOUETTE_FORWARD(KeepApexesPointed, bool)
SILHOUETTE_FORWARD(FeatureLines, bool)
SILHOUETTE_FORWARD(FeatureEdgeDetection, bool)
SILHOUETTE_FORWARD(FeatureAngle, double)
SILHOUETTE_FORWARD(FlatCreaseDetection, bool)
SILHOUETTE_FORWARD(FlatCreaseAngle, double)
SILHOUETTE_FORWARD(NormalSeamFeatures, bool)
SILHOUETTE_FORWARD(WeldCoincidentPoints, bool)
SILHOUETTE_FORWARD(WeldTolerance, double)
SILHOUETTE_FORWARD(ConsistentOrientation, bool)
SILHOUETTE_FORWARD(NormalEstimation, int)
SILHOUETTE_FORWARD(VisibilityMethod, int)

#undef SILHOUETTE_FORWARD

int vtkSilhouetteSmoothingRepresentation::GetSilhouetteReplacedTriangles()
{
  auto m = this->FullMapper();
  return m ? static_cast<int>(m->GetReplacedTriangleCount()) : 0;
}

int vtkSilhouetteSmoothingRepresentation::GetSilhouettePatchTriangles()
{
  auto m = this->FullMapper();
  return m ? static_cast<int>(m->GetPatchTriangleCount()) : 0;
}

int vtkSilhouetteSmoothingRepresentation::GetSilhouetteRenderedBlocks()
{
  auto m = this->FullMapper();
  return m ? m->GetNumberOfRenderedLeaves() : 0;
}

int vtkSilhouetteSmoothingRepresentation::GetSilhouetteDrawnCells()
{
  auto m = this->FullMapper();
  return m ? static_cast<int>(m->GetDrawnCellCount()) : 0;
}

int vtkSilhouetteSmoothingRepresentation::GetSilhouetteSkippedGhostCells()
{
  auto m = this->FullMapper();
  return m ? static_cast<int>(m->GetSkippedGhostCellCount()) : 0;
}

void vtkSilhouetteSmoothingRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SilhouetteSmoothing: " << (this->SilhouetteSmoothing ? "On" : "Off") << "\n";
  os << indent << "SmoothLOD: " << (this->SmoothLOD ? "On" : "Off") << "\n";
}
