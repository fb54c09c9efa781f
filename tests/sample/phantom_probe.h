#pragma once
// Shared phantoms for the sample tests (generated once per test program) and small probes
// that read labels at LPS points.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "sample/phantom.h"

namespace maxillo::test {

// The default phantom (Class I, 1 mm, noise and blur on), generated once.
inline const Phantom& default_phantom() {
  static const Phantom phantom = make_phantom(PhantomSpec{});
  return phantom;
}

// Same anatomy without noise or blur: HU are exact material values.
inline const Phantom& clean_phantom() {
  static const Phantom phantom = [] {
    PhantomSpec spec;
    spec.noise_sigma_hu = 0;
    spec.partial_volume = PartialVolume::Sharp;
    return make_phantom(spec);
  }();
  return phantom;
}

inline Eigen::Vector3d landmark(const Phantom& phantom, const std::string& label) {
  auto p = find_landmark(phantom.landmarks, label);
  EXPECT_TRUE(p.has_value()) << "landmark " << label << " missing";
  return p.value_or(Eigen::Vector3d::Zero());
}

inline Eigen::Vector3i nearest_voxel(const VolumeGeometry& g, const Eigen::Vector3d& lps) {
  Eigen::Vector3d c = g.continuous_index(lps);
  return {int(std::lround(c.x())), int(std::lround(c.y())), int(std::lround(c.z()))};
}

inline Tissue tissue_at(const Phantom& phantom, const Eigen::Vector3d& lps) {
  const auto& g = phantom.labels.geometry;
  Eigen::Vector3i v = nearest_voxel(g, lps);
  if (!g.contains(v.x(), v.y(), v.z())) return Tissue::kAir;
  return Tissue(phantom.labels.labels[g.index(v.x(), v.y(), v.z())]);
}

// Labels of the voxels within `radius` voxels (cube) of the voxel nearest to p.
inline std::set<Tissue> tissues_near(const Phantom& phantom, const Eigen::Vector3d& lps, int radius = 1) {
  const auto& g = phantom.labels.geometry;
  Eigen::Vector3i c = nearest_voxel(g, lps);
  std::set<Tissue> found;
  for (int dk = -radius; dk <= radius; ++dk)
    for (int dj = -radius; dj <= radius; ++dj)
      for (int di = -radius; di <= radius; ++di)
        if (g.contains(c.x() + di, c.y() + dj, c.z() + dk))
          found.insert(Tissue(phantom.labels.labels[g.index(c.x() + di, c.y() + dj, c.z() + dk)]));
  return found;
}

inline bool near(const Phantom& phantom, const Eigen::Vector3d& lps, Tissue tissue, int radius = 1) {
  return tissues_near(phantom, lps, radius).count(tissue) > 0;
}

// Directions in LPS.
inline const Eigen::Vector3d kAnterior{0, -1, 0};
inline const Eigen::Vector3d kPosterior{0, 1, 0};
inline const Eigen::Vector3d kSuperior{0, 0, 1};
inline const Eigen::Vector3d kInferior{0, 0, -1};

// Distance (mm) from p along direction until the first voxel of `tissue` (up to max_mm).
inline double distance_to(const Phantom& phantom, const Eigen::Vector3d& p, const Eigen::Vector3d& direction,
                          Tissue tissue, double max_mm = 60) {
  for (double t = 0; t <= max_mm; t += 0.1)
    if (tissue_at(phantom, p + t * direction) == tissue) return t;
  return INFINITY;
}

}  // namespace maxillo::test
