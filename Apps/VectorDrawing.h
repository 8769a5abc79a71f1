#ifndef VectorDrawing_h
#define VectorDrawing_h

#include <array>
#include <string>
#include <vector>

class vtkPolyData;
class vtkRenderer;

namespace cli
{

/// One polyline of a drawing in image coordinates: x to the right, y down,
/// in pixels from the image's top-left corner, with each point's distance
/// from the eye (along the direction of projection in parallel projection).
struct DrawnLine
{
  std::vector<std::array<double, 2>> Points;
  std::vector<double> Depths;
  std::string
    Kind; ///< silhouette, crease, border, intersection, outline (LineKind 0 to 4), or stroke
  bool Hidden = false;
};

/// The line cells of `lines` (model coordinates, as the renderer's actors
/// would draw them with an identity matrix) projected through the
/// renderer's active camera and viewport. The cell array `Visible` (0:
/// hidden) and `LineKind` give Hidden and Kind when present. In
/// perspective, what lies nearer the eye than the camera's near clipping
/// plane is not drawn, as in a rendering: a polyline is cut where it
/// crosses that plane, and the part in front of it kept (its points may lie
/// far outside the image; the documents clip them to it).
/// With `hiddenOnly`, only the cells whose Visible is 0 are taken.
std::vector<DrawnLine> ProjectLines(vtkPolyData* lines, vtkRenderer* renderer, bool hiddenOnly);

struct DrawingStyle
{
  int Width = 0; ///< the image's size in pixels
  int Height = 0;
  double LineWidth = 2.0; ///< pixels
  /// Each visible line drawn as a filled outline whose width at a point is
  /// LineWidth * ReferenceDepth / depth, within [1/4, 4] times LineWidth
  /// (Kim and Choe 3.3: lines thin out away from the eye).
  bool WidthByDepth = false;
  double ReferenceDepth = 1.0;
  /// Lines of one kind that meet end to end (at one written point) joined
  /// into one path, the straightest continuation first where more meet
  /// (Lines/Core/PathJoining.h): a pen plotter lifts its pen, and inks the
  /// corner, once there.
  bool JoinLines = false;
  std::string Title;
};

/**
 * The SVG document of a line drawing: a white background, then one path per
 * hidden line (grey, dashed, three quarters of the width), then one per
 * visible line (black, round caps and joins; with WidthByDepth a filled
 * outline instead of a stroke), in a short pen order from the top-left
 * corner. Each path's class is its kind, `hidden` added for the hidden
 * ones. The lines are clipped to the image, and each stretch of line is
 * drawn once: where lines run within three quarters of a line's width of
 * each other, one keeps it (visible before hidden, then by kind, then the
 * longer; Lines/Core/DrawingOverlaps.h), which may split a line into
 * several paths, and specks on ink already there are left out. Lines of
 * fewer than two distinct points are left out.
 */
/// `visiblePaths`, when given, counts the visible paths written.
std::string SvgDocument(const std::vector<DrawnLine>& lines, const DrawingStyle& style,
  std::size_t* visiblePaths = nullptr);

/**
 * The same drawing as a one-page PDF document (PDF 1.4, uncompressed): the
 * same paths in the same order, coordinates and widths, on a page of the
 * image's size at 96 pixels to the inch (0.75 point a pixel, as SVG's
 * pixels are printed), so that a printer or an illustration program gets
 * the lines as the SVG gives them to a browser. The title goes to the
 * document's information (UTF-16, bytes that are not UTF-8 as '?').
 */
std::string PdfDocument(const std::vector<DrawnLine>& lines, const DrawingStyle& style,
  std::size_t* visiblePaths = nullptr);

/// Whether `path` names a drawing these documents write: .svg or .pdf
/// (any letter case).
bool IsVectorDrawingPath(const std::string& path);

/// The document of the kind `path` names (.svg or .pdf).
std::string VectorDocument(const std::string& path, const std::vector<DrawnLine>& lines,
  const DrawingStyle& style, std::size_t* visiblePaths = nullptr);

} // namespace cli

#endif
