#include "BoundaryCurveSmoother.h"

#include "ShadingNormals.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{

double rhoForHalfAngle(double cosTheta)
{
  const double c = std::clamp(cosTheta, 0.0, 1.0);
  return c / (1.0 + c);
}

glm::dvec2 HermiteCurve2D::at(double u) const
{
  const double u2 = u * u;
  const double u3 = u2 * u;
  const double h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
  const double h10 = u3 - 2.0 * u2 + u;
  const double h01 = -2.0 * u3 + 3.0 * u2;
  const double h11 = u3 - u2;
  return h00 * this->P0 + h10 * this->T0 + h01 * this->P1 + h11 * this->T1;
}

namespace
{

double cross2(const glm::dvec2& a, const glm::dvec2& b)
{
  return a.x * b.y - a.y * b.x;
}

// The tangent direction at an end: the projected normal turned by pi/2,
// pointing along the chord; the chord itself when the normal has no
// direction in the image.
glm::dvec2 endTangent(const glm::dvec2& normal, const glm::dvec2& chordUnit)
{
  const double length = glm::length(normal);
  if (!(length > 1e-12) || !std::isfinite(length))
  {
    return chordUnit;
  }
  glm::dvec2 t(-normal.y / length, normal.x / length);
  if (glm::dot(t, chordUnit) < 0.0)
  {
    t = -t;
  }
  return t;
}

} // namespace

HermiteCurve2D boundaryCurve(
  const glm::dvec2& x0, const glm::dvec2& x1, const glm::dvec2& n0, const glm::dvec2& n1)
{
  HermiteCurve2D curve;
  curve.P0 = x0;
  curve.P1 = x1;
  const glm::dvec2 chord = x1 - x0;
  const double chordLength = glm::length(chord);
  if (!(chordLength > 0.0) || !std::isfinite(chordLength))
  {
    return curve; // a point: zero tangents
  }
  const glm::dvec2 chordUnit = chord / chordLength;
  const glm::dvec2 t0 = endTangent(n0, chordUnit);
  const glm::dvec2 t1 = endTangent(n1, chordUnit);
  double length0 = 0.0;
  double length1 = 0.0;
  // Q = x0 + a t0 = x1 - b t1: a t0 + b t1 = chord.
  const double det = cross2(t0, t1);
  bool circular = false;
  if (std::abs(det) > 1e-9)
  {
    const double a = cross2(chord, t1) / det;
    const double b = cross2(t0, chord) / det;
    if (a > 0.0 && b > 0.0)
    {
      // theta is half the angle between the end tangents (for an arc, half
      // the angle it subtends).
      const double cos2Theta = std::clamp(glm::dot(t0, t1), -1.0, 1.0);
      const double rho = rhoForHalfAngle(std::sqrt(0.5 * (1.0 + cos2Theta)));
      length0 = 4.0 * rho * a;
      length1 = 4.0 * rho * b;
      circular = true;
    }
  }
  if (!circular)
  {
    length0 = 2.0 * chordLength / (1.0 + std::max(0.0, glm::dot(t0, chordUnit)));
    length1 = 2.0 * chordLength / (1.0 + std::max(0.0, glm::dot(t1, chordUnit)));
  }
  length0 = std::min(length0, 3.0 * chordLength);
  length1 = std::min(length1, 3.0 * chordLength);
  curve.T0 = length0 * t0;
  curve.T1 = length1 * t1;
  return curve;
}

