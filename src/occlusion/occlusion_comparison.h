#pragma once
// Comparing two occlusions (issue 6 item 5, thesis ch. 7 Table 1): the same upper arch placed by
// two poses against the fixed lower arch. The distance map is, per upper vertex of the region
// of interest around the occlusal plane, how far that vertex lies between the two poses; its
// median, P90 and P95 are the source's statistics (intra-observer P95 0.76 mm).
// Poses map upper file coordinates to lower file coordinates (mm).
#include <Eigen/Geometry>
#include <vector>

#include "geometry/signed_distance.h"

namespace maxillo::occlusion {

struct DistanceStatistics {
  int count = 0;  // values summarised
  double median_mm = 0, p90_mm = 0, p95_mm = 0, max_mm = 0;
};

struct OcclusionComparison {
  std::vector<int> region;          // upper vertices of the region of interest
  std::vector<double> distance_mm;  // per region vertex: |pose_b * v - pose_a * v|
  DistanceStatistics statistics;
};

// Median, P90, P95 and maximum (linear-interpolated percentiles); zeros for no values.
DistanceStatistics summarise_distances(const std::vector<double>& distances_mm);

// The comparison over an already chosen region (the benchmark picks it once).
OcclusionComparison compare_poses(const TriangleMesh& upper, const std::vector<int>& region,
                                  const Eigen::Isometry3d& pose_a, const Eigen::Isometry3d& pose_b);

// The region of interest is the upper vertices within roi_mm of the lower arch at pose_a (the
// reference occlusion): the occlusal surfaces, not the gingiva or the roots far from the plane.
OcclusionComparison compare_occlusions(const DistanceField& upper, const DistanceField& lower,
                                       const Eigen::Isometry3d& pose_a, const Eigen::Isometry3d& pose_b, double roi_mm);

}  // namespace maxillo::occlusion
