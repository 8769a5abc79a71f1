#include "VectorDrawing.h"

#include "DrawingOverlaps.h"
#include "MeshIO.h"
#include "PathJoining.h"
#include "PenOrder.h"

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkMath.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

namespace cli
{
namespace
{

const char* KindName(double kind)
{
  if (kind == 1.0)
  {
    return "crease";
  }
  if (kind == 2.0)
  {
    return "border";
  }
  if (kind == 3.0)
  {
    return "intersection";
  }
  if (kind == 4.0)
  {
    return "outline";
  }
  return "silhouette";
}

// The length of the valid UTF-8 sequence at text[i] (1 to 4), or 0 when the
// bytes there are not one (a stray continuation byte, an overlong form, a
// surrogate, beyond U+10FFFF, or cut short), or one of a code point XML
// 1.0 does not allow (U+FFFE, U+FFFF). `codePoint`, when given, gets the
// code point of a valid sequence.
std::size_t Utf8SequenceLength(
  const std::string& text, std::size_t i, unsigned long* codePoint = nullptr)
{
  const auto byte = [&](std::size_t k) {
    return static_cast<unsigned char>(text[k]);
  };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  unsigned long code = 0;
  if (lead < 0x80)
  {
    if (codePoint)
    {
      *codePoint = lead;
    }
    return 1;
  }
  if (lead >= 0xC2 && lead <= 0xDF)
  {
    length = 2;
    code = lead & 0x1Fu;
  }
  else if (lead >= 0xE0 && lead <= 0xEF)
  {
    length = 3;
    code = lead & 0x0Fu;
  }
  else if (lead >= 0xF0 && lead <= 0xF4)
  {
    length = 4;
    code = lead & 0x07u;
  }
  else
  {
    return 0;
  }
  if (i + length > text.size())
  {
    return 0;
  }
  for (std::size_t k = 1; k < length; ++k)
  {
    if ((byte(i + k) & 0xC0u) != 0x80u)
    {
      return 0;
    }
    code = (code << 6) | (byte(i + k) & 0x3Fu);
  }
  const unsigned long smallest[5] = { 0, 0, 0x80, 0x800, 0x10000 };
  // XML 1.0's characters: no surrogates, not U+FFFE or U+FFFF.
  const bool valid = code >= smallest[length] && code <= 0x10FFFF &&
    !(code >= 0xD800 && code <= 0xDFFF) && code != 0xFFFE && code != 0xFFFF;
  if (valid && codePoint)
  {
    *codePoint = code;
  }
  return valid ? length : 0;
}

// Whether a title's character is written as '?' in both formats: a
// control character other than the tab (not allowed in XML 1.0 text).
bool IsControlCharacter(unsigned long code)
{
  return (code < 0x20 && code != '\t') || code == 0x7F;
}

// Text for an XML 1.0 document in UTF-8: markup characters escaped, and
// control characters and bytes that are not UTF-8 (a file name in another
// encoding) written as '?', so that the document always parses.
std::string EscapeXml(const std::string& text)
{
  std::string escaped;
  for (std::size_t i = 0; i < text.size();)
  {
    const char c = text[i];
    const std::size_t length = Utf8SequenceLength(text, i);
    if (length > 1)
    {
      escaped.append(text, i, length);
      i += length;
      continue;
    }
    ++i;
    switch (c)
    {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      default:
        escaped += length == 0 || IsControlCharacter(static_cast<unsigned char>(c)) ? '?' : c;
    }
  }
  return escaped;
}

// A coordinate with two decimals (a hundredth of a pixel), "C" locale.
void AppendNumber(std::string& out, double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  out += std::string(text) == "-0.00" ? "0.00" : text;
}

void AppendPoint(std::string& out, char command, const std::array<double, 2>& p)
{
  out += command;
  AppendNumber(out, p[0]);
  out += ' ';
  AppendNumber(out, p[1]);
}

// The line as it is written: a point whose written coordinates (a hundredth
// of a pixel, AppendNumber) repeat the last kept point's is left out (it has
// no direction). A piece of a silhouette a hundredth of a pixel long, which
// the visibility split leaves where a bore's rim hides its outline, would
// otherwise be a path "M x yL x y": a dot with round caps, which a pen
// plotter draws by lowering its pen.
DrawnLine AsWritten(const DrawnLine& line)
{
  DrawnLine kept = line;
  kept.Points.clear();
  kept.Depths.clear();
  std::string last;
  for (std::size_t i = 0; i < line.Points.size(); ++i)
  {
    std::string written;
    AppendPoint(written, ' ', line.Points[i]);
    if (kept.Points.empty() || written != last)
    {
      kept.Points.push_back(line.Points[i]);
      kept.Depths.push_back(line.Depths[i]);
      last = std::move(written);
    }
  }
  return kept;
}

// The outline of a line whose width varies along it: the left side forward,
// a round end, the right side back, a round start. Each point is offset
// along the bisector of its two segments' normals, lengthened to keep the
// width across a turn (at most twice, so a sharp turn does not shoot a
// spike). The round ends are a stroke's round caps: where lines that run
// over each other were drawn once, a line stops up to one and a half widths
// from the line it meets, and square ends left white breaks there (a user's
// trial).
std::vector<std::array<double, 2>> OutlinePolygon(
  const DrawnLine& line, const std::vector<double>& halfWidths)
{
  const std::size_t n = line.Points.size();
  std::vector<std::array<double, 2>> left(n);
  std::vector<std::array<double, 2>> right(n);
  auto normalOf = [&](std::size_t a, std::size_t b) {
    const double dx = line.Points[b][0] - line.Points[a][0];
    const double dy = line.Points[b][1] - line.Points[a][1];
    const double length = std::hypot(dx, dy);
    return std::array<double, 2>{ -dy / length, dx / length };
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 2> before = normalOf(i == 0 ? 0 : i - 1, i == 0 ? 1 : i);
    const std::array<double, 2> after = normalOf(i + 1 < n ? i : n - 2, i + 1 < n ? i + 1 : n - 1);
    std::array<double, 2> m{ before[0] + after[0], before[1] + after[1] };
    const double length = std::hypot(m[0], m[1]);
    double scale = halfWidths[i];
    if (length > 1e-9)
    {
      m = { m[0] / length, m[1] / length };
      const double cosine = m[0] * after[0] + m[1] * after[1];
      scale /= std::max(cosine, 0.5);
    }
    else
    {
      m = after; // a full turn back: offset across the segment
    }
    left[i] = { line.Points[i][0] + scale * m[0], line.Points[i][1] + scale * m[1] };
    right[i] = { line.Points[i][0] - scale * m[0], line.Points[i][1] - scale * m[1] };
  }
  // Half a circle about an end, from its left side to its right, bulging
  // along `forward`.
  std::vector<std::array<double, 2>> outline;
  const auto cap = [&](std::size_t i, double sign) {
    const std::array<double, 2> normal = sign > 0.0 ? normalOf(n - 2, n - 1) : normalOf(0, 1);
    const std::array<double, 2> forward{ sign * normal[1], -sign * normal[0] };
    const double r = halfWidths[i];
    for (const double degrees : { 60.0, 30.0, 0.0, -30.0, -60.0 })
    {
      const double a = degrees * vtkMath::Pi() / 180.0;
      const double side = sign * std::sin(a); // left at +90 degrees on the way out
      outline.push_back({ line.Points[i][0] + r * (side * normal[0] + std::cos(a) * forward[0]),
        line.Points[i][1] + r * (side * normal[1] + std::cos(a) * forward[1]) });
    }
  };
  outline.insert(outline.end(), left.begin(), left.end());
  cap(n - 1, 1.0);
  outline.insert(outline.end(), right.rbegin(), right.rend());
  cap(0, -1.0);
  return outline;
}

std::string PolylinePath(const DrawnLine& line)
{
  std::string d;
  for (std::size_t i = 0; i < line.Points.size(); ++i)
  {
    AppendPoint(d, i == 0 ? 'M' : 'L', line.Points[i]);
  }
  return d;
}

// Each line's points as the drawing's geometry takes them.
std::vector<std::vector<glm::dvec2>> PointsOf(const std::vector<DrawnLine>& lines)
{
  std::vector<std::vector<glm::dvec2>> points(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    for (const std::array<double, 2>& p : lines[i].Points)
    {
      points[i].emplace_back(p[0], p[1]);
    }
  }
  return points;
}

// The line drawn from its last point to its first.
void Reverse(DrawnLine& line)
{
  std::reverse(line.Points.begin(), line.Points.end());
  std::reverse(line.Depths.begin(), line.Depths.end());
}

// A closed line (its last point its first) drawn round from its point
// `entry` back to it.
void StartAt(DrawnLine& line, std::size_t entry)
{
  line.Points.pop_back();
  std::rotate(line.Points.begin(), line.Points.begin() + entry, line.Points.end());
  line.Points.push_back(line.Points.front());
  if (line.Depths.size() == line.Points.size())
  {
    line.Depths.pop_back();
    std::rotate(line.Depths.begin(), line.Depths.begin() + entry, line.Depths.end());
    line.Depths.push_back(line.Depths.front());
  }
}

// The lines in the order a pen plotter draws them with little travel
// (Lines/Core/PenOrder.h): from the image's top-left corner, where a
// plotter's pen rests, each next line is the one with an end nearest the
// pen, turned round when its last point is the nearer; after an
// `outlines` line (a filled outline) the pen is back at the end it entered
// by. A closed line (its last point its first, as written) is entered at
// its point nearest the pen, and the pen is back there after it. In the
// order the pieces came, the pen travelled 3 to 11 times as far (a user's
// trial, 2026-12-05).
std::vector<DrawnLine> InPenOrder(std::vector<DrawnLine> lines, bool outlines)
{
  std::vector<std::array<glm::dvec2, 2>> ends(lines.size());
  std::vector<std::vector<glm::dvec2>> loops(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    const std::array<double, 2>& first = lines[i].Points.front();
    const std::array<double, 2>& last = lines[i].Points.back();
    ends[i] = { glm::dvec2(first[0], first[1]), glm::dvec2(last[0], last[1]) };
    if (lines[i].Points.size() >= 4 && first == last)
    {
      for (std::size_t k = 0; k + 1 < lines[i].Points.size(); ++k)
      {
        loops[i].emplace_back(lines[i].Points[k][0], lines[i].Points[k][1]);
      }
    }
  }
  std::vector<DrawnLine> ordered;
  ordered.reserve(lines.size());
  for (const silsmooth::PenStep& step : silsmooth::penOrder(ends, glm::dvec2(0.0), outlines, loops))
  {
    DrawnLine next = std::move(lines[step.Line]);
    if (step.Reversed)
    {
      Reverse(next);
    }
    if (step.Entry > 0)
    {
      StartAt(next, step.Entry);
    }
    ordered.push_back(std::move(next));
  }
  return ordered;
}

// How a kind ranks where lines run over each other: the first drawn keeps
// the stretch (the outline is what the silhouette misses, so it ranks last).
int KindRank(const std::string& kind)
{
  static const char* const order[] = { "silhouette", "crease", "border", "intersection",
    "outline" };
  for (int rank = 0; rank < 5; ++rank)
  {
    if (kind == order[rank])
    {
      return rank;
    }
  }
  return 5;
}

// The part of `line` between two positions (Lines/Core/DrawingOverlaps.h).
DrawnLine PieceOf(
  const DrawnLine& line, const std::vector<glm::dvec2>& points, const silsmooth::PolylineSpan& span)
{
  DrawnLine piece;
  piece.Kind = line.Kind;
  piece.Hidden = line.Hidden;
  for (const glm::dvec2& p : silsmooth::valuesAlong(points, span.First, span.Last))
  {
    piece.Points.push_back({ p.x, p.y });
  }
  piece.Depths = silsmooth::valuesAlong(line.Depths, span.First, span.Last);
  return piece;
}

// The lines as written, within the image (a pen plotter would draw the
// rest off the page), with each stretch of line once
// (Lines/Core/DrawingOverlaps.h): where lines run within three quarters of a
// line's width of each other (their strokes overlapping by a quarter), the
// visible before the hidden, then by kind (KindRank), then the longer, keeps
// the stretch; specks up to one and a half widths long on ink already there
// are left out. A brush's strokes overlap by design and are kept as they are.
std::vector<DrawnLine> OnceEach(const std::vector<DrawnLine>& lines, const DrawingStyle& style)
{
  std::vector<DrawnLine> inside;
  {
    const std::vector<std::vector<glm::dvec2>> points = PointsOf(lines);
    for (const silsmooth::PolylineSpan& span :
      silsmooth::spansInside(points, glm::dvec2(0.0), glm::dvec2(style.Width, style.Height)))
    {
      DrawnLine piece = AsWritten(PieceOf(lines[span.Line], points[span.Line], span));
      if (piece.Points.size() >= 2)
      {
        inside.push_back(std::move(piece));
      }
    }
  }
  std::vector<DrawnLine> written;
  std::vector<DrawnLine> once;
  for (DrawnLine& line : inside)
  {
    (line.Kind == "stroke" ? once : written).push_back(std::move(line));
  }
  const std::vector<std::vector<glm::dvec2>> points = PointsOf(written);
  std::vector<double> lengths(written.size());
  std::vector<std::size_t> order(written.size());
  for (std::size_t i = 0; i < written.size(); ++i)
  {
    lengths[i] = silsmooth::polylineLength(points[i]);
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto rank = [&](std::size_t i) {
      return std::make_tuple(written[i].Hidden, KindRank(written[i].Kind), -lengths[i]);
    };
    return rank(a) < rank(b);
  });
  silsmooth::DrawingOverlapParameters parameters;
  parameters.Width = 0.75 * style.LineWidth;
  parameters.ShortestGap = 2.0 * style.LineWidth;
  parameters.LongestSpeck = 1.5 * style.LineWidth;
  for (const silsmooth::PolylineSpan& span :
    silsmooth::spansNotOverlapping(points, order, parameters))
  {
    DrawnLine piece = AsWritten(PieceOf(written[span.Line], points[span.Line], span));
    if (piece.Points.size() >= 2)
    {
      once.push_back(std::move(piece));
    }
  }
  return once;
}

// Whether a class attribute's space-separated names include `kind`.
bool NamesKind(const std::string& classes, const std::string& kind)
{
  std::istringstream names(classes);
  std::string name;
  while (names >> name)
  {
    if (name == kind)
    {
      return true;
    }
  }
  return false;
}

// The lines that meet end to end, at one written point, joined into one
// line each (Lines/Core/PathJoining.h): the visible with the visible, the
// hidden with the hidden, whatever their kinds (a silhouette that ends on a
// crease goes on along it), since every kind is drawn alike. A joined line
// names each of its kinds in its class, in the order drawn. A brush's
// strokes stay as they are.
std::vector<DrawnLine> Joined(const std::vector<DrawnLine>& lines)
{
  const std::vector<std::vector<glm::dvec2>> points = PointsOf(lines);
  std::vector<int> groups(lines.size());
  std::map<std::string, int> groupOf;
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    const std::string group = lines[i].Kind == "stroke" ? "stroke " + std::to_string(i)
      : lines[i].Hidden                                 ? "hidden"
                                                        : "visible";
    groups[i] = groupOf.emplace(group, static_cast<int>(groupOf.size())).first->second;
  }
  const auto written = +[](const glm::dvec2& p) {
    return std::pair<std::int64_t, std::int64_t>(
      std::llround(p.x * 100.0), std::llround(p.y * 100.0));
  };
  std::vector<DrawnLine> joined;
  for (const std::vector<silsmooth::JoinedLine>& path :
    silsmooth::joinedPaths(points, groups, written))
  {
    DrawnLine line;
    line.Hidden = lines[path.front().Line].Hidden;
    for (const silsmooth::JoinedLine& piece : path)
    {
      DrawnLine next = lines[piece.Line];
      if (line.Kind.empty())
      {
        line.Kind = next.Kind;
      }
      else if (!NamesKind(line.Kind, next.Kind))
      {
        line.Kind += " " + next.Kind;
      }
      if (piece.Reversed)
      {
        Reverse(next);
      }
      // The first point repeats the last one's written point.
      const std::size_t from = line.Points.empty() ? 0 : 1;
      line.Points.insert(line.Points.end(), next.Points.begin() + from, next.Points.end());
      line.Depths.insert(line.Depths.end(), next.Depths.begin() + from, next.Depths.end());
    }
    joined.push_back(std::move(line));
  }
  return joined;
}

} // namespace

