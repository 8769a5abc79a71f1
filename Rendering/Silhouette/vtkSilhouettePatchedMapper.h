/**
 * @class   vtkSilhouettePatchedMapper
 * @brief   draws a static mesh with a per-frame patch: some of its triangles hidden, a few new
 * ones drawn in their place
 *
 * Internal to vtkSilhouetteSmoothingMapper (not wrapped). The input mesh's
 * buffers are built once per input change, as vtkOpenGLPolyDataMapper builds
 * them. Per frame, SetPatch() names the triangles (indices among the input's
 * polygons) to hide and the mesh that takes their place:
 *
 * - hiding writes degenerate triangles (v, v, v) into the hidden triangles'
 *   slots of the index buffer, with glBufferSubData over the triangles that
 *   changed since the last frame only. Every other triangle keeps its place
 *   in the index stream, so gl_PrimitiveID, and with it cell scalars, cell
 *   normals and the picking ids of the triangles that are drawn, stay what
 *   the superclass made them;
 * - the patch is drawn in the same RenderPieceDraw by a helper
 *   vtkOpenGLPolyDataMapper with the same actor and this mapper's colouring
 *   settings (vtkMapper::ShallowCopy, SeamlessU/V, the attribute mappings)
 *   and the input's field data (colouring by a field-data tuple), so
 *   property, lighting, textures and lookup tables are the same.
 *
 * Hardware selection: the helper's cell ids start past the input's, and
 * ProcessSelectorPixelBuffers reports for each of its pixels the cell id
 * given with SetPatch (the input cell the patch triangle stands for). In
 * point selection passes the input is drawn whole and the patch not (a user
 * picks the input's points). Representations other than surface draw the
 * input whole, without the patch.
 *
 * Points with a zero normal (those only the input's lines and vertices use:
 * the smoothing, as vtkPolyDataNormals, gives them none) are lit as facing
 * the viewer, as vtkOpenGLPolyDataMapper lights lines without normals; its
 * own shader normalizes the zero vector and draws them black.
 *
 * Invariant: after RenderPieceStart the triangles drawn degenerate are
 * exactly the patch's hidden ones (or none, where the patch is not drawn);
 * an index-buffer rebuild by the superclass restores every triangle, and
 * the hidden set is applied again.
 */
#ifndef vtkSilhouettePatchedMapper_h
#define vtkSilhouettePatchedMapper_h

#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h" // For the patch

#include <map>    // For the patches of a selection
#include <vector> // For the hidden triangles

class vtkIdTypeArray;

class vtkSilhouettePatchedMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkSilhouettePatchedMapper* New();
  vtkTypeMacro(vtkSilhouettePatchedMapper, vtkOpenGLPolyDataMapper);

  /**
   * The frame's patch: `hidden` ascending indices among the input's
   * polygons, `patch` the triangles drawn instead (or nullptr), and for each
   * of its cells the id selection reports (`patchCellIds`, e.g. the input
   * cell it came from) and for each of its points an input point id the
   * process pass can take its process id from (`patchPointSources`). Does
   * not call Modified(): that would rebuild every buffer of the mesh.
   */
  void SetPatch(const std::vector<vtkIdType>& hidden, vtkPolyData* patch,
    vtkIdTypeArray* patchCellIds, const std::vector<vtkIdType>& patchPointSources);

  /// Triangles and glBufferSubData calls of the last frame's index update.
  vtkIdType GetLastPatchedTriangles() const { return this->LastPatchedTriangles; }
  vtkIdType GetLastPatchCalls() const { return this->LastPatchCalls; }

  ///@{
  /// Also the patch's (it draws the same attributes).
  void MapDataArrayToVertexAttribute(const char* vertexAttributeName, const char* dataArrayName,
    int fieldAssociation, int componentno = -1) override;
  void MapDataArrayToMultiTextureAttribute(const char* textureName, const char* dataArrayName,
    int fieldAssociation, int componentno = -1) override;
  void RemoveVertexAttributeMapping(const char* vertexAttributeName) override;
  void RemoveAllVertexAttributeMappings() override;
  ///@}

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;
  void ProcessSelectorPixelBuffers(
    vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop) override;

protected:
  vtkSilhouettePatchedMapper();
  ~vtkSilhouettePatchedMapper() override;

  void BuildIBO(vtkRenderer* ren, vtkActor* act, vtkPolyData* poly) override;
  void UpdateMaximumPointCellIds(vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderNormal(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;

private:
  vtkSilhouettePatchedMapper(const vtkSilhouettePatchedMapper&) = delete;
  void operator=(const vtkSilhouettePatchedMapper&) = delete;

  bool PatchDrawn(vtkRenderer* ren, vtkActor* act);
  void ApplyHidden(vtkRenderer* ren, vtkActor* act);
  void RecordTriangleLayout(vtkPolyData* poly);
  bool LayoutUnchanged(vtkPolyData* poly) const;

  // The triangle index buffer as the superclass uploaded it, and for each
  // polygon its first triangle there and how many it has (VTK leaves out
  // triangles with coincident corners, so they can differ from a fan's).
  std::vector<unsigned int> Pristine;
  std::vector<vtkIdType> FirstTriangle;
  std::vector<int> TriangleCount;
  std::vector<unsigned char> TriangleHidden;
  bool LayoutKnown = false;
  // The polygons the layout was recorded for (compared by address and
  // modification time, never dereferenced unless they match the input's).
  vtkCellArray* LayoutPolys = nullptr;
  vtkMTimeType LayoutPolysTime = 0;
  std::vector<vtkIdType> Applied; // polygons degenerate in the buffer now
  std::vector<vtkIdType> Wanted;

  class PatchMapper;
  vtkSmartPointer<PatchMapper> Patch;
  vtkNew<vtkPolyData> PatchData;
  vtkSmartPointer<vtkIdTypeArray> PatchCellIds;
  std::vector<vtkIdType> PatchPointSources;
  vtkIdType PatchCellOffset = 0;
  vtkIdType PatchPointOffset = 0;
  bool PatchDrawnThisPass = false;
  // What a selection pass drew for each prop: actors that share this mapper
  // have patches of their own (their own matrices), and the selector
  // converts every prop's pixels after the pass has drawn them all. Props
  // are keys only, never dereferenced.
  struct DrawnPatch
  {
    vtkSmartPointer<vtkIdTypeArray> CellIds;
    std::vector<vtkIdType> PointSources;
    vtkIdType CellOffset = 0;
    vtkIdType PointOffset = 0;
    bool Drawn = false;
  };
  std::map<vtkProp*, DrawnPatch> SelectionPatches;
  vtkMTimeType PatchSettingsTime = 0;
  // Whether the patch holds a copy of the input's field data, of this time.
  bool PatchFieldsCopied = false;
  vtkMTimeType PatchFieldsTime = 0;
  vtkIdType LastPatchedTriangles = 0;
  vtkIdType LastPatchCalls = 0;
};

#endif
