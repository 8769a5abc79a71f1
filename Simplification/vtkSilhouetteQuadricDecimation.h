/**
 * @class   vtkSilhouetteQuadricDecimation
 * @brief   quadric edge-collapse decimation to a triangle count, keeping more detail near the
 * contour
 *
 * Garland-Heckbert quadric edge collapse with the error rule of Mata, Pastor
 * and Rodriguez: a point whose silhouette distance label (the point array
 * `SilhouetteDistance` of vtkSilhouetteProximity, or the array named by
 * DistanceArrayName) lies in [NearMinimum, NearMaximum] may take f * e of
 * error, f = NearFactor, where the others take e. With a triangle budget e is
 * not chosen up front: collapses are taken in order of cost (cost / f near
 * the contour) until the mesh has at most TargetTriangles triangles, and e is
 * the largest rank taken (Common/Core/QuadricSimplifier.h has the details).
 * Without the array, or with NearFactor 1, it is a plain quadric decimation.
 *
 * Errors are quadric errors: the sum of squared distances from a point to
 * the planes of the input triangles merged into it (squared model units).
 *
 * Topology: collapses keep the link condition and never turn a triangle
 * over, so a closed manifold stays a closed manifold of the same genus;
 * points on boundary and non-manifold edges do not move. Polygons and strips
 * are triangulated; vertices and lines are dropped.
 *
 * Output: the triangles, with every input point array copied from the input
 * point each output point kept the id of, and
 * - point `QuadricError` (double): the point's quadric error;
 * - point `NearContour` (unsigned char): 1 where the f * e bound applies;
 * - point `OriginalPointId` (vtkIdType);
 * - field data `ErrorThreshold` (double, e), `ReachedTarget` (int),
 *   `InputTriangleCount`, `OutputTriangleCount` (vtkIdType).
 * When the budget cannot be met (NearFactor 0 forbids collapses near the
 * contour) the filter warns and outputs the mesh it got to.
 *
 * Progress is reported during the collapses (every 256); AbortExecute stops
 * them there and leaves the output empty.
 *
 * @sa vtkSilhouetteProximity vtkQuadricDecimation
 */
#ifndef vtkSilhouetteQuadricDecimation_h
#define vtkSilhouetteQuadricDecimation_h

#include "SilhouetteSmoothingFiltersSimplificationModule.h" // For export macro
#include "vtkSilhouettePolyDataAlgorithm.h"                 // For the superclass

#include <string> // For the array name

class SILHOUETTESMOOTHINGFILTERSSIMPLIFICATION_EXPORT vtkSilhouetteQuadricDecimation
  : public vtkSilhouettePolyDataAlgorithm
{
public:
  static vtkSilhouetteQuadricDecimation* New();
  vtkTypeMacro(vtkSilhouetteQuadricDecimation, vtkSilhouettePolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Stop at this many triangles or fewer (at least 4). Default 1000. */
  vtkSetClampMacro(TargetTriangles, vtkIdType, 4, VTK_ID_MAX);
  vtkGetMacro(TargetTriangles, vtkIdType);
  ///@}

  ///@{
  /** The distance interval, in grid cells, that counts as near. Default [1, 3]. */
  virtual void SetNearMinimum(double); ///< NaN refused with a warning
  vtkGetMacro(NearMinimum, double);
  virtual void SetNearMaximum(double); ///< NaN refused with a warning
  vtkGetMacro(NearMaximum, double);
  ///@}

  ///@{
  /** f: the error allowed near the contour is f * e. Default 0.1. */
  virtual void SetNearFactor(double); ///< clamped to [0.0, inf] with a warning; NaN refused
  vtkGetMacro(NearFactor, double);
  ///@}

  ///@{
  /**
   * The point array of distance labels. Default "SilhouetteDistance"; an
   * empty name (or a missing array) makes it a plain quadric decimation.
   */
  void SetDistanceArrayName(const std::string& name);
  const std::string& GetDistanceArrayName() const { return this->DistanceArrayName; }
  ///@}

protected:
  vtkSilhouetteQuadricDecimation() = default;
  ~vtkSilhouetteQuadricDecimation() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType TargetTriangles = 1000;
  double NearMinimum = 1.0;
  double NearMaximum = 3.0;
  double NearFactor = 0.1;
  std::string DistanceArrayName = "SilhouetteDistance";

private:
  vtkSilhouetteQuadricDecimation(const vtkSilhouetteQuadricDecimation&) = delete;
  void operator=(const vtkSilhouetteQuadricDecimation&) = delete;
};

#endif
