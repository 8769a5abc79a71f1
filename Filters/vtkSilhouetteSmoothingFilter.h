/**
 * @class   vtkSilhouetteSmoothingFilter
 * @brief   re-meshes a coarse triangle mesh along its silhouette so the outline looks smooth
 *
 * vtkSilhouetteSmoothingFilter implements the view-dependent silhouette smoothing
 * of L. Wang, C. Tu, W. Wang, X. Meng, B. Chan and D. Yan, "Silhouette Smoothing for
 * Real-Time Rendering of Mesh Surfaces", IEEE TVCG 14(3), 2008. For the current
 * camera it finds the silhouette triangles (those whose vertices differ in
 * visibility N.(E - V) >= 0), reconstructs the smooth silhouette across them with
 * cubic Hermite curves (silhouette bridges on the mixed edges, silhouette points
 * where the interpolated normal is perpendicular to the view, silhouette segments
 * between them), samples each segment adaptively so that the polyline stays
 * within `Tolerance` pixels of the curve, and re-meshes only those triangles.
 * Every other cell passes through unchanged.
 *
 * Input: a vtkPolyData. Polygons and triangle strips are triangulated; vertices
 * and lines are passed through unchanged. Point normals (the active normals of the
 * point data) are used as shading normals when present; otherwise vertex normals
 * are computed (NormalEstimation, area-weighted by default). A given normal that is zero is
 * replaced by the computed one; a point with no defined normal at all counts as visible.
 *
 * The view (from vtkSilhouetteViewAlgorithm): a camera (SetCamera, or the
 * active camera of SetRenderer), the viewport size in pixels (SetViewportSize,
 * or the renderer's size), and optionally the actor (SetProp3D) or its matrix
 * (SetModelMatrix) so that the eye is taken into the data's model coordinates. Perspective and
 * parallel projection are both handled, from the camera (its model-view matrix, so its model and
 * user-view transforms count too). GetMTime() changes whenever the view changes in a way that
 * changes the result (camera, prop matrix, model matrix, viewport), compared by value, so a mapper
 * fed by this filter re-runs it when the view moves, and not when a renderer only resets the
 * clipping range. Before a renderer has created its camera, the input passes through unchanged (the
 * renderer asks for bounds to create it). The view-independent work (triangles, edge table, shading
 * normals) is cached: rebuilt when the input's cells or the settings change, updated when only its
 * points move (a deforming mesh), kept when only its other arrays change (a time series of values),
 * in this input object or another with the same cells (a reader's next time step). An update for
 * the same view, settings and geometry takes the last smoothing again and writes the new values.
 *
 * Output port 0: the re-meshed mesh. All input points come first with their ids
 * unchanged (positions too, but for the perturbation below), then the copies made
 * where feature edges split a vertex (FeatureLines), then the added points. Arrays:
 * - cell `NewGeometry` (unsigned char): 0 = input triangle kept as it was,
 *   1 = made by silhouette re-meshing, 2 = made by re-meshing along feature curves;
 * - point `OriginalPointId` (vtkIdType): the input point each output point is or
 *   copies, -1 for added points;
 * - cell `OriginalCellId` (vtkIdType): the input cell each output cell came from;
 * - point `Normals`: the shading normals, set as the active normals (added points
 *   get the normalised interpolated normal);
 * - every other input point array, interpolated linearly for the added points
 *   along the same parameters; every other input cell array, copied from the
 *   original cell;
 * - field data `SilhouetteTriangleCount`, `NewTriangleCount`, `NewPointCount`,
 *   `InputTriangleCount`, `OutputTriangleCount`, `ConcaveSegmentCount`,
 *   `PerturbedPointCount`, the fold guard's fallbacks (`CrowdedTriangleCount`
 *   among them) and more (vtkIdType, one tuple each; the project's docs/using.md
 *   lists them all).
 *
 * Concave silhouettes (saddle regions, such as a torus's inner rim) would be
 * hidden behind their neighbouring triangles; with PerturbVertices on (the
 * default) the vertices around them are lowered below the planes of the
 * concave segments, as in the paper's section III-E. Only the output's copies
 * move: input points keep their ids, and their positions except for these.
 *
 * Ghost cells (cell array `vtkGhostType` with DUPLICATECELL or HIDDENCELL,
 * as a piece of a partitioned mesh has its neighbours' cells) are never
 * re-meshed: they count for the shading normals, the adjacency and the
 * silhouette points on their edges, so the piece that owns them computes
 * the same points there; they pass through with their flags.
 *
 * Output port 1: the smoothed silhouette as polylines chained across triangles
 * (closed loops repeat their first point at the end), with point `Normals`
 * and cell `LineKind` (unsigned char, 0 = silhouette, as
 * vtkCreaseAndBorderLines numbers the kinds of a line drawing).
 *
 * Guarantees: crack-free (each silhouette point is computed once per undirected
 * edge, so both triangles of an edge split it at the identical point); a closed
 * manifold input gives a closed manifold output with consistent orientation;
 * boundary edges stay boundary edges (a split one bends to its silhouette point,
 * which depends on the view and on the normals: a model cut into pieces stays
 * crack-free along its seams only if every piece carries the same point
 * normals); a view with no silhouette triangle gives triangle input back
 * unchanged (polygons and strips come out triangulated; normals come out
 * normalised, as floats).
 *
 * Defined behaviour for awkward input: an empty input gives an empty output;
 * points with NaN or infinite coordinates make the request fail with an error;
 * cells that repeat a point id are passed through unchanged; edges shared by more
 * than two triangles are split at one shared point for all of them; a missing
 * camera makes the request fail with an error; an eye exactly on the surface is
 * handled like any other view (its vertices count as visible); a singular or
 * non-finite view (e.g. a prop scaled to zero) or a viewport smaller than one
 * pixel makes the request fail with an error. Global and pedigree ids are not
 * interpolated (VTK's attribute rules): they are not in the output.
 *
 * @sa vtkSilhouetteViewAlgorithm vtkPolyDataSilhouette
 */
