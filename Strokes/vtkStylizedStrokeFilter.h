/**
 * @class   vtkStylizedStrokeFilter
 * @brief   stylized strokes (Kim and Choe): polylines offset by brush functions
 *
 * S.-S. Kim and S.-K. Choe, "Stylized Silhouette Rendering Using Progressive
 * Meshes" (3.4, 3.5): every input line cell (a stroke, e.g. a smoothed
 * silhouette polyline from port 1 of vtkSilhouetteSmoothingFilter) is
 * parameterised by arc length s and each point is moved in the view plane,
 * q = p + v_x(s) T + v_y(s) N, with T the stroke's tangent and N the normal
 * in the plane perpendicular to the line of sight, by one of the paper's
 * four brush functions:
 *
 * - CHARCOAL: high-frequency sawtooth across the stroke,
 * - LAZY: low-frequency parabolic arcs across the stroke,
 * - HAND: low-magnitude smooth noise, along and across the stroke,
 * - ROUGH: high-magnitude noise along the stroke (per point).
 *
 * Strokes/Core/StrokeStylizer.h has the formulas. |v_x| and |v_y| never
 * exceed the amplitude, and Amplitude 0 with Spacing 0 gives the input
 * points back. The noise is seeded (Seed) and repeatable. A closed polyline
 * (last point equal to the first) stays closed without a seam: its
 * wavelength is adjusted so a whole number of periods fits its length.
 *
 * Lengths (Amplitude, Wavelength, Spacing) are fractions of the diagonal of
 * the input's bounding box, as the paper scales its brushes by the object's
 * size (dist_z). The view (vtkSilhouetteViewAlgorithm: SetCamera or
 * SetRenderer, and SetProp3D or SetModelMatrix for data drawn with a model
 * transform) gives the line of sight in the data's model coordinates; the
 * viewport size does not matter. The filter re-executes when the view
 * changes (compared by value). Before a renderer has created its camera the
 * output is empty.
 *
 * Input: lines. Points with NaN or infinite coordinates and lines naming
 * missing points fail the request with an error; an input with cells but no
 * lines gives no strokes, with a warning. A stroke shorter than 4 times the
 * amplitude is drawn with a quarter of its length as its amplitude.
 *
 * Output: one polyline per stroke: per input line cell, or per chain of
 * them with JoinLines (verts and polygons are dropped), with point data
 * `BrushOffset` (2 components: v_x and v_y in world units),
 * `StrokeArcLength`, and cell data `StrokeId` (the index among the line
 * cells of the stroke's first input line, which also seeds its noise).
 * Point data of the input is not carried (resampling adds points).
 */
#ifndef vtkStylizedStrokeFilter_h
#define vtkStylizedStrokeFilter_h

#include "SilhouetteSmoothingFiltersStrokesModule.h" // For export macro
#include "vtkSilhouetteViewAlgorithm.h"

class SILHOUETTESMOOTHINGFILTERSSTROKES_EXPORT vtkStylizedStrokeFilter
  : public vtkSilhouetteViewAlgorithm
{
public:
  static vtkStylizedStrokeFilter* New();
  vtkTypeMacro(vtkStylizedStrokeFilter, vtkSilhouetteViewAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Brushes
  {
    CHARCOAL = 0,
    LAZY = 1,
    HAND = 2,
    ROUGH = 3
  };

  ///@{
  /** The brush function. Default CHARCOAL. */
  vtkSetClampMacro(Brush, int, CHARCOAL, ROUGH);
  vtkGetMacro(Brush, int);
  void SetBrushToCharcoal() { this->SetBrush(CHARCOAL); }
  void SetBrushToLazy() { this->SetBrush(LAZY); }
  void SetBrushToHand() { this->SetBrush(HAND); }
  void SetBrushToRough() { this->SetBrush(ROUGH); }
  ///@}

  ///@{
  /** Bound on |v_x| and |v_y|, as a fraction of the input's diagonal. Default 0.006. */
  virtual void SetAmplitude(double); ///< clamped to [0.0, inf] with a warning; NaN refused
  vtkGetMacro(Amplitude, double);
  ///@}

  ///@{
  /**
   * Period of the sawtooth (charcoal) and parabola (lazy), knot spacing of
   * the hand noise; a fraction of the input's diagonal. Default 0.02.
   */
  virtual void SetWavelength(double); ///< clamped to [0.0, inf] with a warning; NaN refused
  vtkGetMacro(Wavelength, double);
  ///@}

  ///@{
  /**
   * When > 0, strokes are resampled at about this spacing (a fraction of the
   * input's diagonal) before the brush, keeping their points. Default 0.002.
   */
  virtual void SetSpacing(double); ///< clamped to [0.0, inf] with a warning; NaN refused
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /**
   * Join input lines whose ends meet (at the same position, to within a
   * hundred-thousandth of the input's diagonal) into one stroke before the
   * brush,
   * so that the brush runs on across the joint; where more than two ends
   * meet, the two that continue each other most straightly are joined. A
   * chain that comes back to its start is a closed stroke. Lines that
   * split one curve (the visible pieces of vtkSilhouetteLineVisibility, the
   * outline's gaps it adds) would otherwise each start and end a stroke
   * there, with its own offsets, and break the drawn curve. Default on.
   */
  vtkSetMacro(JoinLines, vtkTypeBool);
  vtkGetMacro(JoinLines, vtkTypeBool);
  vtkBooleanMacro(JoinLines, vtkTypeBool);
  ///@}

  ///@{
  /** Seed of the noise (hand, rough). Default 1. */
  vtkSetMacro(Seed, vtkTypeUInt64);
  vtkGetMacro(Seed, vtkTypeUInt64);
  ///@}

protected:
  vtkStylizedStrokeFilter();
  ~vtkStylizedStrokeFilter() override;

  int RequestViewData(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    const vtkSilhouetteFilterSupport::View& view) override;

  int Brush = CHARCOAL;
  double Amplitude = 0.006;
  double Wavelength = 0.02;
  double Spacing = 0.002;
  vtkTypeUInt64 Seed = 1;
  vtkTypeBool JoinLines = 1;

private:
  vtkStylizedStrokeFilter(const vtkStylizedStrokeFilter&) = delete;
  void operator=(const vtkStylizedStrokeFilter&) = delete;
};

#endif
