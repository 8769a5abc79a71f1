/**
 * @class   vtkTorusSurfaceSource
 * @brief   a closed triangulated torus with points on the torus and exact normals
 *
 * vtkTorusSurfaceSource samples the torus
 * ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) on a regular U x V grid and
 * splits each quad into two triangles. The seams are joined, so the mesh is a
 * closed manifold of genus one with outward orientation; the point normals are the
 * exact torus normals (cos v cos u, cos v sin u, sin v). The axis is +Z. Its inner
 * silhouette is a saddle region, where smoothed silhouettes turn concave.
 */
#ifndef vtkTorusSurfaceSource_h
#define vtkTorusSurfaceSource_h

#include "SilhouetteSmoothingFiltersSourcesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class SILHOUETTESMOOTHINGFILTERSSOURCES_EXPORT vtkTorusSurfaceSource : public vtkPolyDataAlgorithm
{
public:
  static vtkTorusSurfaceSource* New();
  vtkTypeMacro(vtkTorusSurfaceSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Distance from the axis to the tube's centre (default 1) and the tube's
   * radius (default 0.4).
   */
  virtual void SetRingRadius(double); ///< clamped to [0.0, inf] with a warning; NaN refused
  vtkGetMacro(RingRadius, double);
  virtual void SetTubeRadius(double); ///< clamped to [0.0, inf] with a warning; NaN refused
  vtkGetMacro(TubeRadius, double);
  ///@}

  ///@{
  /**
   * Samples around the ring (default 24) and around the tube (default 12).
   * At least 3 each. The mesh has U * V points and 2 * U * V triangles; an
   * update with more than MaximumPoints points (about 450 MB of mesh) fails
   * with an error.
   */
  vtkSetClampMacro(RingResolution, int, 3, VTK_INT_MAX);
  vtkGetMacro(RingResolution, int);
  vtkSetClampMacro(TubeResolution, int, 3, VTK_INT_MAX);
  vtkGetMacro(TubeResolution, int);
  static constexpr vtkIdType MaximumPoints = vtkIdType(1) << 22; // 4,194,304: 2048 x 2048
  ///@}

protected:
  vtkTorusSurfaceSource();
  ~vtkTorusSurfaceSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double RingRadius = 1.0;
  double TubeRadius = 0.4;
  int RingResolution = 24;
  int TubeResolution = 12;

private:
  vtkTorusSurfaceSource(const vtkTorusSurfaceSource&) = delete;
  void operator=(const vtkTorusSurfaceSource&) = delete;
};

#endif
