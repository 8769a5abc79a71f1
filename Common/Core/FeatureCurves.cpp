#include "FeatureCurves.h"

#include "DisjointSets.h"
#include "ShadingNormals.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace silsmooth
{

std::vector<FeatureEdge> normalizedFeatureEdges(std::vector<FeatureEdge> edges)
{
  for (FeatureEdge& e : edges)
  {
    if (e.first > e.second)
    {
      std::swap(e.first, e.second);
    }
  }
  edges.erase(std::remove_if(edges.begin(), edges.end(),
                [](const FeatureEdge& e) { return e.first == e.second || e.first < 0; }),
    edges.end());
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

namespace
{

double cosineOfDegrees(double degrees)
{
  return std::cos(degrees * 3.14159265358979323846 / 180.0);
}

// The cosine below which an edge turns by more than `degrees`, less a
// millionth of a degree: a turn equal to the limit up to rounding (a regular
// 12-sided cylinder's 30 degrees at a limit of 30) is then not more than it
// on every edge alike, where rounding made some such edges creases and not
// others. No mesh means a turn that small.
double cosineBeyondDegrees(double degrees)
{
  return cosineOfDegrees(degrees + 1e-6);
}

} // namespace

EdgeSides edgeSidesOf(const std::vector<Triangle>& triangles, const EdgeTable& table)
{
  EdgeSides sides;
  sides.First.assign(table.edgeCount(), { { -1, -1 } });
  sides.Count.assign(table.edgeCount(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t e = static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k));
      const unsigned char seen = sides.Count[e];
      if (seen < 2)
      {
        sides.First[e][seen] = static_cast<Id>(t) * 3 + k;
      }
      sides.Count[e] = static_cast<unsigned char>(std::min(seen + 1, 3));
    }
  }
  sides.SameWay.assign(table.edgeCount(), 0);
  for (std::size_t e = 0; e < sides.SameWay.size(); ++e)
  {
    if (sides.Count[e] == 2)
    {
      const Id first = sides.First[e][0];
      const Id second = sides.First[e][1];
      sides.SameWay[e] =
        triangles[static_cast<std::size_t>(first / 3)][static_cast<std::size_t>(first % 3)] ==
          triangles[static_cast<std::size_t>(second / 3)][static_cast<std::size_t>(second % 3)]
        ? 1
        : 0;
    }
  }
  return sides;
}

std::vector<double> dihedralCosines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const EdgeTable& table)
{
  return dihedralCosines(points, triangles, edgeSidesOf(triangles, table));
}

std::vector<double> dihedralCosines(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, const EdgeSides& sides, const ParallelFor& parallelFor)
{
  std::vector<glm::dvec3> faceNormals;
  std::vector<double> cosines;
  dihedralCosines(points, triangles, sides, parallelFor, faceNormals, cosines);
  return cosines;
}

void dihedralCosines(const std::vector<glm::dvec3>& points, const std::vector<Triangle>& triangles,
  const EdgeSides& sides, const ParallelFor& parallelFor, std::vector<glm::dvec3>& faceNormals,
  std::vector<double>& cosines)
{
  // Each triangle's unit normal once (an edge's two triangles each have
  // three edges); NaN-free zero for a triangle that cannot be used. Every
  // entry of both buffers is written below.
  faceNormals.resize(triangles.size());
  parallelFor(triangles.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      const Triangle& tri = triangles[t];
      const glm::dvec3& a = points[static_cast<std::size_t>(tri[0])];
      faceNormals[t] = hasRepeatedCorner(tri)
        ? glm::dvec3(0.0)
        : safeNormalize(glm::cross(points[static_cast<std::size_t>(tri[1])] - a,
            points[static_cast<std::size_t>(tri[2])] - a));
    }
  });
  const std::size_t edgeCount = sides.Count.size();
  cosines.resize(edgeCount);
  parallelFor(edgeCount, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e)
    {
      cosines[e] = std::nan("");
      if (sides.Count[e] != 2)
      {
        continue;
      }
      const Id first = sides.First[e][0];
      const Id second = sides.First[e][1];
      const std::size_t t0 = static_cast<std::size_t>(first / 3);
      const std::size_t t1 = static_cast<std::size_t>(second / 3);
      const glm::dvec3& n0 = faceNormals[t0];
      const glm::dvec3& n1 = faceNormals[t1];
      if (n0 == glm::dvec3(0.0) || n1 == glm::dvec3(0.0))
      {
        continue;
      }
      // Both triangles walking the edge the same way means one of them is
      // turned over: compare it the right way up, or every edge would count.
      cosines[e] = glm::dot(n0, sides.SameWay[e] != 0 ? -n1 : n1);
    }
  });
}

