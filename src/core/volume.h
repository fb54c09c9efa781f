#pragma once
// A CT volume in Hounsfield units on a regular grid placed in the DICOM patient frame (LPS:
// x towards the patient's left, y posterior, z superior; millimetres).
//
// Voxel (i, j, k) lies at  origin + direction * (spacing .* (i, j, k)),
// where direction's columns are the unit vectors of the i, j and k axes in LPS.
// Storage is x-fastest: index = i + size.x * (j + size.y * k).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace maxillo {

struct VolumeGeometry {
  Eigen::Vector3i size{0, 0, 0};                            // voxels along i, j, k
  Eigen::Vector3d spacing{1, 1, 1};                         // mm between voxel centres
  Eigen::Vector3d origin{0, 0, 0};                          // LPS position of voxel (0,0,0), mm
  Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();  // columns: i, j, k axes in LPS

  int64_t voxel_count() const { return int64_t(size.x()) * size.y() * size.z(); }
  int64_t index(int i, int j, int k) const { return i + int64_t(size.x()) * (j + int64_t(size.y()) * k); }
  Eigen::Vector3d world(const Eigen::Vector3d& ijk) const { return origin + direction * spacing.cwiseProduct(ijk); }
  // Continuous voxel coordinates of an LPS point (inverse of world()).
  Eigen::Vector3d continuous_index(const Eigen::Vector3d& lps) const {
    return (direction.transpose() * (lps - origin)).cwiseQuotient(spacing);
  }
  bool contains(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < size.x() && j < size.y() && k < size.z();
  }
};

// Hounsfield units, rescale slope and intercept already applied.
struct Volume {
  VolumeGeometry geometry;
  std::vector<int16_t> hu;  // geometry.voxel_count() values

  int16_t at(int i, int j, int k) const { return hu[geometry.index(i, j, k)]; }
  int16_t& at(int i, int j, int k) { return hu[geometry.index(i, j, k)]; }
};

// A label per voxel on the same grid as a Volume (0 = background).
struct LabelVolume {
  VolumeGeometry geometry;
  std::vector<uint8_t> labels;
};

}  // namespace maxillo
