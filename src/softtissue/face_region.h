#pragma once
// The part of the soft tissue that a bone move deforms, as a voxel mask: the soft tissue
// voxels on the kept side of every cut plane (by default, set up by the caller from landmarks:
// below the orbits, above a plane under the chin, in front of the ears). Tissue beyond the cut
// planes is not modelled; the model's nodes on those planes are held fixed.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/volume.h"

namespace maxillo::softtissue {

// A cut plane of the region: `point` on it, unit `normal` pointing into the kept side.
struct RegionPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double side(const Eigen::Vector3d& p) const { return normal.dot(p - point); }  // > 0: kept
};

// 1 where `tissues` holds one of `soft_labels` and the voxel centre is on the kept side of
// every plane, 0 elsewhere. Same geometry as `tissues`.
LabelVolume face_region(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels,
                        const std::vector<RegionPlane>& planes);

}  // namespace maxillo::softtissue
