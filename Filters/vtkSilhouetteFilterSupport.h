// Pieces shared by the module's view-dependent filters (through their
// superclass vtkSilhouetteViewAlgorithm) and its mesh-output filters
// (vtkBoundaryCurveSmoothingFilter, vtkPNTriangleFilter): the camera, the
// model matrix and the viewport in the data's model coordinates; the view
// signature that decides when a view change re-runs a filter; reading
// triangles from a vtkPolyData; writing a mesh with the module's provenance
// arrays. Private to the module (not wrapped, not installed).
#ifndef vtkSilhouetteFilterSupport_h
#define vtkSilhouetteFilterSupport_h

#include "vtkSilhouetteAttributeSources.h" // PointSource, part of this support
#include "vtkSilhouetteCheckedSetting.h"   // the checked setter macro, for the filters
#include "vtkSilhouetteFittingArrays.h"    // FittingArrays, part of this support
#include "vtkSilhouetteViewTracker.h"      // ViewTracker, part of this support
#include "vtkSmartPointer.h"
#include "vtkTimeStamp.h"
#include "vtkType.h"

#include "MeshTopology.h"
#include "UniformTessellation.h"
#include "ViewGeometry.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkCamera;
class vtkInformation;
class vtkInformationVector;
class vtkCellArray;
class vtkObject;
class vtkMatrix4x4;
class vtkPolyData;
class vtkProp3D;
class vtkRenderer;
class vtkUnsignedCharArray;

