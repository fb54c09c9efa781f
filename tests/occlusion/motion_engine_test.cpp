#include "occlusion/motion_engine.h"

#include <gtest/gtest.h>

#include "occlusion/guided_alignment.h"
#include "support/test_meshes.h"

namespace maxillo::occlusion {
namespace {

using Eigen::Vector3d;
using testing::make_box;

// Lower: a 10x10x2 slab, top at z = 0. Upper: a 4x4x2 block, bottom at z = 1 (1 mm gap).
struct Blocks {
  TriangleMesh lower = make_box({-5, -5, -2}, {5, 5, 0});
  TriangleMesh upper = make_box({-2, -2, 1}, {2, 2, 3});
  DistanceField lower_field{lower}, upper_field{upper};
};

TEST(MotionEngine, CancelsAStepThatWouldPenetrateAndReportsIt) {
  Blocks b;
  MotionEngine engine(b.upper_field, b.lower_field, Eigen::Isometry3d::Identity());
  EXPECT_NEAR(engine.allowed_penetration_mm(), 0.05, 1e-12);
  EXPECT_EQ(engine.translate({0, 0, -1.2}).outcome, StepOutcome::CancelledByCollision);
  EXPECT_TRUE(engine.pose().isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_EQ(engine.translate({0, 0, -0.98}).outcome, StepOutcome::Moved);  // 0.02 mm clearance left
  EXPECT_EQ(engine.translate({1, 0, 0}).outcome, StepOutcome::Moved);      // sliding is free
  EXPECT_EQ(engine.rotate({1, 0, 0}, 10, {0, 0, 2}).outcome, StepOutcome::CancelledByCollision);
  EXPECT_NEAR(engine.pose().translation().z(), -0.98, 1e-12);
}

TEST(MotionEngine, AStepThatWouldTunnelThroughIsCancelled) {
  Blocks b;
  MotionEngine engine(b.upper_field, b.lower_field, Eigen::Isometry3d::Identity());
  // 20 mm down would end below the slab, clear of it; the path crosses it.
  EXPECT_EQ(engine.translate({0, 0, -20}).outcome, StepOutcome::CancelledByCollision);
}

TEST(MotionEngine, ToleratesThePenetrationOfTheStartPose) {
  Blocks b;
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  start.translate(Vector3d(0, 0, -1.3));  // 0.3 mm inside
  MotionEngine engine(b.upper_field, b.lower_field, start);
  EXPECT_NEAR(engine.allowed_penetration_mm(), 0.35, 1e-9);
  EXPECT_EQ(engine.translate({0, 0, -0.04}).outcome, StepOutcome::Moved);
  EXPECT_EQ(engine.translate({0, 0, -0.04}).outcome, StepOutcome::CancelledByCollision);
}

TEST(BestFitTransform, RecoversAKnownRigidTransform) {
  std::mt19937 rng(3);
  const Eigen::Isometry3d truth = testing::random_pose(rng, 5, 1.0);
  std::vector<SpringPair> pairs;
  for (const Vector3d& p : {Vector3d(0, 0, 0), Vector3d(10, 0, 1), Vector3d(0, 8, 2), Vector3d(3, 3, 9)})
    pairs.push_back({p, truth * p});
  EXPECT_TRUE(best_fit_transform(pairs).isApprox(truth, 1e-9));
}

std::vector<SpringPair> springs_pulling_into_the_slab(double dx, double dy) {
  // Upper points on the block's bottom; lower targets 0.5 mm below the slab top, shifted.
  std::vector<SpringPair> pairs;
  for (const Vector3d& p : {Vector3d(-2, -2, 1), Vector3d(2, -2, 1), Vector3d(0, 2, 1)})
    pairs.push_back({p, p + Vector3d(dx, dy, -1.5)});
  return pairs;
}

TEST(GuidedAlignment, SpringsPullTheBlockOntoTheSlabWhereContactsStopIt) {
  Blocks b;
  MotionEngine engine(b.upper_field, b.lower_field, Eigen::Isometry3d::Identity());
  const AlignmentResult result = align_guided(engine, springs_pulling_into_the_slab(1.5, -1.0));
  EXPECT_EQ(result.status, AlignmentStatus::Converged);
  EXPECT_LE(result.penetration_mm, engine.allowed_penetration_mm());
  // Resting on the slab (bottom within the allowance below z = 0), flat, and shifted sideways.
  EXPECT_NEAR(result.pose.translation().z(), -1.0, 0.06);
  EXPECT_NEAR(result.pose.translation().x(), 1.5, 0.01);
  EXPECT_NEAR(result.pose.translation().y(), -1.0, 0.01);
  EXPECT_NEAR(Eigen::AngleAxisd(result.pose.linear()).angle(), 0, 0.01);
  for (double r : result.residual_spring_mm) EXPECT_NEAR(r, 0.5, 0.06);
}

TEST(GuidedAlignment, IsDeterministic) {
  Blocks b;
  MotionEngine first(b.upper_field, b.lower_field, Eigen::Isometry3d::Identity());
  MotionEngine second(b.upper_field, b.lower_field, Eigen::Isometry3d::Identity());
  const auto springs = springs_pulling_into_the_slab(0.7, 0.3);
  const AlignmentResult r1 = align_guided(first, springs), r2 = align_guided(second, springs);
  EXPECT_EQ(r1.iterations, r2.iterations);
  EXPECT_TRUE(r1.pose.matrix() == r2.pose.matrix());
}

TEST(GuidedAlignment, WithoutObstaclesReachesTheBestFit) {
  Blocks b;
  MotionEngine engine(b.upper_field, b.lower_field, Eigen::Isometry3d::Identity());
  std::vector<SpringPair> pairs;
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  target.translate(Vector3d(1, 2, 3)).rotate(Eigen::AngleAxisd(0.2, Vector3d::UnitZ()));
  for (const Vector3d& p : {Vector3d(-2, -2, 1), Vector3d(2, -2, 1), Vector3d(0, 2, 3)})
    pairs.push_back({p, target * p});
  const AlignmentResult result = align_guided(engine, pairs);
  EXPECT_TRUE(result.pose.isApprox(target, 1e-4));
  for (double r : result.residual_spring_mm) EXPECT_LT(r, 1e-3);
}

}  // namespace
}  // namespace maxillo::occlusion
