// Closed air cavities: a sealed cavity is found, one with a one-voxel opening to the outside is not.
#include <gtest/gtest.h>

#include <algorithm>

#include "planning/enclosed_air.h"

namespace maxillo::planning {
namespace {

TEST(EnclosedAir, FindsSealedCavitiesOnly) {
  Volume ct;
  ct.geometry.size = {20, 20, 20};
  ct.hu.assign(ct.geometry.voxel_count(), -1000);  // outside air
  auto fill = [&](int lo, int hi, int16_t hu) {
    for (int k = lo; k <= hi; ++k)
      for (int j = lo; j <= hi; ++j)
        for (int i = lo; i <= hi; ++i) ct.at(i, j, k) = hu;
  };
  fill(2, 17, 40);                                          // a soft-tissue block
  fill(5, 8, -1000);                                        // a sealed 4^3 cavity
  fill(11, 14, -1000);                                      // another cavity...
  for (int i = 14; i <= 17; ++i) ct.at(i, 12, 12) = -1000;  // ...with a channel to the outside
  LabelVolume tissues;
  tissues.geometry = ct.geometry;
  tissues.labels.assign(ct.hu.size(), 0);
  const LabelVolume marked = with_enclosed_air(tissues, ct, -400, 7);
  EXPECT_EQ(std::count(marked.labels.begin(), marked.labels.end(), 7), 64);
  EXPECT_EQ(marked.labels[ct.geometry.index(6, 6, 6)], 7);
  EXPECT_EQ(marked.labels[ct.geometry.index(12, 12, 12)], 0);
  EXPECT_EQ(marked.labels[ct.geometry.index(0, 0, 0)], 0);
}

}  // namespace
}  // namespace maxillo::planning