namespace vtkSilhouetteFilterSupport
{

/// The given camera, else the renderer's active camera if it exists (asking
/// for it would create one, and a renderer that already has a camera skips
/// its first automatic reset).
vtkCamera* ActiveCamera(vtkCamera* camera, vtkRenderer* renderer);

/// The prop's matrix, else the given matrix, else the identity.
void ModelMatrixOf(vtkProp3D* prop, vtkMatrix4x4* matrix, double out[16]);

/// The renderer's size when it has one, else the fallback.
std::array<int, 2> ViewportOf(vtkRenderer* renderer, const int fallback[2]);

/// The view in the data's model coordinates for the core, and (optionally)
/// the matrix that takes model normals to eye coordinates. Returns an empty
/// string, or the error to report (a degenerate view or viewport).
std::string MakeViewGeometry(vtkCamera* camera, const double model[16], std::array<int, 2> viewport,
  silsmooth::ViewGeometry& view, glm::dmat3* normalToEye = nullptr);

/// The view a vtkSilhouetteViewAlgorithm hands its subclasses' RequestData:
/// MakeViewGeometry's two results.
struct View
{
  silsmooth::ViewGeometry Geometry;
  glm::dmat3 NormalToEye{ 1.0 };
};

/// The triangles of a vtkPolyData: polygons as fans from their first corner
/// (a concave polygon, whose fan would cover more than it, by ear cutting),
/// strips with alternating orientation, with the input cell id of each. Also the points and the
/// active point normals (empty when there are none of the right shape).
struct Triangles
{
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Normals;
  std::vector<silsmooth::Triangle> Cells;
  std::vector<vtkIdType> CellIds;
  vtkIdType NonFinitePoints = 0;
  vtkIdType FirstNonFinitePoint = -1;
  /// Polygons of fewer than three points (they make no triangle).
  vtkIdType TooSmallPolygons = 0;
  /// Polygons triangulated by ear clipping (PolygonTriangulation.h), not as
  /// fans: those a fan would fold over.
  vtkIdType ConcavePolygons = 0;
  /// Polygons a fan folds over that ear clipping refused too (they cross
  /// themselves, or have no area): split as fans all the same.
  vtkIdType UntriangulatedPolygons = 0;
};
/// Returns an empty string, or the error to report (cells naming missing
/// points).
std::string ReadTriangles(vtkPolyData* input, Triangles& out);
/// ReadTriangles' points, normals and non-finite count only, leaving the
/// cells empty: for a mesh whose cells are known to be those read before.
void ReadPoints(vtkPolyData* input, Triangles& out);

/// What a filter of one surface reads first: its input and output polydata
/// and the input's triangles.
struct Surface
{
  vtkPolyData* Input = nullptr;
  vtkPolyData* Output = nullptr;
  Triangles Mesh; ///< ReadFiniteTriangles of Input
};

/// RequestData's first step for the filters of one surface. No value after
/// reporting the error on `self` (a missing polydata, cells naming missing
/// points, points with NaN or infinite coordinates).
std::optional<Surface> ReadSurface(
  vtkAlgorithm* self, vtkInformationVector** inputVector, vtkInformationVector* outputVector);

/// ReadTriangles, and also the error for points with NaN or infinite
/// coordinates, for the filters that cannot use such input at all.
std::string ReadFiniteTriangles(vtkPolyData* input, Triangles& out);

/// The input's polygons and strips as the module's filters read them
/// (ReadTriangles), for a program or filter that needs triangles before
/// them (vtkTriangleFilter cuts some concave polygons into fewer
/// triangles than they take): `output` gets the input's points with their
/// point data and one triangle per ReadTriangles triangle with its cell's
/// data; vertex and line cells are left out. Returns "" or ReadTriangles'
/// error (then `output` is left empty).
std::string Triangulate(vtkPolyData* input, vtkPolyData* output);

/// The vertex and line cells a mesh-output filter passes through: those with
/// enough points for their kind (a vertex cell one, a line two), with each
/// one's input cell id. The others draw nothing, and VTK's XML writer crashes
/// on them: they are left out and counted in `Dropped`.
struct PassedCells
{
  vtkSmartPointer<vtkCellArray> Verts;
  vtkSmartPointer<vtkCellArray> Lines;
  std::vector<vtkIdType> CellIds;
  vtkIdType Dropped = 0;
};
PassedCells PassVertsAndLines(vtkPolyData* input);

/// Writes a triangle mesh: the input's points (ids kept) followed by the added
/// points, their point data (input arrays interpolated for added points), the
/// normals as the active `Normals` (input points: `inputNormals`), and the
/// triangles with cell arrays `NewGeometry` (`newGeometry`, 0 kept, 1 new) and
/// `OriginalCellId`, and the input's cell data copied from the original cell.
/// Verts and lines pass through.
void WriteMesh(vtkPolyData* input, vtkPolyData* output, const std::vector<glm::dvec3>& inputNormals,
  const std::vector<glm::dvec3>& addedPoints, const std::vector<glm::dvec3>& addedNormals,
  const std::vector<PointSource>& addedSources, const std::vector<silsmooth::Triangle>& triangles,
  const std::vector<vtkIdType>& originalCell, const std::vector<unsigned char>& newGeometry);

/// Writes a uniform tessellation (PN triangles, Phong tessellation) of the
/// triangles `mesh` was read as, with WriteMesh: the result's points after
/// the input's are the added ones, each cell's OriginalCellId its triangle's
/// input cell, NewGeometry 1 for every patch triangle (0 when `level` is 0).
void WriteTessellation(vtkPolyData* input, vtkPolyData* output, const Triangles& mesh,
  const silsmooth::TessellationResult& result, int level);

/// The whole RequestData of a uniform tessellation filter: ReadSurface, then
/// `tessellate(mesh, progress)`, written with WriteTessellation. `progress`
/// reports to `self` (UpdateProgress) and stops the work when `self` is
/// asked to abort; the output then stays empty.
int RequestTessellation(vtkAlgorithm* self, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, int level,
  const std::function<silsmooth::TessellationResult(
    const Triangles&, const silsmooth::ProgressCallback&)>& tessellate);

/// Reports `fraction` done to `self` (UpdateProgress) and says whether to go
/// on: false once `self` is asked to abort. The filters whose work is a few
/// steps (the line filters, the 2003 method, the proximity) call it between
/// them and, on false, return with the output empty.
bool ReportProgress(vtkAlgorithm* self, double fraction);

/// The cell array `LineKind` of the line filters (0 silhouette, 1 crease,
/// 2 border, 3 where the surface passes through itself, 4 the surface's own
/// outline where no other line is drawn: the kinds of a line drawing),
/// `count` tuples of `kind`.
enum LineKindValue : unsigned char
{
  SilhouetteLine = 0,
  CreaseLine = 1,
  BorderLine = 2,
  IntersectionLine = 3,
  OutlineLine = 4
};
vtkSmartPointer<vtkUnsignedCharArray> LineKindArray(vtkIdType count, LineKindValue kind);

} // namespace vtkSilhouetteFilterSupport

#endif
