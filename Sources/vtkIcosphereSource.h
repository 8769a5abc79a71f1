/**
 * @class   vtkIcosphereSource
 * @brief   a triangulated sphere with every point on the sphere and exact normals
 *
 * vtkIcosphereSource subdivides an icosahedron: each level splits every triangle
 * into four, and the new points are pushed onto the sphere. Level 0 has 20
 * triangles, level 1 has 80, level n has 20 * 4^n. Every point lies exactly on the
 * sphere (up to rounding) and the point normals are the exact sphere normals, so
 * the true silhouette of the surface the mesh samples is known in closed form:
 * the reference for silhouette-accuracy measurements. The mesh is a closed
 * manifold with outward orientation.
 */
#ifndef vtkIcosphereSource_h
#define vtkIcosphereSource_h

#include "SilhouetteSmoothingFiltersSourcesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class SILHOUETTESMOOTHINGFILTERSSOURCES_EXPORT vtkIcosphereSource : public vtkPolyDataAlgorithm
{
public:
  static vtkIcosphereSource* New();
  vtkTypeMacro(vtkIcosphereSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Subdivision level: 20 * 4^level triangles. Default 1 (80 triangles).
   */
  vtkSetClampMacro(SubdivisionLevel, int, 0, 8);
  vtkGetMacro(SubdivisionLevel, int);
  ///@}

  ///@{
  /**
   * Sphere radius (default 1) and centre (default the origin).
   */
  virtual void SetRadius(double); ///< clamped to [0.0, inf] with a warning; NaN refused
  vtkGetMacro(Radius, double);
  vtkSetVector3Macro(Center, double);
  vtkGetVectorMacro(Center, double, 3);
  ///@}

protected:
  vtkIcosphereSource();
  ~vtkIcosphereSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SubdivisionLevel = 1;
  double Radius = 1.0;
  double Center[3] = { 0.0, 0.0, 0.0 };

private:
  vtkIcosphereSource(const vtkIcosphereSource&) = delete;
  void operator=(const vtkIcosphereSource&) = delete;
};

#endif
