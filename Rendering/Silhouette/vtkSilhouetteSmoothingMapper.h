/**
 * @class   vtkSilhouetteSmoothingMapper
 * @brief   draws a coarse triangle mesh with a smooth outline, smoothing its silhouette while it
 * renders
 *
 * Set a coarse mesh as input and the actor's outline is smooth in every
 * renderer it is added to: the mapper takes the camera, the viewport and
 * the actor's matrix while rendering, and smooths the silhouette for them
 * with vtkSilhouetteSmoothingFilter's method and settings
 * (GetSmoothingFilter(): Tolerance, PerturbVertices, FoldPrevention, ...;
 * FrustumCulling is on here, so silhouettes the view cannot show are not
 * smoothed, and so is SkipSubpixelSmoothing, so silhouettes whose smoothing
 * the view would show moved by less than Tolerance pixels are not: on a
 * mesh fine for the view a frame costs little more than finding the
 * silhouette). No SetRenderer or SetProp3D wiring is needed.
 *
 * What a frame costs is the silhouette, not the mesh. The mesh as the
 * smoothing sees it (the filter's BuildBaseMesh: the input's points and the
 * copies its smooth groups need, shading normals, point and cell data) is
 * uploaded once per change of the input or of the filter's settings. Per
 * view, the filter's BuildChanges gives the triangles re-meshed for the
 * view and what replaces them; the mapper hides those triangles in the
 * uploaded index buffer (degenerate triangles written over the ones that
 * changed since the last frame) and draws the replacements from a small
 * buffer of their own. The image is the filter's output drawn by a
 * vtkPolyDataMapper, but for rasterisation order (module test
 * TestSmoothingMapper), and but for what each view's frames take from the
 * frame before (the filter's SkipSubpixelSmoothing margin and
 * ReuseFoldFallbacks: a triangle that folds again may keep the fallback it
 * needed there). A change of the input's arrays alone (new scalars
 * on a still mesh) smooths nothing again: the mesh keeps its points and
 * normals, and each view's replacements take the new values as the
 * smoothing would have given them (module test TestSmoothingMapperUpdates).
 *
 * It colours as vtkPolyDataMapper does (scalar visibility and mode, lookup
 * table, colour mode, point and cell scalars, texture coordinates; the
 * vtkProperty, lighting and textures of the actor). Hardware selection
 * reports the input's cell ids, for the replacements too (the input cell
 * each came from); point selection picks the input's points on the mesh as
 * it is. Representations other than surface draw the mesh as it is, and
 * are not smoothed.
 *
 * Ghost cells (`vtkGhostType` with DUPLICATECELL or HIDDENCELL: another
 * piece's cells) are never re-meshed and never drawn; they count for the
 * normals and the adjacency.
 *
 * Smoothing off (SmoothingOff()) draws the base mesh alone: the coarse
 * outline, with the same shading normals.
 *
 * GetBounds, as a vtkPolyDataMapper's fed by the filter, holds what the last
 * rendered view drew: the input's bounds joined with those of that view's
 * smoothed triangles, which bulge beyond the coarse mesh (by up to 5% of
 * its size on an icosahedron). Before the first render, and after the input
 * changes, they are the input's.
 */
#ifndef vtkSilhouetteSmoothingMapper_h
#define vtkSilhouetteSmoothingMapper_h

#include "SilhouetteSmoothingRenderingSilhouetteModule.h" // For export macro
#include "vtkPolyDataMapper.h"

#include <memory> // For the internals

class vtkSilhouetteSmoothingFilter;

