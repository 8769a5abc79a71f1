// Folds of a smoothed mesh (issue 13): new triangles turned over against the
// surface, and new self-intersections, counted from the filter's output alone
// (its NewGeometry and OriginalCellId cell arrays and its normals) against its
// input. Used by `silhouette compare --truth` and module.TestNoFolds.
#ifndef FoldCounting_h
#define FoldCounting_h

class vtkPolyData;

namespace silhouette_eval
{

struct FoldCount
{
  /// Changed output triangles (new, or kept with a corner the perturbation
  /// moved) whose geometric normal and that of the input triangle they came
  /// from lie on opposite sides of the sum of their corners' shading
  /// normals (FoldGuard.h's rule: a flat piece of an input triangle is never
  /// turned over, whatever its corners' normals).
  long Flipped = 0;
  /// Pairs of output triangles, at least one of them changed, that cut
  /// through each other (TriangleIntersection.h's rule) where their input
  /// triangles neither cut nor touch (trianglesTouch), or that came from one
  /// input triangle.
  long Intersecting = 0;
  /// The changed output triangles examined.
  long Changed = 0;
};

/// `input`: the triangles given to vtkSilhouetteSmoothingFilter (polygons
/// only, as the filter read them); `output`: its output for one view.
FoldCount CountFolds(vtkPolyData* input, vtkPolyData* output);

} // namespace silhouette_eval

#endif
