#include "LineVisibility.h"

#include "BoxInterval.h"

#include "ClosestPoint.h"
#include "FiniteVector.h"
#include "PositionHash.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace silsmooth
{
namespace
{

// Where the ray origin + t dir (dir a unit vector) meets triangle (a, b, c):
// t, or -1 when it misses (Moller and Trumbore). Edges count as inside,
// with a margin of 1e-12 in the barycentric coordinates, so that a ray
// through an edge shared by two triangles cannot slip between them.
double rayHit(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec3& c)
{
  constexpr double margin = 1e-12;
  const glm::dvec3 e1 = b - a;
  const glm::dvec3 e2 = c - a;
  const glm::dvec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (!(std::abs(det) > 0.0))
  {
    return -1.0; // the ray runs in the triangle's plane, or no triangle
  }
  const double inverse = 1.0 / det;
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) * inverse;
  if (!(u >= -margin && u <= 1.0 + margin))
  {
    return -1.0;
  }
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(dir, q) * inverse;
  if (!(v >= -margin && u + v <= 1.0 + margin))
  {
    return -1.0;
  }
  return glm::dot(e2, q) * inverse;
}

// Normals within about a degree of each other (zero or broken ones match).
bool sameNormal(const glm::dvec3& m, const glm::dvec3& n)
{
  const double scale = glm::length(m) * glm::length(n);
  return !(scale > 0.0) || !std::isfinite(scale) || glm::dot(m, n) >= 0.99985 * scale;
}

// The range [enter, leave] of t where origin + t dir lies in the box.
std::pair<double, double> rayInBox(
  const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& low, const glm::dvec3& high)
{
  return lineInBox(origin, dir, low, high, -std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity());
}

} // namespace

LineVisibilityParameters LineVisibilityParameters::forMesh(
  const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles)
{
  LineVisibilityParameters parameters;
  double sum = 0.0;
  std::size_t sides = 0;
  glm::dvec3 low(std::numeric_limits<double>::infinity());
  glm::dvec3 high(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const glm::dvec3& a = points[static_cast<std::size_t>(t[k])];
      const glm::dvec3& b = points[static_cast<std::size_t>(t[(k + 1) % 3])];
      const double length = glm::length(b - a);
      if (std::isfinite(length))
      {
        sum += length;
        ++sides;
      }
      if (isFinite(a))
      {
        low = glm::min(low, a);
        high = glm::max(high, a);
      }
    }
  }
  if (sides > 0)
  {
    const double diagonal = glm::length(high - low);
    parameters.Tolerance = sum / static_cast<double>(sides);
    parameters.Precision = 1e-6 * diagonal;
    parameters.SampleSpacing = diagonal / 400.0;
    parameters.Contact = 1e-5 * diagonal;
  }
  return parameters;
}

OcclusionMesh::OcclusionMesh(std::vector<glm::dvec3> points, std::vector<Triangle> triangles,
  const std::vector<glm::dvec3>& normals)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , Grid(this->Points, this->Triangles)
{
  this->weldVertices(normals);
  this->Low = glm::dvec3(std::numeric_limits<double>::infinity());
  this->High = glm::dvec3(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : this->Triangles)
  {
    for (const Id corner : t)
    {
      const glm::dvec3& p = this->Points[static_cast<std::size_t>(corner)];
      if (isFinite(p))
      {
        this->Low = glm::min(this->Low, p);
        this->High = glm::max(this->High, p);
      }
    }
  }
  this->Step = this->Grid.cellSize();
  this->Pad = glm::dvec3(1e-9 * glm::length(this->High - this->Low));
}

