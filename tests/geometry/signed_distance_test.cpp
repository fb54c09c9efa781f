#include "geometry/signed_distance.h"

#include <gtest/gtest.h>

#include "support/test_meshes.h"

namespace maxillo {
namespace {

using Eigen::Vector3d;

// Analytic signed distance of an axis-aligned box.
double box_distance(const Vector3d& p, const Vector3d& lo, const Vector3d& hi) {
  const Vector3d centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const Vector3d q = (p - centre).cwiseAbs() - half;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

TEST(DistanceField, EqualsTheAnalyticBoxDistanceIncludingEdgesAndCorners) {
  const Vector3d lo(1, 2, 3), hi(4, 6, 5);
  const TriangleMesh box = testing::make_box(lo, hi);
  DistanceField field(box);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 8);
  int inside = 0;
  for (int n = 0; n < 5000; ++n) {
    const Vector3d p(u(rng), u(rng), u(rng));
    const SignedDistance d = field.signed_distance(p, 100);
    ASSERT_TRUE(d.found);
    ASSERT_NEAR(d.distance, box_distance(p, lo, hi), 1e-9) << p.transpose();
    inside += d.distance < 0;
  }
  EXPECT_GT(inside, 50);
  // Points nearest to an edge or a corner (where face normals disagree).
  EXPECT_NEAR(field.signed_distance({0, 1, 3.5}, 100).distance, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(field.signed_distance({0, 1, 2}, 100).distance, std::sqrt(3.0), 1e-12);
  EXPECT_FALSE(field.signed_distance({20, 20, 20}, 1.0).found);
}

TEST(DistanceField, UnderARigidTransformTheDistanceIsInvariant) {
  const TriangleMesh box = testing::make_box({0, 0, 0}, {2, 3, 4});
  DistanceField field(box);
  std::mt19937 rng(9);
  const Eigen::Isometry3d pose = testing::random_pose(rng, 5, 1.0);
  TriangleMesh moved = box;
  for (Eigen::Index v = 0; v < moved.vertex_count(); ++v)
    moved.vertices.row(v) = (pose * Vector3d(box.vertices.row(v).transpose())).transpose();
  DistanceField moved_field(moved);
  std::uniform_real_distribution<double> u(-2, 6);
  for (int n = 0; n < 500; ++n) {
    const Vector3d p(u(rng), u(rng), u(rng));
    ASSERT_NEAR(moved_field.signed_distance(pose * p, 100).distance, field.signed_distance(p, 100).distance, 1e-9);
  }
}

}  // namespace
}  // namespace maxillo
