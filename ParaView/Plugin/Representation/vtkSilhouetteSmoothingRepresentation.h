/**
 * @class   vtkSilhouetteSmoothingRepresentation
 * @brief   ParaView's Surface representation with smooth silhouettes ("Smooth Silhouette Surface")
 *
 * A vtkGeometryRepresentationWithFaces whose mappers (the full-resolution
 * one, the LOD one and the two back-face ones) are vtkSilhouetteCompositeMapper:
 * each rank draws its piece of the surface with the silhouette smoothed for
 * the view's camera and size at render time (vtkSilhouetteSmoothingMapper),
 * so no camera has to be copied anywhere and every camera move is smoothed.
 * Everything else (colouring, lighting, textures, transforms, back faces,
 * selection) is Surface's.
 *
 * The Silhouette* setters forward to all four mappers without calling
 * Modified(): a representation's Modified() re-runs its geometry pipeline
 * and re-delivers the data. The mappers smooth again on the next render.
 *
 * LOD: while interacting, ParaView draws a decimated copy of large data with
 * the LOD mapper. It is smoothed too (SilhouetteSmoothLOD, default on): the decimated
 * mesh is coarse, which is what the smoothing is for, and it costs a base
 * mesh per LOD geometry (built once) and a smoothing per frame in proportion
 * to the silhouette, not to the mesh.
 */
#ifndef vtkSilhouetteSmoothingRepresentation_h
#define vtkSilhouetteSmoothingRepresentation_h

#include "SilhouetteSmoothingParaViewSilhouetteRepresentationModule.h" // For export macro
#include "vtkGeometryRepresentationWithFaces.h"

class vtkSilhouetteCompositeMapper;

class SILHOUETTESMOOTHINGPARAVIEWSILHOUETTEREPRESENTATION_EXPORT
  vtkSilhouetteSmoothingRepresentation : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkSilhouetteSmoothingRepresentation* New();
  vtkTypeMacro(vtkSilhouetteSmoothingRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Smooth the silhouettes at all (default on), and the LOD geometry's too
   * (default on).
   */
  void SetSilhouetteSmoothing(bool smoothing);
  void SetSilhouetteSmoothLOD(bool smoothLOD);
  ///@}

  ///@{
  /**
   * vtkSilhouetteSmoothingFilter's parameters (see there), for all mappers.
   */
  void SetSilhouetteTolerance(double pixels);
  void SetSilhouetteMinimumSamples(int samples);
  void SetSilhouetteMaximumSamples(int samples);
  void SetSilhouetteNewPointBudget(double budget);
  void SetSilhouetteSamplingRule(int rule);
  void SetSilhouettePerturbVertices(bool perturb);
  void SetSilhouetteFoldPrevention(bool prevent);
  void SetSilhouetteReuseFoldFallbacks(bool reuse);
  void SetSilhouetteKeepApexesPointed(bool keep);
  void SetSilhouetteSkipSubpixelSmoothing(bool skip);
  void SetSilhouetteFeatureLines(bool use);
  void SetSilhouetteFeatureEdgeDetection(bool detect);
  void SetSilhouetteFeatureAngle(double degrees);
  void SetSilhouetteFlatCreaseDetection(bool detect);
  void SetSilhouetteFlatCreaseAngle(double degrees);
  void SetSilhouetteNormalSeamFeatures(bool use);
  void SetSilhouetteWeldCoincidentPoints(bool weld);
  void SetSilhouetteWeldTolerance(double tolerance);
  void SetSilhouetteConsistentOrientation(bool orient);
  void SetSilhouetteNormalEstimation(int method);
  void SetSilhouetteVisibilityMethod(int method);
  ///@}

  ///@{
  /**
   * Of the last full-resolution render on this process: the triangles
   * replaced by the smoothing, the triangles drawn in their place, the
   * blocks drawn, their cells drawn and their ghost cells left out.
   */
  int GetSilhouetteReplacedTriangles();
  int GetSilhouettePatchTriangles();
  int GetSilhouetteRenderedBlocks();
  int GetSilhouetteDrawnCells();
  int GetSilhouetteSkippedGhostCells();
  ///@}

  /**
   * How many times this process's blocks were smoothed for a view, counted
   * over their mappers' lives (vtkSilhouetteCompositeMapper's
   * GetSmoothingRunCount).
   */
  int GetSilhouetteSmoothingRuns();

  /**
   * 1 when this process runs among several and its piece of the data has
   * cells but no point normals: the smoothing computes normals for the piece
   * alone, so where the data is split across processes the seams show as
   * lines (ParaView's geometry filter drops ghost cells before any mapper
   * sees them). A warning says so once per change of the data; Generate
   * Surface Normals before the representation avoids it.
   */
  int GetSilhouetteNormalsPerPiece() { return this->NormalsPerPiece ? 1 : 0; }

protected:
  vtkSilhouetteSmoothingRepresentation();
  ~vtkSilhouetteSmoothingRepresentation() override;

  /// The superclass's, then the check of point normals on several processes.
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool SilhouetteSmoothing = true;
  bool SmoothLOD = true;

private:
  vtkSilhouetteSmoothingRepresentation(const vtkSilhouetteSmoothingRepresentation&) = delete;
  void operator=(const vtkSilhouetteSmoothingRepresentation&) = delete;

  vtkSilhouetteCompositeMapper* FullMapper();
  template<typename F>
  void ForEachMapper(F&& f);
  void UpdateSmoothingSwitches();
  void CheckNormalsPerPiece(vtkDataObject* input);

  bool NormalsPerPiece = false;
  vtkMTimeType NormalsCheckedTime = 0;
};

#endif
