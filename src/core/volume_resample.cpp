// Rigid resampling (see volume_resample.h). Each result voxel is mapped back into the source's
// continuous voxel coordinates by one affine map (result ijk -> source ijk), computed once, so
// the inner loop is a matrix-vector step and an interpolation.
#include "core/volume_resample.h"

#include <algorithm>
#include <cmath>

namespace maxillo {
namespace {

// result voxel index (i, j, k) -> continuous source voxel index, as one affine map.
Eigen::Affine3d result_to_source_index(const VolumeGeometry& source, const Eigen::Isometry3d& source_to_result,
                                       const VolumeGeometry& result) {
  Eigen::Affine3d result_index_to_world = Eigen::Affine3d::Identity();
  result_index_to_world.linear() = result.direction * result.spacing.asDiagonal();
  result_index_to_world.translation() = result.origin;
  Eigen::Affine3d world_to_source_index = Eigen::Affine3d::Identity();
  world_to_source_index.linear() = source.spacing.cwiseInverse().asDiagonal() * source.direction.transpose();
  world_to_source_index.translation() = -world_to_source_index.linear() * source.origin;
  return world_to_source_index * Eigen::Affine3d(source_to_result.inverse()) * result_index_to_world;
}

// Trilinear value at continuous index q, or nullopt-like `outside` when q is not within the
// source's voxel centres (a tolerance of 1e-6 voxel keeps exact grid points on the border inside).
double trilinear(const Volume& source, const Eigen::Vector3d& q, bool* inside) {
  const Eigen::Vector3i& n = source.geometry.size;
  constexpr double kEps = 1e-6;
  for (int a = 0; a < 3; ++a)
    if (q[a] < -kEps || q[a] > n[a] - 1 + kEps) {
      *inside = false;
      return 0;
    }
  *inside = true;
  int base[3];
  double frac[3];
  for (int a = 0; a < 3; ++a) {
    const double clamped = std::clamp(q[a], 0.0, double(n[a] - 1));
    base[a] = std::min(int(std::floor(clamped)), std::max(0, n[a] - 2));
    frac[a] = clamped - base[a];
    if (n[a] == 1) frac[a] = 0;
  }
  const int step_i = n.x() > 1 ? 1 : 0;
  const int64_t step_j = n.y() > 1 ? n.x() : 0;
  const int64_t step_k = n.z() > 1 ? int64_t(n.x()) * n.y() : 0;
  const int16_t* p = source.hu.data() + source.geometry.index(base[0], base[1], base[2]);
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  const double c00 = lerp(p[0], p[step_i], frac[0]);
  const double c10 = lerp(p[step_j], p[step_j + step_i], frac[0]);
  const double c01 = lerp(p[step_k], p[step_k + step_i], frac[0]);
  const double c11 = lerp(p[step_k + step_j], p[step_k + step_j + step_i], frac[0]);
  return lerp(lerp(c00, c10, frac[1]), lerp(c01, c11, frac[1]), frac[2]);
}

}  // namespace

Volume resample_rigid(const Volume& source, const Eigen::Isometry3d& source_to_result,
                      const VolumeGeometry& result_geometry, int16_t outside_hu) {
  Volume result;
  result.geometry = result_geometry;
  result.hu.assign(size_t(result_geometry.voxel_count()), outside_hu);
  const Eigen::Affine3d to_source = result_to_source_index(source.geometry, source_to_result, result_geometry);
  const Eigen::Vector3i& n = result_geometry.size;
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j) {
      // Along a row the source index advances by a constant step: no matrix product per voxel.
      Eigen::Vector3d q = to_source * Eigen::Vector3d(0, j, k);
      const Eigen::Vector3d step = to_source.linear().col(0);
      int16_t* out = result.hu.data() + result_geometry.index(0, j, k);
      for (int i = 0; i < n.x(); ++i, q += step) {
        bool inside = false;
        const double value = trilinear(source, q, &inside);
        if (inside) out[i] = int16_t(std::clamp(std::lround(value), -32768L, 32767L));
      }
    }
  return result;
}

double sample_trilinear(const Volume& source, const Eigen::Vector3d& lps, double outside_hu) {
  bool inside = false;
  const double value = trilinear(source, source.geometry.continuous_index(lps), &inside);
  return inside ? value : outside_hu;
}

uint8_t sample_nearest(const LabelVolume& source, const Eigen::Vector3d& lps) {
  const Eigen::Vector3i nearest = source.geometry.continuous_index(lps).array().round().cast<int>();
  if (!source.geometry.contains(nearest.x(), nearest.y(), nearest.z())) return 0;
  return source.labels[size_t(source.geometry.index(nearest.x(), nearest.y(), nearest.z()))];
}

LabelVolume resample_rigid(const LabelVolume& source, const Eigen::Isometry3d& source_to_result,
                           const VolumeGeometry& result_geometry) {
  LabelVolume result;
  result.geometry = result_geometry;
  result.labels.assign(size_t(result_geometry.voxel_count()), 0);
  const Eigen::Affine3d to_source = result_to_source_index(source.geometry, source_to_result, result_geometry);
  const Eigen::Vector3i& n = result_geometry.size;
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        const Eigen::Vector3d q = to_source * Eigen::Vector3d(i, j, k);
        const Eigen::Vector3i nearest = q.array().round().cast<int>();
        if (source.geometry.contains(nearest.x(), nearest.y(), nearest.z()))
          result.labels[size_t(result_geometry.index(i, j, k))] =
              source.labels[size_t(source.geometry.index(nearest.x(), nearest.y(), nearest.z()))];
      }
  return result;
}

}  // namespace maxillo
