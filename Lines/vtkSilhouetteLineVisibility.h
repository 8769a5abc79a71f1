/**
 * @class   vtkSilhouetteLineVisibility
 * @brief   splits lines into the pieces a surface hides from the camera and the pieces it
 * does not
 *
 * Input 0: lines (polylines or lines, such as vtkSilhouetteSmoothingFilter's
 * second output, the smoothed silhouette); input 1 (SetSurfaceConnection):
 * the surface that may hide them (such as the same filter's first output),
 * in the same model coordinates. The view is given as for every
 * view-dependent filter of the module (vtkSilhouetteViewAlgorithm: a camera
 * or a renderer, and the prop's matrix).
 *
 * A point of a line is hidden when the ray from it towards the eye crosses
 * the surface farther than Tolerance from it: lines on the surface
 * (silhouettes graze it) are not hidden by the triangles they lie on, and,
 * with OutlinePixels, a silhouette is drawn where it is the surface's
 * outline.
 * Each line is split where its visibility changes, the change located by
 * bisection along the segment; the output holds every input vertex, in
 * order, plus a point at each change, shared by the pieces on its two sides.
 *
 * Output: one polyline per piece; the point array `Visible` and the cell
 * array `Visible` (unsigned char, 1 visible, 0 hidden); the input's point
 * data (interpolated at change points) and cell data (copied to each piece
 * of the cell); the cell array `OriginalCellId` (the input line); field data
 * `VisiblePieceCount` and `HiddenPieceCount`. With PassHiddenLines off, the
 * hidden pieces are left out.
 *
 * Vertex cells, polygons and strips of input 0 are ignored (with a warning).
 * Without a surface (input 1 empty) every line is visible.
 *
 * Progress is reported every 256 lines; AbortExecute stops there, and the
 * output holds the lines done.
 *
 * @sa vtkSilhouetteSmoothingFilter vtkSilhouetteViewAlgorithm
 */
#ifndef vtkSilhouetteLineVisibility_h
#define vtkSilhouetteLineVisibility_h

#include "SilhouetteSmoothingFiltersLinesModule.h" // For export macro
#include "vtkSilhouetteViewAlgorithm.h"

#include <string> // For CheckSettings

class vtkAlgorithmOutput;

class SILHOUETTESMOOTHINGFILTERSLINES_EXPORT vtkSilhouetteLineVisibility
  : public vtkSilhouetteViewAlgorithm
{
public:
  static vtkSilhouetteLineVisibility* New();
  vtkTypeMacro(vtkSilhouetteLineVisibility, vtkSilhouetteViewAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The surface that hides the lines (input 1).
   */
  void SetSurfaceConnection(vtkAlgorithmOutput* output);
  void SetSurfaceData(vtkDataObject* surface);
  ///@}

  ///@{
  /**
   * Hits nearer a line's point than this, along its ray to the eye, do not
   * hide it, in the data's units. 0 (the default): the surface's mean edge
   * length. Negative, NaN or infinite values fail the
   * request with an error.
   */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * The tolerance, in the data's units, for the lines that lie on the
   * surface itself: cells whose `LineKind` is 1 (crease), 2 (border) or 3
   * (intersection), as vtkCreaseAndBorderLines makes them from the same
   * surface. They lie on it exactly, so only the triangles they lie on must
   * not hide them, and those meet the ray at the line's own point. 0 (the default): 1e-5 of the
   * surface's bounding-box diagonal. (With the silhouette's Tolerance, a mean
   * edge long, a box's hidden edges would show near the visible corners.)
   * Pieces of these lines shorter than ten times this tolerance join their
   * neighbours (the stubs an occluder leaves where it meets the line).
   * Negative, NaN or infinite values fail the
   * request with an error.
   */
  vtkSetMacro(EdgeTolerance, double);
  vtkGetMacro(EdgeTolerance, double);
  ///@}

  ///@{
  /**
   * A silhouette point the tolerance rule hides is kept visible when a point
   * this many pixels beside it, across the line in the image, meets nothing
   * on its way to the eye: the surface's outline passes within that
   * distance. The flat triangles of a smoothed surface can stand a pixel or
   * two beyond its silhouette curve and hide it exactly where it is the
   * outline (gaps in a drawing's outline). Only the point's own sheet, and
   * only within four tolerances of the point, is discounted so: a line
   * passing behind another part keeps its exact change points. Where a
   * contour ends at a cusp (it turns back behind its own sheet), its end
   * moves by up to about twice this distance along the line. The other way
   * round, a silhouette point visible only because the triangles in front
   * of it, within the tolerance, are its own sheet's is hidden when the
   * points 1.5 times this distance beside it on both sides are hidden too:
   * it lies inside the surface's image (the far silhouette of a part thinner
   * than the tolerance, such as a spider's leg), unless it dips inside for
   * less than 8 times this distance between visible pieces and
   * OutlineGapPixels is 0 (with it, the surface's contour closes the
   * outline there). Default 0
   * (off: exact visibility); `silhouette render` uses 1 pixel. Crease and
   * border lines (LineKind 1 and 2) do not use it. Negative, NaN or infinite
   * values fail the request with an error. A positive value makes the output depend on the
   * viewport's size.
   */
  void SetOutlinePixels(double pixels);
  vtkGetMacro(OutlinePixels, double);
  ///@}

  ///@{
  /**
   * Closes the gaps a drawing leaves in the surface's outline. Where a
   * coarse mesh's outline is concave, its silhouette curve can run inside
   * the outline the surface has (its front facets stand beyond the curve,
   * up to several pixels), so the curve is hidden and the outline has no
   * line. With a positive value, the surface's own contour (its edges
   * between a triangle facing the eye and one facing away) is added where
   * it is the outline of the surface's image (the image ends beside it, or
   * jumps in depth by two tolerances) and no visible line of the output
   * covers it: none passes within 1.5 px of it (or this value, when less),
   * nor runs alongside it within this many pixels (its nearest point not an
   * end of the line, its direction within 37 degrees of the contour's: a
   * contour alongside a drawn silhouette would double the stroke). Added
   * pieces are visible pieces of no input cell (`OriginalCellId` -1),
   * `LineKind` 4 when the input has that array, the other arrays' values
   * null. Default 0 (off); `silhouette render` uses 4.
   * Negative, NaN or infinite values fail the
   * request with an error. A positive value makes the output
   * depend on the viewport's size.
   */
  void SetOutlineGapPixels(double pixels);
  vtkGetMacro(OutlineGapPixels, double);
  ///@}

  ///@{
  /**
   * Keep the hidden pieces in the output (flagged 0 in `Visible`). Default on.
   */
  vtkSetMacro(PassHiddenLines, vtkTypeBool);
  vtkGetMacro(PassHiddenLines, vtkTypeBool);
  vtkBooleanMacro(PassHiddenLines, vtkTypeBool);
  ///@}

protected:
  vtkSilhouetteLineVisibility();
  ~vtkSilhouetteLineVisibility() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) override;

  /// The error for settings out of range, else "".
  std::string CheckSettings() const;

  double Tolerance = 0.0;
  double EdgeTolerance = 0.0;
  double OutlinePixels = 0.0;
  double OutlineGapPixels = 0.0;
  vtkTypeBool PassHiddenLines = 1;

private:
  vtkSilhouetteLineVisibility(const vtkSilhouetteLineVisibility&) = delete;
  void operator=(const vtkSilhouetteLineVisibility&) = delete;
};

#endif
