#include "SilhouetteSmoother.h"

#include "SilhouettePass.h"

namespace silsmooth
{

std::vector<double> vertexVisibility(const PreparedMesh& mesh, const ViewGeometry& view,
  VisibilityMethod method, const ParallelFor& parallelFor)
{
  if (method != VisibilityMethod::Hierarchical)
  {
    return vertexVisibility(mesh, view, parallelFor);
  }
  std::vector<double> g;
  mesh.visibilityHierarchy().classify(view, g, parallelFor);
  return g;
}

SmoothingResult smoothSilhouettes(const PreparedMesh& mesh, const ViewGeometry& view,
  const SmoothingParameters& parameters, const ParallelFor& parallelFor)
{
  return detail::SilhouettePass(mesh, view, parameters, parallelFor).run();
}

void assembleTriangles(const PreparedMesh& mesh, const SmoothingResult& result,
  std::vector<Triangle>& triangles, std::vector<Id>& sourceTriangle,
  std::vector<unsigned char>& isNew)
{
  triangles.clear();
  sourceTriangle.clear();
  isNew.clear();
  std::size_t next = 0;
  const std::vector<Triangle>& input = mesh.triangles();
  for (std::size_t t = 0; t < input.size(); ++t)
  {
    if (next < result.RemeshedTriangles.size() &&
      result.RemeshedTriangles[next] == static_cast<Id>(t))
    {
      for (std::size_t r = result.ReplacementOffsets[next]; r < result.ReplacementOffsets[next + 1];
           ++r)
      {
        triangles.push_back(result.Replacements[r]);
        sourceTriangle.push_back(static_cast<Id>(t));
        isNew.push_back(static_cast<unsigned char>(result.RemeshKinds[next]));
      }
      ++next;
      continue;
    }
    triangles.push_back(input[t]);
    sourceTriangle.push_back(static_cast<Id>(t));
    isNew.push_back(0);
  }
}

} // namespace silsmooth