void OcclusionMesh::weldVertices(const std::vector<glm::dvec3>& normals)
{
  const bool withNormals = normals.size() == this->Points.size();
  // Points at one position (and with one normal) are one vertex: the first.
  std::unordered_map<glm::dvec3, std::vector<Id>, PositionHash> atPosition;
  atPosition.reserve(this->Points.size());
  this->VertexOf.resize(this->Points.size());
  for (std::size_t i = 0; i < this->Points.size(); ++i)
  {
    std::vector<Id>& here = atPosition[this->Points[i] + glm::dvec3(0.0)];
    Id vertex = static_cast<Id>(i);
    for (const Id other : here)
    {
      if (!withNormals || sameNormal(normals[static_cast<std::size_t>(other)], normals[i]))
      {
        vertex = other;
        break;
      }
    }
    if (vertex == static_cast<Id>(i))
    {
      here.push_back(vertex);
    }
    this->VertexOf[i] = vertex;
  }
  // The triangles around each vertex, in compressed rows.
  this->VertexTriangleOffsets.assign(this->Points.size() + 1, 0);
  for (const Triangle& t : this->Triangles)
  {
    for (const Id corner : t)
    {
      ++this->VertexTriangleOffsets[static_cast<std::size_t>(
                                      this->VertexOf[static_cast<std::size_t>(corner)]) +
        1];
    }
  }
  for (std::size_t v = 0; v < this->Points.size(); ++v)
  {
    this->VertexTriangleOffsets[v + 1] += this->VertexTriangleOffsets[v];
  }
  this->VertexTriangles.resize(this->VertexTriangleOffsets.back());
  std::vector<std::size_t> fill(
    this->VertexTriangleOffsets.begin(), this->VertexTriangleOffsets.end() - 1);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (const Id corner : this->Triangles[t])
    {
      const auto v = static_cast<std::size_t>(this->VertexOf[static_cast<std::size_t>(corner)]);
      this->VertexTriangles[fill[v]++] = static_cast<Id>(t);
    }
  }
}

double OcclusionMesh::distanceTo(const glm::dvec3& point, Id triangle) const
{
  const Triangle& t = this->Triangles[static_cast<std::size_t>(triangle)];
  return glm::length(point -
    closestPointOnTriangle(point, this->Points[static_cast<std::size_t>(t[0])],
      this->Points[static_cast<std::size_t>(t[1])], this->Points[static_cast<std::size_t>(t[2])]));
}

std::vector<Id> OcclusionMesh::trianglesUnder(const glm::dvec3& point, double contact) const
{
  std::vector<Id> under;
  std::vector<Id> candidates;
  this->Grid.query(point - glm::dvec3(contact), point + glm::dvec3(contact), candidates);
  for (const Id c : candidates)
  {
    if (this->distanceTo(point, c) <= contact)
    {
      under.push_back(c);
    }
  }
  return under;
}

std::vector<Id> OcclusionMesh::localSheet(
  const glm::dvec3& point, std::vector<Id> sheet, double radius) const
{
  // Breadth first through shared vertices, within the ball. Each vertex's
  // triangles are read once: at the centre of a fan of thousands, every
  // triangle of the sheet has that vertex (a 10,000-sided cone's line
  // drawing took over 300 s when each read them all again).
  std::unordered_set<Id> seen(sheet.begin(), sheet.end());
  std::unordered_set<std::size_t> expanded;
  for (std::size_t next = 0; next < sheet.size(); ++next)
  {
    const Triangle& t = this->Triangles[static_cast<std::size_t>(sheet[next])];
    for (const Id corner : t)
    {
      const auto v = static_cast<std::size_t>(this->VertexOf[static_cast<std::size_t>(corner)]);
      if (!expanded.insert(v).second)
      {
        continue;
      }
      for (std::size_t k = this->VertexTriangleOffsets[v]; k < this->VertexTriangleOffsets[v + 1];
           ++k)
      {
        const Id around = this->VertexTriangles[k];
        if (seen.insert(around).second && this->distanceTo(point, around) <= radius)
        {
          sheet.push_back(around);
        }
      }
    }
  }
  std::sort(sheet.begin(), sheet.end());
  return sheet;
}