std::vector<DrawnLine> ProjectLines(vtkPolyData* lines, vtkRenderer* renderer, bool hiddenOnly)
{
  std::vector<DrawnLine> drawn;
  if (!lines || !lines->GetLines() || lines->GetNumberOfLines() == 0)
  {
    return drawn;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  double eye[3];
  double direction[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  const bool parallel = camera->GetParallelProjection() != 0;
  const int* size = renderer->GetSize();
  vtkDataArray* visible = lines->GetCellData()->GetArray("Visible");
  vtkDataArray* kinds = lines->GetCellData()->GetArray("LineKind");

  // In perspective, what lies nearer the eye than the near clipping plane
  // is not drawn (as in a rendering): a line is cut where it crosses it.
  const double nearest = std::max(camera->GetClippingRange()[0], 1e-12 * camera->GetDistance());
  const auto project = [&](const double p[3], DrawnLine& line) {
    const double toPoint[3] = { p[0] - eye[0], p[1] - eye[1], p[2] - eye[2] };
    renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
    renderer->WorldToDisplay();
    const double* display = renderer->GetDisplayPoint();
    line.Points.push_back({ display[0], static_cast<double>(size[1]) - display[1] });
    line.Depths.push_back(parallel ? vtkMath::Dot(toPoint, direction) : vtkMath::Norm(toPoint));
  };
  auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  vtkIdType cell = lines->GetNumberOfVerts(); // cell ids count vertices first
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    DrawnLine line;
    line.Hidden = visible && visible->GetComponent(cell, 0) == 0.0;
    if (hiddenOnly && !line.Hidden)
    {
      continue;
    }
    line.Kind = kinds ? KindName(kinds->GetComponent(cell, 0)) : "stroke";
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    double last[3] = { 0.0, 0.0, 0.0 };
    double lastAhead = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      lines->GetPoint(ids[i], p);
      const double toPoint[3] = { p[0] - eye[0], p[1] - eye[1], p[2] - eye[2] };
      const double ahead = vtkMath::Dot(toPoint, direction);
      const bool inFront = parallel || ahead > nearest;
      const bool lastInFront = parallel || lastAhead > nearest;
      if (i > 0 && inFront != lastInFront)
      {
        // Where the segment crosses the near plane.
        const double t = (nearest - lastAhead) / (ahead - lastAhead);
        const double crossing[3] = { last[0] + t * (p[0] - last[0]), last[1] + t * (p[1] - last[1]),
          last[2] + t * (p[2] - last[2]) };
        project(crossing, line);
        if (!inFront)
        {
          if (line.Points.size() >= 2)
          {
            drawn.push_back(line);
          }
          line.Points.clear();
          line.Depths.clear();
        }
      }
      if (inFront)
      {
        project(p, line);
      }
      std::copy(p, p + 3, last);
      lastAhead = ahead;
    }
    if (line.Points.size() >= 2)
    {
      drawn.push_back(std::move(line));
    }
  }
  return drawn;
}

