// Volume -> write_ct_series -> DICOM files -> load_series_volume: the LPS geometry and the HU
// values come back exactly (to the precision of DICOM decimal strings).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "dicom/dicom_series_writer.h"
#include "imaging/volume_assembly.h"
#include "support/temporary_folder.h"
#include "synthetic_slices.h"

namespace maxillo {
namespace {

Volume patterned_volume(const Eigen::Matrix3d& direction) {
  Volume v;
  v.geometry.size = {9, 6, 5};
  v.geometry.spacing = {0.48828125, 0.6, 1.25};
  v.geometry.origin = {-120.3, 15.75, -302.5};
  v.geometry.direction = direction;
  v.hu.resize(size_t(v.geometry.voxel_count()));
  for (size_t n = 0; n < v.hu.size(); ++n) v.hu[n] = int16_t(int(n * 7919 % 5000) - 1500);
  return v;
}

void expect_same_volume(const Volume& a, const Volume& b) {
  EXPECT_EQ(a.geometry.size, b.geometry.size);
  // Decimal strings carry 10 significant digits: positions come back to ~1e-7 mm.
  EXPECT_LT((a.geometry.spacing - b.geometry.spacing).cwiseAbs().maxCoeff(), 1e-6) << b.geometry.spacing.transpose();
  EXPECT_LT((a.geometry.origin - b.geometry.origin).norm(), 1e-6) << b.geometry.origin.transpose();
  EXPECT_LT((a.geometry.direction - b.geometry.direction).cwiseAbs().maxCoeff(), 1e-8) << b.geometry.direction;
  EXPECT_EQ(a.hu, b.hu);
}

TEST(SeriesRoundTrip, AxialSeriesComesBackExactly) {
  TemporaryFolder folder("round-trip-axial");
  const Volume v = patterned_volume(Eigen::Matrix3d::Identity());
  auto files = write_ct_series(v, {}, folder.path()).files;
  std::shuffle(files.begin(), files.end(), std::mt19937(7));  // file order must not matter
  expect_same_volume(v, load_series_volume(files));
}

TEST(SeriesRoundTrip, ObliqueSeriesComesBackExactly) {
  TemporaryFolder folder("round-trip-oblique");
  const Volume v = patterned_volume(testing::oblique_axes());
  expect_same_volume(v, load_series_volume(write_ct_series(v, {}, folder.path()).files));
}

TEST(SeriesRoundTrip, LeftHandedVolumeComesBackFlippedButSamePlaces) {
  // k runs against row x column (slices listed top-down): the series reads back with k along
  // the normal, so the same voxels sit at the same LPS places with the slice order reversed.
  TemporaryFolder folder("round-trip-flipped");
  Eigen::Matrix3d direction = testing::oblique_axes();
  direction.col(2) *= -1;
  const Volume v = patterned_volume(direction);
  const Volume back = load_series_volume(write_ct_series(v, {}, folder.path()).files);
  EXPECT_NEAR(back.geometry.direction.determinant(), 1.0, 1e-9);
  ASSERT_EQ(back.geometry.size, v.geometry.size);
  const int nz = v.geometry.size.z();
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < v.geometry.size.y(); ++j)
      for (int i = 0; i < v.geometry.size.x(); ++i) {
        ASSERT_EQ(back.at(i, j, nz - 1 - k), v.at(i, j, k));
        ASSERT_LT((back.geometry.world(Eigen::Vector3d(i, j, nz - 1 - k)) - v.geometry.world(Eigen::Vector3d(i, j, k)))
                      .norm(),
                  1e-6);
      }
}

}  // namespace
}  // namespace maxillo