template<typename Counts>
bool OcclusionMesh::anyHit(
  const ViewGeometry& view, const glm::dvec3& point, double from, double to, Counts counts) const
{
  if (this->Grid.empty() || !isFinite(point) || !(this->Step > 0.0))
  {
    return false;
  }
  const glm::dvec3 toward = view.towardViewerFrom(point);
  const double reach = glm::length(toward); // to the eye; parallel: no end
  if (!(reach > 0.0) || !std::isfinite(reach))
  {
    return false;
  }
  const glm::dvec3 dir = toward / reach;
  const double end = std::min(to, view.Parallel ? std::numeric_limits<double>::infinity() : reach);
  // Only where the ray is inside the surface's box can it meet a triangle.
  const auto [enter, leave] = rayInBox(point, dir, this->Low, this->High);
  const double first = std::max(enter, from);
  const double last = std::min(leave, end);
  if (!(first <= last))
  {
    return false;
  }
  // The ray in pieces about a grid cell long, near to far: the triangles
  // whose boxes meet a piece's box include every triangle the piece crosses.
  std::vector<Id> candidates;
  for (double t = first; t <= last; t += this->Step)
  {
    const double next = std::min(t + this->Step, last);
    const glm::dvec3 a = point + t * dir;
    const glm::dvec3 b = point + next * dir;
    // Padded: a flat face on the box's side (a cube's) must not be missed
    // when rounding ends the last piece a hair short of it.
    this->Grid.query(glm::min(a, b) - this->Pad, glm::max(a, b) + this->Pad, candidates);
    for (const Id c : candidates)
    {
      const Triangle& tri = this->Triangles[static_cast<std::size_t>(c)];
      const double hit = rayHit(point, dir, this->Points[static_cast<std::size_t>(tri[0])],
        this->Points[static_cast<std::size_t>(tri[1])],
        this->Points[static_cast<std::size_t>(tri[2])]);
      if (hit > from && hit <= end && counts(c, hit))
      {
        return true;
      }
    }
    if (next >= last || !(t + this->Step > t))
    {
      break; // the end, or a step too short to advance at this distance
    }
  }
  return false;
}

bool OcclusionMesh::hides(const ViewGeometry& view, const glm::dvec3& point, double tolerance) const
{
  return this->anyHit(view, point, tolerance, std::numeric_limits<double>::infinity(),
    [](Id, double) { return true; });
}

double OcclusionMesh::toleranceAt(
  const std::vector<Id>& under, const LineVisibilityParameters& rule) const
{
  double longest = 0.0;
  for (const Id c : under)
  {
    const Triangle& t = this->Triangles[static_cast<std::size_t>(c)];
    for (int k = 0; k < 3; ++k)
    {
      longest = std::max(longest,
        glm::length(this->Points[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])] -
          this->Points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])]));
    }
  }
  if (!(rule.LocalToleranceFactor > 0.0) || !(longest > 0.0) || !std::isfinite(longest))
  {
    return rule.Tolerance; // no cap, or on no triangle: the plain rule
  }
  // Never down to the contact distance, within which every hit is ignored,
  // and never above the mesh-wide tolerance.
  return std::min(
    rule.Tolerance, std::max(rule.LocalToleranceFactor * longest, 2.0 * rule.Contact));
}

std::optional<std::array<glm::dvec3, 2>> OcclusionMesh::besidePoints(const ViewGeometry& view,
  const glm::dvec3& point, const glm::dvec3& direction, double pixels) const
{
  const glm::dvec3 toward = view.towardViewerFrom(point);
  glm::dvec3 across = glm::cross(toward, direction);
  const double acrossLength = glm::length(across);
  const double distance = glm::length(toward);
  if (!(pixels > 0.0) || !(acrossLength > 0.0) || !std::isfinite(acrossLength) || !(distance > 0.0))
  {
    return std::nullopt;
  }
  across /= acrossLength;
  // Model units per pixel here, from a step small against the distance to
  // the eye (parallel, an affine map: against the surface's size).
  const double step = 1e-3 * (view.Parallel ? glm::length(this->High - this->Low) : distance);
  glm::dvec2 at;
  glm::dvec2 beside;
  if (!(step > 0.0) || !view.toPixels(point, at) || !view.toPixels(point + step * across, beside))
  {
    return std::nullopt;
  }
  const double pixelsPerStep = glm::length(beside - at);
  if (!(pixelsPerStep > 0.0) || !std::isfinite(pixelsPerStep))
  {
    return std::nullopt;
  }
  const glm::dvec3 offset = (pixels * step / pixelsPerStep) * across;
  return std::array<glm::dvec3, 2>{ point + offset, point - offset };
}