int boundaryCurveSampleCount(const HermiteCurve2D& curve, const BoundaryCurveParameters& p)
{
  if (p.SamplesPerCurve >= 2)
  {
    return p.SamplesPerCurve;
  }
  // Bezier control points of the curve; the polyline of k equal pieces stays
  // within 0.75 M / k^2 of it, M the larger second difference (the bound the
  // 2008 filter uses, Filters/Core/AdaptiveSampling.h).
  const glm::dvec2 b0 = curve.P0;
  const glm::dvec2 b1 = curve.P0 + curve.T0 / 3.0;
  const glm::dvec2 b2 = curve.P1 - curve.T1 / 3.0;
  const glm::dvec2 b3 = curve.P1;
  const double m = std::max(glm::length(b0 - 2.0 * b1 + b2), glm::length(b1 - 2.0 * b2 + b3));
  const double tolerance = std::max(p.TolerancePixels, 1e-6);
  const double pieces = std::ceil(std::sqrt(0.75 * m / tolerance));
  const int lo = std::max(2, p.MinimumSamples);
  const int hi = std::max(lo, p.MaximumSamples);
  if (!std::isfinite(pieces))
  {
    return lo;
  }
  return static_cast<int>(
    std::clamp(pieces + 1.0, static_cast<double>(lo), static_cast<double>(hi)));
}

BoundaryCurveMesh::BoundaryCurveMesh(std::vector<glm::dvec3> points,
  std::vector<Triangle> triangles, const std::vector<glm::dvec3>& normals)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , Edges(this->Triangles)
{
  const std::vector<glm::dvec3> computed = angleWeightedNormals(this->Points, this->Triangles);
  this->Normals.resize(this->Points.size());
  for (std::size_t i = 0; i < this->Points.size(); ++i)
  {
    glm::dvec3 n = i < normals.size() ? safeNormalize(normals[i]) : glm::dvec3(0.0);
    if (n == glm::dvec3(0.0))
    {
      n = computed[i];
    }
    this->Normals[i] = n;
  }
  this->FaceNormals.resize(this->Triangles.size());
  this->EdgeTriangles.assign(this->Edges.edgeCount(), { { -1, -1 } });
  this->EdgeManifold.assign(this->Edges.edgeCount(), 1);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    const Triangle& tri = this->Triangles[t];
    const glm::dvec3& a = this->Points[static_cast<std::size_t>(tri[0])];
    const glm::dvec3& b = this->Points[static_cast<std::size_t>(tri[1])];
    const glm::dvec3& c = this->Points[static_cast<std::size_t>(tri[2])];
    this->FaceNormals[t] = glm::cross(b - a, c - a);
    if (hasRepeatedCorner(tri))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const auto e = static_cast<std::size_t>(this->Edges.sideEdge(static_cast<Id>(t), k));
      std::array<Id, 2>& slots = this->EdgeTriangles[e];
      if (slots[0] < 0)
      {
        slots[0] = static_cast<Id>(t);
      }
      else if (slots[1] < 0)
      {
        slots[1] = static_cast<Id>(t);
      }
      else
      {
        this->EdgeManifold[e] = 0;
      }
    }
  }
}

BoundaryCurveResult BoundaryCurveMesh::smooth(const ViewGeometry& view,
  const glm::dmat3& normalToEye, const BoundaryCurveParameters& parameters) const
{
  BoundaryCurveResult result;
  const std::vector<unsigned char> front = this->frontFacing(view);
  // Per edge: the index of its curve in result.Curves, or -1.
  std::vector<Id> edgeCurve(this->Edges.edgeCount(), -1);
  const glm::dmat4 clipToModel = glm::inverse(view.ModelToClip);
  for (std::size_t e = 0; e < this->Edges.edgeCount(); ++e)
  {
    const std::array<Id, 2>& tris = this->EdgeTriangles[e];
    if (this->EdgeManifold[e] && tris[0] >= 0 && tris[1] >= 0 &&
      front[static_cast<std::size_t>(tris[0])] != front[static_cast<std::size_t>(tris[1])])
    {
      ++result.SilhouetteEdgeCount;
      this->curveEdge(e, view, clipToModel, normalToEye, parameters, edgeCurve, result);
    }
  }
  // Re-mesh: every triangle with a curved side.
  result.Triangles.reserve(this->Triangles.size() + result.NewPoints.size() * 2);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    this->remeshTriangle(t, edgeCurve, result);
  }
  return result;
}

