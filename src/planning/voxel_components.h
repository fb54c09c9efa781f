#pragma once
// Connected components of a binary voxel mask (6-connectivity: faces only, so two regions that
// touch along an edge or a corner, like bone across a saw cut one voxel wide, stay apart).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace maxillo::planning {

struct VoxelComponents {
  std::vector<int32_t> id;  // per voxel: 0 = outside the mask, else 1..count
  int32_t count = 0;
  std::vector<int64_t> sizes;  // sizes[c] = voxels of component c (sizes[0] = 0)
};

// `mask` is x-fastest over `size` voxels (core/volume.h order); non-zero = inside.
VoxelComponents voxel_components(const std::vector<uint8_t>& mask, const Eigen::Vector3i& size);

}  // namespace maxillo::planning