std::vector<FeatureEdge> featureEdgesByAngle(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, double angleDegrees, const EdgeTable* given)
{
  const EdgeTable built = given ? EdgeTable() : EdgeTable(triangles);
  const EdgeTable& table = given ? *given : built;
  return featureEdgesByAngle(dihedralCosines(points, triangles, table), table, angleDegrees);
}

std::vector<FeatureEdge> featureEdgesByAngle(
  const std::vector<double>& cosines, const EdgeTable& table, double angleDegrees)
{
  const double cosLimit = cosineBeyondDegrees(angleDegrees);
  std::vector<FeatureEdge> result;
  for (std::size_t e = 0; e < table.edgeCount(); ++e)
  {
    if (cosines[e] < cosLimit) // false for NaN
    {
      result.emplace_back(table.edge(static_cast<Id>(e)).low, table.edge(static_cast<Id>(e)).high);
    }
  }
  return result; // the edge table is sorted by (low, high)
}

std::vector<FeatureEdge> flatSidedCreases(const std::vector<glm::dvec3>& points,
  const std::vector<Triangle>& triangles, double angleDegrees, const EdgeTable* given)
{
  const EdgeTable built = given ? EdgeTable() : EdgeTable(triangles);
  const EdgeTable& table = given ? *given : built;
  const EdgeSides sides = edgeSidesOf(triangles, table);
  return flatSidedCreases(dihedralCosines(points, triangles, sides), sides, table, angleDegrees);
}

namespace
{

// The edges on the outline of a planar face of two or more triangles that is
// sharper than cosLimit all round (1 per such edge, by edge id): a cone's or
// a dome's flat base, a pyramid's. Where the other side is a curved surface
// of single triangles, the both-flat rule cannot tell such an edge from a
// coarse organic mesh's; an outline sharp all round can (the few coplanar
// neighbours of an organic mesh have gentle edges about them). A face that
// meets a border or a non-manifold edge has no closed outline and counts
// as not sharp all round. Serial: a face's triangles are joined in any order.
std::vector<unsigned char> sharpFaceOutlines(const std::vector<double>& cosines,
  const EdgeSides& sides, const EdgeTable& table, double cosLimit, double cosFlat,
  const std::vector<unsigned char>& flat)
{
  std::vector<unsigned char> outline(table.edgeCount(), 0);
  // Only a flat triangle with a sharp edge can be on such an outline; fine
  // and organic meshes have none, and skip the joining (28 ms at 1.3M
  // triangles all lying flat against their neighbours).
  bool candidate = false;
  for (std::size_t e = 0; e < table.edgeCount() && !candidate; ++e)
  {
    candidate = cosines[e] < cosLimit &&
      (flat[static_cast<std::size_t>(sides.First[e][0] / 3)] ||
        flat[static_cast<std::size_t>(sides.First[e][1] / 3)]);
  }
  if (!candidate)
  {
    return outline;
  }
  const std::size_t none = flat.size();
  DisjointSets faces(flat.size());
  for (std::size_t e = 0; e < table.edgeCount(); ++e)
  {
    if (cosines[e] >= cosFlat) // false for NaN: not exactly two sides
    {
      faces.unite(static_cast<std::size_t>(sides.First[e][0] / 3),
        static_cast<std::size_t>(sides.First[e][1] / 3));
    }
  }
  // Each triangle's face (`none` for a triangle in no planar face).
  std::vector<std::size_t> face(flat.size(), none);
  for (std::size_t t = 0; t < flat.size(); ++t)
  {
    face[t] = flat[t] ? faces.find(t) : none;
  }
  std::vector<unsigned char> notSharp(flat.size(), 0);
  // A face touching a border or a non-manifold edge, from every side (an
  // edge's sides beyond its first two are only found from the triangles).
  for (std::size_t t = 0; t < flat.size(); ++t)
  {
    for (int k = 0; k < 3 && face[t] != none; ++k)
    {
      if (sides.Count[static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k))] != 2)
      {
        notSharp[face[t]] = 1;
      }
    }
  }
  // Below, only edges of exactly two sides: the others are counted above.
  auto facesOf = [&](std::size_t e) {
    return std::make_pair(face[static_cast<std::size_t>(sides.First[e][0] / 3)],
      face[static_cast<std::size_t>(sides.First[e][1] / 3)]);
  };
  for (std::size_t e = 0; e < table.edgeCount(); ++e)
  {
    if (sides.Count[e] != 2 || cosines[e] < cosLimit)
    {
      continue;
    }
    const auto [a, b] = facesOf(e);
    if (a != b) // a gentle (or NaN) edge on a face's outline
    {
      for (const std::size_t f : { a, b })
      {
        if (f != none)
        {
          notSharp[f] = 1;
        }
      }
    }
  }
  for (std::size_t e = 0; e < table.edgeCount(); ++e)
  {
    if (sides.Count[e] != 2)
    {
      continue;
    }
    const auto [a, b] = facesOf(e);
    outline[e] = a != b && ((a != none && !notSharp[a]) || (b != none && !notSharp[b])) ? 1 : 0;
  }
  return outline;
}

} // namespace