namespace
{

// The drawing's lines as both documents write them: each stretch once
// (OnceEach), joined when asked, hidden and visible apart, each in pen
// order; with WidthByDepth, each visible line's filled outline.
struct WrittenLines
{
  std::vector<DrawnLine> Hidden;
  std::vector<DrawnLine> Visible;
  std::vector<std::vector<std::array<double, 2>>> VisibleOutlines; // WidthByDepth only
};

WrittenLines WrittenLinesOf(const std::vector<DrawnLine>& lines, const DrawingStyle& style)
{
  // Each stretch of line once: lines drawn over each other (a border that
  // is also a crease, a piece and its reverse) would be inked twice by a
  // pen plotter.
  std::vector<DrawnLine> hidden, visible;
  std::vector<DrawnLine> once = OnceEach(lines, style);
  if (style.JoinLines)
  {
    once = Joined(once);
  }
  for (DrawnLine& line : once)
  {
    (line.Hidden ? hidden : visible).push_back(std::move(line));
  }
  WrittenLines written;
  written.Hidden = InPenOrder(std::move(hidden), false);
  // A filled outline (WidthByDepth) goes round its line and closes where it
  // began, so the pen is back at the end it entered by.
  written.Visible = InPenOrder(std::move(visible), style.WidthByDepth);
  if (style.WidthByDepth)
  {
    for (const DrawnLine& line : written.Visible)
    {
      std::vector<double> halfWidths(line.Points.size());
      for (std::size_t i = 0; i < halfWidths.size(); ++i)
      {
        const double ratio = line.Depths[i] > 0.0 ? style.ReferenceDepth / line.Depths[i] : 4.0;
        halfWidths[i] = 0.5 * style.LineWidth * std::clamp(ratio, 0.25, 4.0);
      }
      written.VisibleOutlines.push_back(OutlinePolygon(line, halfWidths));
    }
  }
  return written;
}

std::string Number(double value)
{
  std::string text;
  AppendNumber(text, value);
  return text;
}

// A path of PDF's operators: moveto, then linetos (the points as the SVG
// writes them, a hundredth of a pixel), then `paint` (S strokes, f fills).
std::string PdfPath(const std::vector<std::array<double, 2>>& points, const char* paint)
{
  std::string path;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    AppendNumber(path, points[i][0]);
    path += ' ';
    AppendNumber(path, points[i][1]);
    path += i == 0 ? " m\n" : " l\n";
  }
  return path + paint + "\n";
}

