// Whether two smoothing passes gave the same frame, field for field: for the
// core tests that compare two ways to the same answer (the silhouette
// triangle tree against the scan, built in the call or in the background).
#pragma once

#include "SilhouetteSmoother.h"

#include <gtest/gtest.h>

#include <string>

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

} // namespace coretest