std::vector<FeatureEdge> flatSidedCreases(const std::vector<double>& cosines,
  const EdgeSides& sides, const EdgeTable& table, double angleDegrees,
  const ParallelFor& parallelFor)
{
  const double cosLimit = cosineBeyondDegrees(angleDegrees);
  const double cosFlat = cosineBeyondDegrees(FlatNeighbourDegrees); // at most, up to rounding
  // Every edge found below, of either kind, is sharper than the angle: a
  // mesh with no such edge (a smooth or finely curved one) has none, and
  // skips the passes over the triangles (9 ms a frame at 1.3M triangles,
  // most of a deforming sphere's crease test).
  if (std::none_of(cosines.begin(), cosines.end(), [cosLimit](double c) { return c < cosLimit; }))
  {
    return {};
  }
  // Triangles lying flat against a neighbour across some edge.
  const std::size_t triangleCount = table.sideCount() / 3;
  std::vector<unsigned char> flat(triangleCount, 0);
  parallelFor(triangleCount, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (cosines[static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k))] >= cosFlat)
        {
          flat[t] = 1;
        }
      }
    }
  });
  // A face of one triangle (a wedge's end, a cube's cut-off corner): every
  // edge sharper than the angle, and a flat triangle across each. It has no
  // coplanar neighbour to be told by; its flat neighbours tell it from a
  // spike of a coarse organic mesh, whose neighbours are curved (one flat
  // neighbour was too few: a 100-triangle bunny had a crease by chance).
  // Read from `flat` only, written to `lone`, so the order does not matter.
  std::vector<unsigned char> lone(triangleCount, 0);
  parallelFor(triangleCount, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      bool lonelyFace = !flat[t];
      for (int k = 0; k < 3 && lonelyFace; ++k)
      {
        // False for NaN: a border or a fan; otherwise the edge has two sides.
        const auto e = static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k));
        const Id first = sides.First[e][0] / 3;
        lonelyFace = cosines[e] < cosLimit &&
          flat[static_cast<std::size_t>(
            first == static_cast<Id>(t) ? sides.First[e][1] / 3 : first)];
      }
      lone[t] = lonelyFace ? 1 : 0;
    }
  });
  const std::vector<unsigned char> outline =
    sharpFaceOutlines(cosines, sides, table, cosLimit, cosFlat, flat);
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    flat[t] = flat[t] || lone[t];
  }
  // Sharp edges between two flat triangles (a cosine is NaN unless the edge
  // has exactly two sides), and the outlines of planar faces sharp all round.
  std::vector<FeatureEdge> result;
  for (std::size_t e = 0; e < table.edgeCount(); ++e)
  {
    if (outline[e] ||
      (cosines[e] < cosLimit && flat[static_cast<std::size_t>(sides.First[e][0] / 3)] &&
        flat[static_cast<std::size_t>(sides.First[e][1] / 3)]))
    {
      result.emplace_back(table.edge(static_cast<Id>(e)).low, table.edge(static_cast<Id>(e)).high);
    }
  }
  // An edge that meets no other at either end, nor a border, is no crease:
  // the creases of a solid bound its faces and meet at its corners (a folded
  // sheet's run to its borders), while a stretched coarse grid (a UV sphere
  // of 8 x 6 scaled by 2) has a lone sharp edge at each pointed end, between
  // planar quads, which made a kink there.
  std::unordered_map<Id, int> degree;
  for (const FeatureEdge& edge : result)
  {
    ++degree[edge.first];
    ++degree[edge.second];
  }
  for (std::size_t e = 0; e < table.edgeCount() && !result.empty(); ++e)
  {
    if (sides.Count[e] != 2)
    {
      // A border or a non-manifold edge: its ends count as met.
      const Edge& edge = table.edge(static_cast<Id>(e));
      for (const Id end : { edge.low, edge.high })
      {
        const auto found = degree.find(end);
        if (found != degree.end())
        {
          found->second += 2;
        }
      }
    }
  }
  result.erase(
    std::remove_if(result.begin(), result.end(),
      [&](const FeatureEdge& edge) { return degree[edge.first] == 1 && degree[edge.second] == 1; }),
    result.end());
  return result;
}