std::optional<bool> OcclusionMesh::hiddenOnBothSides(const ViewGeometry& view,
  const glm::dvec3& point, const glm::dvec3& direction, double pixels, double contact) const
{
  const auto beside = this->besidePoints(view, point, direction, pixels);
  if (!beside)
  {
    return std::nullopt;
  }
  return this->hides(view, (*beside)[0], contact) && this->hides(view, (*beside)[1], contact);
}

bool OcclusionMesh::covers(const ViewGeometry& view, const glm::dvec3& point, double behind) const
{
  // From the point `behind` farther along its line of sight, the ray
  // towards the viewer crosses all of the line that counts.
  glm::dvec3 away = -view.towardViewerFrom(point);
  const double length = glm::length(away);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  // Beyond the surface's box at most: no triangle lies farther.
  const double reach = std::min(behind,
    2.0 * glm::length(this->High - this->Low) +
      glm::length(point - 0.5 * (this->Low + this->High)));
  const glm::dvec3 start = point + (reach / length) * away;
  return isFinite(start) && this->hides(view, start, 0.0);
}

bool OcclusionMesh::nearTheOutline(const ViewGeometry& view, const glm::dvec3& point,
  const glm::dvec3& direction, const LineVisibilityParameters& rule) const
{
  if (this->hiddenOnBothSides(view, point, direction, rule.OutlinePixels, rule.Contact)
        .value_or(true))
  {
    return false; // no outline within that distance (or no image to tell)
  }
  // Only the point's own sheet may hide it, and only near it: a surface
  // standing a little beyond its silhouette curve, not an occluder in front
  // of a line that passes behind it (whose change points stay exact).
  const double reach = OutlineSheetTolerances * rule.Tolerance;
  if (this->hides(view, point, reach))
  {
    return false;
  }
  const std::vector<Id> under = this->trianglesUnder(point, rule.Contact);
  if (under.empty())
  {
    return false;
  }
  const std::vector<Id> sheet = this->localSheet(point, under, reach);
  return !this->anyHit(view, point, rule.Contact, reach,
    [&](Id t, double) { return !std::binary_search(sheet.begin(), sheet.end(), t); });
}

bool OcclusionMesh::besideTheOutline(const ViewGeometry& view, const glm::dvec3& point,
  const glm::dvec3& direction, double pixels, double behind, double contact) const
{
  const auto beside = this->besidePoints(view, point, direction, pixels);
  if (!beside)
  {
    return false;
  }
  std::vector<Id> sheet;
  if (std::isfinite(behind) && contact > 0.0)
  {
    sheet = this->localSheet(point, this->trianglesUnder(point, contact), behind);
  }
  if (sheet.empty())
  {
    return !this->covers(view, (*beside)[0], behind) || !this->covers(view, (*beside)[1], behind);
  }
  // Covered: anything in front of the point beside, or the contour's own
  // sheet within `behind` behind it (a fold of the re-meshing); another part
  // just behind leaves the contour an outline (a head over a thorax).
  auto coveredBy = [&](const glm::dvec3& side) {
    if (this->hides(view, side, 0.0))
    {
      return true;
    }
    const glm::dvec3 away = -view.towardViewerFrom(side);
    const double length = glm::length(away);
    if (!(length > 0.0) || !std::isfinite(length))
    {
      return false;
    }
    const glm::dvec3 start = side + (behind / length) * away;
    return isFinite(start) && this->anyHit(view, start, 0.0, behind, [&](Id c, double) {
      return std::binary_search(sheet.begin(), sheet.end(), c);
    });
  };
  return !coveredBy((*beside)[0]) || !coveredBy((*beside)[1]);
}