// Front-facing triangles (the face normal towards the viewer).
std::vector<unsigned char> BoundaryCurveMesh::frontFacing(const ViewGeometry& view) const
{
  const std::size_t triangleCount = this->Triangles.size();
  std::vector<unsigned char> front(triangleCount, 0);
  for (std::size_t t = 0; t < triangleCount; ++t)
  {
    const Triangle& tri = this->Triangles[t];
    const glm::dvec3 centre = (this->Points[static_cast<std::size_t>(tri[0])] +
                                this->Points[static_cast<std::size_t>(tri[1])] +
                                this->Points[static_cast<std::size_t>(tri[2])]) /
      3.0;
    front[t] = glm::dot(this->FaceNormals[t], view.towardViewerFrom(centre)) > 0.0 ? 1 : 0;
  }
  return front;
}

// The Hermite curve of silhouette edge e in the image, sampled and lifted
// back onto the view rays at the edge's own depth.
void BoundaryCurveMesh::curveEdge(std::size_t e, const ViewGeometry& view,
  const glm::dmat4& clipToModel, const glm::dmat3& normalToEye,
  const BoundaryCurveParameters& parameters, std::vector<Id>& edgeCurve,
  BoundaryCurveResult& result) const
{
  const auto inputPoints = static_cast<Id>(this->Points.size());
  ++result.SilhouetteEdgeCount;
  const Edge& edge = this->Edges.edge(static_cast<Id>(e));
  const glm::dvec3& p0 = this->Points[static_cast<std::size_t>(edge.low)];
  const glm::dvec3& p1 = this->Points[static_cast<std::size_t>(edge.high)];
  const glm::dvec4 c0 = view.ModelToClip * glm::dvec4(p0, 1.0);
  const glm::dvec4 c1 = view.ModelToClip * glm::dvec4(p1, 1.0);
  glm::dvec2 x0;
  glm::dvec2 x1;
  if (!view.toPixels(p0, x0) || !view.toPixels(p1, x1))
  {
    return; // reaches behind the eye: stays straight
  }
  const glm::dvec3& m0 = this->Normals[static_cast<std::size_t>(edge.low)];
  const glm::dvec3& m1 = this->Normals[static_cast<std::size_t>(edge.high)];
  const glm::dvec3 e0 = normalToEye * m0;
  const glm::dvec3 e1 = normalToEye * m1;
  const HermiteCurve2D curve =
    boundaryCurve(x0, x1, glm::dvec2(e0.x, e0.y), glm::dvec2(e1.x, e1.y));
  const int samples = boundaryCurveSampleCount(curve, parameters);
  std::vector<Id> ids;
  ids.reserve(static_cast<std::size_t>(samples));
  ids.push_back(edge.low);
  for (int s = 1; s + 1 < samples; ++s)
  {
    const double u = static_cast<double>(s) / (samples - 1);
    const glm::dvec2 pixel = curve.at(u);
    // The view ray through the pixel, at the edge's own depth there.
    const glm::dvec4 onEdge = (1.0 - u) * c0 + u * c1;
    const double ndcX = 2.0 * pixel.x / view.ViewportWidth - 1.0;
    const double ndcY = 2.0 * pixel.y / view.ViewportHeight - 1.0;
    const glm::dvec4 clip(ndcX * onEdge.w, ndcY * onEdge.w, onEdge.z, onEdge.w);
    const glm::dvec4 model = clipToModel * clip;
    glm::dvec3 point = glm::dvec3(model) / model.w;
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
    {
      point = (1.0 - u) * p0 + u * p1;
    }
    ids.push_back(inputPoints + static_cast<Id>(result.NewPoints.size()));
    result.NewPoints.push_back(point);
    glm::dvec3 normal = safeNormalize((1.0 - u) * m0 + u * m1);
    result.NewNormals.push_back(normal);
    BoundaryCurvePointSource source;
    source.Points = { { edge.low, edge.high, edge.high } };
    source.Weights = { { 1.0 - u, u, 0.0 } };
    result.NewPointSources.push_back(source);
  }
  ids.push_back(edge.high);
  edgeCurve[e] = static_cast<Id>(result.Curves.size());
  result.Curves.push_back(std::move(ids));
}

