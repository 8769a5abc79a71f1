// Phong tessellation (Boubekeur and Alexa 2008): flat stays flat, corners
// kept, a = 0 is the flat tessellation, a sphere's normals give a rounder
// surface than flat subdivision, watertight on a closed input, known answers
// computed by hand, counts, and the normal fallbacks. Checks are paired with
// a wrong case they must tell apart (normals that are not the face's, a = 3/4
// against a = 0, the projection's sign turned against the sphere bound, PN
// triangles' edge point against Phong's, bent normals against the fallback).
#include "PNTriangles.h"
#include "PhongTessellation.h"
#include "ShadingNormals.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

using silsmooth::Id;
using silsmooth::PhongTessellationResult;
using silsmooth::Triangle;

namespace
{

struct Mesh
{
  std::vector<glm::dvec3> Points;
  std::vector<Triangle> Triangles;
};

// The regular icosahedron on the unit sphere, outward.
Mesh icosahedron()
{
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  m.Points = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g }, { 0, 1, g },
    { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 }, { -g, 0, 1 } };
  for (glm::dvec3& p : m.Points)
  {
    p = glm::normalize(p);
  }
  m.Triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
    { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 },
    { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  return m;
}

// One 1-to-4 split with the new points pushed onto the unit sphere.
Mesh subdivideOnSphere(const Mesh& in)
{
  Mesh out{ in.Points, {} };
  std::map<std::pair<Id, Id>, Id> middle;
  auto mid = [&](Id a, Id b) {
    const auto key = std::minmax(a, b);
    const auto found = middle.find(key);
    if (found != middle.end())
    {
      return found->second;
    }
    out.Points.push_back(glm::normalize(
      out.Points[static_cast<std::size_t>(a)] + out.Points[static_cast<std::size_t>(b)]));
    const auto id = static_cast<Id>(out.Points.size() - 1);
    middle[key] = id;
    return id;
  };
  for (const Triangle& t : in.Triangles)
  {
    const Id ab = mid(t[0], t[1]);
    const Id bc = mid(t[1], t[2]);
    const Id ca = mid(t[2], t[0]);
    out.Triangles.push_back({ { t[0], ab, ca } });
    out.Triangles.push_back({ { ab, t[1], bc } });
    out.Triangles.push_back({ { ca, bc, t[2] } });
    out.Triangles.push_back({ { ab, bc, ca } });
  }
  return out;
}

// The flat point of output point i: its barycentric combination of sources,
// evaluated in the order the tessellation evaluates it.
glm::dvec3 flatPoint(
  const PhongTessellationResult& r, const std::vector<glm::dvec3>& input, std::size_t i)
{
  const auto& s = r.SourcePoints[i];
  const glm::dvec3& w = r.SourceWeights[i];
  return w.x * input[static_cast<std::size_t>(s[0])] + w.y * input[static_cast<std::size_t>(s[1])] +
    w.z * input[static_cast<std::size_t>(s[2])];
}

double largestDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b)
{
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    worst = std::max(worst, glm::distance(a[i], b[i]));
  }
  return worst;
}

double largestRadialError(const std::vector<glm::dvec3>& points)
{
  double worst = 0.0;
  for (const glm::dvec3& p : points)
  {
    worst = std::max(worst, std::abs(glm::length(p) - 1.0));
  }
  return worst;
}

// A planar fan around `centre` in the plane spanned by u and v.
Mesh fan(const glm::dvec3& centre, const glm::dvec3& u, const glm::dvec3& v)
{
  Mesh m{ { centre }, {} };
  for (int i = 0; i < 6; ++i)
  {
    const double angle = i * M_PI / 3.0 + 0.1 * i;
    m.Points.push_back(centre + (1.0 + 0.3 * i) * (std::cos(angle) * u + std::sin(angle) * v));
    m.Triangles.push_back({ { 0, 1 + i, 1 + (i + 1) % 6 } });
  }
  return m;
}

} // namespace

