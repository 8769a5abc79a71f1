// Whether two smoothing passes gave the same frame, field for field: for the
// core tests that compare two ways to the same answer (the silhouette
// triangle tree against the scan, built in the call or in the background);
// and whether a frame's output is closed.
#pragma once

#include "SilhouetteSmoother.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace coretest
{

inline void expectSameSmoothing(const silsmooth::SmoothingResult& a,
  const silsmooth::SmoothingResult& b, const std::string& label)
{
  ASSERT_EQ(a.RemeshedTriangles, b.RemeshedTriangles) << label;
  EXPECT_FALSE(a.RemeshedTriangles.empty()) << label;
  ASSERT_EQ(a.NewPoints.size(), b.NewPoints.size()) << label;
  for (std::size_t i = 0; i < a.NewPoints.size(); ++i)
  {
    EXPECT_EQ(a.NewPoints[i].Position, b.NewPoints[i].Position) << label;
    EXPECT_EQ(a.NewPoints[i].Normal, b.NewPoints[i].Normal) << label;
    EXPECT_EQ(a.NewPoints[i].Weights, b.NewPoints[i].Weights) << label;
  }
  EXPECT_EQ(a.ReplacementOffsets, b.ReplacementOffsets) << label;
  EXPECT_EQ(a.Replacements, b.Replacements) << label;
  EXPECT_EQ(a.Polylines, b.Polylines) << label;
  EXPECT_EQ(a.ConcaveSegmentCount, b.ConcaveSegmentCount) << label;
  EXPECT_EQ(a.MovedPoints, b.MovedPoints) << label;
}

/// Whether the frame's output is closed and consistently oriented once
/// points at one position are merged (a feature point's copies, one per side
/// of the crease, are one point of the surface): every directed edge once,
/// and its reverse once.
inline bool closedOnceWelded(
  const silsmooth::PreparedMesh& mesh, const silsmooth::SmoothingResult& result)
{
  using silsmooth::Id;
  std::vector<silsmooth::Triangle> triangles;
  std::vector<Id> source;
  std::vector<unsigned char> isNew;
  silsmooth::assembleTriangles(mesh, result, triangles, source, isNew);
  auto position = [&](Id id) {
    const std::size_t n = mesh.points().size();
    return static_cast<std::size_t>(id) < n
      ? mesh.points()[static_cast<std::size_t>(id)]
      : result.NewPoints[static_cast<std::size_t>(id) - n].Position;
  };
  std::map<std::array<double, 3>, Id> weld;
  auto welded = [&](Id id) {
    const glm::dvec3 p = position(id);
    return weld.emplace(std::array<double, 3>{ { p.x, p.y, p.z } }, static_cast<Id>(weld.size()))
      .first->second;
  };
  std::map<std::pair<Id, Id>, int> directed;
  for (const silsmooth::Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ welded(t[k]), welded(t[(k + 1) % 3]) }];
    }
  }
  for (const auto& [edge, count] : directed)
  {
    const auto reverse = directed.find({ edge.second, edge.first });
    if (count != 1 || reverse == directed.end() || reverse->second != 1)
    {
      return false;
    }
  }
  return true;
}

} // namespace coretest
