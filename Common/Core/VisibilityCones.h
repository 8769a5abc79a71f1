// What the two visibility hierarchies share (VisibilityHierarchy.h for
// vertices, SilhouetteTriangleHierarchy.h for triangles): the map of a vertex
// to a unit vector on S^3 whose angle to the view's query vector tells the
// sign of g(V) = N . (E - V), and the cone test that decides a whole cluster
// of such vectors at once.
//
// For perspective, V' = (N, -N.v) with v = (V - Centre) * InverseScale and the
// query E' = (e, 1), e = (E - Centre) * InverseScale: sign(E'.V') = sign(g).
// For parallel projection V' = (N, 0) and the query is (D, 0), D towards the
// viewer. A cone (unit axis A, half-angle T) is decided visible when
// angle(A, Q) + T < pi/2 - Margin and invisible when
// angle(A, Q) - T > pi/2 + Margin; then every member's direct g has that
// sign, since a decided member has |g| >= about 3.7e-8 |N| |E - V|, nine
// orders of magnitude beyond the rounding of the direct dot product.
#pragma once

#include "FiniteVector.h"

#include "ViewGeometry.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace silsmooth
{
namespace visibility_cones
{

/// Angular margin of a decision (radians). A decided vertex has
/// |g| >= sin(Margin) |N| |E - V| / (1 + sqrt 3) (the 4D map scales by at
/// most 1 + |v|, |v| <= sqrt 3), about 3.7e-8 |N| |E - V|, against a rounding
/// error of the direct dot product below 1e-15 |N| |E - V| and angle errors of
/// the trees' own arithmetic of the same order.
constexpr double Margin = 1e-7;
/// Normals and positions outside these magnitudes are evaluated directly (no
/// overflow or underflow can reach the margin's scale inside them).
constexpr double SmallestNormal = 1e-100;
constexpr double LargestNormal = 1e100;
constexpr double LargestCoordinate = 1e140;
constexpr double SmallestHalfExtent = 1e-140;
constexpr double HalfPi = 1.57079632679489661923;

inline double maxAbs(const glm::dvec3& v)
{
  return std::max({ std::abs(v.x), std::abs(v.y), std::abs(v.z) });
}

/// Unit vector of a non-zero finite 4D vector, without overflow or underflow.
inline glm::dvec4 unit(glm::dvec4 v)
{
  const double m = std::max({ std::abs(v.x), std::abs(v.y), std::abs(v.z), std::abs(v.w) });
  v /= m;
  return v / std::sqrt(glm::dot(v, v));
}

/// The angle between unit vectors, accurate near 0 and pi too.
inline double angleBetween(const glm::dvec4& a, const glm::dvec4& b)
{
  const double d = glm::dot(a, b);
  const glm::dvec4 p = b - d * a;
  return std::atan2(std::sqrt(glm::dot(p, p)), d);
}

/// Whether a vertex can be clustered: finite, with a normal of a length and
/// a position of a magnitude the margin covers. Others are evaluated
/// directly.
inline bool clusterable(const glm::dvec3& point, const glm::dvec3& normal)
{
  const double length = isFinite(normal) ? maxAbs(normal) : 0.0;
  return isFinite(point) && maxAbs(point) <= LargestCoordinate && length >= SmallestNormal &&
    length <= LargestNormal;
}

/// The perspective map's conditioning: centre on the clustered points' box,
/// scale by a power of two (exact) at least half its largest side, so that
/// |v| <= sqrt 3.
struct Conditioning
{
  glm::dvec3 Centre{ 0.0 };
  double InverseScale = 1.0;
  /// False when the box is too small for the perspective vectors (a
  /// perspective tree is then not built).
  bool PerspectiveUsable = true;

  static Conditioning ofBox(const glm::dvec3& lo, const glm::dvec3& hi)
  {
    Conditioning c;
    c.Centre = 0.5 * lo + 0.5 * hi;
    const double halfExtent = 0.5 * std::max({ hi.x - lo.x, hi.y - lo.y, hi.z - lo.z });
    int exponent = 0;
    if (halfExtent > 0.0)
    {
      std::frexp(halfExtent, &exponent); // halfExtent < 2^exponent
    }
    c.InverseScale = std::ldexp(1.0, -exponent);
    c.PerspectiveUsable = halfExtent == 0.0 || halfExtent >= SmallestHalfExtent;
    return c;
  }

  /// V' of a clusterable vertex.
  glm::dvec4 vectorOf(const glm::dvec3& point, const glm::dvec3& normal, bool perspective) const
  {
    const glm::dvec3 n = normal / maxAbs(normal);
    const glm::dvec3 unitNormal = n / std::sqrt(glm::dot(n, n));
    if (!perspective)
    {
      return glm::dvec4(unitNormal, 0.0);
    }
    const glm::dvec3 v = (point - this->Centre) * this->InverseScale;
    return unit(glm::dvec4(unitNormal, -glm::dot(unitNormal, v)));
  }

  /// The view's query vector; false when the view allows none (then every
  /// vertex is evaluated directly).
  bool queryOf(const ViewGeometry& view, glm::dvec4& query) const
  {
    if (view.Parallel)
    {
      const double m = isFinite(view.TowardViewer) ? maxAbs(view.TowardViewer) : 0.0;
      if (!(m >= SmallestNormal && m <= LargestNormal))
      {
        return false;
      }
      query = unit(glm::dvec4(view.TowardViewer, 0.0));
      return true;
    }
    if (!isFinite(view.Eye) || maxAbs(view.Eye) > LargestCoordinate)
    {
      return false;
    }
    query = unit(glm::dvec4((view.Eye - this->Centre) * this->InverseScale, 1.0));
    return true;
  }
};

/// +1: every vector of the cone (axis, halfAngle) is visible from `query`;
/// -1: every one is invisible; 0: undecided. A half-angle beyond pi/2 is
/// never decided.
inline int decide(const glm::dvec4& axis, double halfAngle, const glm::dvec4& query)
{
  if (!(halfAngle < HalfPi))
  {
    return 0;
  }
  const double angle = angleBetween(axis, query);
  if (angle + halfAngle < HalfPi - Margin)
  {
    return 1;
  }
  if (angle - halfAngle > HalfPi + Margin)
  {
    return -1;
  }
  return 0;
}

/// A node of a cone tree: its members are the items at tree positions
/// [Begin, End), every one within HalfAngle of Axis (an item's own radius
/// included).
struct ConeNode
{
  glm::dvec4 Axis{ 0.0 };
  double HalfAngle = 4.0; // > pi: never decided
  std::uint32_t Begin = 0;
  std::uint32_t End = 0;
  std::int32_t FirstChild = -1; // children FirstChild and FirstChild + 1; -1 for a leaf
};

struct ConeTree
{
  /// Breadth-first; children follow their parent.
  std::vector<ConeNode> Nodes;
  /// Roots of the subtrees handed to parallel workers, covering the tree.
  std::vector<std::int32_t> Tasks;
  /// The item at each tree position (a permutation of the items).
  std::vector<std::uint32_t> Items;
};

/// The tree of `keys` (unit vectors on S^3): median splits along the widest
/// coordinate down to leaves of at most 32 items. Item i stands for a cap of
/// angular radius radii[i] around keys[i] (no radii: points), and a node's
/// cone covers its items' caps. At most 2^32 - 1 items.
ConeTree buildConeTree(const std::vector<glm::dvec4>& keys, const std::vector<double>& radii = {});

} // namespace visibility_cones
} // namespace silsmooth
