// The real cadaver head (../shared/data/cthead-stanford) moved by 4 degrees and 7 mm is registered
// back within 0.05 mm RMS over the skin (issue 7), to one answer (issue 14, defect 12). Skips when
// the data are absent. The speed comparison with elastix is `maxillo bench register`, not a test.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>

#include "imaging/converted_copy.h"
#include "imaging/rigid_registration.h"
#include "core/volume_resample.h"
#include "bench/registration_benchmark.h"
#include "support/temporary_folder.h"

namespace maxillo {
namespace {

const std::filesystem::path kSlices = std::filesystem::path(MAXILLO_SHARED_DATA) / "cthead-stanford" / "slices";

// The head, the head moved by the known 4 degrees and 7 mm, the skin the errors are measured on
// and the options with the default (cranial) box.
struct MovedHead {
  Volume fixed, moving;
  Eigen::Isometry3d known;
  Eigen::MatrixX3d skin;
  RigidRegistrationOptions options;
};
MovedHead moved_head() {
  MovedHead head;
  head.fixed = bench::read_cadaver_head(kSlices);
  head.known = bench::known_rigid_move(head.fixed.geometry, 4, 7);
  head.moving = resample_rigid(head.fixed, head.known, head.fixed.geometry);
  head.skin = bench::skin_vertices(head.fixed);
  head.options.box = cranial_registration_box(head.fixed);
  return head;
}

TEST(CadaverRegistration, RecoversFourDegreesAndSevenMillimetresWithinFiftyMicrons) {
  if (!std::filesystem::exists(kSlices / "CThead.113")) GTEST_SKIP() << "real data absent: " << kSlices;
  const auto [fixed, moving, known, skin, options] = moved_head();
  EXPECT_NEAR(Eigen::AngleAxisd(known.linear()).angle() * 180 / M_PI, 4, 1e-9);
  const RigidRegistrationResult result = register_rigid(fixed, moving, options);
  ASSERT_GT(skin.rows(), 10000);
  const double rms = bench::rms_error_mm(skin, result.moving_to_fixed, known);
  const double start_rms = bench::rms_error_mm(skin, Eigen::Isometry3d::Identity(), known);
  std::cout << "[cadaver registration] " << result.seconds << " s, " << result.iterations << " iterations, RMS " << rms
            << " mm over " << skin.rows() << " skin vertices (start " << start_rms << " mm)\n";
  EXPECT_GT(start_rms, 7);
  EXPECT_LE(rms, 0.05);
}

// How far apart two answers lie: the rotation between them (degrees) and the RMS distance over
// the skin between where they put it (mm).
struct Apart {
  double degrees, mm;
};
Apart apart(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const Eigen::MatrixX3d& skin) {
  return {Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle() * 180 / M_PI,
          bench::rms_error_mm(skin, a, b.inverse())};
}

// Issue 14, defect 12: a validation tool gives one answer. The default registration (as many
// threads as cores) twice, and once each with one and with three threads: the same bits (before,
// the default used one thread because more gave answers up to 0.011 deg apart). From two
// different starting guesses (1 degree and 1 mm apart): the optimum, not where the optimiser
// stopped, within 0.01 degree and 0.01 mm over the skin.
TEST(CadaverRegistration, RepeatedAndDifferentlyStartedRegistrationsAgree) {
  if (!std::filesystem::exists(kSlices / "CThead.113")) GTEST_SKIP() << "real data absent: " << kSlices;
  auto [fixed, moving, known, skin, options] = moved_head();
  const auto first = register_rigid(fixed, moving, options), second = register_rigid(fixed, moving, options);
  const Apart repeated = apart(second.moving_to_fixed, first.moving_to_fixed, skin);
  std::cout << "[cadaver registration] repeated: " << repeated.degrees << " deg, " << repeated.mm << " mm apart\n";
  EXPECT_LT(repeated.degrees, 0.01);
  EXPECT_LT(repeated.mm, 0.01);
  EXPECT_EQ(first.moving_to_fixed.matrix(), second.moving_to_fixed.matrix());
  for (int threads : {1, 3}) {
    RigidRegistrationOptions counted = options;
    counted.threads = threads;
    EXPECT_EQ(register_rigid(fixed, moving, counted).moving_to_fixed.matrix(), first.moving_to_fixed.matrix())
        << threads << " threads";
  }

  Eigen::Isometry3d nudge = Eigen::Isometry3d::Identity();
  nudge.rotate(Eigen::AngleAxisd(M_PI / 180, Eigen::Vector3d(1, -1, 2).normalized()))
      .pretranslate(Eigen::Vector3d(0.6, -0.5, 0.6));
  options.initial = nudge * known.inverse();
  const Apart nudged = apart(register_rigid(fixed, moving, options).moving_to_fixed, first.moving_to_fixed, skin);
  std::cout << "[cadaver registration] differently started: " << nudged.degrees << " deg, " << nudged.mm
            << " mm apart\n";
  EXPECT_LT(nudged.degrees, 0.01);
  EXPECT_LT(nudged.mm, 0.01);
}

// Issue 14, defect 12: both CTs converted another way (float pixels with a rescale intercept,
// slices top-down, the moving CT's origin half a voxel off, padding at the border; see
// converted_copy.h) register to the same answer as the originals, once the shift is undone
// (before: 0.011 deg and 0.021 mm apart).
TEST(CadaverRegistration, ACopyConvertedAnotherWayGivesTheSameAnswer) {
  if (!std::filesystem::exists(kSlices / "CThead.113")) GTEST_SKIP() << "real data absent: " << kSlices;
  const auto [fixed, moving, known, skin, options] = moved_head();
  const Eigen::Isometry3d original = register_rigid(fixed, moving, options).moving_to_fixed;

  TemporaryFolder folder("cadaver-copy");
  const Eigen::Vector3d shift = 0.5 * moving.geometry.spacing;
  const Volume fixed_copy = testing::converted_copy(fixed, folder.path(), "fixed");
  const Volume moving_copy = testing::converted_copy(moving, folder.path(), "moving", {.origin_shift = shift});
  const Eigen::Isometry3d copied = register_rigid(fixed_copy, moving_copy, options).moving_to_fixed;

  const Apart copy = apart(copied * Eigen::Translation3d(shift), original, skin);  // moving -> copy -> fixed
  std::cout << "[cadaver registration] converted copy: " << copy.degrees << " deg, " << copy.mm << " mm apart\n";
  EXPECT_LT(copy.degrees, 0.01);
  EXPECT_LT(copy.mm, 0.01);
}

TEST(CadaverRegistration, ElastixEulerTransformIsReadAsMovingToFixed) {
  // An elastix transform written by hand: R = Rz Rx Ry about the centre c, then t; elastix maps
  // fixed to moving, so the result must be its inverse.
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "maxillo-elastix-euler-test.txt";
  std::ofstream(file) << "(Transform \"EulerTransform\")\n(NumberOfParameters 6)\n"
                         "(TransformParameters 0.1 -0.2 0.3 1.5 -2 4)\n(CenterOfRotationPoint 10 20 30)\n"
                         "(ComputeZYX \"false\")\n";
  const Eigen::Isometry3d moving_to_fixed = bench::read_elastix_euler(file);
  std::filesystem::remove(file);
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()))
          .toRotationMatrix();
  const Eigen::Vector3d c(10, 20, 30), p(3, -7, 50);
  const Eigen::Vector3d in_moving = r * (p - c) + c + Eigen::Vector3d(1.5, -2, 4);
  EXPECT_LT((moving_to_fixed * in_moving - p).norm(), 1e-9);
}

}  // namespace
}  // namespace maxillo