glm::dvec3 circleTangentAlong(const glm::dvec3& direction, const glm::dvec3& chord)
{
  const double chordLength = glm::length(chord);
  const double directionLength = glm::length(direction);
  if (!(chordLength > 0.0) || !(directionLength > 0.0) || !std::isfinite(directionLength))
  {
    return chord;
  }
  glm::dvec3 unit = direction / directionLength;
  double cosTheta = glm::dot(unit, chord) / chordLength;
  if (cosTheta < 0.0)
  {
    unit = -unit;
    cosTheta = -cosTheta;
  }
  cosTheta = std::min(cosTheta, 1.0);
  return unit * (2.0 * chordLength / (1.0 + cosTheta));
}

namespace
{

// The angle a polyline turns by from edge `in` to the next edge `out`.
double turnBetween(const glm::dvec3& in, const glm::dvec3& out)
{
  const glm::dvec3 u0 = safeNormalize(in);
  const glm::dvec3 u1 = safeNormalize(out);
  return std::atan2(glm::length(glm::cross(u0, u1)), glm::dot(u0, u1));
}

// How much of the long edge's direction vertex v's tangent takes (0 to 1):
// where one edge is from half of FeatureLineRatio to FeatureLineRatio times
// as long as the other, rising smoothly, and only where a line meets an
// arc: v turns by at most 3/4 of what the short edge's far end does (half
// of it there; on a curve merely sampled unevenly v turns about as much,
// alternating edges, or (1 + ratio) / 2 times as much, and eq. 1 is right).
// w0 and w1 are v's incoming and outgoing edges (lengths l0 and l1), the
// short one ending at shortEnd.
double lineMeetsArcWeight(const std::vector<glm::dvec3>& points,
  const std::vector<std::size_t>& offsets, const std::vector<Id>& neighbours, std::size_t v,
  std::size_t shortEnd, const glm::dvec3& w0, const glm::dvec3& w1, double l0, double l1)
{
  const double ratio = std::max(l0, l1) / std::min(l0, l1);
  const double t =
    std::clamp((ratio - 0.5 * FeatureLineRatio) / (0.5 * FeatureLineRatio), 0.0, 1.0);
  if (!(t > 0.0) || offsets[shortEnd + 1] - offsets[shortEnd] != 2)
  {
    return 0.0;
  }
  const Id first = neighbours[offsets[shortEnd]];
  const std::size_t beyond = static_cast<std::size_t>(
    first == static_cast<Id>(v) ? neighbours[offsets[shortEnd] + 1] : first);
  const double turnHere = turnBetween(w0, w1);
  const double turnThere =
    turnBetween(points[shortEnd] - points[v], points[beyond] - points[shortEnd]);
  if (!(turnHere <= 0.75 * turnThere))
  {
    return 0.0;
  }
  return t * t * (3.0 - 2.0 * t);
}

} // namespace