std::vector<std::array<Id, 2>> OcclusionMesh::contourEdges(const ViewGeometry& view) const
{
  auto vertex = [&](Id corner) {
    return this->VertexOf[static_cast<std::size_t>(corner)];
  };
  auto faces = [&](const Triangle& t) {
    const glm::dvec3& a = this->Points[static_cast<std::size_t>(t[0])];
    const glm::dvec3 normal = glm::cross(this->Points[static_cast<std::size_t>(t[1])] - a,
      this->Points[static_cast<std::size_t>(t[2])] - a);
    return view.visibility(a, normal) > 0.0;
  };
  std::vector<std::array<Id, 2>> edges;
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    const Triangle& front = this->Triangles[t];
    const Triangle corners = { vertex(front[0]), vertex(front[1]), vertex(front[2]) };
    if (hasRepeatedCorner(corners) || !faces(front))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const Id u = corners[static_cast<std::size_t>(k)];
      const Id v = corners[static_cast<std::size_t>((k + 1) % 3)];
      // The other triangles with both ends: exactly one, facing away.
      Id across = -1;
      int others = 0;
      const auto row = static_cast<std::size_t>(u);
      for (std::size_t i = this->VertexTriangleOffsets[row];
           i < this->VertexTriangleOffsets[row + 1] && others < 2; ++i)
      {
        const Id other = this->VertexTriangles[i];
        const Triangle& o = this->Triangles[static_cast<std::size_t>(other)];
        if (other != static_cast<Id>(t) &&
          (vertex(o[0]) == v || vertex(o[1]) == v || vertex(o[2]) == v))
        {
          across = other;
          ++others;
        }
      }
      if (others == 1 && !faces(this->Triangles[static_cast<std::size_t>(across)]))
      {
        edges.push_back({ u, v });
      }
    }
  }
  return edges;
}

bool OcclusionMesh::insideTheOutline(const ViewGeometry& view, const glm::dvec3& point,
  const glm::dvec3& direction, const LineVisibilityParameters& rule) const
{
  return this
    ->hiddenOnBothSides(
      view, point, direction, InsideOutlineFactor * rule.OutlinePixels, rule.Contact)
    .value_or(false);
}

bool OcclusionMesh::hides(
  const ViewGeometry& view, const glm::dvec3& point, const LineVisibilityParameters& rule) const
{
  return this->occlusion(view, point, rule) == Occlusion::Hidden;
}

OcclusionMesh::Occlusion OcclusionMesh::occlusion(
  const ViewGeometry& view, const glm::dvec3& point, const LineVisibilityParameters& rule) const
{
  // The triangles the point lies on: they cap its tolerance and seed its
  // local sheet.
  const bool onSurfaceRule = rule.Contact > 0.0 && rule.Contact < rule.Tolerance && isFinite(point);
  std::vector<Id> under =
    onSurfaceRule ? this->trianglesUnder(point, rule.Contact) : std::vector<Id>{};
  const double tolerance = this->toleranceAt(under, rule);
  // A hit beyond the tolerance hides the point whatever the triangle.
  if (this->hides(view, point, tolerance))
  {
    return Occlusion::Hidden;
  }
  if (!onSurfaceRule || !(rule.Contact < tolerance))
  {
    return Occlusion::Clear;
  }
  // The nearer hits; the sheet is worked out only when there are some.
  std::vector<Id> near;
  this->anyHit(view, point, rule.Contact, tolerance, [&](Id triangle, double) {
    near.push_back(triangle);
    return false;
  });
  if (near.empty())
  {
    return Occlusion::Clear;
  }
  const std::vector<Id> sheet = this->localSheet(point, std::move(under), tolerance);
  if (sheet.empty())
  {
    return Occlusion::Clear; // not on the surface: the plain rule's answer
  }
  return std::any_of(near.begin(), near.end(),
           [&](Id triangle) { return !std::binary_search(sheet.begin(), sheet.end(), triangle); })
    ? Occlusion::Hidden
    : Occlusion::BehindItsOwnSheet;
}

