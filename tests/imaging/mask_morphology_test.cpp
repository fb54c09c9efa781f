// The plain mask algorithms of segmentation: components on runs, hole filling, and ball
// morphology by exact distance transforms, against brute force and analytic answers.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "imaging/distance_morphology.h"
#include "imaging/mask_components.h"

namespace maxillo {
namespace {

MaskGrid grid(size_t nx, size_t ny, size_t nz, std::array<double, 3> spacing = {1, 1, 1}) {
  MaskGrid g;
  g.size = {nx, ny, nz};
  g.spacing = spacing;
  return g;
}

void set_box(Mask& mask, const MaskGrid& g, std::array<size_t, 3> lo, std::array<size_t, 3> hi, uint8_t value = 1) {
  for (size_t k = lo[2]; k < hi[2]; ++k)
    for (size_t j = lo[1]; j < hi[1]; ++j)
      for (size_t i = lo[0]; i < hi[0]; ++i) mask[g.index(i, j, k)] = value;
}

size_t count(const Mask& mask) { return size_t(std::count(mask.begin(), mask.end(), 1)); }

TEST(MaskComponents, LargestComponentIsFaceConnected) {
  const auto g = grid(12, 10, 8);
  Mask mask(g.voxel_count(), 0);
  set_box(mask, g, {0, 0, 0}, {2, 2, 2});  // 8 voxels
  set_box(mask, g, {5, 5, 3}, {8, 8, 6});  // 27 voxels
  mask[g.index(2, 2, 2)] = 1;              // touches the first box by a corner only: separate
  const Mask largest = largest_component(mask, g);
  EXPECT_EQ(count(largest), 27u);
  EXPECT_EQ(largest[g.index(6, 6, 4)], 1);
  EXPECT_EQ(largest[g.index(0, 0, 0)], 0);
  const Mask big_enough = components_of_at_least(mask, g, 8);
  EXPECT_EQ(count(big_enough), 35u);  // the single corner voxel is dropped
  EXPECT_EQ(big_enough[g.index(2, 2, 2)], 0);
  EXPECT_EQ(count(largest_component(Mask(g.voxel_count(), 0), g)), 0u);
}

TEST(MaskComponents, ShapesWindingThroughRowsAndSlicesAreOneComponent) {
  const auto g = grid(9, 9, 9);
  Mask mask(g.voxel_count(), 0);
  // A staircase: each step moves one row or one slice on, its x range overlapping the last's.
  for (size_t s = 0; s < 8; ++s) {
    const size_t y = (s + 1) / 2, z = s / 2;
    set_box(mask, g, {s, y, z}, {s + 2, y + 1, z + 1});
  }
  EXPECT_EQ(count(largest_component(mask, g)), count(mask));
  mask[g.index(1, 5, 5)] = 1;  // and a voxel touching nothing
  EXPECT_EQ(count(largest_component(mask, g)), count(mask) - 1);
}

TEST(MaskComponents, HolesAreFilledButCavitiesOpenToTheBorderAreNot) {
  const auto g = grid(10, 10, 10);
  Mask shell(g.voxel_count(), 0);
  set_box(shell, g, {2, 2, 2}, {8, 8, 8});
  set_box(shell, g, {3, 3, 3}, {7, 7, 7}, 0);  // a closed hollow cube: 64 empty voxels inside
  EXPECT_EQ(count(holes_filled(shell, g)), 216u);
  Mask open = shell;
  open[g.index(5, 5, 2)] = 0;  // a hole through the floor
  EXPECT_EQ(count(holes_filled(open, g)), count(open));
}

// Brute force: the smallest squared distance over all feature voxels.
float brute_squared_distance(const Mask& to, const MaskGrid& g, size_t i, size_t j, size_t k) {
  float best = 1e20f;
  for (size_t c = 0; c < g.size[2]; ++c)
    for (size_t b = 0; b < g.size[1]; ++b)
      for (size_t a = 0; a < g.size[0]; ++a) {
        if (!to[g.index(a, b, c)]) continue;
        const double dx = (double(a) - double(i)) * g.spacing[0], dy = (double(b) - double(j)) * g.spacing[1],
                     dz = (double(c) - double(k)) * g.spacing[2];
        best = std::min(best, float(dx * dx + dy * dy + dz * dz));
      }
  return best;
}

TEST(DistanceMorphology, SquaredDistancesEqualBruteForceOnAnisotropicGrids) {
  std::mt19937 random(11);
  for (auto spacing : {std::array<double, 3>{1, 1, 1}, std::array<double, 3>{0.5, 0.7, 2.0}}) {
    const auto g = grid(11, 9, 7, spacing);
    Mask features(g.voxel_count(), 0);
    for (int n = 0; n < 6; ++n) features[random() % features.size()] = 1;
    const auto d = squared_distance_to(features, g);
    for (size_t k = 0; k < g.size[2]; ++k)
      for (size_t j = 0; j < g.size[1]; ++j)
        for (size_t i = 0; i < g.size[0]; ++i)
          EXPECT_NEAR(d[g.index(i, j, k)], brute_squared_distance(features, g, i, j, k), 1e-3)
              << i << " " << j << " " << k;
  }
  const auto g = grid(4, 4, 4);
  EXPECT_GT(squared_distance_to(Mask(g.voxel_count(), 0), g)[0], 1e18f);  // nothing to be near
}

TEST(DistanceMorphology, DilationOfAPointIsTheBallOfItsRadius) {
  const auto g = grid(21, 21, 21, {0.5, 0.5, 0.5});
  Mask point(g.voxel_count(), 0);
  point[g.index(10, 10, 10)] = 1;
  const Mask ball = dilated(point, g, 3.0);
  size_t expected = 0;
  for (int k = -10; k <= 10; ++k)
    for (int j = -10; j <= 10; ++j)
      for (int i = -10; i <= 10; ++i) expected += 0.25 * (i * i + j * j + k * k) <= 9.0;
  EXPECT_EQ(count(ball), expected);  // 925 voxels of 0.5 mm: about (4/3) pi 3^3 / 0.125 = 905
}

TEST(DistanceMorphology, OpeningCutsAThinBridgeAndKeepsTheBlocks) {
  const auto g = grid(40, 16, 16);
  Mask mask(g.voxel_count(), 0);
  set_box(mask, g, {1, 1, 1}, {15, 15, 15});
  set_box(mask, g, {25, 1, 1}, {39, 15, 15});
  set_box(mask, g, {15, 7, 7}, {25, 9, 9});  // a 2 mm thick bridge: a head rest's contact
  const Mask open = opened(mask, g, 2.0);
  EXPECT_EQ(open[g.index(20, 8, 8)], 0);  // the bridge is gone
  EXPECT_EQ(open[g.index(8, 8, 8)], 1);
  EXPECT_EQ(open[g.index(32, 8, 8)], 1);
  const Mask box_corner_region = largest_component(open, g);
  EXPECT_LT(count(box_corner_region), count(open));  // two separate blocks now
}

TEST(DistanceMorphology, CoarseningKeepsMajoritiesAndRefiningFillsBlocks) {
  const auto fine = grid(8, 6, 4, {0.5, 0.5, 1.0});
  Mask mask(fine.voxel_count(), 0);
  set_box(mask, fine, {0, 0, 0}, {4, 6, 4});  // the left half
  mask[fine.index(6, 0, 0)] = 1;              // a lone voxel: a minority of its block
  MaskGrid coarse;
  const std::array<size_t, 3> factor{2, 2, 1};
  const Mask small = coarsened(mask, fine, factor, coarse);
  EXPECT_EQ(coarse.size, (std::array<size_t, 3>{4, 3, 4}));
  EXPECT_DOUBLE_EQ(coarse.spacing[0], 1.0);
  const Mask back = refined(small, coarse, factor, fine);
  Mask expected(fine.voxel_count(), 0);
  set_box(expected, fine, {0, 0, 0}, {4, 6, 4});
  EXPECT_EQ(back, expected);
}

}  // namespace
}  // namespace maxillo