TEST(PhongTessellation, FlatTriangleWithFaceNormalsStaysFlat)
{
  // In the plane z = 0 with normal +z every tangent-plane projection is the
  // identity, so p* is the flat point exactly (p* = p + a * 0).
  const Mesh plane = fan({ 0.25, -0.5, 0.0 }, { 1, 0, 0 }, { 0, 1, 0 });
  const std::vector<glm::dvec3> up(plane.Points.size(), { 0, 0, 1 });
  const PhongTessellationResult r =
    silsmooth::tessellatePhong(plane.Points, plane.Triangles, up, 3);
  ASSERT_EQ(r.Points.size(), 7u + 12u * 3u + 6u * 3u);
  for (std::size_t i = 0; i < r.Points.size(); ++i)
  {
    EXPECT_EQ(r.Points[i].z, 0.0);
    EXPECT_EQ(r.Points[i], flatPoint(r, plane.Points, i));
    EXPECT_LT(glm::distance(r.Normals[i], glm::dvec3(0, 0, 1)), 1e-15);
  }

  // A tilted plane stays in its plane to rounding.
  const glm::dvec3 normal = glm::normalize(glm::dvec3(1, 2, 3));
  const glm::dvec3 u = glm::normalize(glm::cross(normal, glm::dvec3(0, 0, 1)));
  const Mesh tilted = fan({ 0.5, -1, 2 }, u, glm::cross(normal, u));
  const std::vector<glm::dvec3> normals(tilted.Points.size(), normal);
  const PhongTessellationResult t =
    silsmooth::tessellatePhong(tilted.Points, tilted.Triangles, normals, 3);
  for (std::size_t i = 0; i < t.Points.size(); ++i)
  {
    EXPECT_NEAR(glm::dot(t.Points[i] - tilted.Points[0], normal), 0.0, 1e-12);
    EXPECT_LT(glm::distance(t.Normals[i], normal), 1e-12);
  }

  // The wrong case: corner normals that are not the face normal lift the
  // same flat fan out of its plane by much more than the bound above.
  std::vector<glm::dvec3> bent(plane.Points.size());
  for (std::size_t i = 0; i < bent.size(); ++i)
  {
    bent[i] = glm::normalize(glm::dvec3(0, 0, 1) + 0.5 * (plane.Points[i] - plane.Points[0]));
  }
  const PhongTessellationResult b =
    silsmooth::tessellatePhong(plane.Points, plane.Triangles, bent, 3);
  double lifted = 0.0;
  for (const glm::dvec3& p : b.Points)
  {
    lifted = std::max(lifted, std::abs(p.z));
  }
  EXPECT_GT(lifted, 0.05);
}

TEST(PhongTessellation, CornersKeepTheirPositions)
{
  const Mesh sphere = subdivideOnSphere(icosahedron());
  for (int level = 0; level <= 4; ++level)
  {
    const PhongTessellationResult r =
      silsmooth::tessellatePhong(sphere.Points, sphere.Triangles, sphere.Points, level);
    for (std::size_t i = 0; i < sphere.Points.size(); ++i)
    {
      EXPECT_EQ(r.Points[i], sphere.Points[i]);
      EXPECT_LT(glm::distance(r.Normals[i], sphere.Points[i]), 1e-15);
      const auto id = static_cast<Id>(i);
      EXPECT_EQ(r.SourcePoints[i], (std::array<Id, 3>{ { id, id, id } }));
      EXPECT_EQ(r.SourceWeights[i], glm::dvec3(1, 0, 0));
    }
  }
  // The patch interpolates its corners exactly.
  const std::array<glm::dvec3, 3> p{ { { 1, 0, 0 }, { 0, 1, 0 }, { 0.2, 0.3, 1 } } };
  const std::array<glm::dvec3, 3> n{ { glm::normalize(glm::dvec3(1, 0.2, 0)),
    glm::normalize(glm::dvec3(0, 1, 0.4)), glm::normalize(glm::dvec3(0.1, 0.3, 1)) } };
  EXPECT_EQ(silsmooth::phongPosition(p, n, 1, 0, 0), p[0]);
  EXPECT_EQ(silsmooth::phongPosition(p, n, 0, 1, 0), p[1]);
  EXPECT_EQ(silsmooth::phongPosition(p, n, 0, 0, 1), p[2]);
}

