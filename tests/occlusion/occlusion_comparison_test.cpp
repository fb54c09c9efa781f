#include "occlusion/occlusion_comparison.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_meshes.h"

namespace maxillo::occlusion {
namespace {

using testing::make_box;

struct SlabAndRaisedBlock {
  TriangleMesh lower = make_box({-5, -5, -2}, {5, 5, 0});
  TriangleMesh upper = make_box({-2, -2, 0.5}, {2, 2, 2.5});  // 0.5 mm above the slab
  DistanceField lower_field{lower}, upper_field{upper};
};

TEST(CompareOcclusions, APureTranslationMovesEveryRegionVertexByItsLength) {
  SlabAndRaisedBlock s;
  const Eigen::Isometry3d a = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d b = a;
  b.pretranslate(Eigen::Vector3d(0.3, -0.4, 1.2));  // |d| = 1.3 mm
  const OcclusionComparison c = compare_occlusions(s.upper_field, s.lower_field, a, b, 1.0);
  ASSERT_EQ(c.region.size(), 4u);  // the block's bottom corners: the top ones are 2.5 mm away
  for (int v : c.region) EXPECT_NEAR(s.upper.vertices(v, 2), 0.5, 1e-12);
  for (double d : c.distance_mm) EXPECT_NEAR(d, 1.3, 1e-12);
  EXPECT_EQ(c.statistics.count, 4);
  EXPECT_NEAR(c.statistics.median_mm, 1.3, 1e-12);
  EXPECT_NEAR(c.statistics.p90_mm, 1.3, 1e-12);
  EXPECT_NEAR(c.statistics.p95_mm, 1.3, 1e-12);
  EXPECT_NEAR(c.statistics.max_mm, 1.3, 1e-12);
}

TEST(CompareOcclusions, ARotationMovesEachVertexByTheChordOfItsRadius) {
  SlabAndRaisedBlock s;
  const Eigen::Isometry3d a = Eigen::Isometry3d::Identity();
  const double angle = 3.0 * M_PI / 180;
  const Eigen::Isometry3d b(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()));  // about the z axis through 0
  const OcclusionComparison c = compare_occlusions(s.upper_field, s.lower_field, a, b, 1.0);
  ASSERT_EQ(c.region.size(), 4u);
  const double radius = std::sqrt(8.0);  // bottom corners at (+-2, +-2)
  for (double d : c.distance_mm) EXPECT_NEAR(d, 2 * radius * std::sin(angle / 2), 1e-12);
}

TEST(CompareOcclusions, TheRegionIsChosenAtTheReferencePose) {
  SlabAndRaisedBlock s;
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.pretranslate(Eigen::Vector3d(0, 0, 10));
  EXPECT_EQ(compare_occlusions(s.upper_field, s.lower_field, far, Eigen::Isometry3d::Identity(), 1.0).region.size(),
            0u);
  EXPECT_EQ(compare_occlusions(s.upper_field, s.lower_field, Eigen::Isometry3d::Identity(), far, 1.0).region.size(),
            4u);
}

TEST(SummariseDistances, GivesTheSourcesStatistics) {
  const DistanceStatistics s = summarise_distances({5, 1, 4, 2, 3});
  EXPECT_EQ(s.count, 5);
  EXPECT_DOUBLE_EQ(s.median_mm, 3);
  EXPECT_DOUBLE_EQ(s.p90_mm, 4.6);
  EXPECT_DOUBLE_EQ(s.p95_mm, 4.8);
  EXPECT_DOUBLE_EQ(s.max_mm, 5);
  EXPECT_EQ(summarise_distances({}).count, 0);
}

}  // namespace
}  // namespace maxillo::occlusion
