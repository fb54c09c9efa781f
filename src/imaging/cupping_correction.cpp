#include "imaging/cupping_correction.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "core/parallel_slabs.h"

namespace maxillo {
namespace {

constexpr double kRingMm = 5;
constexpr int64_t kMinRingSamples = 500;
// The soft-tissue band: from 40 % below to 40 % above soft tissue's level over air (about -380
// to +460 HU): fat, muscle, brain and skin, with room for the loss itself; neither air nor bone.
constexpr double kBandBelow = 0.6, kBandAbove = 1.4;

// The distance (mm) of voxel (i, j) from the grid's centre line.
struct Axis {
  double ci, cj, si, sj;
  double radius(int i, int j) const { return std::hypot((i - ci) * si, (j - cj) * sj); }
};

Axis axis_of(const VolumeGeometry& g) {
  return {(g.size.x() - 1) / 2.0, (g.size.y() - 1) / 2.0, g.spacing.x(), g.spacing.y()};
}

// The median of a ring's histogram of integer values (offset by `low`).
double median_of(const std::vector<int64_t>& counts, int64_t total, int low) {
  int64_t seen = 0;
  for (size_t v = 0; v < counts.size(); ++v)
    if ((seen += counts[v]) * 2 >= total) return low + double(v);
  return low + double(counts.size());
}

}  // namespace

RadialCupping estimate_cupping(const Volume& volume, const GreyCalibration& grey) {
  RadialCupping none;
  const auto& g = volume.geometry;
  const double level = grey.soft_tissue - grey.air;
  if (volume.hu.empty() || level <= 0) return none;
  const int low = int(std::floor(grey.air + kBandBelow * level)), high = int(std::ceil(grey.air + kBandAbove * level));
  const Axis axis = axis_of(g);
  const int rings = int(axis.radius(0, 0) / kRingMm) + 1;
  std::vector<std::vector<int64_t>> counts(size_t(rings), std::vector<int64_t>(size_t(high - low + 1), 0));
  std::vector<int64_t> totals(size_t(rings), 0);
  for (int k = 0; k < g.size.z(); k += 2)
    for (int j = 0; j < g.size.y(); j += 2)
      for (int i = 0; i < g.size.x(); i += 2) {
        const int v = volume.at(i, j, k);
        if (v < low || v > high || (grey.padding && v == *grey.padding)) continue;
        const size_t ring = size_t(axis.radius(i, j) / kRingMm);
        ++counts[ring][size_t(v - low)];
        ++totals[ring];
      }
  // level(r) = a + b r^2, weighted by the rings' samples, fitted to the rings' medians.
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
  double rim = 0;
  for (int ring = 0; ring < rings; ++ring) {
    if (totals[size_t(ring)] < kMinRingSamples) continue;
    const double r = (ring + 0.5) * kRingMm, w = double(totals[size_t(ring)]);
    const double median = median_of(counts[size_t(ring)], totals[size_t(ring)], low) - grey.air;
    const Eigen::Vector2d basis(1, r * r);
    normal += w * basis * basis.transpose();
    rhs += w * median * basis;
    rim = r;
  }
  if (rim == 0 || std::abs(normal.determinant()) < 1e-9 * normal.trace() * normal.trace()) return none;
  const Eigen::Vector2d ab = normal.ldlt().solve(rhs);
  RadialCupping cupping;
  cupping.soft_at_axis = ab[0];
  cupping.soft_at_rim = ab[0] + ab[1] * rim * rim;
  cupping.rim_radius_mm = rim;
  if (!(cupping.soft_at_axis > 0) || !(cupping.soft_at_rim > 0)) return none;
  return cupping;
}

Volume without_cupping(const Volume& volume, const GreyCalibration& grey, const RadialCupping& cupping) {
  Volume corrected = volume;
  const auto& g = volume.geometry;
  const Axis axis = axis_of(g);
  const double b = (cupping.soft_at_rim - cupping.soft_at_axis) / (cupping.rim_radius_mm * cupping.rim_radius_mm);
  // The gain per column (i, j), the same in every slice; beyond the rim it stays at the rim's 1.
  std::vector<double> gain(size_t(g.size.x()) * size_t(g.size.y()));
  for (int j = 0; j < g.size.y(); ++j)
    for (int i = 0; i < g.size.x(); ++i) {
      const double r = std::min(axis.radius(i, j), cupping.rim_radius_mm);
      gain[size_t(j) * size_t(g.size.x()) + size_t(i)] = cupping.soft_at_rim / (cupping.soft_at_axis + b * r * r);
    }
  for_each_slab(0, g.size.z(), [&](int first, int last) {
    for (int k = first; k < last; ++k)
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          int16_t& v = corrected.at(i, j, k);
          if (grey.padding && v == *grey.padding) continue;
          const double scaled = grey.air + (v - grey.air) * gain[size_t(j) * size_t(g.size.x()) + size_t(i)];
          v = int16_t(std::lround(std::clamp(scaled, -32768.0, 32767.0)));
        }
  });
  return corrected;
}

}  // namespace maxillo
