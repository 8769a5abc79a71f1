/**
 * @class   vtkPhongTessellationFilter
 * @brief   Phong tessellation (Boubekeur and Alexa 2008), tessellated uniformly
 *
 * T. Boubekeur, M. Alexa, "Phong Tessellation", ACM TOG 27(5), SIGGRAPH Asia
 * 2008, a view-independent peer of vtkPNTriangleFilter: every triangle
 * becomes a quadratic patch, the flat point moved towards the mean of its
 * projections onto the corners' tangent planes by `ShapeFactor`, with Phong
 * normals (the corner normals interpolated linearly, normalised). It is
 * tessellated with `Level` points inserted on every edge, so each input
 * triangle gives (Level + 1)^2 triangles (Baselines/Core/PhongTessellation.h
 * has the formulas).
 *
 * Input: a vtkPolyData; polygons are fan-triangulated, strips split; point
 * normals are used when present (zero ones are replaced), angle-weighted
 * normals otherwise. NaN or infinite coordinates fail the request. Output:
 * the input's points first (ids and positions kept), then the edge points
 * (shared by the triangles of an edge, so a closed input gives a watertight
 * output), then the interior points; point `Normals` (the Phong normals),
 * other point data interpolated barycentrically (at the flat point), cell
 * `NewGeometry` (1 for every triangle of a patch, 0 when Level is 0),
 * `OriginalCellId`, cell data copied. Verts and lines pass through.
 *
 * @sa vtkPNTriangleFilter
 */
#ifndef vtkPhongTessellationFilter_h
#define vtkPhongTessellationFilter_h

#include "SilhouetteSmoothingFiltersBaselinesModule.h" // For export macro
#include "vtkSilhouettePolyDataAlgorithm.h"            // For the superclass

class SILHOUETTESMOOTHINGFILTERSBASELINES_EXPORT vtkPhongTessellationFilter
  : public vtkSilhouettePolyDataAlgorithm
{
public:
  static vtkPhongTessellationFilter* New();
  vtkTypeMacro(vtkPhongTessellationFilter, vtkSilhouettePolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Points inserted on every edge (k). Default 2 (9 triangles per input
   * triangle).
   */
  vtkSetClampMacro(Level, int, 0, 64);
  vtkGetMacro(Level, int);
  ///@}

  ///@{
  /**
   * How far the points move from the flat triangle towards the tangent
   * planes' patch: 0 is the flat tessellation, 1 the full projection. Default
   * 0.75, the paper's.
   */
  virtual void SetShapeFactor(double); ///< clamped to [0.0, 1.0] with a warning; NaN refused
  vtkGetMacro(ShapeFactor, double);
  ///@}

protected:
  vtkPhongTessellationFilter() = default;
  ~vtkPhongTessellationFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Level = 2;
  double ShapeFactor = 0.75;

private:
  vtkPhongTessellationFilter(const vtkPhongTessellationFilter&) = delete;
  void operator=(const vtkPhongTessellationFilter&) = delete;
};

#endif
