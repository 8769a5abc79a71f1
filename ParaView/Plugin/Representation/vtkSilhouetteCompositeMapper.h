/**
 * @class   vtkSilhouetteCompositeMapper
 * @brief   a vtkCompositePolyDataMapper2 that draws each leaf with a smooth outline
 *
 * The mapper of the Smooth Silhouette Surface representation. ParaView's
 * geometry representations always hand their mapper a vtkMultiBlockDataSet
 * and expect a vtkCompositePolyDataMapper2 (they set its block attributes,
 * id array names and selection). This one renders every visible leaf through
 * a vtkSilhouetteSmoothingMapper of its own, which smooths the leaf's
 * silhouette for the renderer's camera, viewport and the actor's matrix
 * while it renders.
 *
 * Settings: GetSmoothingFilter() holds the smoothing's parameters
 * (vtkSilhouetteSmoothingFilter's Tolerance, PerturbVertices, ...); they are
 * copied to the leaves' mappers when they change. They are kept apart from
 * this mapper's MTime: a mapper's MTime change makes ParaView and VTK rebuild
 * buffers, a parameter change only makes the leaves build their base mesh
 * again (the parameters that shape it) or smooth again.
 *
 * What differs from vtkCompositePolyDataMapper2:
 * - cells marked as ghosts (vtkGhostType with DUPLICATECELL or HIDDENCELL)
 *   are not drawn (the stock mapper of VTK 9.2 draws them): the leaf's
 *   vtkSilhouetteSmoothingMapper smooths with them and never draws them, so
 *   a mesh split across ranks with a ghost layer draws each cell once;
 * - block visibility, colour and opacity are honoured, inherited down the
 *   tree as the superclass does: a leaf with a block colour or opacity of
 *   its own is drawn with a copy of the actor's property that has them (the
 *   colour as the ambient and diffuse colour, with scalar colouring off for
 *   that leaf, as Surface draws it), a leaf whose opacity is below 1 or whose
 *   colours are not opaque (a colour map with opacity mapping) in the
 *   translucent pass and the others in the opaque pass;
 * - hardware selection passes are rendered by the superclass, that is with the
 *   leaves as they are (not smoothed): the ids ParaView needs
 *   (vtkOriginalCellIds/PointIds, vtkProcessId, vtkCompositeIndex, the block's
 *   flat index) are then exactly Surface's. A pick differs from Surface's
 *   only in the sliver between the coarse and the smooth outline.
 */
#ifndef vtkSilhouetteCompositeMapper_h
#define vtkSilhouetteCompositeMapper_h

#include "SilhouetteSmoothingParaViewSilhouetteRepresentationModule.h" // For export macro
#include "vtkCompositePolyDataMapper2.h"
#include "vtkNew.h"                       // For the settings
#include "vtkSilhouetteSmoothingFilter.h" // For the settings

#include <map>    // For the leaves
#include <memory> // For the leaves

class SILHOUETTESMOOTHINGPARAVIEWSILHOUETTEREPRESENTATION_EXPORT vtkSilhouetteCompositeMapper
  : public vtkCompositePolyDataMapper2
{
public:
  static vtkSilhouetteCompositeMapper* New();
  vtkTypeMacro(vtkSilhouetteCompositeMapper, vtkCompositePolyDataMapper2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The smoothing's parameters (never run as a filter): copied to every
   * leaf's vtkSilhouetteSmoothingMapper before it renders.
   */
  vtkSilhouetteSmoothingFilter* GetSmoothingFilter();

  ///@{
  /**
   * Smooth the silhouettes (default on). Off: each leaf is drawn as it is
   * (with the smoothing's shading normals). Does not change the MTime.
   */
  void SetSmoothing(bool smoothing) { this->Smoothing = smoothing; }
  bool GetSmoothing() const { return this->Smoothing; }
  ///@}

  ///@{
  /**
   * Summed over the leaves, each as of its last render (in the opaque or the
   * translucent pass, whichever draws it): the input triangles replaced, the
   * triangles drawn in their place, the leaves drawn, their cells drawn
   * (ghost cells not counted) and their ghost cells (not drawn).
   */
  vtkIdType GetReplacedTriangleCount() const { return this->ReplacedTriangleCount; }
  vtkIdType GetPatchTriangleCount() const { return this->PatchTriangleCount; }
  int GetNumberOfRenderedLeaves() const { return this->RenderedLeaves; }
  vtkIdType GetDrawnCellCount() const { return this->DrawnCells; }
  vtkIdType GetSkippedGhostCellCount() const { return this->SkippedGhostCells; }
  ///@}

  /**
   * How many times the leaves' mappers smoothed a view, since each was made
   * (summed over the leaves drawn last): unchanged while neither the view nor
   * the geometry changes (new values on a still mesh, a time series of
   * them, smooth nothing again).
   */
  vtkIdType GetSmoothingRunCount() const { return this->SmoothingRunCount; }

  void Render(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkSilhouetteCompositeMapper();
  ~vtkSilhouetteCompositeMapper() override;

  bool Smoothing = true;
  vtkIdType ReplacedTriangleCount = 0;
  vtkIdType PatchTriangleCount = 0;
  int RenderedLeaves = 0;
  vtkIdType DrawnCells = 0;
  vtkIdType SkippedGhostCells = 0;
  vtkIdType SmoothingRunCount = 0;

private:
  vtkSilhouetteCompositeMapper(const vtkSilhouetteCompositeMapper&) = delete;
  void operator=(const vtkSilhouetteCompositeMapper&) = delete;

  struct Leaf;
  /// What a block passes down to its children (vtkCompositeDataDisplayAttributes).
  struct BlockLook
  {
    bool Visible = true;
    bool HasColor = false;
    double Color[3] = { 1.0, 1.0, 1.0 };
    bool HasOpacity = false;
    double Opacity = 1.0;
  };
  void RenderLeaf(vtkRenderer* ren, vtkActor* act, vtkDataObject* dobj, unsigned int& flatIndex,
    BlockLook look, std::map<unsigned int, std::unique_ptr<Leaf>>& used);
  vtkActor* ActorForLeaf(vtkActor* act, Leaf& leaf, const BlockLook& look);

  // The pass being rendered, and whether the actor renders the other one.
  bool TranslucentPass = false;
  bool OtherPassDrawn = false;
  vtkNew<vtkSilhouetteSmoothingFilter> Settings;
  std::map<unsigned int, std::unique_ptr<Leaf>> Leaves; // by flat index
};

#endif