// Text for a PDF text string: UTF-16BE with its byte order mark, in hex.
// Bytes that are not UTF-8 (a file name in another encoding) and control
// characters are written as '?', as in the SVG's title.
std::string PdfTextString(const std::string& text)
{
  std::vector<unsigned long> units{ 0xFEFF };
  for (std::size_t i = 0; i < text.size();)
  {
    unsigned long code = 0;
    const std::size_t length = Utf8SequenceLength(text, i, &code);
    i += std::max<std::size_t>(length, 1);
    if (length == 0 || IsControlCharacter(code))
    {
      units.push_back('?');
    }
    else if (code >= 0x10000)
    {
      code -= 0x10000;
      units.push_back(0xD800 + (code >> 10));
      units.push_back(0xDC00 + (code & 0x3FF));
    }
    else
    {
      units.push_back(code);
    }
  }
  std::string hex = "<";
  for (const unsigned long unit : units)
  {
    char digits[8];
    std::snprintf(digits, sizeof digits, "%04lX", unit);
    hex += digits;
  }
  return hex + ">";
}

} // namespace

std::string SvgDocument(
  const std::vector<DrawnLine>& lines, const DrawingStyle& style, std::size_t* visiblePaths)
{
  std::string svg;
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
    std::to_string(style.Width) + "\" height=\"" + std::to_string(style.Height) +
    "\" viewBox=\"0 0 " + std::to_string(style.Width) + " " + std::to_string(style.Height) +
    "\">\n";
  if (!style.Title.empty())
  {
    svg += "<title>" + EscapeXml(style.Title) + "</title>\n";
  }
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

  const std::string width = Number(style.LineWidth);
  // The hidden lines first: the visible ones are drawn over them where
  // they cross.
  svg += "<g id=\"hidden\" fill=\"none\" stroke=\"#999999\" stroke-width=\"" +
    Number(0.75 * style.LineWidth) + "\" stroke-dasharray=\"" + Number(3.0 * style.LineWidth) +
    " " + width + "\" stroke-linecap=\"butt\">\n";
  const WrittenLines written = WrittenLinesOf(lines, style);
  for (const DrawnLine& line : written.Hidden)
  {
    svg += "<path class=\"hidden " + line.Kind + "\" d=\"" + PolylinePath(line) + "\"/>\n";
  }
  svg += "</g>\n";
  if (visiblePaths)
  {
    *visiblePaths = written.Visible.size();
  }
  svg += style.WidthByDepth ? "<g id=\"visible\" fill=\"black\" stroke=\"none\">\n"
                            : "<g id=\"visible\" fill=\"none\" stroke=\"black\" stroke-width=\"" +
      width + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (std::size_t i = 0; i < written.Visible.size(); ++i)
  {
    std::string d;
    if (style.WidthByDepth)
    {
      const std::vector<std::array<double, 2>>& outline = written.VisibleOutlines[i];
      for (std::size_t k = 0; k < outline.size(); ++k)
      {
        AppendPoint(d, k == 0 ? 'M' : 'L', outline[k]);
      }
      d += 'Z';
    }
    else
    {
      d = PolylinePath(written.Visible[i]);
    }
    svg += "<path class=\"" + written.Visible[i].Kind + "\" d=\"" + d + "\"/>\n";
  }
  svg += "</g>\n</svg>\n";
  return svg;
}

