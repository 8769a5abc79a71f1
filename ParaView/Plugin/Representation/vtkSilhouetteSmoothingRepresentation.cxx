#include "vtkSilhouetteSmoothingRepresentation.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkPointData.h"
#include "vtkSelection.h"
#include "vtkSilhouetteCompositeMapper.h"
#include "vtkSilhouetteSmoothingFilter.h"
#include "vtkSmartPointer.h"

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
SILHOUETTE_FORWARD(ReuseFoldFallbacks, bool)
SILHOUETTE_FORWARD(KeepApexesPointed, bool)
SILHOUETTE_FORWARD(SkipSubpixelSmoothing, bool)
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

int vtkSilhouetteSmoothingRepresentation::GetSilhouetteSmoothingRuns()
{
  auto m = this->FullMapper();
  return m ? static_cast<int>(m->GetSmoothingRunCount()) : 0;
}

int vtkSilhouetteSmoothingRepresentation::GetSilhouetteSkippedGhostCells()
{
  auto m = this->FullMapper();
  return m ? static_cast<int>(m->GetSkippedGhostCellCount()) : 0;
}

int vtkSilhouetteSmoothingRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const int done = this->Superclass::RequestData(request, inputVector, outputVector);
  this->CheckNormalsPerPiece(vtkDataObject::GetData(inputVector[0], 0));
  return done;
}

void vtkSilhouetteSmoothingRepresentation::CheckNormalsPerPiece(vtkDataObject* input)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int processes = controller ? controller->GetNumberOfProcesses() : 1;
  if (!input || processes < 2)
  {
    this->NormalsPerPiece = false;
    return;
  }
  if (input->GetMTime() == this->NormalsCheckedTime)
  {
    return; // checked, and warned, for this data
  }
  this->NormalsCheckedTime = input->GetMTime();
  bool without = false;
  const auto check = [&without](vtkDataObject* data) {
    vtkDataSet* set = vtkDataSet::SafeDownCast(data);
    without = without || (set && set->GetNumberOfCells() > 0 && !set->GetPointData()->GetNormals());
  };
  if (vtkCompositeDataSet* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      check(it->GetCurrentDataObject());
    }
  }
  else
  {
    check(input);
  }
  this->NormalsPerPiece = without;
  if (without && this->SilhouetteSmoothing)
  {
    vtkWarningMacro("Smooth Silhouette Surface on "
      << processes
      << " processes: this piece of the data has no point normals, so the smoothing computes "
         "them for the piece alone, and where the data is split across processes the seams "
         "show as lines. Apply Generate Surface Normals (or give the data normals) first.");
  }
}

void vtkSilhouetteSmoothingRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SilhouetteSmoothing: " << (this->SilhouetteSmoothing ? "On" : "Off") << "\n";
  os << indent << "SmoothLOD: " << (this->SmoothLOD ? "On" : "Off") << "\n";
}
