/**
 * @class   vtkOpenSubdivRefiner
 * @brief   Loop subdivision surface of a triangle mesh with OpenSubdiv: the fine reference
 *
 * vtkOpenSubdivRefiner refines a triangle mesh uniformly with OpenSubdiv's Loop
 * scheme (Far::TopologyRefiner, Far::PrimvarRefinerReal<double>) to `Level`
 * levels, each level splitting every triangle into four, and optionally moves
 * the points of the last level onto the Loop limit surface. It produces the
 * smooth reference surface that a coarse mesh stands for.
 *
 * Subdivision rules (OpenSubdiv's Sdc options):
 * - Loop's original weights (beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n);
 * - boundaries: Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER. Boundary edges are
 *   infinitely sharp, so the limit boundary is the cubic B-spline curve of the
 *   boundary polygon alone (it does not depend on interior points: a boundary
 *   vertex goes to (previous + 4 v + next) / 6), and boundary vertices with only
 *   one incident triangle are corners that stay where they are (with
 *   VTX_BOUNDARY_EDGE_ONLY they would be rounded off too). Loop is approximating:
 *   other boundary vertices are not interpolated.
 * - creases: edges can be made infinitely sharp (Sdc::Crease::SHARPNESS_INFINITE).
 *   A crease limit curve is the cubic B-spline of its crease polygon; a vertex
 *   with three or more crease edges is a corner and stays put; a vertex with
 *   exactly one crease edge (the crease ends there) is smooth (a dart). Crease
 *   edges come from two sources, which add up:
 *   (a) the input's line cells (VTK_LINE and VTK_POLY_LINE): the segment between
 *       two consecutive points of a line cell marks the triangle-mesh edge
 *       between those two points as a crease. Segments that are not an edge of
 *       the triangle mesh are ignored with one warning giving their count.
 *   (b) `FeatureAngle` (degrees, default 0 = off): an interior edge is a crease
 *       when the angle between the normals of its two triangles exceeds it.
 *
 * Limit projection (`ProjectToLimit`, default on): the points of the last level
 * are replaced by their limit positions (PrimvarRefiner::Limit), and the point
 * array `Normals` (set as the active normals) holds the unit limit normal: the
 * cross product of OpenSubdiv's two limit tangents, oriented to agree with the
 * refined triangles (the sign is chosen so that it has a positive dot product
 * with the area-weighted normal of the triangles around the point; where the
 * tangents are parallel, that area-weighted normal is used). Every other point
 * array is projected to its limit too. With `ProjectToLimit` off the output is
 * the refined control mesh and has no normals: compute them downstream
 * (vtkPolyDataNormals) if needed.
 *
 * Input: a vtkPolyData. Polygons are triangulated as fans from their first point,
 * triangle strips into their triangles. Vertex cells are dropped; line cells are
 * only crease marks and are not passed on. Cells that repeat a point id are
 * dropped (warning). Points not used by any triangle are dropped.
 *
 * Output: triangles only, consistently oriented as the input. Arrays:
 * - point `Normals` (same precision as the output points), when projecting;
 * - every input point vtkDataArray of any numeric type and component count,
 *   carried through the same subdivision masks in double precision and written
 *   back as the input's type (integer types are rounded to the nearest value
 *   and clamped to their range). The input's normals attribute (or an array
 *   named `Normals`) is not carried: it is replaced by the limit normals, or
 *   dropped without projection. Active attributes (scalars, texture coordinates,
 *   ...) stay active;
 * - cell `OriginalCellId` (vtkIdType): the id of the input cell (in vtkPolyData's
 *   numbering: vertices, lines, polygons, strips) whose triangle each output
 *   triangle refines, found through OpenSubdiv's parent faces;
 * - every other input cell array, copied from that original cell (cell normals
 *   are not copied).
 *
 * Output points are ordered as OpenSubdiv orders the vertices of the last level.
 * `OutputPointsPrecision` sets their type: SINGLE_PRECISION (float),
 * DOUBLE_PRECISION, or DEFAULT_PRECISION (the default: float for float input
 * points, double otherwise). All the arithmetic is done in double
 * (Far::PrimvarRefinerReal<double>, whose masks OpenSubdiv computes in double).
 *
 * Bad input: an empty input (no triangles) gives an empty output without error.
 * The request fails with an error (and an empty output) for: an edge shared by
 * three or more triangles, two triangles that use an edge in the same direction
 * (inconsistent orientation), NaN or infinite coordinates of a used point, cells
 * naming missing points, meshes too large for OpenSubdiv's 32-bit indices at the
 * requested level. Vertices where several fans of triangles meet (bowties)
 * are accepted: OpenSubdiv treats them as non-manifold corners, which stay put.
 *
 * @sa vtkLoopSubdivisionFilter
 */
#ifndef vtkOpenSubdivRefiner_h
#define vtkOpenSubdivRefiner_h

#include "SilhouetteSmoothingFiltersReferenceModule.h" // For export macro
#include "vtkSilhouettePolyDataAlgorithm.h"            // For the superclass

class SILHOUETTESMOOTHINGFILTERSREFERENCE_EXPORT vtkOpenSubdivRefiner
  : public vtkSilhouettePolyDataAlgorithm
{
public:
  static vtkOpenSubdivRefiner* New();
  vtkTypeMacro(vtkOpenSubdivRefiner, vtkSilhouettePolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of uniform refinement levels: each multiplies the triangle count by
   * 4. Default 3; clamped to 0..8. Level 0 with ProjectToLimit gives the input
   * triangles with their points moved to the limit surface.
   */
  vtkSetClampMacro(Level, int, 0, 8);
  vtkGetMacro(Level, int);
  ///@}

  ///@{
  /**
   * Move the points of the last level to the limit surface and output the limit
   * normals as point `Normals`. Default on.
   */
  vtkSetMacro(ProjectToLimit, bool);
  vtkGetMacro(ProjectToLimit, bool);
  vtkBooleanMacro(ProjectToLimit, bool);
  ///@}

  ///@{
  /**
   * Interior edges whose dihedral angle (between the normals of their two
   * triangles) exceeds this angle in degrees become infinitely sharp creases.
   * Default 0: off. Clamped to 0..180.
   */
  virtual void SetFeatureAngle(double); ///< clamped to [0.0, 180.0] with a warning; NaN refused
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Precision of the output points (and normals): vtkAlgorithm::SINGLE_PRECISION,
   * DOUBLE_PRECISION or DEFAULT_PRECISION (the default: float if the input
   * points are float, double otherwise).
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkOpenSubdivRefiner() = default;
  ~vtkOpenSubdivRefiner() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Level = 3;
  bool ProjectToLimit = true;
  double FeatureAngle = 0.0;
  int OutputPointsPrecision = DEFAULT_PRECISION;

private:
  vtkOpenSubdivRefiner(const vtkOpenSubdivRefiner&) = delete;
  void operator=(const vtkOpenSubdivRefiner&) = delete;
};

#endif
