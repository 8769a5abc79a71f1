// libFuzzer target for the algorithm core: random meshes (repeated ids,
// non-manifold fans, inconsistent orientation, zero normals, coordinates from
// 1e-30 to 1e30) and random views go through the whole smoothing pass, which
// must not crash, hang, or produce non-finite points, out-of-range ids or
// triangles that repeat an id.
#include "SilhouetteSmoother.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace
{

// Reads the fuzzer's bytes as a stream of small values; zeros when exhausted.
class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  std::uint8_t byte() { return this->At < this->Size ? this->Data[this->At++] : 0; }
  double unit() // in [-1, 1]
  {
    const int value = (this->byte() << 8) | this->byte();
    return value / 32767.5 - 1.0;
  }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t At = 0;
};

void require(bool condition)
{
  if (!condition)
  {
    std::abort();
  }
}

bool finite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace silsmooth;
  Bytes bytes(data, size);
  const double scale = std::pow(10.0, static_cast<int>(bytes.byte() % 61) - 30);
  const std::size_t pointCount = 3 + bytes.byte() % 40;
  const std::size_t triangleCount = 1 + bytes.byte() % 80;
  const bool withNormals = bytes.byte() % 2 == 0;

  std::vector<glm::dvec3> points(pointCount);
  std::vector<glm::dvec3> normals;
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
  std::vector<Triangle> triangles(triangleCount);
  for (Triangle& t : triangles)
  {
    for (Id& id : t)
    {
      id = static_cast<Id>(bytes.byte() % pointCount);
    }
  }
  const PreparedMesh mesh(points, triangles, normals);

  ViewGeometry view;
  view.Parallel = bytes.byte() % 4 == 0;
  view.Eye = 3.0 * scale * glm::dvec3(bytes.unit(), bytes.unit(), bytes.unit());
  view.TowardViewer = glm::dvec3(bytes.unit(), bytes.unit(), 1.0 + bytes.unit());
  view.TowardViewer = glm::length(view.TowardViewer) > 0 ? glm::normalize(view.TowardViewer)
                                                         : glm::dvec3(0, 0, 1);
  view.ViewportWidth = 1 + bytes.byte() * 8;
  view.ViewportHeight = 1 + bytes.byte() * 8;
  const glm::dvec3 target = scale * glm::dvec3(bytes.unit(), bytes.unit(), bytes.unit());
  if (target != view.Eye)
  {
    const glm::dvec3 up = std::abs(glm::normalize(target - view.Eye).y) < 0.9
      ? glm::dvec3(0, 1, 0)
      : glm::dvec3(1, 0, 0);
    view.ModelToClip = glm::perspective(0.5, 1.0, 1e-3 * scale, 1e3 * scale) *
      glm::lookAt(view.Eye, target, up);
  }

  SmoothingParameters parameters;
  parameters.Sampling.TolerancePixels = 0.1 + (bytes.byte() % 50) / 10.0;
  parameters.Sampling.MaximumSamples = 64;
  parameters.PerturbConcaveSilhouettes = bytes.byte() % 2 == 0;
  parameters.Visibility =
    bytes.byte() % 2 == 0 ? VisibilityMethod::PerVertex : VisibilityMethod::Hierarchical;
  const SmoothingResult result = smoothSilhouettes(mesh, view, parameters);

  // Both visibility methods decide alike, vertex by vertex.
  const std::vector<double> plain = vertexVisibility(mesh, view, VisibilityMethod::PerVertex);
  const std::vector<double> clustered =
    vertexVisibility(mesh, view, VisibilityMethod::Hierarchical);
  require(plain.size() == clustered.size());
  for (std::size_t i = 0; i < plain.size(); ++i)
  {
    require((plain[i] >= 0.0) == (clustered[i] >= 0.0));
  }

  const Id total = static_cast<Id>(pointCount + result.NewPoints.size());
  for (const NewPoint& p : result.NewPoints)
  {
    require(finite(p.Position) && finite(p.Normal));
  }
  for (const auto& moved : result.MovedPoints)
  {
    require(moved.first >= 0 && moved.first < static_cast<Id>(pointCount) && finite(moved.second));
  }
  require(result.ReplacementOffsets.size() == result.SilhouetteTriangles.size() + 1);
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
  return 0;
}
