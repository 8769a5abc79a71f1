// Outline fidelity against the true shape (issue 13): how near each method's
// outline of a coarse version of a real mesh comes to the outline of the
// mesh it was made from, from the same cameras.
//
// The truth: the original dense mesh refined by an interpolating scheme
// (VTK's Butterfly subdivision, two levels), which passes through the
// original's points and so does not shrink the shape as Loop's approximating
// limit does; and the original itself. The coarse version: our link-condition
// quadric decimation, every point moved onto the original surface (or, as an
// option, onto the reference). Methods,
// all from that coarse version: the raw coarse mesh; coarse + silhouette
// smoothing with its own normals, and with the original's normals carried to
// the coarse points (a user may or may not have a fine mesh), and with the
// fold guard off; PN triangles and Phong tessellation from the coarse mesh
// with the normals ours uses by default (area-weighted), at the level whose
// triangle count is nearest ours, and at level 3.
#ifndef FidelityEvaluation_h
#define FidelityEvaluation_h

#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

namespace silhouette_eval
{

struct FidelityOptions
{
  int Width = 1024;
  int Height = 768;
  int Views = 12;
  double Tolerance = 0.5;
  int CoarseTriangles = 500;
  int ReferenceLevels = 2; ///< Butterfly subdivision levels of the original
  int HighLevel = 3;       ///< the peers' fixed level
  /// Where the coarse version's points are moved: onto the original (false,
  /// the protocol of issue 13) or onto the reference (true). The original's
  /// facets lie inside the reference, so points on them sit inside the true
  /// shape, a bias every interpolating method inherits (docs/fidelity.md);
  /// on the reference the coarse points sample the true shape itself, and
  /// "carried normals" are the reference's.
  bool CoarsePointsOnReference = false;
  std::function<void(const std::string&)> Progress;
};

struct FidelityRow
{
  std::string Method;
  double Triangles = 0; ///< rendered, averaged over the views
  /// Outline distance to the interpolating reference, px: the mean over the
  /// views of each view's mean, and the largest of any view.
  double Mean = 0;
  double Max = 0;
  /// The same against the original mesh itself.
  double MeanToOriginal = 0;
  double MaxToOriginal = 0;
  /// Where Max is: the first view (0-based) with it, and whether the
  /// method's outline lies outside the reference's there (an overshoot) or
  /// inside it (a part shrunk, or a gap seen through the mesh that the
  /// reference has not); BoundaryDistance::FarthestOutside.
  int WorstView = -1;
  bool WorstOutside = false;
  /// Ours only (-1 for the others), summed over the views: output
  /// triangles turned over and pairs cutting through each other where the
  /// input did not (FoldCounting.h; the folds of issue 13), and the
  /// silhouette triangles the fold guard re-meshed along the chord.
  long TurnedOver = -1;
  long Cutting = -1;
  long ChordFallbacks = -1;
};

struct FidelityResult
{
  std::string Name;
  long OriginalTriangles = 0;
  long CoarseTriangles = 0;
  long ReferenceTriangles = 0;
  /// How far the reference strays from the original: the largest distance
  /// of a reference point from the original surface, outside (positive)
  /// and inside (negative), as fractions of the original's bounding-box
  /// diagonal. Butterfly subdivision overshoots at sharp creases (the
  /// hand's flat wrist: 0.044 outside, about 26 px), and every method is
  /// then measured against that error too.
  double ReferenceOutside = 0;
  double ReferenceInside = 0;
  bool CoarsePointsOnReference = false; ///< as FidelityOptions'
  /// coarse; ours with the coarse mesh's own normals estimated by angle,
  /// area, Max's weights and a quadric fit; ours with carried normals; ours
  /// (area) without the fold guard; then the peers.
  std::vector<FidelityRow> Rows;
};

/// Throws std::runtime_error when the original is not a closed manifold of
/// triangles or a step fails.
FidelityResult EvaluateFidelity(
  const std::string& name, vtkPolyData* original, const FidelityOptions& options);

/// The Butterfly refinement of a closed triangle mesh (64-bit cells, as VTK
/// 9.1's filter needs).
vtkSmartPointer<vtkPolyData> InterpolatingRefinement(vtkPolyData* original, int levels);

} // namespace silhouette_eval

#endif