#ifndef vtkSilhouetteSmoothingFilter_h
#define vtkSilhouetteSmoothingFilter_h

#include "SilhouetteSmoothingFiltersSilhouetteModule.h" // For export macro
#include "vtkSilhouetteViewAlgorithm.h"

#include <array>  // For the viewer of BuildChanges
#include <memory> // For the cached core mesh

class vtkCamera;
class vtkIdTypeArray;
class vtkSilhouetteSmoothingMapper;
namespace vtkSilhouetteFilterSupport
{
struct AttributeSources;
}

class SILHOUETTESMOOTHINGFILTERSSILHOUETTE_EXPORT vtkSilhouetteSmoothingFilter
  : public vtkSilhouetteViewAlgorithm
{
public:
  static vtkSilhouetteSmoothingFilter* New();
  vtkTypeMacro(vtkSilhouetteSmoothingFilter, vtkSilhouetteViewAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Takes every setting of the smoothing from `other` (tolerance, sampling,
   * perturbation, fold guard, apexes, culling, sub-pixel skip, feature
   * curves, welding, orientation, normals, visibility method), not its view
   * (camera, renderer, prop, viewport) nor its output's point precision: what
   * a mapper that smooths with this filter copies (vtkSilhouetteSmoothingMapper's
   * ShallowCopy, ParaView's composite mapper). A setting already equal
   * leaves the MTime alone. Null is ignored.
   */
  void CopySmoothingSettings(vtkSilhouetteSmoothingFilter* other);

  ///@{
  /**
   * Largest distance, in pixels, allowed between a sampled silhouette segment
   * and its curve. Default 0.5 (the paper's range is 0.5 to 2). Values below
   * 1e-3 are raised to it, with a warning; NaN is refused with a warning.
   */
  virtual void SetTolerance(double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Fewest and most points sampled on one silhouette segment, counting both
   * ends. Defaults 2 (the chord, when the curve is within tolerance of it)
   * and 256; values outside [2, 65536] are clamped with a warning. An update
   * with MinimumSamples above MaximumSamples fails with an error. A frame
   * samples fewer points when NewPointBudget requires it.
   */
  virtual void SetMinimumSamples(int);
  vtkGetMacro(MinimumSamples, int);
  virtual void SetMaximumSamples(int);
  vtkGetMacro(MaximumSamples, int);
  ///@}

  ///@{
  /**
   * The most points one frame's sampling may add, as a multiple of the
   * input's points (and never fewer than 100,000). A frame whose segments
   * could need more samples than that at MaximumSamples samples them with
   * fewer (2 + budget / segments each), warns, and reports the lowered
   * maximum in the field data's SampleBudgetMaximum; a frame within budget
   * reports 0 there. So a large MinimumSamples on a large mesh degrades the
   * sampling instead of exhausting memory. Default 8; clamped to [1, 1e6].
   */
  virtual void SetNewPointBudget(double);
  vtkGetMacro(NewPointBudget, double);
  ///@}

  enum SamplingRules
  {
    SECOND_DIFFERENCE =
      0,                ///< bounds the projected curve's chord error: keeps the tolerance (default)
    WANG_EQUATION_8 = 1 ///< the paper's eq. 8, which under-samples (kept for comparison)
  };

  ///@{
  /**
   * How the number of samples per silhouette segment is chosen (see
   * Filters/Core/AdaptiveSampling.h for the bound and the measurements).
   */
  virtual void SetSamplingRule(
    int); ///< clamped to [SECOND_DIFFERENCE, WANG_EQUATION_8] with a warning
  vtkGetMacro(SamplingRule, int);
  void SetSamplingRuleToSecondDifference() { this->SetSamplingRule(SECOND_DIFFERENCE); }
  void SetSamplingRuleToWangEquation8() { this->SetSamplingRule(WANG_EQUATION_8); }
  ///@}

  ///@{
  /**
   * Lower the vertices around concave silhouette segments so that the
   * smoothed curve is not blocked by its neighbouring triangles (paper III-E).
   * Default on.
   */
  vtkSetMacro(PerturbVertices, bool);
  vtkGetMacro(PerturbVertices, bool);
  vtkBooleanMacro(PerturbVertices, bool);
  ///@}

  ///@{
  /**
   * Never fold (default on): a silhouette triangle whose new triangles turn
   * over against the surface or cut through another output triangle is
   * re-meshed along the chord between its silhouette points, then with its
   * silhouette points on its straight edges, then with its curved feature
   * segments straight; a perturbed vertex that folds its triangles is left
   * in place (Filters/Core/FoldGuard.h). The field data counts each
   * fallback: ChordFallbackCount, StraightSilhouettePointCount,
   * StraightFeatureSegmentCount, PinnedPointCount, and UnresolvedFoldCount
   * (folds no fallback could undo; none expected).
   */
  vtkSetMacro(FoldPrevention, bool);
  vtkGetMacro(FoldPrevention, bool);
  vtkBooleanMacro(FoldPrevention, bool);
  ///@}

  ///@{
  /**
   * In vtkSilhouetteSmoothingMapper's frames (BuildChanges), reuse the fold
   * fallbacks of the same viewer's frame before (default on): each frame
   * still starts with none and checks for folds, but a triangle found
   * folding goes at once to the fallback it needed there (and the creases
   * beside it that were drawn straight there), instead of climbing to it
   * one re-meshing round at a time. A coarse mesh's folds stay put from one
   * frame of an orbit to the next: each frame took 2 to 4 rounds on assimp's
   * spider. Nothing is kept that the frame does not need, so a triangle whose
   * curve no longer folds is drawn curved; where a fold needs only the first
   * fallback now, the one it needed before is kept while it folds. Field
   * data `ReusedFallbackCount` (BuildChanges' changes) and the mapper's
   * GetReusedFallbackCount count what was reused. The filter's own output
   * (RequestData) reuses nothing: it depends on its view alone.
   */
  vtkSetMacro(ReuseFoldFallbacks, bool);
  vtkGetMacro(ReuseFoldFallbacks, bool);
  vtkBooleanMacro(ReuseFoldFallbacks, bool);
  ///@}

  ///@{
  /**
   * Keep cones pointed (default on): at a vertex where the surface comes to
   * a point (a cone's apex: its triangles' normals spread more than 30
   * degrees from their mean while neighbouring ones turn little), no one
   * normal serves, and the curves through the apex's mean normal round the
   * cone into a dome. Silhouette triangles there keep the silhouette on
   * their straight edges and chords instead; the field data counts them
   * (ApexTriangleCount). Off: smoothed like any other triangle.
   */
  vtkSetMacro(KeepApexesPointed, bool);
  vtkGetMacro(KeepApexesPointed, bool);
  vtkBooleanMacro(KeepApexesPointed, bool);
  ///@}

  ///@{
  /**
   * Leave the silhouette triangles the camera cannot show as they are:
   * those beyond a plane of the view frustum by more than their longest
   * side, so that no smoothed curve of theirs could reach into the view
   * (field data `CulledTriangleCount`); with SkipSubpixelSmoothing, a
   * feature curve's segment whose triangles are all such is drawn by its
   * chord (counted in `SubpixelFeatureSegmentCount`). Default off: a mesh
   * written out wants every silhouette smoothed.
   * vtkSilhouetteSmoothingMapper turns it on.
   */
  vtkSetMacro(FrustumCulling, bool);
  vtkGetMacro(FrustumCulling, bool);
  vtkBooleanMacro(FrustumCulling, bool);
  ///@}

  ///@{
  /**
   * Leave as they are the silhouette triangles whose smoothing would move no
   * point of the image by more than Tolerance pixels (field data
   * `SubpixelTriangleCount`), when the whole strip of silhouette triangles
   * they belong to (joined through the edges the silhouette crosses) is
   * such: a bound on how far the re-meshing could move any point of the
   * triangle, projected with the view's pixels. On a mesh fine for the view
   * (tens of thousands of triangles across the image) that is the whole
   * silhouette, and a frame costs little more than finding it. Their
   * silhouette is the chord between points on their edges. Likewise a
   * smoothed feature segment (a crease's curve) whose curve would move no
   * point of its triangles by more than Tolerance pixels is drawn straight,
   * its triangles not re-meshed for it (field data
   * `SubpixelFeatureSegmentCount`): a finely divided CAD part's rims. In BuildChanges
   * (the mapper's frames) a strip its last call smoothed is left whole only
   * within three quarters of Tolerance (a segment, likewise), so an outline near it does not blink
   * between smoothed and not from frame to frame. Default off: a
   * mesh written out does not know the pixels it will be seen at.
   * vtkSilhouetteSmoothingMapper turns it on. On a piece with ghost cells,
   * a strip or segment that reaches them is always smoothed (the piece that
   * owns them does so too), and the rest as on a whole mesh.
   */
  vtkSetMacro(SkipSubpixelSmoothing, bool);
  vtkGetMacro(SkipSubpixelSmoothing, bool);
  vtkBooleanMacro(SkipSubpixelSmoothing, bool);
  ///@}

  ///@{
  /**
   * Feature edges (creases) marked on the input: every segment of a line
   * cell that is an edge of the triangles. Default on (line cells that run
   * along the surface's edges are taken as a deliberate mark, as
   * vtkOpenSubdivRefiner reads creases).
   */
  vtkSetMacro(FeatureLines, bool);
  vtkGetMacro(FeatureLines, bool);
  vtkBooleanMacro(FeatureLines, bool);
  ///@}

  ///@{
  /**
   * Also take as feature edges the edges whose two triangles meet at more
   * than FeatureAngle degrees (the angle between their normals). Default off:
   * smooth models need none, and a coarse smooth mesh can have edges sharper
   * than any fixed angle.
   */
  vtkSetMacro(FeatureEdgeDetection, bool);
  vtkGetMacro(FeatureEdgeDetection, bool);
  vtkBooleanMacro(FeatureEdgeDetection, bool);
  virtual void SetFeatureAngle(double); ///< degrees in [0, 180], clamped with a warning
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Take points at one position as one vertex of the surface, whatever their
   * ids (asset files give a surface point one mesh point per texture chart,
   * per hard edge or per triangle corner). Each triangle keeps its own
   * points: added points are interpolated from the points of the triangle
   * they are in, so texture seams stay seams (an added point on a seam is
   * made once per side, at one position). Default on. WeldTolerance 0 (the
   * default) joins equal coordinates only; d > 0 joins points within d of
   * each other, transitively. Edges shorter than 1e-5 of the mesh's size
   * (near copies of a point, as some exporters write them) draw a warning
   * that gives a tolerance that welds them.
   */
  vtkSetMacro(WeldCoincidentPoints, bool);
  vtkGetMacro(WeldCoincidentPoints, bool);
  vtkBooleanMacro(WeldCoincidentPoints, bool);
  virtual void SetWeldTolerance(double); ///< at least 0, raised with a warning
  vtkGetMacro(WeldTolerance, double);
  ///@}

  ///@{
  /**
   * Orient the triangles consistently per connected component before
   * computing normals and visibility: a closed component outward (positive
   * signed volume), an open one the way its given normals point, else the way
   * most of its area faces. Given normals pointing into the oriented surface
   * are reversed. The output writes each component with the winding most of
   * its triangles have in the input (a consistently wound input keeps its
   * own; a triangle against its component's majority is turned over), and
   * its normals follow that winding, so every triangle is lit from outside,
   * an inside-out mesh's included.
   * Triangles that cannot be oriented consistently (a non-orientable
   * component) keep the orientation spread from the component's first
   * triangle, with a warning. Default on.
   */
  vtkSetMacro(ConsistentOrientation, bool);
  vtkGetMacro(ConsistentOrientation, bool);
  vtkBooleanMacro(ConsistentOrientation, bool);
  ///@}

  ///@{
  /**
   * Take as feature edges (creases) the edges where points at one position
   * carry normals more than 1 degree apart: how OBJ, PLY and glTF files mark
   * hard edges. Each side then keeps its own given normal. Needs point
   * normals on the input and WeldCoincidentPoints. Normals that are only the
   * triangles' own (flat shading: split along at least half of the edges,
   * every corner of all but 1% of the triangles carrying its triangle's
   * normal) tell nothing about the smooth surface:
   * they are not used at all, with a warning, and the shading normals are
   * computed. Default on.
   */
  vtkSetMacro(NormalSeamFeatures, bool);
  vtkGetMacro(NormalSeamFeatures, bool);
  vtkBooleanMacro(NormalSeamFeatures, bool);
  ///@}

  ///@{
  /**
   * The type of the output points: vtkAlgorithm::DEFAULT_PRECISION (the
   * input's, the default), SINGLE_PRECISION or DOUBLE_PRECISION. Added points
   * are computed in double; storing them in float far from the origin rounds
   * them visibly.
   */
  virtual void SetOutputPointsPrecision(
    int); ///< clamped to [SINGLE_PRECISION, DEFAULT_PRECISION] with a warning
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * Take as feature edges the creases between flat faces: edges sharper than
   * FlatCreaseAngle degrees (default 65) whose two triangles each lie flat
   * (within half a degree) against another of their neighbours, as the faces
   * of boxes and CAD parts do; a face of one triangle whose three edges are
   * all that sharp counts as flat beside such a face (a wedge's ends). The
   * outline of a flat face of two or more triangles that is that sharp all
   * round is a crease too, whatever lies beyond it (a cone's base, a hoof's
   * sole). Tessellated smooth surfaces almost never have
   * flat neighbours, even where they are coarse enough to have edges sharper
   * than any fixed angle (the coarse bunny has 15 edges above 80 degrees, a
   * CAD part's edges are 90), so this can be on by default where
   * FeatureEdgeDetection cannot. Parametric grids are the exception: their
   * quads are planar, so a grid torus or UV sphere with fewer than 6 segments
   * around (rings more than 65 degrees apart) is taken as creased, and a
   * hexagonal prism's 60-degree edges are not creases unless FlatCreaseAngle
   * is lowered. A found edge that meets no other, nor a border, at either
   * end is left out (a stretched coarse grid's lone sharp edge; a solid's
   * creases meet at its corners). Default on.
   */
  vtkSetMacro(FlatCreaseDetection, bool);
  vtkGetMacro(FlatCreaseDetection, bool);
  vtkBooleanMacro(FlatCreaseDetection, bool);
  virtual void SetFlatCreaseAngle(double); ///< degrees in [0, 180], clamped with a warning
  vtkGetMacro(FlatCreaseAngle, double);
  ///@}

  enum NormalEstimations
  {
    ANGLE_WEIGHTED = 0, ///< face normals weighted by corner angle
    AREA_WEIGHTED = 1,  ///< face normals weighted by area (default)
    MAX_WEIGHTED = 2,   ///< Max (1999): exact for points on a sphere
    QUADRIC_FIT = 3     ///< a quadric height field fitted to the 1-ring
  };

  ///@{
  /**
   * How the shading normals the input does not give are estimated (given
   * normals are used as they are). Default AREA_WEIGHTED: against the truth
   * on seven real meshes at 500 triangles (docs/fidelity.md) it left the
   * lowest mean outline distance of the four on five of them (0.49 to 0.71 of
   * the raw mean, against 0.50 to 0.92 with angle weights) and kept the
   * worst place below the raw mesh's on six (angle weights: three). It makes
   * more flipped new triangles than angle weights on six of the seven, though
   * (docs/fidelity.md): choose ANGLE_WEIGHTED where folds matter more.
   */
  virtual void SetNormalEstimation(
    int); ///< clamped to [ANGLE_WEIGHTED, QUADRIC_FIT] with a warning
  vtkGetMacro(NormalEstimation, int);
  void SetNormalEstimationToAngleWeighted() { this->SetNormalEstimation(ANGLE_WEIGHTED); }
  void SetNormalEstimationToAreaWeighted() { this->SetNormalEstimation(AREA_WEIGHTED); }
  void SetNormalEstimationToMaxWeighted() { this->SetNormalEstimation(MAX_WEIGHTED); }
  void SetNormalEstimationToQuadricFit() { this->SetNormalEstimation(QUADRIC_FIT); }
  ///@}

  enum VisibilityMethods
  {
    PER_VERTEX = 0,  ///< g = N . (E - V) at every vertex (default)
    HIERARCHICAL = 1 ///< clusters of vertices decided at once (paper III-B)
  };

  ///@{
  /**
   * How the vertices facing the viewer are found. Both make exactly the same
   * decisions, so the output is the same; HIERARCHICAL clusters the vertices
   * once per input (on its first update) and then decides whole clusters per
   * view. It pays from about 50,000 triangles (visibility 1.5-2.5x faster
   * there, the whole frame up to 15-20% on spheres), costs more on coarse
   * meshes, and its one-off build is about 0.6x the input's preparation (see
   * Common/Core/VisibilityHierarchy.h, Testing/Benchmarks/VisibilityBenchmark.cpp).
   */
  virtual void SetVisibilityMethod(int); ///< clamped to [PER_VERTEX, HIERARCHICAL] with a warning
  vtkGetMacro(VisibilityMethod, int);
  void SetVisibilityMethodToPerVertex() { this->SetVisibilityMethod(PER_VERTEX); }
  void SetVisibilityMethodToHierarchical() { this->SetVisibilityMethod(HIERARCHICAL); }
  ///@}

  /**
   * The smoothed silhouette polylines (output port 1).
   */
  vtkPolyData* GetSilhouetteOutput();

  ///@{
  /**
   * Render-time smoothing (vtkSilhouetteSmoothingMapper): the output split
   * into what changes with the input only and what changes with the view,
   * outside the pipeline, with this filter's settings. Both prepare `input`
   * as RequestData does (the surface is built once per settings change and
   * per new cells, in this input object or another; new points move it; new
   * values alone leave it as it is) and return 0
   * after reporting an error: arrays of the wrong length are refused (the
   * pipeline leaves them out before RequestData; vtkSilhouetteSmoothingMapper
   * leaves them out before it calls these) and an exception inside becomes
   * an error.
   *
   * BuildBaseMesh fills `base` with what RequestData outputs for a view that
   * re-meshes nothing: the input's vertices and lines, its points and the
   * copies its smooth groups need, the shading normals, the point and cell
   * data, `OriginalPointId`, `OriginalCellId` and `NewGeometry`, and one
   * triangle per input triangle, in input order.
   *
   * BuildChanges smooths for the view (a camera, the prop's model matrix,
   * row-major as vtkMatrix4x4, and the viewport in pixels) and fills
   * `replacedTriangles` with the base mesh's triangles whose place changes
   * (ascending indices among its polygons: the re-meshed ones and those the
   * perturbation moved) and `changes` with what takes their place, over
   * points of its own, with the arrays of the whole output. Invariant: the
   * base mesh with those triangles replaced is RequestData's output for the
   * same view, triangle for triangle, up to the points' numbering, but for
   * what the calls before leave: SkipSubpixelSmoothing's margin and the fold
   * fallbacks of ReuseFoldFallbacks (with both off, nothing). The cost is in
   * the silhouette, not the mesh.
   */
  int BuildBaseMesh(vtkPolyData* input, vtkPolyData* base);
  int BuildChanges(vtkPolyData* input, vtkCamera* camera, const double modelMatrix[16], int width,
    int height, vtkPolyData* changes, vtkIdTypeArray* replacedTriangles);
  ///@}

protected:
  vtkSilhouetteSmoothingFilter();
  ~vtkSilhouetteSmoothingFilter() override;

  ///@{
  /**
   * For vtkSilhouetteSmoothingMapper. BuildChanges, and where the changes'
   * points and cells take their attributes from in `input`
   * (vtkSilhouetteFilterSupport::RefillAttributes fills them again from new
   * arrays). GetGeometryTime: the time the geometry smoothing reads (points,
   * normals, cells, ghost flags) last changed, as of the last BuildBaseMesh or
   * BuildChanges; what BuildChanges made since then still holds for the
   * input, whatever else of it changed (its other arrays). BuildBaseMesh
   * keeps the base mesh's points and normals while it stays. `viewer` names
   * whose frames follow one another (the mapper's renderer and prop): what
   * SkipSubpixelSmoothing left whole and smoothed in that viewer's last
   * frame is its history (the public BuildChanges has one of its own).
   */
  friend class vtkSilhouetteSmoothingMapper;
  int BuildChanges(vtkPolyData* input, vtkCamera* camera, const double modelMatrix[16], int width,
    int height, vtkPolyData* changes, vtkIdTypeArray* replacedTriangles,
    vtkSilhouetteFilterSupport::AttributeSources* sources,
    const std::array<const void*, 2>& viewer);
  vtkMTimeType GetGeometryTime() const;
  ///@}

  int BuildBaseMeshUnguarded(vtkPolyData* input, vtkPolyData* base);
  int BuildChangesUnguarded(vtkPolyData* input, vtkCamera* camera, const double modelMatrix[16],
    int width, int height, vtkPolyData* changes, vtkIdTypeArray* replacedTriangles,
    vtkSilhouetteFilterSupport::AttributeSources* sources,
    const std::array<const void*, 2>& viewer);

  int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) override;

  double Tolerance = 0.5;
  int MinimumSamples = 2;
  int MaximumSamples = 256;
  double NewPointBudget = 8.0;
  int SamplingRule = SECOND_DIFFERENCE;
  bool PerturbVertices = true;
  bool FoldPrevention = true;
  bool ReuseFoldFallbacks = true;
  bool KeepApexesPointed = true;
  bool FrustumCulling = false;
  bool SkipSubpixelSmoothing = false;
  bool FeatureLines = true;
  bool FeatureEdgeDetection = false;
  double FeatureAngle = 30.0;
  int VisibilityMethod = PER_VERTEX;
  bool WeldCoincidentPoints = true;
  double WeldTolerance = 0.0;
  bool ConsistentOrientation = true;
  bool NormalSeamFeatures = true;
  bool FlatCreaseDetection = true;
  double FlatCreaseAngle = 65.0;
  int OutputPointsPrecision = DEFAULT_PRECISION;
  int NormalEstimation = AREA_WEIGHTED;

private:
  vtkSilhouetteSmoothingFilter(const vtkSilhouetteSmoothingFilter&) = delete;
  void operator=(const vtkSilhouetteSmoothingFilter&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
