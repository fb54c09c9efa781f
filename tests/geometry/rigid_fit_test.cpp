#include "geometry/rigid_fit.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace maxillo {
namespace {

Eigen::Isometry3d rigid(double degrees, const Eigen::Vector3d& axis, const Eigen::Vector3d& shift) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(shift);
  t.rotate(Eigen::AngleAxisd(degrees * M_PI / 180, axis.normalized()));
  return t;
}

std::vector<Eigen::Vector3d> random_points(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> where(-40, 40);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) points.emplace_back(where(rng), where(rng), where(rng));
  return points;
}

TEST(BestRigidTransform, RecoversAKnownMoveExactly) {
  const Eigen::Isometry3d truth = rigid(37, {1, -2, 0.5}, {12, -7, 30});
  const auto from = random_points(1, 50);
  std::vector<Eigen::Vector3d> to;
  for (const auto& p : from) to.push_back(truth * p);
  const Eigen::Isometry3d fit = best_rigid_transform(from, to);
  EXPECT_LT((fit.matrix() - truth.matrix()).norm(), 1e-10);
}

TEST(BestRigidTransform, ThreePointsAreEnoughAndTheAnswerIsNeverAReflection) {
  // A mirror image has no rotation that maps it: the best proper rotation is returned instead.
  const std::vector<Eigen::Vector3d> from = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
  std::vector<Eigen::Vector3d> mirrored;
  for (const auto& p : from) mirrored.emplace_back(-p.x(), p.y(), p.z());
  const Eigen::Isometry3d fit = best_rigid_transform(from, mirrored);
  EXPECT_NEAR(fit.linear().determinant(), 1, 1e-12);
  const Eigen::Isometry3d truth = rigid(90, {0, 0, 1}, {5, 5, 5});
  std::vector<Eigen::Vector3d> three(from.begin(), from.begin() + 3), moved;
  for (const auto& p : three) moved.push_back(truth * p);
  EXPECT_LT((best_rigid_transform(three, moved).matrix() - truth.matrix()).norm(), 1e-10);
}

TEST(BestRigidTransform, MinimisesTheSumOfSquaresUnderNoise) {
  // The fit to noisy targets is at least as good as the true move, and close to it.
  const Eigen::Isometry3d truth = rigid(12, {0, 1, 1}, {-3, 4, 1});
  const auto from = random_points(2, 400);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.2);
  std::vector<Eigen::Vector3d> to;
  for (const auto& p : from) to.push_back(truth * p + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  const Eigen::Isometry3d fit = best_rigid_transform(from, to);
  auto sum_of_squares = [&](const Eigen::Isometry3d& t) {
    double sum = 0;
    for (size_t i = 0; i < from.size(); ++i) sum += (t * from[i] - to[i]).squaredNorm();
    return sum;
  };
  EXPECT_LE(sum_of_squares(fit), sum_of_squares(truth));
  EXPECT_LE(sum_of_squares(fit), sum_of_squares(rigid(0.2, {1, 0, 0}, {0, 0, 0}) * fit));
  EXPECT_LT((fit.translation() - truth.translation()).norm(), 0.1);
}

TEST(NearestRotation, RestoresARotationThatHasDrifted) {
  const Eigen::Matrix3d rotation = rigid(50, {1, 1, 1}, {0, 0, 0}).linear();
  EXPECT_LT((nearest_rotation(rotation) - rotation).norm(), 1e-12);
  const Eigen::Matrix3d drifted = rotation + 1e-4 * Eigen::Matrix3d::Ones();
  const Eigen::Matrix3d restored = nearest_rotation(drifted);
  EXPECT_LT((restored.transpose() * restored - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR(restored.determinant(), 1, 1e-12);
  EXPECT_LT((restored - rotation).norm(), 3e-4);
}

}  // namespace
}  // namespace maxillo