FeatureCurves::FeatureCurves(const std::vector<glm::dvec3>& points, std::vector<FeatureEdge> edges)
{
  edges = normalizedFeatureEdges(std::move(edges));
  const Id pointCount = static_cast<Id>(points.size());
  edges.erase(std::remove_if(edges.begin(), edges.end(),
                [pointCount](const FeatureEdge& e) { return e.second >= pointCount; }),
    edges.end());
  this->Edges = std::move(edges);
  const std::size_t n = this->Edges.size();
  this->Curves.resize(n);
  this->Curved.assign(n, 0);

  // Feature neighbours of every point (compressed rows).
  std::vector<std::size_t> offsets(points.size() + 1, 0);
  for (const FeatureEdge& e : this->Edges)
  {
    ++offsets[static_cast<std::size_t>(e.first) + 1];
    ++offsets[static_cast<std::size_t>(e.second) + 1];
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<Id> neighbours(offsets.back());
  std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
  for (const FeatureEdge& e : this->Edges)
  {
    neighbours[fill[static_cast<std::size_t>(e.first)]++] = e.second;
    neighbours[fill[static_cast<std::size_t>(e.second)]++] = e.first;
  }

  // Inside a polyline (two feature edges, no sharp turn): the eq. 1 tangent.
  const double cosCorner = std::cos(FeatureCornerAngleDegrees * 3.14159265358979323846 / 180.0);
  std::vector<glm::dvec3> insideTangent(points.size(), glm::dvec3(0.0));
  std::vector<unsigned char> inside(points.size(), 0);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    if (offsets[v + 1] - offsets[v] != 2)
    {
      continue;
    }
    const glm::dvec3 w0 = points[v] - points[static_cast<std::size_t>(neighbours[offsets[v]])];
    const glm::dvec3 w1 = points[static_cast<std::size_t>(neighbours[offsets[v] + 1])] - points[v];
    const double l0 = glm::length(w0);
    const double l1 = glm::length(w1);
    if (!(l0 > 0.0) || !(l1 > 0.0) || !std::isfinite(l0 * l1))
    {
      continue;
    }
    if (glm::dot(w0, w1) < cosCorner * l0 * l1)
    {
      continue; // a corner: ends two polylines
    }
    insideTangent[v] = safeNormalize(l1 * w0 + l0 * w1);
    // A CAD tessellation's line meeting an arc tangentially (a rounded
    // rectangle's side beside its corner's short segments), which eq. 1
    // would bow: the long edge's own direction (LineMeetsArc).
    const std::size_t shortEnd =
      static_cast<std::size_t>(neighbours[offsets[v] + (l0 < l1 ? 0 : 1)]);
    const double weight =
      lineMeetsArcWeight(points, offsets, neighbours, v, shortEnd, w0, w1, l0, l1);
    if (weight > 0.0)
    {
      const glm::dvec3 along = l0 > l1 ? w0 / l0 : w1 / l1;
      insideTangent[v] = safeNormalize((1.0 - weight) * insideTangent[v] + weight * along);
    }
    inside[v] = insideTangent[v] != glm::dvec3(0.0) ? 1 : 0;
  }

  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t a = static_cast<std::size_t>(this->Edges[i].first);
    const std::size_t b = static_cast<std::size_t>(this->Edges[i].second);
    const glm::dvec3 chord = points[b] - points[a];
    HermiteCurve& curve = this->Curves[i];
    curve.P0 = points[a];
    curve.P1 = points[b];
    curve.T0 = chord;
    curve.T1 = chord;
    if (!inside[a] && !inside[b])
    {
      continue; // a polyline of one edge, or an edge between two corners
    }
    // At an end, the circle through the end and the next two points: its
    // tangent at the next point (eq. 1 there) mirrored in the chord's
    // perpendicular bisector.
    auto endTangent = [&](std::size_t next, const glm::dvec3& towardNext) {
      const glm::dvec3 u = safeNormalize(towardNext);
      const glm::dvec3& t = insideTangent[next];
      return 2.0 * glm::dot(t, u) * u - t;
    };
    const glm::dvec3 directionA = inside[a] ? insideTangent[a] : endTangent(b, chord);
    const glm::dvec3 directionB = inside[b] ? insideTangent[b] : endTangent(a, -chord);
    curve.T0 = circleTangentAlong(directionA, chord);
    curve.T1 = circleTangentAlong(directionB, chord);
    this->Curved[i] = 1;
    ++this->CurvedCount;
  }
}

