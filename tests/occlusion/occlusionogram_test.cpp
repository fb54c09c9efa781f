#include "occlusion/occlusionogram.h"

#include <gtest/gtest.h>

#include "support/test_meshes.h"

namespace maxillo::occlusion {
namespace {

using testing::make_box;

TEST(Occlusionogram, DistancesContactsAndTeethOfTwoBlocksOverASlab) {
  const TriangleMesh lower = make_box({-10, -10, -2}, {10, 10, 0});
  // Two "teeth": one 0.5 mm above the slab, one 3 mm above.
  const TriangleMesh upper = testing::append(make_box({-6, -1, 0.5}, {-4, 1, 2.5}), make_box({4, -1, 3}, {6, 1, 5}));
  DistanceField u(upper), l(lower);
  const Occlusionogram o = compute_occlusionogram(u, l, Eigen::Isometry3d::Identity());
  ASSERT_EQ(o.upper.teeth.size(), 2u);
  EXPECT_NEAR(o.upper.teeth[0].min_distance_mm, 0.5, 1e-12);
  EXPECT_NEAR(o.upper.teeth[1].min_distance_mm, 3.0, 1e-12);
  EXPECT_EQ(o.upper.teeth[0].contact_vertices, 4);  // the bottom corners
  EXPECT_EQ(o.upper.teeth[1].contact_vertices, 0);
  EXPECT_EQ(o.upper.contact_vertices, 4);
  EXPECT_GT(o.upper.teeth[0].contact_area_mm2, 0);
  EXPECT_EQ(o.upper.teeth[1].contact_area_mm2, 0);
  // The slab's corners are far from the blocks: capped at the search radius.
  ASSERT_EQ(o.lower.teeth.size(), 1u);
  EXPECT_EQ(o.lower.distance_mm[0], 5.0);
  EXPECT_EQ(o.lower.contact_vertices, 0);
  // Moving the upper arch 0.6 mm down makes the first block penetrate by 0.1 mm.
  Eigen::Isometry3d down = Eigen::Isometry3d::Identity();
  down.translate(Eigen::Vector3d(0, 0, -0.6));
  EXPECT_NEAR(compute_occlusionogram(u, l, down).upper.teeth[0].min_distance_mm, -0.1, 1e-12);
}

TEST(VertexComponents, LabelsSeparateShells) {
  const TriangleMesh mesh = testing::append(make_box({0, 0, 0}, {1, 1, 1}), make_box({3, 0, 0}, {4, 1, 1}));
  int count = 0;
  const auto labels = vertex_components(mesh, &count);
  EXPECT_EQ(count, 2);
  EXPECT_EQ(labels[0], 0);
  EXPECT_EQ(labels[8], 1);
}

}  // namespace
}  // namespace maxillo::occlusion