class SILHOUETTESMOOTHINGRENDERINGSILHOUETTE_EXPORT vtkSilhouetteSmoothingMapper
  : public vtkPolyDataMapper
{
public:
  static vtkSilhouetteSmoothingMapper* New();
  vtkTypeMacro(vtkSilhouetteSmoothingMapper, vtkPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The smoothing's settings live on this filter (it is never run as a
   * pipeline here: the mapper calls its BuildBaseMesh and BuildChanges).
   * Changing its settings changes the mapper's MTime.
   */
  vtkSilhouetteSmoothingFilter* GetSmoothingFilter();

  ///@{
  /**
   * Smooth the silhouette (default on). Off: the mesh as it is, with the
   * smoothing's shading normals.
   */
  vtkSetMacro(Smoothing, bool);
  vtkGetMacro(Smoothing, bool);
  vtkBooleanMacro(Smoothing, bool);
  ///@}

  ///@{
  /**
   * Of the last rendered frame: the input triangles re-meshed or moved, the
   * triangles drawn in their place, the silhouette triangles left as they
   * are because the view cannot show them (FrustumCulling), and those left
   * because their smoothing would move the image by less than the
   * tolerance (SkipSubpixelSmoothing).
   */
  vtkIdType GetReplacedTriangleCount() const { return this->ReplacedTriangleCount; }
  vtkIdType GetPatchTriangleCount() const { return this->PatchTriangleCount; }
  vtkIdType GetCulledTriangleCount() const { return this->CulledTriangleCount; }
  vtkIdType GetSubpixelTriangleCount() const { return this->SubpixelTriangleCount; }
  /// Curved feature segments (creases) drawn by their chords, their curves
  /// within the tolerance (SkipSubpixelSmoothing).
  vtkIdType GetSubpixelFeatureSegmentCount() const { return this->SubpixelFeatureSegmentCount; }
  /// The silhouette triangles re-meshed, and the triangles the re-meshing
  /// made (the patch without the kept triangles the perturbation moved):
  /// the filter's SilhouetteTriangleCount and NewTriangleCount.
  vtkIdType GetSilhouetteTriangleCount() const { return this->SilhouetteTriangleCount; }
  vtkIdType GetNewTriangleCount() const { return this->NewTriangleCount; }
  /// How many times the fold guard re-meshed the frame again, and how many
  /// fold fallbacks it took at once from this viewer's frame before (the
  /// smoothing filter's ReuseFoldFallbacks).
  vtkIdType GetFoldGuardRoundCount() const { return this->FoldGuardRoundCount; }
  vtkIdType GetReusedFallbackCount() const { return this->ReusedFallbackCount; }
  ///@}

  /**
   * Wall-clock seconds the last RenderPiece spent before drawing: the base
   * mesh when it had to be built again, and the frame's smoothing and patch
   * when the view changed (the patch's index-buffer update is part of the
   * draw: a few glBufferSubData calls over the triangles that changed).
   */
  double GetLastPrepareSeconds() const { return this->LastPrepareSeconds; }

  /**
   * Wall-clock seconds before drawing of the last RenderPiece that made its
   * patch again (the view, the input or Smoothing had changed): what a
   * camera move costs. A render
   * of an unchanged view reuses the patch, and GetLastPrepareSeconds is then
   * next to nothing; this keeps the figure of the last real work.
   */
  double GetLastSmoothingSeconds() const { return this->LastSmoothingSeconds; }

  /**
   * How many times the mapper has smoothed for a view since it was made.
   * It keeps the patches of the last four views it drew, compared by value
   * (stereo's two eyes, a shadow map's light and the camera, renderers
   * showing one actor, or actors sharing this mapper), so rendering any of
   * them again adds nothing; a fifth view replaces the one drawn longest
   * ago. A change of the input's geometry or of the filter's settings
   * forgets them; new values on the same geometry do not (the patches take
   * them). A render with smoothing off, or of a representation other than
   * surface, smooths nothing and counts nothing.
   */
  vtkIdType GetSmoothingRunCount() const { return this->SmoothingRunCount; }

  ///@{
  /**
   * Generic vertex attributes and the texture coordinates of named textures
   * (multi-texturing), as vtkOpenGLPolyDataMapper takes them: handed to the
   * mapper that draws (vtkPolyDataMapper's own are stubs). Point data only,
   * as there.
   */
  void MapDataArrayToVertexAttribute(const char* vertexAttributeName, const char* dataArrayName,
    int fieldAssociation, int componentno = -1) override;
  void MapDataArrayToMultiTextureAttribute(const char* textureName, const char* dataArrayName,
    int fieldAssociation, int componentno = -1) override;
  void RemoveVertexAttributeMapping(const char* vertexAttributeName) override;
  void RemoveAllVertexAttributeMappings() override;
  ///@}

  /**
   * vtkPolyDataMapper's settings, and from another smoothing mapper its
   * Smoothing and its filter's smoothing settings
   * (vtkSilhouetteSmoothingFilter::CopySmoothingSettings).
   */
  void ShallowCopy(vtkAbstractMapper* other) override;

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;
  bool GetSupportsSelection() override { return true; }
  void ProcessSelectorPixelBuffers(
    vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop) override;
  vtkMTimeType GetMTime() override;

  ///@{
  /**
   * The input's bounds, joined with those of the smoothed triangles the last
   * rendered view of this input drew (see above).
   */
  double* GetBounds() VTK_SIZEHINT(6) override;
  void GetBounds(double bounds[6]) override { this->Superclass::GetBounds(bounds); }
  ///@}

protected:
  vtkSilhouetteSmoothingMapper();
  ~vtkSilhouetteSmoothingMapper() override;

  bool Smoothing = true;
  vtkIdType ReplacedTriangleCount = 0;
  vtkIdType PatchTriangleCount = 0;
  vtkIdType CulledTriangleCount = 0;
  vtkIdType SubpixelTriangleCount = 0;
  vtkIdType SubpixelFeatureSegmentCount = 0;
  vtkIdType FoldGuardRoundCount = 0;
  vtkIdType ReusedFallbackCount = 0;
  vtkIdType SilhouetteTriangleCount = 0;
  vtkIdType NewTriangleCount = 0;
  double LastPrepareSeconds = 0.0;
  double LastSmoothingSeconds = 0.0;
  vtkIdType SmoothingRunCount = 0;

private:
  // The figures of a frame that draws nothing.
  void ClearFrameCounts();

  vtkSilhouetteSmoothingMapper(const vtkSilhouetteSmoothingMapper&) = delete;
  void operator=(const vtkSilhouetteSmoothingMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
