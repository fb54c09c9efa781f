// assemble_volume: sorting, geometry, refusals with their reasons, spacing handling.
#include "imaging/volume_assembly.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/error.h"
#include "synthetic_slices.h"

namespace maxillo {
namespace {

using testing::make_stack;
using testing::marker_hu;
using testing::oblique_axes;

std::vector<double> evenly(int count, double step) {
  std::vector<double> along;
  for (int k = 0; k < count; ++k) along.push_back(k * step);
  return along;
}

// Runs assemble_volume expecting a refusal; returns the Error.
Error refusal(std::vector<DicomSlice> slices) {
  try {
    assemble_volume(std::move(slices));
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "assemble_volume accepted an inconsistent series";
  return Error(ErrorCode::kProcessing, "", "");
}

TEST(VolumeAssembly, ShuffledSlicesGiveTheSameVolumeAsSortedOnes) {
  auto sorted = make_stack(evenly(7, 1.5), oblique_axes());
  auto shuffled = sorted;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(42));
  ASSERT_NE(shuffled.front().path, sorted.front().path);
  Volume a = assemble_volume(sorted), b = assemble_volume(shuffled);
  EXPECT_EQ(a.hu, b.hu);
  EXPECT_TRUE(a.geometry.origin.isApprox(b.geometry.origin));
  EXPECT_TRUE(a.geometry.direction.isApprox(b.geometry.direction));
}

TEST(VolumeAssembly, GeometryFollowsDicomConventions) {
  const Eigen::Matrix3d axes = oblique_axes();
  AssemblyReport report;
  Volume v = assemble_volume(make_stack(evenly(5, 2.0), axes, {1, 2, 3}), &report);
  EXPECT_EQ(v.geometry.size, Eigen::Vector3i(6, 5, 5));
  EXPECT_DOUBLE_EQ(v.geometry.spacing.x(), 0.6);  // between columns = Pixel Spacing[1]
  EXPECT_DOUBLE_EQ(v.geometry.spacing.y(), 0.8);  // between rows = Pixel Spacing[0]
  EXPECT_NEAR(v.geometry.spacing.z(), 2.0, 1e-12);
  EXPECT_TRUE(v.geometry.origin.isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_TRUE(v.geometry.direction.isApprox(axes, 1e-12));
  EXPECT_NEAR(v.geometry.direction.determinant(), 1.0, 1e-12);
  EXPECT_EQ(report.spacing, SliceSpacing::Uniform);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(v.at(3, 2, k), marker_hu(3, 2, 2.0 * k));
}

TEST(VolumeAssembly, SlicesListedAgainstTheNormalAreReversed) {
  // Positions decreasing along row x column (a top-down axial series): k still follows the normal.
  auto slices = make_stack({0, -1, -2, -3});
  Volume v = assemble_volume(slices);
  EXPECT_TRUE(v.geometry.origin.isApprox(slices.back().position));
  EXPECT_EQ(v.at(0, 0, 0), marker_hu(0, 0, -3));
  EXPECT_EQ(v.at(0, 0, 3), marker_hu(0, 0, 0));
}

TEST(VolumeAssembly, SmallJitterIsTolerated) {
  AssemblyReport report;
  Volume v = assemble_volume(make_stack({0, 1.02, 1.98, 3.03, 4.0}), &report);
  EXPECT_EQ(report.spacing, SliceSpacing::Uniform);
  EXPECT_NEAR(report.max_deviation_mm, 0.03, 1e-9);
  EXPECT_EQ(v.geometry.size.z(), 5);
  EXPECT_NEAR(v.geometry.spacing.z(), 1.0, 1e-12);
}

TEST(VolumeAssembly, UnevenSpacingIsResampledLinearly) {
  // 1 mm and 1.25 mm gaps mixed; HU grows linearly along the normal, so interpolation is exact.
  const std::vector<double> along = {0, 1, 2, 3.25, 4.5, 5.75, 6.75, 7.75};
  auto slices = make_stack(along);
  for (size_t k = 0; k < along.size(); ++k)
    std::fill(slices[k].hu.begin(), slices[k].hu.end(), int16_t(100 * along[k]));
  AssemblyReport report;
  Volume v = assemble_volume(slices, &report);
  EXPECT_EQ(report.spacing, SliceSpacing::Resampled);
  EXPECT_DOUBLE_EQ(v.geometry.spacing.z(), 1.0);  // the median gap
  ASSERT_EQ(v.geometry.size.z(), 8);              // 0, 1, ..., 7 mm
  for (int k = 0; k < 8; ++k) EXPECT_EQ(v.at(2, 3, k), 100 * k) << "k = " << k;
}

TEST(VolumeAssembly, RefusesMixedOrientationNamingTheFile) {
  auto slices = make_stack(evenly(5, 1));
  slices[3].row_direction = Eigen::Vector3d(0.99, 0.141067, 0).normalized();
  Error e = refusal(slices);
  EXPECT_EQ(e.code(), ErrorCode::kInconsistentSeries);
  EXPECT_EQ(e.subject(), "slice3.dcm");
  EXPECT_NE(e.reason().find("mixed orientations"), std::string::npos) << e.reason();
}

TEST(VolumeAssembly, RefusesMixedSizesSpacingsAndSeries) {
  auto sizes = make_stack(evenly(4, 1));
  sizes[2] = testing::make_slice("small.dcm", sizes[2].position, 2, Eigen::Matrix3d::Identity(), 6, 4);
  EXPECT_NE(refusal(sizes).reason().find("6x4"), std::string::npos);

  auto spacings = make_stack(evenly(4, 1));
  spacings[1].row_spacing = 0.9;
  EXPECT_NE(refusal(spacings).reason().find("pixel spacing"), std::string::npos);

  auto series = make_stack(evenly(4, 1));
  series[2].series_instance_uid = "9.9.9";
  Error e = refusal(series);
  EXPECT_EQ(e.subject(), "slice2.dcm");
  EXPECT_NE(e.reason().find("9.9.9"), std::string::npos) << e.reason();
}

TEST(VolumeAssembly, RefusesMissingSlicesNamingTheGap) {
  Error e = refusal(make_stack({0, 1, 2, 4, 5, 6}));
  EXPECT_EQ(e.code(), ErrorCode::kInconsistentSeries);
  EXPECT_NE(e.reason().find("missing slices"), std::string::npos) << e.reason();
  EXPECT_NE(e.reason().find("slice2.dcm and slice3.dcm"), std::string::npos) << e.reason();
}

TEST(VolumeAssembly, RefusesDuplicatePositions) {
  auto slices = make_stack({0, 1, 2, 3, 4});
  slices[3].position = slices[1].position;
  Error e = refusal(slices);
  EXPECT_NE(e.reason().find("duplicate slice"), std::string::npos) << e.reason();
  EXPECT_TRUE(e.subject() == "slice1.dcm" || e.subject() == "slice3.dcm") << e.subject();
}

TEST(VolumeAssembly, RefusesGantryTiltWithItsAngle) {
  // Axial slices whose positions shift posteriorly by tan(15 deg) per mm along z.
  auto slices = make_stack(evenly(6, 2));
  for (size_t k = 0; k < slices.size(); ++k) {
    slices[k].position.y() += std::tan(15.0 * M_PI / 180) * 2.0 * double(k);
    slices[k].gantry_tilt_degrees = 15;
  }
  Error e = refusal(slices);
  EXPECT_NE(e.reason().find("gantry tilt of 15 degrees"), std::string::npos) << e.reason();
}

TEST(VolumeAssembly, RefusesFewerThanThreeSlices) {
  Error e = refusal(make_stack({0, 1}));
  EXPECT_NE(e.reason().find("at least 3 slices"), std::string::npos) << e.reason();
}

}  // namespace
}  // namespace maxillo
