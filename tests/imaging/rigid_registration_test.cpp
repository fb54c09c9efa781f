// register_rigid on a synthetic head (tests/imaging/synthetic_head.h, 2 mm voxels) moved by a
// known rigid transform, cranial_registration_box, and the refusals.
//
// Tolerance: 0.2 mm RMS at the corners of a 100 mm cube (points 87 mm from the centre, further out
// than the head's surface), a tenth of a voxel. The moving CT is the fixed one resampled, so the
// optimum of the metric is the true pose up to the interpolation blur and the sampling noise of
// Mattes MI (the real head reaches 0.05 mm at 1 x 1 x 2 mm, see bench register).
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "core/error.h"
#include "imaging/rigid_registration.h"
#include "imaging/synthetic_head.h"
#include "imaging/volume_resample.h"

namespace maxillo {
namespace {

constexpr double kToleranceMm = 0.2;

class SyntheticRegistration : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { fixed_ = new Volume(testing::synthetic_head()); }
  static void TearDownTestSuite() { delete fixed_; }
  static inline Volume* fixed_ = nullptr;
};

TEST_F(SyntheticRegistration, RecoversAKnownMoveOverTheWholeImage) {
  const Eigen::Isometry3d known = testing::oblique_move(5, {4, -3, 5}, {3, -5, 8});
  const Volume moving = resample_rigid(*fixed_, known, fixed_->geometry);
  const RigidRegistrationResult result = register_rigid(*fixed_, moving);
  EXPECT_LT(testing::corner_rms(result.moving_to_fixed, known), kToleranceMm);
  EXPECT_LT(result.metric, -0.1) << "Mattes MI is reported negated: aligned images give a clearly negative value";
  EXPECT_GT(result.iterations, 3);
  EXPECT_GT(result.seconds, 0);
  EXPECT_TRUE(result.moving_to_fixed.linear().isUnitary(1e-9));
  EXPECT_NEAR(result.moving_to_fixed.linear().determinant(), 1, 1e-9);
}

TEST_F(SyntheticRegistration, RecoversAKnownMoveInsideABoxAndFromAnInitialGuess) {
  const Eigen::Isometry3d known = testing::oblique_move(-4, {-6, 2, 3});
  const Volume moving = resample_rigid(*fixed_, known, fixed_->geometry);
  RigidRegistrationOptions options;
  options.box = RegistrationBox{{-70, -80, -50}, {70, 80, 90}};
  options.initial = testing::oblique_move(-3, {-5, 1, 2}).inverse();  // close to the truth
  const RigidRegistrationResult result = register_rigid(*fixed_, moving, options);
  EXPECT_LT(testing::corner_rms(result.moving_to_fixed, known), kToleranceMm);
}

// The default (one thread, see RigidRegistrationOptions::threads) gives the same bits whatever
// else the machine is doing: here with a busy thread competing for the cores.
TEST_F(SyntheticRegistration, TheDefaultGivesTheSameAnswerUnderLoad) {
  const Eigen::Isometry3d known = testing::oblique_move(3, {2, 2, -2});
  const Volume moving = resample_rigid(*fixed_, known, fixed_->geometry);
  const auto reference = register_rigid(*fixed_, moving);
  std::atomic<bool> stop{false};
  std::thread busy([&] {
    volatile double x = 0;
    while (!stop) x = x + 1;
  });
  for (int run = 0; run < 3; ++run)
    EXPECT_TRUE(register_rigid(*fixed_, moving).moving_to_fixed.isApprox(reference.moving_to_fixed, 1e-15)) << run;
  stop = true;
  busy.join();
}

TEST_F(SyntheticRegistration, RefusesABoxOutsideTheImageAndAnEmptyVolume) {
  RigidRegistrationOptions options;
  options.box = RegistrationBox{{500, 500, 500}, {600, 600, 600}};
  try {
    register_rigid(*fixed_, *fixed_, options);
    FAIL() << "a box outside the image was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kBadValue);
    EXPECT_EQ(e.subject(), "registration box");
  }
  try {
    register_rigid(*fixed_, Volume{});
    FAIL() << "an empty volume was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kBadValue);
    EXPECT_EQ(e.subject(), "moving CT");
  }
}

TEST_F(SyntheticRegistration, CranialBoxFromOrbitaleOrFromTheTopOfTheHead) {
  const RegistrationBox bounds = volume_bounds(fixed_->geometry);
  // Without landmarks: the top 45 % of the tissue's S extent. The ellipsoid spans z = -84..84 mm;
  // planes are 2 mm apart and count once they hold ~1 cm2 of tissue, so the extent is within a
  // plane or two of that.
  const RegistrationBox top = cranial_registration_box(*fixed_);
  EXPECT_NEAR(top.min.z(), 84 - 0.45 * 168, 3.5);
  EXPECT_NEAR(top.max.z(), 84, 3.5);
  EXPECT_TRUE(top.min.head<2>().isApprox(bounds.min.head<2>()));
  EXPECT_TRUE(top.max.head<2>().isApprox(bounds.max.head<2>()));
  // With orbitale landmarks: 5 mm above their mean height, up to the top of the image.
  const LandmarkSet landmarks = {{"OrR", {-30, -60, 10}}, {"OrL", {30, -60, 14}}, {"N", {0, -70, 30}}};
  const RegistrationBox orbit = cranial_registration_box(*fixed_, &landmarks);
  EXPECT_DOUBLE_EQ(orbit.min.z(), 12 + kAboveOrbitaleMm);
  EXPECT_DOUBLE_EQ(orbit.max.z(), bounds.max.z());
  const LandmarkSet underscored = {{"Or_R", {-30, -60, 0}}, {"Or_L", {30, -60, 2}}};
  EXPECT_DOUBLE_EQ(cranial_registration_box(*fixed_, &underscored).min.z(), 1 + kAboveOrbitaleMm);
}

}  // namespace
}  // namespace maxillo
