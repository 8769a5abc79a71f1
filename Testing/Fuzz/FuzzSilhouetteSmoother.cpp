// libFuzzer target for the algorithm core: random meshes (repeated ids,
// non-manifold fans, inconsistent orientation, zero normals, coordinates from
// 1e-30 to 1e30), random feature edges and random views go through the whole
// smoothing pass, which
// must not crash, hang, or produce non-finite points, out-of-range ids,
// triangles that repeat an id, or a fold its fold guard leaves unresolved.
#include "FuzzBytes.h"
#include "SilhouetteSmoother.h"
#include "SilhouetteTriangleHierarchy.h"
#include "WeldedSurface.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace
{

using fuzz::Bytes;
using fuzz::require;

bool finite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The mesh: a scale from 1e-30 to 1e30, points, maybe normals (some zero),
// triangles over random point ids.
struct FuzzMesh
{
  double Scale = 1.0;
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Normals; ///< empty: none
  std::vector<silsmooth::Triangle> Triangles;
};

FuzzMesh ReadMesh(Bytes& bytes)
{
  using namespace silsmooth;
  FuzzMesh out;
  const double scale = out.Scale = std::pow(10.0, static_cast<int>(bytes.byte() % 61) - 30);
  const std::size_t pointCount = 3 + bytes.byte() % 40;
  const std::size_t triangleCount = 1 + bytes.byte() % 80;
  const bool withNormals = bytes.byte() % 2 == 0;

  std::vector<glm::dvec3>& points = out.Points;
  std::vector<glm::dvec3>& normals = out.Normals;
  points.resize(pointCount);
  for (glm::dvec3& p : points)
  {
    p = scale * glm::dvec3(bytes.unit(), bytes.unit(), bytes.unit());
  }
  if (withNormals)
  {
    normals.resize(pointCount);
    for (glm::dvec3& n : normals)
    {
      n = glm::dvec3(bytes.unit(), bytes.unit(), bytes.unit()); // may be zero
    }
  }
  std::vector<Triangle>& triangles = out.Triangles;
  triangles.resize(triangleCount);
  for (Triangle& t : triangles)
  {
    for (Id& id : t)
    {
      id = static_cast<Id>(bytes.byte() % pointCount);
    }
  }
  return out;
}

// The view: parallel or perspective, from anywhere near the mesh.
silsmooth::ViewGeometry ReadView(Bytes& bytes, double scale)
{
  using namespace silsmooth;
  ViewGeometry view;
  view.Parallel = bytes.byte() % 4 == 0;
  view.Eye = 3.0 * scale * glm::dvec3(bytes.unit(), bytes.unit(), bytes.unit());
  view.TowardViewer = glm::dvec3(bytes.unit(), bytes.unit(), 1.0 + bytes.unit());
  view.TowardViewer =
    glm::length(view.TowardViewer) > 0 ? glm::normalize(view.TowardViewer) : glm::dvec3(0, 0, 1);
  view.ViewportWidth = 1 + bytes.byte() * 8;
  view.ViewportHeight = 1 + bytes.byte() * 8;
  const glm::dvec3 target = scale * glm::dvec3(bytes.unit(), bytes.unit(), bytes.unit());
  if (target != view.Eye)
  {
    const glm::dvec3 up = std::abs(glm::normalize(target - view.Eye).y) < 0.9 ? glm::dvec3(0, 1, 0)
                                                                              : glm::dvec3(1, 0, 0);
    view.ModelToClip =
      glm::perspective(0.5, 1.0, 1e-3 * scale, 1e3 * scale) * glm::lookAt(view.Eye, target, up);
  }
  return view;
}

silsmooth::SmoothingParameters ReadParameters(Bytes& bytes)
{
  using namespace silsmooth;
  SmoothingParameters parameters;
  parameters.Sampling.TolerancePixels = 0.1 + (bytes.byte() % 50) / 10.0;
  parameters.Sampling.MaximumSamples = 64;
  parameters.PerturbConcaveSilhouettes = bytes.byte() % 2 == 0;
  return parameters;
}

// Feature edges last, so that older inputs keep their meaning: none, by a
// random dihedral angle, or random pairs (some of them triangle sides,
// some not, some repeated or reversed).
std::vector<silsmooth::FeatureEdge> ReadFeatures(Bytes& bytes, const FuzzMesh& mesh)
{
  using namespace silsmooth;
  std::vector<FeatureEdge> features;
  const std::vector<glm::dvec3>& points = mesh.Points;
  const std::vector<Triangle>& triangles = mesh.Triangles;
  const std::size_t pointCount = points.size();
  const std::size_t triangleCount = triangles.size();
  const int featureMode = bytes.byte() % 3;
  if (featureMode == 1)
  {
    features = featureEdgesByAngle(points, triangles, 180.0 * (bytes.byte() / 255.0));
  }
  else if (featureMode == 2)
  {
    const int count = bytes.byte() % 32;
    for (int i = 0; i < count; ++i)
    {
      const Triangle& t = triangles[bytes.byte() % triangleCount];
      const int k = bytes.byte() % 4;
      features.emplace_back(k < 3 ? t[static_cast<std::size_t>(k)] : bytes.byte() % pointCount,
        t[static_cast<std::size_t>((k + 1) % 3)]);
    }
  }
  return features;
}

// What the pass promises: the visibility methods agree, points are finite,
// ids in range, no repeated corner, no fold left unresolved.
void CheckSmoothing(const silsmooth::PreparedMesh& mesh, const silsmooth::ViewGeometry& view,
  const silsmooth::SmoothingResult& result, std::size_t pointCount)
{
  using namespace silsmooth;
  // Both visibility methods decide alike, vertex by vertex.
  const std::vector<double> plain = vertexVisibility(mesh, view, VisibilityMethod::PerVertex);
  const std::vector<double> clustered =
    vertexVisibility(mesh, view, VisibilityMethod::Hierarchical);
  require(plain.size() == clustered.size());
  for (std::size_t i = 0; i < plain.size(); ++i)
  {
    require((plain[i] >= 0.0) == (clustered[i] >= 0.0));
  }
  // The triangle hierarchy finds exactly the triangles a scan finds.
  std::vector<Id> scanned;
  for (std::size_t t = 0; t < mesh.triangles().size(); ++t)
  {
    const Triangle& tri = mesh.triangles()[t];
    const bool v0 = plain[static_cast<std::size_t>(tri[0])] >= 0.0;
    const bool v1 = plain[static_cast<std::size_t>(tri[1])] >= 0.0;
    const bool v2 = plain[static_cast<std::size_t>(tri[2])] >= 0.0;
    if (!hasRepeatedCorner(tri) && (v0 != v1 || v1 != v2))
    {
      scanned.push_back(static_cast<Id>(t));
    }
  }
  const SilhouetteTriangleHierarchy tree(
    mesh.points(), mesh.normals(), mesh.triangles(), !view.Parallel);
  std::vector<Id> found;
  if (tree.find(view, mesh.points(), mesh.normals(), mesh.triangles(), serialFor, found))
  {
    require(found == scanned);
  }

  const Id prepared = static_cast<Id>(mesh.points().size());
  require(prepared >= static_cast<Id>(pointCount));
  for (const glm::dvec3& n : mesh.normals())
  {
    require(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
  }
  // The fold guard always finds a fallback (FoldGuard.h's invariant): a
  // whole mesh, not a piece, so every silhouette point may be straightened.
  require(result.UnresolvedFolds == 0);
  const Id total = static_cast<Id>(prepared + result.NewPoints.size());
  for (const NewPoint& p : result.NewPoints)
  {
    require(finite(p.Position) && finite(p.Normal));
  }
  for (const auto& moved : result.MovedPoints)
  {
    require(moved.first >= 0 && moved.first < prepared && finite(moved.second));
  }
  require(result.ReplacementOffsets.size() == result.RemeshedTriangles.size() + 1);
  for (const Triangle& t : result.Replacements)
  {
    for (const Id id : t)
    {
      require(id >= 0 && id < total);
    }
    require(!hasRepeatedCorner(t));
  }
  for (const std::vector<Id>& line : result.Polylines)
  {
    for (const Id id : line)
    {
      require(id >= 0 && id < total);
    }
  }
}

// The asset-file preparation (WeldedSurface) on the same mesh, or on its
// triangle soup, with points snapped to a coarse grid so that many
// coincide; the frame it assembles names valid points only.
void CheckWeldedSurface(Bytes& bytes, const FuzzMesh& mesh,
  const std::vector<silsmooth::FeatureEdge>& features, const silsmooth::ViewGeometry& view,
  const silsmooth::SmoothingParameters& parameters)
{
  using namespace silsmooth;
  const double scale = mesh.Scale;
  const std::vector<glm::dvec3>& points = mesh.Points;
  const std::vector<glm::dvec3>& normals = mesh.Normals;
  const std::vector<Triangle>& triangles = mesh.Triangles;
  const bool withNormals = !normals.empty();
  const int surfaceMode = bytes.byte() % 4;
  if (surfaceMode == 0)
  {
    return;
  }
  std::vector<glm::dvec3> surfacePoints = points;
  std::vector<Triangle> surfaceTriangles = triangles;
  std::vector<glm::dvec3> surfaceNormals = normals;
  if (surfaceMode >= 2)
  {
    for (glm::dvec3& q : surfacePoints)
    {
      q = scale * glm::round(4.0 * q / scale) / 4.0;
    }
  }
  if (surfaceMode == 3)
  {
    std::vector<glm::dvec3> soup;
    std::vector<glm::dvec3> soupNormals;
    for (Triangle& t : surfaceTriangles)
    {
      for (Id& id : t)
      {
        soup.push_back(surfacePoints[static_cast<std::size_t>(id)]);
        if (withNormals)
        {
          soupNormals.push_back(normals[static_cast<std::size_t>(id)]);
        }
        id = static_cast<Id>(soup.size() - 1);
      }
    }
    surfacePoints = std::move(soup);
    surfaceNormals = std::move(soupNormals);
  }
  SurfaceOptions options;
  const int flags = bytes.byte();
  options.Weld = (flags & 1) == 0;
  options.Orient = (flags & 2) == 0;
  options.NormalSeams = (flags & 4) == 0;
  options.DetectFlatCreases = (flags & 8) == 0;
  options.WeldTolerance = (flags & 16) ? scale * 0.1 * (bytes.byte() / 255.0) : 0.0;
  std::vector<FeatureEdge> marked;
  if (surfaceMode == 1)
  {
    marked = features;
  }
  const WeldedSurface surface(surfacePoints, surfaceTriangles, surfaceNormals, marked, options);
  const SmoothingResult frameResult = smoothSilhouettes(surface.prepared(), view, parameters);
  const SurfaceFrame frame = surface.assemble(frameResult);
  const Id base = static_cast<Id>(surface.outputPointCount());
  const Id outputTotal = base + static_cast<Id>(frame.Added.size());
  for (Id o = 0; o < base; ++o)
  {
    require(surface.outputSource(o) >= 0 &&
      surface.outputSource(o) < static_cast<Id>(surfacePoints.size()));
    require(surface.outputPrepared(o) >= 0 &&
      surface.outputPrepared(o) < static_cast<Id>(surface.prepared().points().size()));
  }
  for (const SurfaceFrame::AddedPoint& added : frame.Added)
  {
    require(added.NewPoint < frameResult.NewPoints.size());
    for (const Id source : added.Sources)
    {
      require(source >= 0 && source < static_cast<Id>(surfacePoints.size()));
    }
  }
  require(frame.Triangles.size() == frame.SourceTriangle.size() &&
    frame.Triangles.size() == frame.Kind.size());
  for (std::size_t t = 0; t < frame.Triangles.size(); ++t)
  {
    require(frame.SourceTriangle[t] >= 0 &&
      frame.SourceTriangle[t] < static_cast<Id>(surfaceTriangles.size()));
    for (const Id id : frame.Triangles[t])
    {
      require(id >= 0 && id < outputTotal);
    }
  }
  for (const std::vector<Id>& line : frame.Polylines)
  {
    for (const Id id : line)
    {
      require(id >= 0 && id < outputTotal);
    }
  }
  for (const auto& moved : frame.Moved)
  {
    require(moved.first >= 0 && moved.first < base && finite(moved.second));
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace silsmooth;
  // The bytes are read in this order, so that older inputs keep their meaning.
  Bytes bytes(data, size);
  const FuzzMesh input = ReadMesh(bytes);
  const ViewGeometry view = ReadView(bytes, input.Scale);
  SmoothingParameters parameters = ReadParameters(bytes);
  const std::vector<FeatureEdge> features = ReadFeatures(bytes, input);
  const PreparedMesh mesh(input.Points, input.Triangles, input.Normals, features);
  parameters.Visibility =
    bytes.byte() % 2 == 0 ? VisibilityMethod::PerVertex : VisibilityMethod::Hierarchical;
  const SmoothingResult result = smoothSilhouettes(mesh, view, parameters);
  CheckSmoothing(mesh, view, result, input.Points.size());
  CheckWeldedSurface(bytes, input, features, view, parameters);
  return 0;
}
