// resample_rigid against analytic answers: whole-voxel translations are exact, a linear ramp stays
// linear under rotation (trilinear interpolation reproduces linear functions exactly), labels
// follow a quarter turn exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "core/volume_resample.h"

namespace maxillo {
namespace {

VolumeGeometry tilted_grid() {
  VolumeGeometry g;
  g.size = {10, 12, 8};
  g.spacing = {1.0, 1.5, 2.0};
  g.origin = {-4, 3, 10};
  g.direction = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  return g;
}

int16_t pattern(int i, int j, int k) { return int16_t((i * 37 + j * 101 + k * 211) % 997 - 500); }

TEST(VolumeResample, WholeVoxelTranslationIsExact) {
  Volume source;
  source.geometry = tilted_grid();
  source.hu.resize(size_t(source.geometry.voxel_count()));
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 10; ++i) source.at(i, j, k) = pattern(i, j, k);
  // Move by (+2, -1, +3) voxels along the grid's own axes.
  const Eigen::Vector3i shift(2, -1, 3);
  Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
  move.translation() = source.geometry.direction * source.geometry.spacing.cwiseProduct(shift.cast<double>());
  const Volume result = resample_rigid(source, move, source.geometry, -1234);
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 10; ++i) {
        const int si = i - shift.x(), sj = j - shift.y(), sk = k - shift.z();
        const int16_t expected = source.geometry.contains(si, sj, sk) ? pattern(si, sj, sk) : int16_t(-1234);
        ASSERT_EQ(result.at(i, j, k), expected) << i << "," << j << "," << k;
      }
}

TEST(VolumeResample, LinearRampStaysLinearUnderRotation) {
  Volume source;
  source.geometry.size = {40, 40, 30};
  source.geometry.origin = {-19.5, -19.5, -14.5};
  source.hu.resize(size_t(source.geometry.voxel_count()));
  const Eigen::Vector3d gradient(3, -2, 5);  // HU per mm
  for (int k = 0; k < 30; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i)
        source.at(i, j, k) = int16_t(std::lround(gradient.dot(source.geometry.world(Eigen::Vector3d(i, j, k)))));
  // Voxel centres sit at half-integer mm, where 3x - 2y + 5z is an integer: the stored ramp is
  // exactly linear, trilinear interpolation reproduces it, and only the result's rounding to
  // whole HU (<= 0.5) remains.
  Eigen::Isometry3d move = Eigen::Isometry3d::Identity();
  move.rotate(Eigen::AngleAxisd(0.35, Eigen::Vector3d(1, 2, 2).normalized()));
  move.pretranslate(Eigen::Vector3d(1.3, -0.7, 0.4));
  const Volume result = resample_rigid(source, move, source.geometry, -1000);
  const Eigen::Isometry3d back = move.inverse();
  int inside = 0, outside = 0;
  for (int k = 0; k < 30; ++k)
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i) {
        const Eigen::Vector3d x = source.geometry.world(Eigen::Vector3d(i, j, k));
        const Eigen::Vector3d q = source.geometry.continuous_index(back * x);
        const bool within = (q.array() > 1e-3).all() && (q.array() < Eigen::Array3d(39, 39, 29) - 1e-3).all();
        const bool beyond = (q.array() < -1e-3).any() || (q.array() > Eigen::Array3d(39, 39, 29) + 1e-3).any();
        if (within) {
          ++inside;
          ASSERT_NEAR(result.at(i, j, k), gradient.dot(back * x), 0.5 + 1e-9) << i << "," << j << "," << k;
        } else if (beyond) {
          ++outside;
          ASSERT_EQ(result.at(i, j, k), -1000);
        }
      }
  EXPECT_GT(inside, 20000);
  EXPECT_GT(outside, 1000);
}

TEST(VolumeResample, LabelsFollowAQuarterTurnExactly) {
  LabelVolume source;
  source.geometry.size = {9, 9, 4};
  source.labels.resize(size_t(source.geometry.voxel_count()));
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i) source.labels[size_t(source.geometry.index(i, j, k))] = uint8_t(i + 9 * j + k);
  // A quarter turn about z through the centre (4, 4): (x, y) -> (8 - y, x) in voxel units, so
  // result(i, j) = source(j, 8 - i).
  const Eigen::Vector3d centre(4, 4, 0);
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.translate(centre).rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())).translate(-centre);
  const LabelVolume result = resample_rigid(source, turn, source.geometry);
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 9; ++j)
      for (int i = 0; i < 9; ++i)
        ASSERT_EQ(result.labels[size_t(source.geometry.index(i, j, k))],
                  source.labels[size_t(source.geometry.index(j, 8 - i, k))]);
  // A shift by 3 voxels along x leaves background where nothing maps.
  Eigen::Isometry3d shift = Eigen::Isometry3d::Identity();
  shift.translation() = Eigen::Vector3d(3, 0, 0);
  const LabelVolume shifted = resample_rigid(source, shift, source.geometry);
  EXPECT_EQ(shifted.labels[size_t(source.geometry.index(2, 5, 1))], 0);
  EXPECT_EQ(shifted.labels[size_t(source.geometry.index(7, 5, 1))],
            source.labels[size_t(source.geometry.index(4, 5, 1))]);
}

}  // namespace
}  // namespace maxillo