Id FeatureCurves::find(Id a, Id b) const
{
  const FeatureEdge key = a < b ? FeatureEdge(a, b) : FeatureEdge(b, a);
  const auto it = std::lower_bound(this->Edges.begin(), this->Edges.end(), key);
  return (it != this->Edges.end() && *it == key) ? static_cast<Id>(it - this->Edges.begin()) : -1;
}

FeatureSplit splitAtFeatureEdges(
  std::size_t pointCount, const std::vector<Triangle>& triangles, const FeatureCurves& features)
{
  FeatureSplit split;
  split.Triangles = triangles;
  split.OnFeature.assign(pointCount, 0);
  for (const FeatureEdge& e : features.edges())
  {
    if (static_cast<std::size_t>(e.second) < pointCount)
    {
      split.OnFeature[static_cast<std::size_t>(e.first)] = 1;
      split.OnFeature[static_cast<std::size_t>(e.second)] = 1;
    }
  }
  if (features.empty())
  {
    return split;
  }

  // Corners 3t + k at feature points are joined across non-feature edges:
  // each class of joined corners around a point is one smooth group.
  const EdgeTable table(triangles);
  std::vector<Id> firstSide(table.edgeCount(), -1);
  DisjointSets groups(triangles.size() * 3);
  auto cornerOf = [&](Id t, Id v) -> std::size_t {
    const Triangle& tri = triangles[static_cast<std::size_t>(t)];
    const int k = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
    return static_cast<std::size_t>(t) * 3 + static_cast<std::size_t>(k);
  };
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = triangles[t];
    if (hasRepeatedCorner(tri))
    {
      continue; // keeps its ids: never re-meshed
    }
    for (int k = 0; k < 3; ++k)
    {
      const Id u = tri[static_cast<std::size_t>(k)];
      const Id w = tri[static_cast<std::size_t>((k + 1) % 3)];
      if (!split.OnFeature[static_cast<std::size_t>(u)] &&
        !split.OnFeature[static_cast<std::size_t>(w)])
      {
        continue;
      }
      if (features.find(u, w) >= 0)
      {
        continue; // a feature edge separates the groups
      }
      const std::size_t e = static_cast<std::size_t>(table.sideEdge(static_cast<Id>(t), k));
      if (firstSide[e] < 0)
      {
        firstSide[e] = static_cast<Id>(t);
        continue;
      }
      groups.unite(cornerOf(firstSide[e], u), cornerOf(static_cast<Id>(t), u));
      groups.unite(cornerOf(firstSide[e], w), cornerOf(static_cast<Id>(t), w));
    }
  }

  // The group holding a point's lowest corner keeps the point's id; every
  // other group gets a copy, in corner order (deterministic).
  std::vector<Id> keeper(pointCount, -1); // root corner that kept the id
  std::vector<Id> copyOfRoot(triangles.size() * 3, -1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    Triangle& tri = split.Triangles[t];
    if (hasRepeatedCorner(tri))
    {
      continue;
    }
    for (std::size_t k = 0; k < 3; ++k)
    {
      const Id v = tri[k];
      if (!split.OnFeature[static_cast<std::size_t>(v)])
      {
        continue;
      }
      const std::size_t root = groups.find(t * 3 + k);
      Id& kept = keeper[static_cast<std::size_t>(v)];
      if (kept < 0)
      {
        kept = static_cast<Id>(root);
      }
      if (kept == static_cast<Id>(root))
      {
        continue;
      }
      Id& copy = copyOfRoot[root];
      if (copy < 0)
      {
        copy = static_cast<Id>(pointCount + split.CopySources.size());
        split.CopySources.push_back(v);
        split.OnFeature.push_back(1);
      }
      tri[k] = copy;
    }
  }
  return split;
}

} // namespace silsmooth
