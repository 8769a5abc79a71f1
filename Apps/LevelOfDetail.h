// `render --lod` and `view --lod`: the input refined for the view by
// vtkViewDependentLevelOfDetail before it is smoothed and drawn (issue 18).
#ifndef LevelOfDetail_h
#define LevelOfDetail_h

#include "CommandLine.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkCamera;
class vtkPolyData;

namespace cli
{

struct LevelOfDetailRun
{
  vtkSmartPointer<vtkPolyData> Mesh; ///< the extracted mesh, for this view
  long long InputTriangles = 0;
  long long Triangles = 0;
  double BuildMilliseconds = 0.0; ///< the hierarchy and the first cut
  /// One line for people: the counts and the time.
  std::string summary() const;
};

/// Refines `mesh` for `camera` and the viewport of `options` with the filter's
/// default tolerances. Throws RuntimeError on any VTK error.
LevelOfDetailRun ExtractForView(vtkPolyData* mesh, vtkCamera* camera, const CameraOptions& options);

} // namespace cli

#endif