namespace
{

double pieceLength(const LinePiece& piece)
{
  double length = 0.0;
  for (std::size_t k = 1; k < piece.Points.size(); ++k)
  {
    length += glm::length(piece.Points[k] - piece.Points[k - 1]);
  }
  return length;
}

// Appends `next` to `piece` (they share the change point at the joint).
void appendPiece(LinePiece& piece, const LinePiece& next)
{
  piece.Points.insert(piece.Points.end(), next.Points.begin() + 1, next.Points.end());
  piece.Along.insert(piece.Along.end(), next.Along.begin() + 1, next.Along.end());
}

// splitByVisibility's last step before mergeShortPieces: a hidden piece
// shorter than InsideGapOutlines times OutlinePixels in the image, between
// two visible pieces, that no probe found hidden by the ray rule
// (`hiddenByRay`, per piece: only insideTheOutline hid it) joins the pieces
// on both sides, and the change points inside the joined piece go: the line
// is as if it had not been split there.
std::vector<LinePiece> closeShortInsideGaps(std::vector<LinePiece> pieces,
  const std::vector<unsigned char>& hiddenByRay, const ViewGeometry& view,
  const LineVisibilityParameters& rule)
{
  const double longest = OcclusionMesh::InsideGapOutlines * rule.OutlinePixels;
  if (!rule.DrawShortDips || !(longest > 0.0) || pieces.size() < 3)
  {
    return pieces;
  }
  std::vector<LinePiece> closed;
  std::vector<unsigned char> joined; // per closed piece: a gap was closed in it
  closed.push_back(std::move(pieces[0]));
  joined.push_back(0);
  for (std::size_t i = 1; i < pieces.size(); ++i)
  {
    LinePiece& piece = pieces[i];
    const bool gap = !piece.Visible && !hiddenByRay[i] && i + 1 < pieces.size() &&
      closed.back().Visible && pixelLength(piece.Points, view, longest) < longest;
    if (gap || piece.Visible == closed.back().Visible)
    {
      appendPiece(closed.back(), piece);
      joined.back() = 1;
    }
    else
    {
      closed.push_back(std::move(piece));
      joined.push_back(0);
    }
  }
  for (std::size_t i = 0; i < closed.size(); ++i)
  {
    LinePiece& piece = closed[i];
    if (!joined[i])
    {
      continue;
    }
    std::size_t kept = 1;
    for (std::size_t k = 1; k < piece.Points.size(); ++k)
    {
      const bool inside = k + 1 < piece.Points.size();
      if (inside && piece.Along[k] != std::floor(piece.Along[k]))
      {
        continue;
      }
      piece.Points[kept] = piece.Points[k];
      piece.Along[kept] = piece.Along[k];
      ++kept;
    }
    piece.Points.resize(kept);
    piece.Along.resize(kept);
  }
  return closed;
}

} // namespace

double pixelLength(const std::vector<glm::dvec3>& points, const ViewGeometry& view, double enough)
{
  double length = 0.0;
  glm::dvec2 last;
  for (std::size_t k = 0; k < points.size() && length < enough; ++k)
  {
    glm::dvec2 at;
    if (!view.toPixels(points[k], at))
    {
      return std::numeric_limits<double>::infinity();
    }
    length += k > 0 ? glm::length(at - last) : 0.0;
    last = at;
  }
  return length;
}

std::vector<LinePiece> mergeShortPieces(std::vector<LinePiece> pieces, double minimumLength)
{
  if (!(minimumLength > 0.0))
  {
    return pieces;
  }
  // The shortest piece below the limit takes its neighbours' state and
  // joins them, until none is left or one piece remains; alternation keeps
  // both neighbours of a piece in the other state.
  while (pieces.size() > 1)
  {
    std::size_t shortest = pieces.size();
    double shortestLength = minimumLength;
    for (std::size_t i = 0; i < pieces.size(); ++i)
    {
      const double length = pieceLength(pieces[i]);
      if (length < shortestLength)
      {
        shortest = i;
        shortestLength = length;
      }
    }
    if (shortest == pieces.size())
    {
      break;
    }
    const std::size_t first = shortest > 0 ? shortest - 1 : 0;
    const std::size_t last = std::min(shortest + 1, pieces.size() - 1);
    LinePiece merged = std::move(pieces[first]);
    merged.Visible = !pieces[shortest].Visible;
    for (std::size_t i = first + 1; i <= last; ++i)
    {
      appendPiece(merged, pieces[i]);
    }
    pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(first) + 1,
      pieces.begin() + static_cast<std::ptrdiff_t>(last) + 1);
    pieces[first] = std::move(merged);
  }
  return pieces;
}

