#pragma once
// A scan of the same head lying otherwise in the scanner: the volume's voxels unchanged, its
// geometry (direction and origin) moved by a rigid pose. Detectors must move their answers with it.
#include <Eigen/Geometry>

#include "core/volume.h"

namespace maxillo::testing {

inline Volume posed(Volume ct, const Eigen::Isometry3d& pose) {
  ct.geometry.direction = pose.linear() * ct.geometry.direction;
  ct.geometry.origin = pose * ct.geometry.origin;
  return ct;
}

}  // namespace maxillo::testing