TEST(PhongTessellation, ZeroShapeFactorIsTheFlatTessellation)
{
  const Mesh ico = icosahedron();
  const PhongTessellationResult flat =
    silsmooth::tessellatePhong(ico.Points, ico.Triangles, ico.Points, 3, 0.0);
  const PhongTessellationResult phong =
    silsmooth::tessellatePhong(ico.Points, ico.Triangles, ico.Points, 3);
  ASSERT_EQ(flat.Points.size(), phong.Points.size());
  double moved = 0.0;
  for (std::size_t i = 0; i < flat.Points.size(); ++i)
  {
    EXPECT_EQ(flat.Points[i], flatPoint(flat, ico.Points, i));
    EXPECT_EQ(flat.Normals[i], phong.Normals[i]); // a shapes the points only
    moved = std::max(moved, glm::distance(phong.Points[i], flatPoint(phong, ico.Points, i)));
  }
  EXPECT_EQ(flat.Triangles, phong.Triangles);
  // The wrong case: the default a = 3/4 is far from flat on this mesh.
  EXPECT_GT(moved, 0.05);
}

TEST(PhongTessellation, IcosphereWithExactNormalsIsNearerTheSphere)
{
  // Exact (radial) normals. The flat faces of the icosahedron are up to
  // 1 - 0.795 = 0.205 inside the sphere at their centres.
  const Mesh coarse[] = { icosahedron(), subdivideOnSphere(icosahedron()) };
  for (const Mesh& mesh : coarse)
  {
    for (int level = 1; level <= 4; ++level)
    {
      const double flat = largestRadialError(
        silsmooth::tessellatePhong(mesh.Points, mesh.Triangles, mesh.Points, level, 0.0).Points);
      const double phong = largestRadialError(
        silsmooth::tessellatePhong(mesh.Points, mesh.Triangles, mesh.Points, level).Points);
      const double pn = largestRadialError(
        silsmooth::tessellatePNTriangles(mesh.Points, mesh.Triangles, mesh.Points, level).Points);
      // The wrong case: the projection's sign turned (a = -3/4) moves the
      // points inwards, and must miss the bound.
      const double wrong = largestRadialError(
        silsmooth::tessellatePhong(mesh.Points, mesh.Triangles, mesh.Points, level, -0.75).Points);
      std::printf("%zu triangles, level %d: largest |r - 1| flat %.5f, Phong %.5f (%.3f x flat), "
                  "PN %.5f, Phong with the sign turned %.5f\n",
        mesh.Triangles.size(), level, flat, phong, phong / flat, pn, wrong);
      EXPECT_LT(phong, 0.5 * flat);
      EXPECT_GT(wrong, 0.5 * flat);
    }
  }
}

TEST(PhongTessellation, WatertightOnAClosedInput)
{
  const Mesh ico = icosahedron();
  for (int level = 1; level <= 3; ++level)
  {
    const PhongTessellationResult r =
      silsmooth::tessellatePhong(ico.Points, ico.Triangles, ico.Points, level);
    std::map<std::pair<Id, Id>, int> undirected;
    std::map<std::pair<Id, Id>, int> directed;
    for (const Triangle& t : r.Triangles)
    {
      EXPECT_FALSE(silsmooth::hasRepeatedCorner(t));
      for (int k = 0; k < 3; ++k)
      {
        const Id a = t[static_cast<std::size_t>(k)];
        const Id b = t[static_cast<std::size_t>((k + 1) % 3)];
        ++undirected[std::minmax(a, b)];
        ++directed[{ a, b }];
      }
    }
    for (const auto& [edge, count] : undirected)
    {
      EXPECT_EQ(count, 2) << "edge " << edge.first << "-" << edge.second << " at level " << level;
    }
    for (const auto& [edge, count] : directed)
    {
      EXPECT_EQ(count, 1);
    }
    // Closed genus 0: V - E + F = 2, and every point is used.
    EXPECT_EQ(static_cast<long>(r.Points.size()) - static_cast<long>(undirected.size()) +
        static_cast<long>(r.Triangles.size()),
      2);
  }
  // The two patches of an edge agree there (to rounding), so the shared
  // point is each one's own.
  const std::array<glm::dvec3, 3> p0{ { ico.Points[0], ico.Points[11], ico.Points[5] } };
  const std::array<glm::dvec3, 3> p1{ { ico.Points[11], ico.Points[0], ico.Points[10] } };
  for (int i = 1; i < 5; ++i)
  {
    const double t = i / 5.0;
    const glm::dvec3 a = silsmooth::phongPosition(p0, p0, 1.0 - t, t, 0.0);
    const glm::dvec3 b = silsmooth::phongPosition(p1, p1, t, 1.0 - t, 0.0);
    EXPECT_LT(glm::distance(a, b), 1e-15);
  }
}

