#include "occlusion/occlusion_benchmark.h"

#include <gtest/gtest.h>

#include "support/test_meshes.h"

namespace maxillo::occlusion {
namespace {

using testing::make_box;

TEST(Percentile, InterpolatesBetweenRanks) {
  EXPECT_DOUBLE_EQ(percentile({4, 1, 3, 2, 5}, 50), 3);
  EXPECT_DOUBLE_EQ(percentile({1, 2, 3, 4, 5}, 95), 4.8);
  EXPECT_DOUBLE_EQ(percentile({1, 2}, 100), 2);
  EXPECT_DOUBLE_EQ(percentile({}, 50), 0);
}

TEST(RandomDisplacement, StaysWithinTheLimits) {
  std::mt19937 rng(4);
  const Eigen::Vector3d centre(10, 20, 30);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Isometry3d m = random_displacement(rng, centre, 3.0, 5.0);
    EXPECT_LE((m * centre - centre).norm(), 3.0 + 1e-12);
    EXPECT_LE(Eigen::AngleAxisd(m.linear()).angle(), 5.0 * M_PI / 180 + 1e-12);
  }
}

struct SlabAndBlock {
  TriangleMesh lower = make_box({-5, -5, -2}, {5, 5, 0});
  TriangleMesh upper = make_box({-2, -2, 0}, {2, 2, 2});  // resting on the slab
  DistanceField lower_field{lower}, upper_field{upper};
};

TEST(PlaceInContact, BringsTheArchToTheTargetDepthFromAboveAndFromBelow) {
  SlabAndBlock s;
  for (double z : {3.0, -1.0}) {
    Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
    start.translate(Eigen::Vector3d(0.5, 0, z));
    const Eigen::Isometry3d placed = place_in_contact(s.upper_field, s.lower_field, start, 0.2);
    EXPECT_NEAR(placed.translation().z(), -0.2, 0.011) << "from z = " << z;
    EXPECT_NEAR(placed.translation().x(), 0.5, 1e-12);
  }
}

TEST(ContactSpringPairs, PicksSpreadContactPoints) {
  SlabAndBlock s;
  const auto pairs = contact_spring_pairs(s.upper_field, s.lower_field, Eigen::Isometry3d::Identity(), 4, 0.1);
  ASSERT_EQ(pairs.size(), 4u);  // the four bottom corners, the farthest-apart contacts
  for (const SpringPair& p : pairs) {
    EXPECT_NEAR(p.upper.z(), 0, 1e-12);
    EXPECT_NEAR((p.upper - p.lower).norm(), 0, 1e-12);
    EXPECT_NEAR(std::abs(p.upper.x()), 2, 1e-12);
    EXPECT_NEAR(std::abs(p.upper.y()), 2, 1e-12);
  }
  EXPECT_EQ(occlusal_region(s.upper_field, s.lower_field, Eigen::Isometry3d::Identity(), 1.0).size(), 4u);
}

}  // namespace
}  // namespace maxillo::occlusion
