// Where the points and cells of a mesh vtkSilhouetteSmoothingFilter writes
// take their attributes from in its input (part of
// vtkSilhouetteFilterSupport, in a header of its own with VTK types only, so
// that the render-time mapper's module can use it too). Private to the
// modules' build (not wrapped, not installed).
#ifndef vtkSilhouetteAttributeSources_h
#define vtkSilhouetteAttributeSources_h

#include "vtkType.h"

#include <array>
#include <vector>

class vtkCellData;
class vtkDataSetAttributes;
class vtkPointData;
class vtkPolyData;
class vtkUnsignedCharArray;

namespace vtkSilhouetteFilterSupport
{

/// Where one output point's attributes come from: a copy of an input
/// point, or an added point as a weighted sum of input points (weights sum
/// to one), interpolated by VTK's rules.
struct PointSource
{
  /// The input point copied, or -1 for an interpolated point.
  vtkIdType Copied = -1;
  std::array<vtkIdType, 3> Ids{ { 0, 0, 0 } };
  std::array<double, 3> Weights{ { 1.0, 0.0, 0.0 } };

  static PointSource Copy(vtkIdType point);
  /// The point whose values an interpolated point takes of the arrays VTK
  /// does not interpolate (ids, labels, strings): the copied point, else the
  /// source of the largest weight.
  vtkIdType Nearest() const;
};

/// Enough to fill a mesh's point and cell data again from its input's
/// arrays alone, without smoothing again: for an input whose arrays change
/// and whose geometry does not (new scalars on a still mesh).
struct AttributeSources
{
  std::vector<PointSource> Points;
  /// The input cell of each output cell.
  std::vector<vtkIdType> Cells;
};

/// Fills `out` with `in`'s point data for `leadingCopies` copies of input
/// points 0, 1, ... (copied as one block), then a point for each of `rest`:
/// VTK's interpolation rules, the arrays they leave out copied from the
/// nearest source under their own names, and `OriginalPointId`, each copied
/// point's input point (-1 for the interpolated), composed with an input
/// array of that name. The input's normals are left out: the caller sets the
/// shading normals.
void FillPointData(vtkPointData* in, vtkPointData* out, vtkIdType leadingCopies,
  const std::vector<PointSource>& rest);

/// Output cell c takes the data of input cell origin[c] (the arrays VTK's
/// rules leave out as plain copies), with `newGeometry` and
/// `OriginalCellId` (origin composed with an input array of that name).
void FillCellData(vtkCellData* in, vtkCellData* out, const std::vector<vtkIdType>& origin,
  vtkUnsignedCharArray* newGeometry);

/// Refills `mesh`'s point and cell data from `input`'s arrays as
/// `sources` says, keeping the mesh's normals and NewGeometry (which follow
/// the geometry, not the input's arrays). Returns false, and leaves the mesh
/// as it was, when `sources` does not describe it (other counts, a source
/// past the input's points or cells, no NewGeometry).
bool RefillAttributes(vtkPolyData* input, const AttributeSources& sources, vtkPolyData* mesh);

/// Copies of every `in` array that VTK's attribute rules left out of `out`
/// (vtkIdType and string arrays, global and pedigree ids) but `skip`:
/// from[i] is the input tuple of output tuple i. They come out as plain
/// arrays under their own names: ids repeated on copies are no longer
/// unique.
void AddUncopiedArrays(vtkDataSetAttributes* in, vtkDataSetAttributes* out,
  const std::vector<vtkIdType>& from, const char* skip);

} // namespace vtkSilhouetteFilterSupport

#endif
