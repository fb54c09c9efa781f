#pragma once
// What an intraoral scanner would see of real teeth (issue 30's test and benchmark input): each
// tooth's crown without its root, a collar of gingiva around the crown's neck (surface that lies on
// no tooth, as a scan's gums do not lie on the CT's teeth), noise on every point, and another
// triangulation (each triangle split in four). The crown is the tooth's part within
// `crown_height_mm` of its biting end along its long axis (its widest principal direction); the
// biting end is the one towards `occlusal_side` (a point between the two arches).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/triangle_mesh.h"

namespace maxillo {

struct DentalScanOptions {
  double crown_height_mm = 8.0;
  double collar_width_mm = 2.0;  // how far the gingiva reaches out from the crown's neck
  double noise_mm = 0.02;        // standard deviation of each coordinate's noise
  uint32_t seed = 1;
};

// The crowns of `teeth` (closed, outward-oriented, one mesh per tooth, in one frame) as one open
// scan surface in the same frame.
TriangleMesh simulated_dental_scan(const std::vector<TriangleMesh>& teeth, const Eigen::Vector3d& occlusal_side,
                                   const DentalScanOptions& options = {});

// Each triangle split in four at its edges' midpoints (shared edges share their midpoint).
TriangleMesh split_triangles(const TriangleMesh& mesh);

}  // namespace maxillo
