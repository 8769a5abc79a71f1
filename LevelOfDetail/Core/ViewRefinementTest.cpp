#include "ViewRefinementTest.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace silsmooth
{

namespace
{
constexpr double HalfPi = 1.57079632679489661923;
constexpr double DegreesToRadians = 3.14159265358979323846 / 180.0;
}

ViewRefinementTest::ViewRefinementTest(const VertexHierarchy& hierarchy, const ViewGeometry& view,
  const ViewRefinementTolerances& tolerances)
  : Hierarchy(hierarchy)
  , View(view)
  , Tolerances(tolerances)
{
  for (int r = 0; r < 4; ++r)
  {
    this->Rows[r] = glm::dvec4(view.ModelToClip[0][r], view.ModelToClip[1][r],
      view.ModelToClip[2][r], view.ModelToClip[3][r]);
  }
  const glm::dvec4 planes[4] = { this->Rows[3] + this->Rows[0], this->Rows[3] - this->Rows[0],
    this->Rows[3] + this->Rows[1], this->Rows[3] - this->Rows[1] };
  for (int k = 0; k < 4; ++k)
  {
    const double length = glm::length(glm::dvec3(planes[k]));
    this->SidePlanes[k] = length > 0.0 ? planes[k] / length : glm::dvec4(0.0, 0.0, 0.0, 1.0);
  }
  const double sx = 0.5 * view.ViewportWidth * glm::length(glm::dvec3(this->Rows[0]));
  const double sy = 0.5 * view.ViewportHeight * glm::length(glm::dvec3(this->Rows[1]));
  this->PixelsPerClipUnit = std::max(sx, sy);
  this->DepthPerUnit = glm::length(glm::dvec3(this->Rows[3]));
  this->Margin = std::max(0.0, tolerances.ContourMarginDegrees) * DegreesToRadians;
  this->HysteresisMargin = std::max(0.0, tolerances.HysteresisDegrees) * DegreesToRadians;
}

ViewRefinementTest::NodeClass ViewRefinementTest::classify(
  VertexHierarchy::Index node, double marginRadians) const
{
  const VertexHierarchy::Node& n = this->Hierarchy.node(node);
  const BoundingSphere& sphere = n.Bound;
  if (this->Tolerances.CullOutsideFrustum)
  {
    const glm::dvec4 center(sphere.Center, 1.0);
    for (const glm::dvec4& plane : this->SidePlanes)
    {
      if (glm::dot(plane, center) < -sphere.Radius)
        return NodeClass::Outside;
    }
  }
  if (n.Normals.HalfAngle < 0.0)
    return NodeClass::Front; // no triangle with a normal: nothing to draw an outline
  const glm::dvec3 toward = this->View.towardViewerFrom(sphere.Center);
  const double towardLength = glm::length(toward);
  double seen = 0.0; // the sphere's angular radius from the eye
  if (!this->View.Parallel)
  {
    if (towardLength <= sphere.Radius)
      return NodeClass::Contour;
    seen = std::asin(sphere.Radius / towardLength);
  }
  if (!(towardLength > 0.0))
    return NodeClass::Contour;
  const double angle =
    std::acos(std::clamp(glm::dot(n.Normals.Axis, toward) / towardLength, -1.0, 1.0));
  const double spread = n.Normals.HalfAngle + seen + marginRadians;
  if (angle + spread < HalfPi)
    return NodeClass::Front;
  if (angle - spread > HalfPi)
    return NodeClass::Back;
  return NodeClass::Contour;
}

double ViewRefinementTest::screenError(VertexHierarchy::Index node) const
{
  const VertexHierarchy::Node& n = this->Hierarchy.node(node);
  const double nearestW =
    glm::dot(this->Rows[3], glm::dvec4(n.Bound.Center, 1.0)) - n.Bound.Radius * this->DepthPerUnit;
  if (!(nearestW > 1e-12))
    return std::numeric_limits<double>::infinity();
  return n.Error * this->PixelsPerClipUnit / nearestW;
}

double ViewRefinementTest::tolerance(NodeClass nodeClass) const
{
  switch (nodeClass)
  {
    case NodeClass::Contour:
      return this->Tolerances.ContourPixels;
    case NodeClass::Front:
      return this->Tolerances.InteriorPixels;
    case NodeClass::Back:
      return this->Tolerances.BackPixels;
    case NodeClass::Outside:
      break;
  }
  return std::numeric_limits<double>::infinity();
}

bool ViewRefinementTest::refine(
  VertexHierarchy::Index node, double scale, double marginRadians) const
{
  const double allowed = this->tolerance(this->classify(node, marginRadians));
  if (std::isinf(allowed))
    return false;
  if (allowed <= 0.0)
    return true;
  return this->screenError(node) > allowed * scale;
}

bool ViewRefinementTest::needs(VertexHierarchy::Index node) const
{
  return this->refine(node, 1.0, this->Margin);
}

bool ViewRefinementTest::keeps(VertexHierarchy::Index node) const
{
  const double hysteresis = std::clamp(this->Tolerances.Hysteresis, 1e-6, 1.0);
  return this->refine(node, hysteresis, this->Margin + this->HysteresisMargin);
}

} // namespace silsmooth
