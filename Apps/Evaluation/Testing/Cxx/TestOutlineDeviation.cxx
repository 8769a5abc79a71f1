// OutlineDeviation's farthest place on masks whose answers are known: a disk
// inside a larger disk (10 px apart, the smaller one inside), and a disk
// with a slit cut into it (a gap seen through the mesh, inside the solid
// disk). Each case is measured both ways round, so a side taken from the
// wrong mask fails.
#include "SilhouetteMasks.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{

using silhouette_eval::BoundaryDistance;
using silhouette_eval::Mask;

Mask Disk(int size, double radius)
{
  Mask mask;
  mask.Width = size;
  mask.Height = size;
  mask.Covered.assign(static_cast<std::size_t>(size) * size, 0);
  const double centre = 0.5 * size;
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      if (std::hypot(i + 0.5 - centre, j + 0.5 - centre) <= radius)
      {
        mask.Covered[static_cast<std::size_t>(j) * size + i] = 1;
      }
    }
  }
  return mask;
}

bool Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "TestOutlineDeviation: " << what << "\n";
  }
  return condition;
}

} // namespace

int TestOutlineDeviation(int, char*[])
{
  bool ok = true;
  const int size = 100;
  const Mask small = Disk(size, 20.0);
  const Mask large = Disk(size, 30.0);

  // The outlines are 10 px apart everywhere (to within the pixel grid).
  const BoundaryDistance inside = silhouette_eval::OutlineDeviation(small, large);
  ok &= Check(inside.Max >= 9.0 && inside.Max <= 11.0,
    "disks 10 px apart measured " + std::to_string(inside.Max));
  ok &= Check(!inside.FarthestOutside, "the smaller disk was reported outside the larger");
  const BoundaryDistance outside = silhouette_eval::OutlineDeviation(large, small);
  ok &= Check(outside.Max == inside.Max, "the distance is not symmetric");
  ok &= Check(outside.FarthestOutside, "the larger disk was reported inside the smaller");

  // A slit 1 px wide from the centre out to 25 px, on the +x axis: the
  // farthest outline pixel is the slit's end at the centre, 30 px from the
  // solid disk's outline, and there the slit disk lies inside the solid one.
  Mask slit = large;
  const int row = size / 2;
  for (int i = size / 2; i < size / 2 + 25; ++i)
  {
    slit.Covered[static_cast<std::size_t>(row) * size + i] = 0;
  }
  const BoundaryDistance gap = silhouette_eval::OutlineDeviation(slit, large);
  ok &= Check(
    gap.Max >= 28.0 && gap.Max <= 31.0, "the slit's far end measured " + std::to_string(gap.Max));
  ok &= Check(std::abs(gap.FarthestX - size / 2) <= 2 && std::abs(gap.FarthestY - row) <= 2,
    "the farthest place is at (" + std::to_string(gap.FarthestX) + ", " +
      std::to_string(gap.FarthestY) + "), not at the slit's end");
  ok &= Check(!gap.FarthestOutside, "a gap through the mask was reported outside");
  const BoundaryDistance gapReversed = silhouette_eval::OutlineDeviation(large, slit);
  ok &= Check(gapReversed.FarthestOutside, "the solid disk was reported inside the slit one");

  // An empty mask: nothing to compare, and no place.
  Mask empty = small;
  empty.Covered.assign(empty.Covered.size(), 0);
  const BoundaryDistance none = silhouette_eval::OutlineDeviation(empty, large);
  ok &= Check(none.Samples == 0 && none.FarthestX < 0, "an empty mask gave a farthest place");
  return ok ? 0 : 1;
}