std::vector<LinePiece> splitWhere(const std::vector<glm::dvec3>& polyline, double spacing,
  double precision, const std::function<bool(const glm::dvec3&, const glm::dvec3&)>& holds,
  const std::function<void(bool)>& pieceEnds)
{
  std::vector<LinePiece> pieces;
  if (polyline.empty())
  {
    return pieces;
  }
  glm::dvec3 direction(0.0);
  for (std::size_t i = 1; i < polyline.size() && direction == glm::dvec3(0.0); ++i)
  {
    direction = polyline[i] - polyline[i - 1];
  }
  LinePiece current;
  current.Visible = holds(polyline.front(), direction);
  current.Points.push_back(polyline.front());
  current.Along.push_back(0.0);
  for (std::size_t i = 1; i < polyline.size(); ++i)
  {
    const glm::dvec3& a = polyline[i - 1];
    const glm::dvec3& b = polyline[i];
    if (b != a)
    {
      direction = b - a;
    }
    const double length = glm::length(b - a);
    // Probes at fractions k / probes of the segment; the last is b.
    const double wanted =
      spacing > 0.0 && std::isfinite(length) ? std::ceil(length / spacing) : 1.0;
    const int probes = static_cast<int>(std::clamp(wanted, 1.0, 100000.0));
    double before = 0.0; // the fraction of the last probe, in the current state
    for (int k = 1; k <= probes; ++k)
    {
      const double at = k == probes ? 1.0 : static_cast<double>(k) / probes;
      const bool state = holds(k == probes ? b : a + at * (b - a), direction);
      if (state != current.Visible)
      {
        // Bisection between the probes: `low` keeps the current state.
        double low = before;
        double high = at;
        for (int step = 0; step < 64 && (high - low) * length > precision; ++step)
        {
          const double middle = 0.5 * (low + high);
          (holds(a + middle * (b - a), direction) == current.Visible ? low : high) = middle;
        }
        const double fraction = 0.5 * (low + high);
        const glm::dvec3 change = a + fraction * (b - a);
        const double along = static_cast<double>(i - 1) + fraction;
        current.Points.push_back(change);
        current.Along.push_back(along);
        if (pieceEnds)
        {
          pieceEnds(current.Visible);
        }
        pieces.push_back(std::move(current));
        current = LinePiece();
        current.Visible = state;
        current.Points.push_back(change);
        current.Along.push_back(along);
      }
      before = at;
    }
    current.Points.push_back(b);
    current.Along.push_back(static_cast<double>(i));
  }
  if (pieceEnds)
  {
    pieceEnds(current.Visible);
  }
  pieces.push_back(std::move(current));
  return pieces;
}

std::vector<LinePiece> splitByVisibility(const OcclusionMesh& surface, const ViewGeometry& view,
  const std::vector<glm::dvec3>& polyline, const LineVisibilityParameters& parameters)
{
  // Whether p is visible (`direction` is OutlinePixels' "along the line");
  // each piece also records whether a probe of it was hidden by the ray
  // rule, not only by insideTheOutline (closeShortInsideGaps).
  bool byRayIn[2] = { false, false }; // per state, since the last piece in it ended
  auto visible = [&](const glm::dvec3& p, const glm::dvec3& direction) {
    bool byRay = false;
    bool state = true;
    switch (surface.occlusion(view, p, parameters))
    {
      case OcclusionMesh::Occlusion::Hidden:
        byRay = !surface.nearTheOutline(view, p, direction, parameters);
        state = !byRay;
        break;
      case OcclusionMesh::Occlusion::BehindItsOwnSheet:
        state = !surface.insideTheOutline(view, p, direction, parameters);
        break;
      default:
        break;
    }
    byRayIn[state] = byRayIn[state] || byRay;
    return state;
  };
  std::vector<unsigned char> hiddenByRay; // per piece
  auto pieceEnds = [&](bool state) {
    hiddenByRay.push_back(byRayIn[state] ? 1 : 0);
    byRayIn[state] = false;
  };
  std::vector<LinePiece> pieces =
    splitWhere(polyline, parameters.SampleSpacing, parameters.Precision, visible, pieceEnds);
  pieces = closeShortInsideGaps(std::move(pieces), hiddenByRay, view, parameters);
  return mergeShortPieces(std::move(pieces), parameters.MinimumPieceLength);
}

} // namespace silsmooth
