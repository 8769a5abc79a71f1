/**
 * @class   vtkFaceSilhouetteLines
 * @brief   the face-based silhouette of a triangle mesh: straight segments across its silhouette
 * triangles
 *
 * The silhouette of the linearly interpolated visibility g = N . (E - V)
 * (A. Hertzmann and D. Zorin, "Illustrating smooth surfaces", SIGGRAPH 2000;
 * the "face-based silhouette" of Xing's Fig. 6b). A vertex is visible when
 * g >= 0, with the same shading normals, eye and rule as
 * vtkSilhouetteSmoothingFilter; a triangle whose vertices differ is a
 * silhouette triangle, and g interpolated linearly over it is zero on one
 * straight segment between the zero crossings of its two mixed edges. This
 * filter outputs those segments, chained across triangles into polylines.
 * Nothing is re-meshed: it is the unsmoothed line drawing that the smoothed
 * silhouette of vtkSilhouetteSmoothingFilter's second port replaces.
 *
 * Unlike vtkPolyDataSilhouette, which outputs mesh edges between front- and
 * back-facing faces (a zig-zag along the triangles), these lines cross the
 * triangles, with one point per mixed edge computed once per edge: the two
 * triangles of an edge share it, so the polylines have no cracks, and on a
 * closed mesh every polyline is a closed loop (its last point id is its
 * first).
 *
 * Input: a vtkPolyData; polygons (as fans) and triangle strips are used,
 * vertices and lines ignored. Point normals (the active normals) are the
 * shading normals when present, otherwise area-weighted vertex normals are
 * computed (vtkSilhouetteSmoothingFilter's default NormalEstimation).
 *
 * The view: a camera (SetCamera, or the active camera of SetRenderer) and
 * optionally the prop (SetProp3D) or its matrix (SetModelMatrix), as for
 * vtkSilhouetteSmoothingFilter (from vtkSilhouetteViewAlgorithm); GetMTime()
 * changes when the camera or the matrix changes by value (not when only the
 * clipping range does). The viewport size plays no part (neither the
 * renderer's nor SetViewportSize's). Before a renderer has created its
 * camera, the output is empty.
 *
 * Output: polylines. Point arrays:
 * - `Normals` (float): the normalised linear interpolation of the shading
 *   normals along the edge (the active normals);
 * - `EdgeEnds` (vtkIdType, 2 components): the input point ids of the edge the
 *   point lies on, lower id first (where several input points share a
 *   position, the lowest of them: the mesh is prepared as
 *   vtkSilhouetteSmoothingFilter prepares it by default, welded at equal
 *   positions and consistently oriented, so triangle soups and texture seams
 *   give the lines of the surface they stand for);
 * - `EdgeParameter` (double): t such that the point is (1 - t) * first end +
 *   t * second end;
 * - every other input point array, interpolated linearly along the edge.
 * Cell array `LineKind` (unsigned char, 0 = silhouette, as vtkCreaseAndBorderLines
 * numbers the kinds of a line drawing).
 * Field data `SilhouetteTriangleCount` (vtkIdType): how many triangles the
 * lines cross (one segment each).
 *
 * Awkward input: an empty input gives an empty output; NaN or infinite
 * coordinates, cells naming missing points, a missing camera or a degenerate
 * view fail the request with an error; triangles repeating a point id are
 * skipped; at an edge shared by more than two triangles a polyline ends.
 *
 * @sa vtkSilhouetteSmoothingFilter vtkSilhouetteViewAlgorithm vtkPolyDataSilhouette
 */
#ifndef vtkFaceSilhouetteLines_h
#define vtkFaceSilhouetteLines_h

#include "SilhouetteSmoothingFiltersLinesModule.h" // For export macro
#include "vtkSilhouetteViewAlgorithm.h"

#include <memory> // For the cached core mesh

class SILHOUETTESMOOTHINGFILTERSLINES_EXPORT vtkFaceSilhouetteLines
  : public vtkSilhouetteViewAlgorithm
{
public:
  static vtkFaceSilhouetteLines* New();
  vtkTypeMacro(vtkFaceSilhouetteLines, vtkSilhouetteViewAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkFaceSilhouetteLines();
  ~vtkFaceSilhouetteLines() override;

  int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) override;

private:
  vtkFaceSilhouetteLines(const vtkFaceSilhouetteLines&) = delete;
  void operator=(const vtkFaceSilhouetteLines&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