TEST(PhongTessellation, KnownAnswers)
{
  // Edge (0,0,0)-(1,0,0) with normals tilted 45 degrees outwards, as on an
  // arc of a circle. At the midpoint p = (1/2, 0, 0):
  //   (p - p0) . n0 = -1/(2 sqrt 2), pi_0(p) = p - that n0 = (1/4, 0, 1/4),
  //   pi_1(p) = (3/4, 0, 1/4), their mean (1/2, 0, 1/4),
  //   p* = (1 - a) p + a (1/2, 0, 1/4) = (1/2, 0, a/4): z = 0.1875 for a = 3/4
  // (the circle is at 0.2071, PN triangles' cubic at 0.125). Normal +z.
  const std::vector<glm::dvec3> points{ { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, -1, 0 } };
  const std::vector<glm::dvec3> normals{ glm::normalize(glm::dvec3(-1, 0, 1)),
    glm::normalize(glm::dvec3(1, 0, 1)), { 0, 0, 1 } };
  const std::vector<Triangle> triangle{ { 0, 2, 1 } };
  for (const double a : { 0.75, 0.5, 1.0 })
  {
    const PhongTessellationResult r = silsmooth::tessellatePhong(points, triangle, normals, 1, a);
    int found = 0;
    for (std::size_t i = points.size(); i < r.Points.size(); ++i)
    {
      if (r.SourcePoints[i] == std::array<Id, 3>{ { 0, 1, 1 } })
      {
        ++found;
        EXPECT_EQ(r.SourceWeights[i], glm::dvec3(0.5, 0.5, 0.0));
        EXPECT_LT(glm::distance(r.Points[i], glm::dvec3(0.5, 0.0, a / 4.0)), 1e-15) << "a " << a;
        EXPECT_LT(glm::distance(r.Normals[i], glm::dvec3(0, 0, 1)), 1e-15);
      }
    }
    EXPECT_EQ(found, 1);
  }
  // The wrong case: PN triangles' edge point, 1/8 high, is not Phong's.
  const auto pn = silsmooth::tessellatePNTriangles(points, triangle, normals, 1);
  for (std::size_t i = points.size(); i < pn.Points.size(); ++i)
  {
    if (pn.SourcePoints[i] == std::array<Id, 3>{ { 0, 1, 1 } })
    {
      EXPECT_NEAR(pn.Points[i].z, 0.125, 1e-15);
    }
  }

  // Interior: the octant triangle e_x, e_y, e_z with radial normals. At the
  // centroid p = (1/3, 1/3, 1/3): pi_x(p) = p + (2/3) e_x = (1, 1/3, 1/3) and
  // the like, their mean (5/9, 5/9, 5/9), p* = 1/3 + a 2/9 = 1/2 for a = 3/4.
  const std::array<glm::dvec3, 3> octant{ { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  const double third = 1.0 / 3.0;
  EXPECT_LT(
    glm::distance(silsmooth::phongPosition(octant, octant, third, third, third), glm::dvec3(0.5)),
    1e-15);
  EXPECT_LT(glm::distance(
              silsmooth::phongNormal(octant, third, third, third), glm::normalize(glm::dvec3(1))),
    1e-15);
  EXPECT_LT(glm::distance(silsmooth::phongPosition(octant, octant, third, third, third, 0.0),
              glm::dvec3(third)),
    1e-15);
}

TEST(PhongTessellation, CountsPerInputTriangle)
{
  Mesh mesh = icosahedron();
  mesh.Triangles.push_back({ { 3, 3, 7 } }); // repeats a corner: copied unchanged
  const std::size_t corners = mesh.Points.size();
  const std::size_t edges = 30;
  const std::size_t faces = 20;
  for (int level = 0; level <= 5; ++level)
  {
    const PhongTessellationResult r =
      silsmooth::tessellatePhong(mesh.Points, mesh.Triangles, mesh.Points, level);
    const auto k = static_cast<std::size_t>(level);
    EXPECT_EQ(r.Triangles.size(), faces * (k + 1) * (k + 1) + 1);
    ASSERT_EQ(r.TriangleSource.size(), r.Triangles.size());
    std::vector<std::size_t> perInput(mesh.Triangles.size(), 0);
    for (std::size_t t = 0; t < r.Triangles.size(); ++t)
    {
      ++perInput[static_cast<std::size_t>(r.TriangleSource[t])];
      if (r.TriangleSource[t] == 20)
      {
        EXPECT_EQ(r.Triangles[t], mesh.Triangles[20]);
      }
    }
    for (std::size_t t = 0; t < faces; ++t)
    {
      EXPECT_EQ(perInput[t], (k + 1) * (k + 1));
    }
    EXPECT_EQ(perInput[20], 1u);
    // Points: corners, k per edge (the degenerate triangle's side (3, 7) is
    // an edge too, (3, 3) is not), (k - 1) k / 2 inside each face.
    const std::size_t inside = level > 0 ? k * (k - 1) / 2 : 0;
    EXPECT_EQ(r.Points.size(), corners + (edges + 1) * k + faces * inside);
  }
}

TEST(PhongTessellation, NormalFallbacksAndCancelling)
{
  const Mesh ico = icosahedron();
  const std::vector<glm::dvec3> computed =
    silsmooth::angleWeightedNormals(ico.Points, ico.Triangles);
  const PhongTessellationResult given =
    silsmooth::tessellatePhong(ico.Points, ico.Triangles, computed, 2);
  const PhongTessellationResult none = silsmooth::tessellatePhong(ico.Points, ico.Triangles, {}, 2);
  std::vector<glm::dvec3> someZero = computed;
  someZero[4] = glm::dvec3(0.0);
  someZero[9] = glm::dvec3(0.0);
  const PhongTessellationResult zero =
    silsmooth::tessellatePhong(ico.Points, ico.Triangles, someZero, 2);
  // The given normals are normalised again, so equal to rounding only.
  for (const PhongTessellationResult* r : { &none, &zero })
  {
    ASSERT_EQ(r->Points.size(), given.Points.size());
    EXPECT_LT(largestDistance(r->Points, given.Points), 1e-14);
    EXPECT_LT(largestDistance(r->Normals, given.Normals), 1e-14);
  }
  // The wrong case: radial normals bent by 0.2 at two points (not the
  // computed ones) move the output well past that tolerance.
  std::vector<glm::dvec3> bent = computed;
  bent[4] = glm::normalize(bent[4] + glm::dvec3(0.2, 0, 0));
  bent[9] = glm::normalize(bent[9] + glm::dvec3(0, 0.2, 0));
  const PhongTessellationResult b = silsmooth::tessellatePhong(ico.Points, ico.Triangles, bent, 2);
  EXPECT_GT(largestDistance(b.Points, given.Points), 1e-3);
  for (std::size_t i = 0; i < given.Normals.size(); ++i)
  {
    EXPECT_NEAR(glm::length(given.Normals[i]), 1.0, 1e-14);
    EXPECT_GT(glm::dot(given.Normals[i], given.Points[i]), 0.0);
  }
  // Opposite corner normals cancel at the midpoint: zero, not NaN.
  const std::array<glm::dvec3, 3> opposite{ { { 0, 0, 1 }, { 0, 0, -1 }, { 0, 0, 1 } } };
  EXPECT_EQ(silsmooth::phongNormal(opposite, 0.5, 0.5, 0.0), glm::dvec3(0.0));
  EXPECT_EQ(silsmooth::phongNormal(opposite, 0.25, 0.75, 0.0), glm::dvec3(0, 0, -1));
}
