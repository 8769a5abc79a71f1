/**
 * @class   vtkCreaseAndBorderLines
 * @brief   the creases, open borders and self-intersections of a surface as polylines, for a line
 * drawing
 *
 * Input: a surface (polygons and strips are read as triangles; vertex and
 * line cells are ignored). Points at equal coordinates (or within
 * WeldTolerance) are one vertex, so the copies a surface keeps along its
 * hard edges and texture seams do not open it. An edge is drawn as
 * - a border (LineKind 2) when one triangle has it;
 * - a crease (LineKind 1) when the surface has point normals and they jump
 *   across the edge: the two sides use copies of an end whose normals
 *   differ by more than NormalJumpAngle. This is how
 *   vtkSilhouetteSmoothingFilter's output marks its feature edges (one
 *   normal per side), with each smoothed feature curve sampled as the
 *   surface is, and how vtkPolyDataNormals with splitting marks edges
 *   sharper than its feature angle. A texture seam, whose copies share the
 *   normal, is not a crease. Without point normals, a crease is an edge
 *   whose faces meet at more than FeatureAngle degrees. Edges of more than
 *   two triangles are creases too.
 * Polylines stop where other than two lines of a kind meet (a box's
 * corners); closed loops repeat their first point at the end.
 *
 * Where parts of the surface pass through each other (two spheres joined
 * without a union, a figure's head sunk into its body, as asset files often
 * overlap their parts), the curve where they meet is an edge of the image
 * too: drawn as an intersection line (LineKind 3) when Intersections is on,
 * its points new, on both triangles, with point data interpolated on one of
 * them. Triangles sharing a vertex are not tested, and a curve that runs
 * through a vertex of both parts may lose the short pieces beside it.
 *
 * Output: polylines that lie on the surface (crease and border lines are
 * its edges), so vtkSilhouetteLineVisibility tests them against that
 * surface without a tolerance (see its EdgeTolerance); the points they use,
 * with the surface's point data; cell `LineKind` (unsigned char: 1 crease,
 * 2 border, 3 intersection; 0 is the silhouette, as in the smoothing
 * filters' line outputs, so they append into one drawing); field data
 * `CreaseLineCount`, `BorderLineCount` and `IntersectionLineCount`. Points with NaN or infinite
 * coordinates make the request fail with an error.
 * @sa vtkSilhouetteLineVisibility vtkSilhouetteSmoothingFilter vtkFeatureEdges
 */
#ifndef vtkCreaseAndBorderLines_h
#define vtkCreaseAndBorderLines_h

#include "SilhouetteSmoothingFiltersLinesModule.h" // For export macro
#include "vtkSilhouettePolyDataAlgorithm.h"        // For the superclass

class SILHOUETTESMOOTHINGFILTERSLINES_EXPORT vtkCreaseAndBorderLines
  : public vtkSilhouettePolyDataAlgorithm
{
public:
  static vtkCreaseAndBorderLines* New();
  vtkTypeMacro(vtkCreaseAndBorderLines, vtkSilhouettePolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Draw creases (default on) and open borders (default on).
   */
  vtkSetMacro(Creases, vtkTypeBool);
  vtkGetMacro(Creases, vtkTypeBool);
  vtkBooleanMacro(Creases, vtkTypeBool);
  vtkSetMacro(Borders, vtkTypeBool);
  vtkGetMacro(Borders, vtkTypeBool);
  vtkBooleanMacro(Borders, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Draw where the surface passes through itself (default on). It costs a
   * search of the whole surface for triangles that cut each other, about as
   * much as the creases and borders.
   */
  vtkSetMacro(Intersections, vtkTypeBool);
  vtkGetMacro(Intersections, vtkTypeBool);
  vtkBooleanMacro(Intersections, vtkTypeBool);
  ///@}

  ///@{
  /**
   * With point normals: copies of a point whose normals differ by more than
   * this many degrees make the edges between them creases. Default 1;
   * clamped to [0, 180].
   */
  virtual void SetNormalJumpAngle(double degrees);
  vtkGetMacro(NormalJumpAngle, double);
  ///@}

  ///@{
  /**
   * Without point normals: edges whose faces meet at more than this many
   * degrees (the angle between their normals) are creases. Default 30;
   * clamped to [0, 180].
   */
  virtual void SetFeatureAngle(double degrees);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * 0 (the default): points at equal coordinates are one vertex. d > 0:
   * points within d of each other are, transitively, as
   * vtkSilhouetteSmoothingFilter welds with its WeldTolerance; draw a
   * surface that filter made with the tolerance it used. Otherwise the near
   * copies an exporter leaves (OpenSCAD's STL files round the points where
   * two solids meet, joined by sliver triangles) cut the surface, and the
   * slivers' arbitrary facets and normals make creases along them. Clamped
   * to at least 0.
   */
  virtual void SetWeldTolerance(double tolerance);
  vtkGetMacro(WeldTolerance, double);
  ///@}

protected:
  vtkCreaseAndBorderLines();
  ~vtkCreaseAndBorderLines() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkTypeBool Creases = 1;
  vtkTypeBool Borders = 1;
  vtkTypeBool Intersections = 1;
  double NormalJumpAngle = 1.0;
  double FeatureAngle = 30.0;
  double WeldTolerance = 0.0;

private:
  vtkCreaseAndBorderLines(const vtkCreaseAndBorderLines&) = delete;
  void operator=(const vtkCreaseAndBorderLines&) = delete;
};

#endif
