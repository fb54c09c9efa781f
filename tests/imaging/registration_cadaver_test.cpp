// The real cadaver head (../shared/data/cthead-stanford) moved by 4 degrees and 7 mm is registered
// back within 0.05 mm RMS over the skin (issue 7). Skips when the data are absent. The speed
// comparison with elastix is `maxillo bench register`, not a test.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>

#include "imaging/rigid_registration.h"
#include "imaging/volume_resample.h"
#include "pipeline/registration_benchmark.h"

namespace maxillo {
namespace {

const std::filesystem::path kSlices = std::filesystem::path(MAXILLO_SHARED_DATA) / "cthead-stanford" / "slices";

TEST(CadaverRegistration, RecoversFourDegreesAndSevenMillimetresWithinFiftyMicrons) {
  if (!std::filesystem::exists(kSlices / "CThead.113")) GTEST_SKIP() << "real data absent: " << kSlices;
  const Volume fixed = pipeline::read_cadaver_head(kSlices);
  const Eigen::Isometry3d known = pipeline::known_rigid_move(fixed.geometry, 4, 7);
  EXPECT_NEAR(Eigen::AngleAxisd(known.linear()).angle() * 180 / M_PI, 4, 1e-9);
  const Volume moving = resample_rigid(fixed, known, fixed.geometry);

  RigidRegistrationOptions options;
  options.box = cranial_registration_box(fixed);
  const RigidRegistrationResult result = register_rigid(fixed, moving, options);
  const Eigen::MatrixX3d skin = pipeline::skin_vertices(fixed);
  ASSERT_GT(skin.rows(), 10000);
  const double rms = pipeline::rms_error_mm(skin, result.moving_to_fixed, known);
  const double start_rms = pipeline::rms_error_mm(skin, Eigen::Isometry3d::Identity(), known);
  std::cout << "[cadaver registration] " << result.seconds << " s, " << result.iterations << " iterations, RMS "
            << rms << " mm over " << skin.rows() << " skin vertices (start " << start_rms << " mm)\n";
  EXPECT_GT(start_rms, 7);
  EXPECT_LE(rms, 0.05);
}

// Issue 14, defect 12: a validation tool gives one answer. Twice the same registration: the same
// bits. From two different starting guesses (1 degree and 1 mm apart): the optimum, not where
// the optimiser stopped, within 0.01 degree and 0.01 mm over the skin.
TEST(CadaverRegistration, RepeatedAndDifferentlyStartedRegistrationsAgree) {
  if (!std::filesystem::exists(kSlices / "CThead.113")) GTEST_SKIP() << "real data absent: " << kSlices;
  const Volume fixed = pipeline::read_cadaver_head(kSlices);
  const Eigen::Isometry3d known = pipeline::known_rigid_move(fixed.geometry, 4, 7);
  const Volume moving = resample_rigid(fixed, known, fixed.geometry);
  const Eigen::MatrixX3d skin = pipeline::skin_vertices(fixed);
  RigidRegistrationOptions options;
  options.box = cranial_registration_box(fixed);
  const auto first = register_rigid(fixed, moving, options), second = register_rigid(fixed, moving, options);
  EXPECT_TRUE(first.moving_to_fixed.isApprox(second.moving_to_fixed, 1e-15));

  Eigen::Isometry3d nudge = Eigen::Isometry3d::Identity();
  nudge.rotate(Eigen::AngleAxisd(M_PI / 180, Eigen::Vector3d(1, -1, 2).normalized())).pretranslate(Eigen::Vector3d(0.6, -0.5, 0.6));
  options.initial = nudge * known.inverse();
  const auto nudged = register_rigid(fixed, moving, options);
  const double degrees =
      Eigen::AngleAxisd(nudged.moving_to_fixed.linear() * first.moving_to_fixed.linear().transpose()).angle() * 180 / M_PI;
  const double mm = pipeline::rms_error_mm(skin, nudged.moving_to_fixed, first.moving_to_fixed.inverse());
  std::cout << "[cadaver registration] differently started: " << degrees << " deg, " << mm << " mm apart\n";
  EXPECT_LT(degrees, 0.01);
  EXPECT_LT(mm, 0.01);
}

TEST(CadaverRegistration, ElastixEulerTransformIsReadAsMovingToFixed) {
  // An elastix transform written by hand: R = Rz Rx Ry about the centre c, then t; elastix maps
  // fixed to moving, so the result must be its inverse.
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "maxillo-elastix-euler-test.txt";
  std::ofstream(file) << "(Transform \"EulerTransform\")\n(NumberOfParameters 6)\n"
                         "(TransformParameters 0.1 -0.2 0.3 1.5 -2 4)\n(CenterOfRotationPoint 10 20 30)\n"
                         "(ComputeZYX \"false\")\n";
  const Eigen::Isometry3d moving_to_fixed = pipeline::read_elastix_euler(file);
  std::filesystem::remove(file);
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  const Eigen::Vector3d c(10, 20, 30), p(3, -7, 50);
  const Eigen::Vector3d in_moving = r * (p - c) + c + Eigen::Vector3d(1.5, -2, 4);
  EXPECT_LT((moving_to_fixed * in_moving - p).norm(), 1e-9);
}

}  // namespace
}  // namespace maxillo
