// The cone-beam cupping (imaging/cupping_correction.h) measured on a soft-tissue cylinder
// whose loss towards the axis is known, and undone; a scan without it left alone; and the
// cone-beam phantom's soft tissue made level across its field.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "imaging/cupping_correction.h"
#include "imaging/grey_calibration.h"
#include "sample/phantom.h"
#include "sample/phantom_variation.h"

namespace maxillo {
namespace {

constexpr double kAir = 200, kSoft = 1000;  // grey values of air and of soft tissue at the rim

// A cylinder of soft tissue (radius 70 mm) in air, 1 mm voxels, whose level above air is
// multiplied by 1 - depth (1 - r^2 / 70^2): the phantom's and a scanner's parabolic loss.
Volume cupped_cylinder(double depth) {
  Volume v;
  v.geometry.size = {161, 161, 12};
  v.geometry.spacing.setConstant(1.0);
  v.hu.assign(size_t(v.geometry.voxel_count()), int16_t(kAir));
  std::mt19937 noise(7);
  std::normal_distribution<double> sigma(0, 15);
  for (int k = 0; k < v.geometry.size.z(); ++k)
    for (int j = 0; j < v.geometry.size.y(); ++j)
      for (int i = 0; i < v.geometry.size.x(); ++i) {
        const double r = std::hypot(i - 80, j - 80);
        if (r > 70) continue;
        const double loss = 1 - depth * (1 - r * r / (70 * 70));
        v.at(i, j, k) = int16_t(std::lround(kAir + (kSoft - kAir) * loss + sigma(noise)));
      }
  return v;
}

double mean_in_ring(const Volume& v, double r0, double r1) {
  double sum = 0;
  int n = 0;
  for (int j = 0; j < v.geometry.size.y(); ++j)
    for (int i = 0; i < v.geometry.size.x(); ++i) {
      const double r = std::hypot(i - 80, j - 80);
      if (r < r0 || r >= r1) continue;
      sum += v.at(i, j, 5);
      ++n;
    }
  return sum / n;
}

TEST(CuppingCorrection, AKnownParabolicLossIsMeasuredAndUndone) {
  const Volume scan = cupped_cylinder(0.15);
  GreyCalibration grey;
  grey.air = kAir, grey.soft_tissue = 0.9 * kSoft, grey.from_histogram = true;
  const RadialCupping cupping = estimate_cupping(scan, grey);
  ASSERT_TRUE(cupping.significant());
  // The rim's ring ends 2.5 mm inside the cylinder, where the loss is 0.15 (1 - 67.5^2/70^2) = 1 %.
  EXPECT_NEAR(cupping.depth(), 0.14, 0.015);
  const Volume level = without_cupping(scan, grey, cupping);
  const double axis = mean_in_ring(level, 0, 10), rim = mean_in_ring(level, 55, 65);
  EXPECT_NEAR((axis - kAir) / (rim - kAir), 1.0, 0.02);
  // Before: 11.5 % apart (0.85 against 0.96).
  EXPECT_LT((mean_in_ring(scan, 0, 10) - kAir) / (mean_in_ring(scan, 55, 65) - kAir), 0.9);
}

TEST(CuppingCorrection, AScanWithoutLossIsNotCorrected) {
  const Volume scan = cupped_cylinder(0);
  GreyCalibration grey;
  grey.air = kAir, grey.soft_tissue = kSoft, grey.from_histogram = true;
  EXPECT_FALSE(estimate_cupping(scan, grey).significant());
}

TEST(CuppingCorrection, TheConeBeamPhantomsSoftTissueReadsTheSameAtItsRim) {
  PhantomSpec spec = varied_phantom_spec("CBCT-1", ScannerKind::kConeBeam, 1.0);
  spec.cone_beam->cupping = 0.2;  // the flavour's strongest
  const Phantom scan = make_phantom(spec);
  const GreyCalibration grey = estimate_grey_calibration(scan.ct);
  const RadialCupping cupping = estimate_cupping(scan.ct, grey);
  ASSERT_TRUE(cupping.significant()) << spec.cone_beam->cupping;
  EXPECT_GT(cupping.depth(), 0.7 * spec.cone_beam->cupping);
  EXPECT_LT(cupping.depth(), 1.1 * spec.cone_beam->cupping);
  // Soft tissue near the axis (the brain, the tongue) and near the rim (inside the field's
  // 76 mm), read through the calibration: apart before, closer after (its estimate done again).
  const Volume level = without_cupping(scan.ct, grey, cupping);
  const GreyCalibration after = estimate_grey_calibration(level);
  // Soft tissue 3 voxels from any other tissue: no partial volume with the air at the skin.
  auto deep_in_soft_tissue = [&](int i, int j, int k) {
    const auto& geo = scan.labels.geometry;
    for (int d = -3; d <= 3; d += 6)
      for (const Eigen::Vector3i& n : {Eigen::Vector3i(i + d, j, k), Eigen::Vector3i(i, j + d, k),
                                       Eigen::Vector3i(i, j, k + d), Eigen::Vector3i(i, j, k)}) {
        if ((n.array() < 0).any() || (n.array() >= geo.size.array()).any()) return false;
        if (scan.labels.labels[size_t(geo.index(n.x(), n.y(), n.z()))] != uint8_t(Tissue::kSoftTissue)) return false;
      }
    return true;
  };
  auto soft_tissue_hu = [&](const Volume& v, const GreyCalibration& g, double r0, double r1) {
    const auto& geo = v.geometry;
    double sum = 0;
    int64_t n = 0;
    for (int k = 0; k < geo.size.z(); k += 2)
      for (int j = 0; j < geo.size.y(); j += 2)
        for (int i = 0; i < geo.size.x(); i += 2) {
          const double r = std::hypot(i - (geo.size.x() - 1) / 2.0, j - (geo.size.y() - 1) / 2.0) * geo.spacing.x();
          if (r < r0 || r >= r1 || !deep_in_soft_tissue(i, j, k)) continue;
          sum += g.to_hu(v.at(i, j, k));
          ++n;
        }
    return sum / double(n);
  };
  const double before_gap = soft_tissue_hu(scan.ct, grey, 50, 65) - soft_tissue_hu(scan.ct, grey, 0, 20);
  const double after_gap = soft_tissue_hu(level, after, 50, 65) - soft_tissue_hu(level, after, 0, 20);
  std::cout << "soft tissue, rim less axis: " << before_gap << " HU before, " << after_gap << " HU after\n";
  EXPECT_GT(before_gap, 100);
  EXPECT_LT(std::abs(after_gap), before_gap / 3);
}

}  // namespace
}  // namespace maxillo
