// libFuzzer target for the Kim and Choe units of the core: random meshes
// (repeated ids, fins, inconsistent orientation, coordinates from 1e-30 to
// 1e30) through the progressive mesh, which must come back to the input
// exactly and keep its ids in range at every level; random strokes and
// brushes through the stylizer, whose offsets must stay within the
// amplitude; random views through the edge classification.
#include "EdgeClassification.h"
#include "FuzzBytes.h"
#include "ProgressiveMesh.h"
#include "StrokeStylizer.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace
{

using fuzz::Bytes;
using fuzz::require;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace silsmooth;
  Bytes bytes(data, size);
  const double scale = std::pow(10.0, (bytes.byte() % 61) - 30);
  const int pointCount = 3 + bytes.byte() % 40;
  std::vector<glm::dvec3> points;
  for (int i = 0; i < pointCount; ++i)
  {
    points.emplace_back(scale * bytes.unit(), scale * bytes.unit(), scale * bytes.unit());
  }
  const int triangleCount = 1 + bytes.byte() % 80;
  std::vector<Triangle> triangles;
  for (int t = 0; t < triangleCount; ++t)
  {
    triangles.push_back(
      { bytes.byte() % pointCount, bytes.byte() % pointCount, bytes.byte() % pointCount });
  }

  ProgressiveMesh pm(points, triangles, bytes.byte() % 8);
  require(pm.points() == points && pm.triangles() == triangles);
  const std::size_t levels = pm.splitCount();
  for (int step = 0; step < 4; ++step)
  {
    pm.setLevel(levels == 0 ? 0 : bytes.byte() % (levels + 1));
    for (const Triangle& t : pm.triangles())
    {
      for (Id v : t)
      {
        require(v >= 0 && v < pointCount);
      }
    }
  }
  pm.setTriangleCount(triangles.size());
  require(pm.points() == points && pm.triangles() == triangles);

  EdgeView view;
  view.parallel = bytes.byte() & 1;
  view.eye = glm::dvec3(3 * scale * bytes.unit(), 3 * scale * bytes.unit(), 3 * scale);
  view.direction = glm::dvec3(bytes.unit(), bytes.unit(), bytes.unit() - 1.5);
  const std::vector<FlaggedEdge> edges = classifyEdges(points, triangles, view, 30.0);
  for (const FlaggedEdge& e : edges)
  {
    require(e.a < e.b && e.a >= 0 && e.b < pointCount);
  }
  const std::vector<std::vector<Id>> chains =
    chainFlaggedEdges(edges, SilhouetteEdge | CreaseEdge | BorderEdge);
  for (const std::vector<Id>& chain : chains)
  {
    std::vector<glm::dvec3> stroke;
    for (Id v : chain)
    {
      require(v >= 0 && v < pointCount);
      stroke.push_back(points[v]);
    }
    StrokeParameters parameters;
    parameters.brush = static_cast<Brush>(bytes.byte() % 4);
    parameters.amplitude = scale * std::abs(bytes.unit());
    parameters.wavelength = scale * std::abs(bytes.unit());
    parameters.spacing = scale * (0.05 + std::abs(bytes.unit()));
    parameters.seed = bytes.byte();
    StrokeView strokeView;
    strokeView.parallel = view.parallel;
    strokeView.eye = view.eye;
    strokeView.direction = view.direction;
    const StylizedStroke s = stylizeStroke(stroke, strokeView, parameters, bytes.byte());
    require(s.points.size() == s.base.size());
    for (std::size_t i = 0; i < s.points.size(); ++i)
    {
      require(std::abs(s.tangentOffset[i]) <= parameters.amplitude);
      require(std::abs(s.normalOffset[i]) <= parameters.amplitude);
    }
  }
  return 0;
}