// Triangle t as it is, or re-meshed when a side is curved: a fan from the
// corner opposite one curved side (the paper's A P_i P_i+1), else from a new
// centre point.
void BoundaryCurveMesh::remeshTriangle(
  std::size_t t, const std::vector<Id>& edgeCurve, BoundaryCurveResult& result) const
{
  const auto inputPoints = static_cast<Id>(this->Points.size());
  const Triangle& tri = this->Triangles[t];
  int curved = 0;
  std::array<const std::vector<Id>*, 3> sideCurve{ { nullptr, nullptr, nullptr } };
  if (!hasRepeatedCorner(tri))
  {
    for (int k = 0; k < 3; ++k)
    {
      const Id c = edgeCurve[static_cast<std::size_t>(this->Edges.sideEdge(static_cast<Id>(t), k))];
      if (c >= 0)
      {
        sideCurve[static_cast<std::size_t>(k)] = &result.Curves[static_cast<std::size_t>(c)];
        ++curved;
      }
    }
  }
  if (curved == 0)
  {
    result.Triangles.push_back(tri);
    result.TriangleSource.push_back(static_cast<Id>(t));
    result.TriangleIsNew.push_back(0);
    return;
  }
  ++result.RemeshedTriangleCount;
  // The outline of the triangle, corner 0 first, each curved side by its
  // samples in the triangle's own order.
  std::vector<Id> loop;
  std::array<std::size_t, 3> cornerAt{ { 0, 0, 0 } };
  for (int k = 0; k < 3; ++k)
  {
    cornerAt[static_cast<std::size_t>(k)] = loop.size();
    loop.push_back(tri[static_cast<std::size_t>(k)]);
    if (const std::vector<Id>* samples = sideCurve[static_cast<std::size_t>(k)])
    {
      const bool forward = samples->front() == tri[static_cast<std::size_t>(k)];
      const std::size_t n = samples->size();
      for (std::size_t s = 1; s + 1 < n; ++s)
      {
        loop.push_back((*samples)[forward ? s : n - 1 - s]);
      }
    }
  }
  auto emit = [&](Id a, Id b, Id c) {
    result.Triangles.push_back({ { a, b, c } });
    result.TriangleSource.push_back(static_cast<Id>(t));
    result.TriangleIsNew.push_back(1);
  };
  if (curved == 1)
  {
    // Fan from the vertex opposite the curved side (the paper's A P_i P_i+1).
    int k = 0;
    while (!sideCurve[static_cast<std::size_t>(k)])
    {
      ++k;
    }
    const std::size_t begin = cornerAt[static_cast<std::size_t>(k)];
    const std::size_t end = k == 2 ? loop.size() : cornerAt[static_cast<std::size_t>(k + 1)];
    const Id apex = tri[static_cast<std::size_t>((k + 2) % 3)];
    for (std::size_t i = begin; i < end; ++i)
    {
      emit(loop[i], loop[(i + 1) % loop.size()], apex);
    }
  }
  else
  {
    const Id centre = inputPoints + static_cast<Id>(result.NewPoints.size());
    const glm::dvec3 position = (this->Points[static_cast<std::size_t>(tri[0])] +
                                  this->Points[static_cast<std::size_t>(tri[1])] +
                                  this->Points[static_cast<std::size_t>(tri[2])]) /
      3.0;
    result.NewPoints.push_back(position);
    result.NewNormals.push_back(safeNormalize(this->Normals[static_cast<std::size_t>(tri[0])] +
      this->Normals[static_cast<std::size_t>(tri[1])] +
      this->Normals[static_cast<std::size_t>(tri[2])]));
    BoundaryCurvePointSource source;
    source.Points = tri;
    source.Weights = { { 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 } };
    result.NewPointSources.push_back(source);
    for (std::size_t i = 0; i < loop.size(); ++i)
    {
      emit(loop[i], loop[(i + 1) % loop.size()], centre);
    }
  }
}

} // namespace silsmooth
