#pragma once
// A small synthetic "head" for registration tests: an ellipsoid of soft tissue with a bone shell
// and asymmetric inner structures (a dense rod, a soft lump, an air pocket, a vertical gradient),
// so that no rotation or translation maps it onto itself. 2 mm voxels, centred on the origin.
#include <Eigen/Geometry>
#include <cmath>

#include "core/volume.h"

namespace maxillo::testing {

inline double synthetic_head_hu(const Eigen::Vector3d& p) {
  const Eigen::Vector3d semi(60, 72, 84);
  const double r = p.cwiseQuotient(semi).norm();  // 1 on the skin
  if (r > 1) return -1000;
  if ((p - Eigen::Vector3d(-22, -30, -12)).norm() < 12) return -900;                                // air pocket
  if (Eigen::Vector2d(p.y() + 45, p.z() + 30).norm() < 7 && std::abs(p.x() - 8) < 30) return 1600;  // rod
  if ((p - Eigen::Vector3d(25, -20, 35)).norm() < 14) return 250;                                   // lump
  if (r > 0.82 && r < 0.92) return 900;                                                             // bone shell
  return 20 + 0.4 * p.z() + 0.2 * p.x();  // tissue with a gradient
}

inline Volume synthetic_head(const Eigen::Vector3i& size = {72, 84, 96}, double spacing = 2) {
  Volume v;
  v.geometry.size = size;
  v.geometry.spacing = Eigen::Vector3d::Constant(spacing);
  v.geometry.origin = -0.5 * spacing * (size.cast<double>() - Eigen::Vector3d::Ones());
  v.hu.resize(size_t(v.geometry.voxel_count()));
  for (int k = 0; k < size.z(); ++k)
    for (int j = 0; j < size.y(); ++j)
      for (int i = 0; i < size.x(); ++i)
        v.at(i, j, k) = int16_t(std::lround(synthetic_head_hu(v.geometry.world(Eigen::Vector3d(i, j, k)))));
  return v;
}

// A rigid move of `degrees` about an oblique axis through `centre`, then `shift` mm.
inline Eigen::Isometry3d oblique_move(double degrees, const Eigen::Vector3d& shift,
                                      const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.translate(centre + shift).rotate(Eigen::AngleAxisd(degrees * M_PI / 180, Eigen::Vector3d(-2, 1, 3).normalized()));
  m.translate(-centre);
  return m;
}

// RMS of |estimate(truth_fixed_to_moving(p)) - p| over the corners of a cube of half-side `half` mm.
inline double corner_rms(const Eigen::Isometry3d& moving_to_fixed, const Eigen::Isometry3d& fixed_to_moving,
                         double half = 50) {
  double sum = 0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d p((c & 1) ? half : -half, (c & 2) ? half : -half, (c & 4) ? half : -half);
    sum += (moving_to_fixed * (fixed_to_moving * p) - p).squaredNorm();
  }
  return std::sqrt(sum / 8);
}

}  // namespace maxillo::testing