std::string PdfDocument(
  const std::vector<DrawnLine>& lines, const DrawingStyle& style, std::size_t* visiblePaths)
{
  const WrittenLines written = WrittenLinesOf(lines, style);
  if (visiblePaths)
  {
    *visiblePaths = written.Visible.size();
  }
  // Pixels, y down from the top-left corner, as in the SVG document: one
  // transformation to points, y up from the bottom-left corner.
  const double scale = 0.75;
  const std::string pageWidth = Number(scale * style.Width);
  const std::string pageHeight = Number(scale * style.Height);
  std::string content = Number(scale) + " 0 0 " + Number(-scale) + " 0 " + pageHeight + " cm\n";
  content +=
    "1 g 0 0 " + std::to_string(style.Width) + " " + std::to_string(style.Height) + " re f\n";
  const std::string width = Number(style.LineWidth);
  // The hidden lines first (grey, dashed, butt ends, SVG's default miter
  // joins), the visible ones over them.
  content += "q 0.6 G " + Number(0.75 * style.LineWidth) + " w [" + Number(3.0 * style.LineWidth) +
    " " + width + "] 0 d 0 J 0 j 4 M\n";
  for (const DrawnLine& line : written.Hidden)
  {
    content += PdfPath(line.Points, "S");
  }
  content += "Q\n";
  content += style.WidthByDepth ? "q 0 g\n" : "q 0 G " + width + " w 1 J 1 j\n";
  for (std::size_t i = 0; i < written.Visible.size(); ++i)
  {
    content += style.WidthByDepth ? PdfPath(written.VisibleOutlines[i], "h f")
                                  : PdfPath(written.Visible[i].Points, "S");
  }
  content += "Q\n";

  // Objects 1 to 5, each at the offset the cross-reference table gives.
  std::string pdf = "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n"; // binary bytes: a binary file
  std::vector<std::size_t> offsets;
  const auto object = [&](const std::string& body) {
    offsets.push_back(pdf.size());
    pdf += std::to_string(offsets.size()) + " 0 obj\n" + body + "\nendobj\n";
  };
  object("<< /Type /Catalog /Pages 2 0 R >>");
  object("<< /Type /Pages /Kids [3 0 R] /Count 1 >>");
  object("<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " + pageWidth + " " + pageHeight +
    "] /Resources << >> /Contents 4 0 R >>");
  object(
    "<< /Length " + std::to_string(content.size()) + " >>\nstream\n" + content + "\nendstream");
  object("<< /Producer (silhouette)" +
    (style.Title.empty() ? std::string() : " /Title " + PdfTextString(style.Title)) + " >>");
  const std::size_t table = pdf.size();
  pdf += "xref\n0 " + std::to_string(offsets.size() + 1) + "\n0000000000 65535 f \n";
  for (const std::size_t offset : offsets)
  {
    char entry[32];
    std::snprintf(entry, sizeof entry, "%010zu 00000 n \n", offset);
    pdf += entry;
  }
  pdf += "trailer\n<< /Size " + std::to_string(offsets.size() + 1) +
    " /Root 1 0 R /Info 5 0 R >>\nstartxref\n" + std::to_string(table) + "\n%%EOF\n";
  return pdf;
}

bool IsVectorDrawingPath(const std::string& path)
{
  const std::string extension = LowercaseExtension(path);
  return extension == ".svg" || extension == ".pdf";
}

std::string VectorDocument(const std::string& path, const std::vector<DrawnLine>& lines,
  const DrawingStyle& style, std::size_t* visiblePaths)
{
  return LowercaseExtension(path) == ".pdf" ? PdfDocument(lines, style, visiblePaths)
                                            : SvgDocument(lines, style, visiblePaths);
}

} // namespace cli
