#pragma once
// The bone surface of a scan sampled on a coarse grid aligned with the patient axes (LPS), as
// the symmetry search needs it: the surface voxels as points and their distance map.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/volume.h"
#include "landmarking/symmetry_plane.h"

namespace maxillo::landmarking {

struct BoneSurface {
  std::vector<Eigen::Vector3d> points;  // LPS mm, surface voxel centres in grid order
  std::unique_ptr<SurfaceDistance> distance;
  Eigen::Vector3d bone_centre{0, 0, 0};  // centroid of the bone voxels, LPS mm
  double bone_cm3 = 0;
  Eigen::Vector3d lo{0, 0, 0}, hi{0, 0, 0};  // the bone's bounding box, LPS mm
};

// Bone = grey value >= `bone_grey`, sampled every `spacing_mm` over the scan's box.
BoneSurface sample_bone_surface(const Volume& ct, double bone_grey, double spacing_mm);

}  // namespace maxillo::landmarking
