/**
 * @class   vtkPNTriangleFilter
 * @brief   curved PN triangles (Vlachos et al. 2001), tessellated uniformly
 *
 * A. Vlachos, J. Peters, C. Boyd, J. L. Mitchell, "Curved PN Triangles",
 * I3D 2001, the view-independent method the 2008 paper's Table I compares
 * with: every triangle becomes a cubic Bezier triangle built from its
 * corners' positions and normals, with quadratic normals, tessellated with
 * `Level` points inserted on every edge, so each input triangle gives
 * (Level + 1)^2 triangles (Baselines/Core/PNTriangles.h has the formulas).
 *
 * Input: a vtkPolyData; polygons are fan-triangulated, strips split; point
 * normals are used when present (zero ones are replaced), angle-weighted
 * normals otherwise. Output: the input's points first (ids and positions
 * kept), then the edge points (shared by the triangles of an edge, so a
 * closed input gives a watertight output), then the interior points; point
 * `Normals` (the patch normals), other point data interpolated
 * barycentrically, cell `NewGeometry` (1 for every triangle of a patch, 0
 * when Level is 0), `OriginalCellId`, cell data copied. Verts and lines pass
 * through.
 */
#ifndef vtkPNTriangleFilter_h
#define vtkPNTriangleFilter_h

#include "SilhouetteSmoothingFiltersBaselinesModule.h" // For export macro
#include "vtkSilhouettePolyDataAlgorithm.h"            // For the superclass

class SILHOUETTESMOOTHINGFILTERSBASELINES_EXPORT vtkPNTriangleFilter
  : public vtkSilhouettePolyDataAlgorithm
{
public:
  static vtkPNTriangleFilter* New();
  vtkTypeMacro(vtkPNTriangleFilter, vtkSilhouettePolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Points inserted on every edge (k). Default 2 (9 triangles per input
   * triangle).
   */
  vtkSetClampMacro(Level, int, 0, 64);
  vtkGetMacro(Level, int);
  ///@}

protected:
  vtkPNTriangleFilter() = default;
  ~vtkPNTriangleFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Level = 2;

private:
  vtkPNTriangleFilter(const vtkPNTriangleFilter&) = delete;
  void operator=(const vtkPNTriangleFilter&) = delete;
};

#endif
