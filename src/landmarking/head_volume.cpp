#include "landmarking/head_volume.h"

#include <cmath>

#include "core/parallel_slabs.h"
#include "core/volume_resample.h"

namespace maxillo::landmarking {
namespace {

constexpr int16_t kOutside = std::numeric_limits<int16_t>::min();  // marks points outside the scan

// Trilinear weights of a continuous index along one axis, clamped to the grid.
struct AxisWeight {
  int base;
  double weight;
};

}  // namespace

HeadVolume::HeadVolume(const Volume& ct, const GreyCalibration& grey, const Eigen::Isometry3d& frame_to_lps,
                       const FrameBox& box, double spacing_mm)
    : frame_to_lps_(frame_to_lps), box_(box), spacing_(spacing_mm), scan_voxel_mm_(ct.geometry.spacing.maxCoeff()) {
  VolumeGeometry g;
  g.spacing = Eigen::Vector3d::Constant(spacing_mm);
  g.origin = box.lo;
  for (int a = 0; a < 3; ++a) g.size[a] = std::max(2, int(std::floor((box.hi[a] - box.lo[a]) / spacing_mm)) + 1);
  volume_ = resample_rigid(ct, frame_to_lps.inverse(), g, kOutside);
  scanned_.assign(volume_.hu.size(), 1);
  for_each_slab(0, g.size.z(), [&](int first, int last) {
    const size_t begin = size_t(g.index(0, 0, first)), end = size_t(g.index(0, 0, last));
    for (size_t i = begin; i < end; ++i) {
      int16_t& v = volume_.hu[i];
      // The scanner's padding (a cone-beam scan's corners outside its cylinder) was not scanned
      // either; it keeps its value, which reads as air.
      if (grey.padding && v == *grey.padding) scanned_[i] = 0;
      if (v == kOutside) {
        scanned_[i] = 0;
        v = -1000;
      } else {
        v = int16_t(std::lround(std::clamp(grey.to_hu(v), -1024.0, 30000.0)));
      }
    }
  });
}

double HeadVolume::hu(const Eigen::Vector3d& p) const {
  const auto& g = volume_.geometry;
  AxisWeight w[3];
  for (int a = 0; a < 3; ++a) {
    const double index = (p[a] - g.origin[a]) / spacing_;
    if (index < 0 || index > g.size[a] - 1) return -1000;
    w[a].base = std::min(int(index), g.size[a] - 2);
    w[a].weight = index - w[a].base;
  }
  double value = 0;
  for (int corner = 0; corner < 8; ++corner) {
    double weight = 1;
    int at[3];
    for (int a = 0; a < 3; ++a) {
      const bool upper = (corner >> a) & 1;
      at[a] = w[a].base + (upper ? 1 : 0);
      weight *= upper ? w[a].weight : 1 - w[a].weight;
    }
    if (weight != 0) value += weight * volume_.hu[size_t(g.index(at[0], at[1], at[2]))];
  }
  return value;
}

bool HeadVolume::scanned(const Eigen::Vector3d& p) const {
  const auto& g = volume_.geometry;
  int at[3];
  for (int a = 0; a < 3; ++a) {
    at[a] = int(std::lround((p[a] - g.origin[a]) / spacing_));
    if (at[a] < 0 || at[a] >= g.size[a]) return false;
  }
  return scanned_[size_t(g.index(at[0], at[1], at[2]))] != 0;
}

}  // namespace maxillo::landmarking
