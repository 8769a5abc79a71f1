/**
 * The output builders of vtkSilhouetteSmoothingFilter: its mesh (points with
 * the input's point data, cells with the input's cell data, feature copies
 * and new points interpolated), its silhouette lines and the changed-cells
 * output of BuildChanges. Private to the module: not wrapped or installed.
 */
#ifndef vtkSilhouetteSmoothingOutput_h
#define vtkSilhouetteSmoothingOutput_h

#include "vtkFloatArray.h"
#include "vtkSilhouetteAttributeSources.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include "SilhouetteSmoother.h"
#include "WeldedSurface.h"

#include <cstdint>
#include <vector>

class vtkCellData;
class vtkDataSetAttributes;
class vtkFieldData;
class vtkPointData;
class vtkPoints;
class vtkPolyData;

namespace vtkSilhouetteSmoothingOutput
{

void AddCount(vtkFieldData* fd, const char* name, vtkIdType value);

int OutputPointType(vtkPolyData* input, int precision);

// Input points (ids kept), copies of input points for extra smooth groups,
// then the added points; points lowered by the perturbation move in every
// copy. With `only`, just those output points (ascending ids), in order.
vtkSmartPointer<vtkPoints> BuildPoints(vtkPolyData* input, int pointType,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only = nullptr);

// Input point arrays are copied and extended with values interpolated for the
// added points (VTK's interpolation rules; the arrays those rules do not
// interpolate take the nearest source's value). The shading normals replace
// the input's normals (if any) as the active normals, keeping the input's
// array name. `OriginalPointId` gives every output point's input point (-1
// for added points), composed with an input array of that name. With
// `only`, just those output points (ascending ids), in order.
void BuildPointData(vtkPointData* in, vtkPointData* out, vtkIdType numPoints,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only = nullptr);

// Where output points first..end-1 (with `only`, points only[first] ..
// only[end - 1]) take their attributes from: BuildPointData's sources.
std::vector<vtkSilhouetteFilterSupport::PointSource> PointSourcesOf(
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, vtkIdType first, vtkIdType end,
  const std::vector<vtkIdType>* only = nullptr);

// BuildPointData's shading normals (as the input's own winding faces),
// named as the input's normals, else "Normals".
vtkSmartPointer<vtkFloatArray> ShadingNormals(vtkPointData* in,
  const silsmooth::WeldedSurface& surface, const silsmooth::SmoothingResult& result,
  const silsmooth::SurfaceFrame& frame, const std::vector<vtkIdType>* only = nullptr);

// Verts and lines pass through (PassVertsAndLines: `droppedCells` counts the
// ones left out); polygons and strips become the frame's triangles, written
// by the surface straight into the cell arrays. `OriginalCellId` is composed
// with an input array of that name.
silsmooth::SurfaceFrame BuildCells(vtkPolyData* input, vtkPolyData* output,
  const std::vector<vtkIdType>& triangleCell, const silsmooth::WeldedSurface& surface,
  const silsmooth::SmoothingResult& result, vtkIdType& droppedCells);

// The cell data BuildCells gives a frame that re-meshes nothing (the base
// mesh: its verts and lines, then one triangle per input triangle, in input
// order), without building the cells again: for a mesh whose points moved
// and whose cells did not.
void BuildBaseCellData(
  vtkPolyData* input, vtkCellData* output, const std::vector<vtkIdType>& triangleCell);

// The output points a frame's changed triangles use, ascending, and each
// one's place among them: a bit per output point, ranked by counting bits.
// Sorting the triangles' corners and searching the list for each corner
// cost about 3 ms a frame at 9,000 new triangles; this costs a pass over
// the bits.
class UsedPoints
{
public:
  /// `pointCount`: the output's point count (every corner is below it).
  UsedPoints(const std::vector<silsmooth::Triangle>& triangles, std::size_t pointCount);
  const std::vector<vtkIdType>& ids() const { return this->Ids; }
  /// The place of output point `id` in ids(); `id` must be used.
  vtkIdType indexOf(silsmooth::Id id) const;

private:
  std::vector<std::uint64_t> Bits;
  std::vector<vtkIdType> Before; // used points below each 64-bit word
  std::vector<vtkIdType> Ids;
};

// A frame's changes (WeldedSurface::assembleChanges) as a mesh of their own:
// the triangles over the output points they use (`used`), each with its
// input cell's data, NewGeometry and OriginalCellId as the whole output
// gives them. Returns the input cell of each changed cell.
std::vector<vtkIdType> BuildChangedCells(vtkPolyData* input, vtkPolyData* changes,
  const std::vector<vtkIdType>& triangleCell, const silsmooth::SurfaceFrame& frame,
  const UsedPoints& used);

// Output port 1: the silhouette polylines over their own compact point set.
void BuildSilhouetteLines(
  vtkPolyData* mesh, const silsmooth::SurfaceFrame& frame, vtkPolyData* lines);

} // namespace vtkSilhouetteSmoothingOutput

#endif
