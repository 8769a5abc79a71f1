// What the module's view-dependent filters share (private to the module):
// finding the camera, the prop's matrix and the viewport; the view's
// signature, so that GetMTime() changes exactly when the view does; the
// silsmooth::ViewGeometry in the data's model coordinates; and the triangles
// of a vtkPolyData's polygons and strips.
#ifndef SilhouetteViewSupport_h
#define SilhouetteViewSupport_h

#include "vtkTimeStamp.h"
#include "vtkType.h"

#include "MeshTopology.h"
#include "ViewGeometry.h"

#include <array>
#include <string>
#include <vector>

class vtkCamera;
class vtkMatrix4x4;
class vtkPolyData;
class vtkProp3D;
class vtkRenderer;

namespace silsmooth_vtk
{

/// The camera if set, else the renderer's active camera, but only if the
/// renderer has one already: asking for it would create one, and a renderer
/// that already has a camera skips its first automatic reset.
vtkCamera* ActiveCamera(vtkCamera* camera, vtkRenderer* renderer);

/// The prop's matrix, else `matrix`, else the identity (row-major).
void ModelMatrixOf(vtkProp3D* prop, vtkMatrix4x4* matrix, double out[16]);

/// The renderer's size in pixels when it has one, else `fallback`.
std::array<int, 2> ViewportOf(vtkRenderer* renderer, const int fallback[2]);

/// Everything about the view that changes a view-dependent result. The
/// camera's own MTime is not enough: renderers reset its clipping range every
/// frame, which would re-run a filter for nothing, while a prop's matrix or a
/// window's size can change without touching the camera at all. The camera
/// enters through its model-view matrix (position, orientation, model and
/// user-view transforms) and its projection parameters, which do not depend
/// on the clipping range. Signatures are compared bitwise, so a NaN in the
/// view compares equal to itself instead of re-running the filter on every
/// update.
struct ViewSignature
{
  std::array<double, 16> ModelView{};
  std::array<double, 16> ExplicitProjection{};
  std::array<double, 17> Projection{};
  std::array<double, 16> Model{};
  std::array<int, 2> Viewport{};

  bool operator==(const ViewSignature& o) const;
  bool operator!=(const ViewSignature& o) const { return !(*this == o); }
};

ViewSignature SignatureOf(vtkCamera* camera, const double model[16], std::array<int, 2> viewport);

/// Remembers the last view a filter's GetMTime() saw, and when it changed.
class ViewTracker
{
public:
  /// The time the view last changed (by value), updated for this view.
  vtkMTimeType Update(vtkCamera* camera, const double model[16], std::array<int, 2> viewport);

private:
  ViewSignature Last;
  bool HaveView = false;
  vtkTimeStamp Time;
};

/// The view in the data's model coordinates: model -> eye is the camera's
/// model-view matrix (which includes its model and user-view transforms)
/// times the model matrix; the eye is its inverse applied to the origin, the
/// direction towards the viewer its inverse applied to +z; model -> clip is
/// the camera's projection for the viewport's aspect. Returns an empty string,
/// or the error message when the view is degenerate (singular, not affine or
/// not finite) or the viewport is smaller than one pixel.
std::string MakeViewGeometry(vtkCamera* camera, const double model[16], std::array<int, 2> viewport,
  silsmooth::ViewGeometry& view);

/// The polygons as fans and the strips with alternating orientation, so that
/// every triangle keeps its cell's orientation; per triangle its cell id
/// (counting verts and lines first, as vtkPolyData does). Counts polygons
/// of fewer than 3 points in `tooSmall`. Returns false when a triangle names
/// a point that does not exist.
bool ExtractTriangles(vtkPolyData* input, std::vector<silsmooth::Triangle>& triangles,
  std::vector<vtkIdType>& triangleCell, vtkIdType& tooSmall);

/// The input's point normals (active normals, 3 components, one per point),
/// or empty.
std::vector<glm::dvec3> PointNormalsOf(vtkPolyData* input);

} // namespace silsmooth_vtk

#endif
