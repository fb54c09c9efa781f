#include "occlusion/occlusion_comparison.h"

#include <algorithm>

#include "occlusion/occlusion_benchmark.h"

namespace maxillo::occlusion {

DistanceStatistics summarise_distances(const std::vector<double>& distances_mm) {
  DistanceStatistics s;
  s.count = int(distances_mm.size());
  if (distances_mm.empty()) return s;
  s.median_mm = percentile(distances_mm, 50);
  s.p90_mm = percentile(distances_mm, 90);
  s.p95_mm = percentile(distances_mm, 95);
  s.max_mm = *std::max_element(distances_mm.begin(), distances_mm.end());
  return s;
}

OcclusionComparison compare_poses(const TriangleMesh& upper, const std::vector<int>& region,
                                  const Eigen::Isometry3d& pose_a, const Eigen::Isometry3d& pose_b) {
  OcclusionComparison c;
  c.region = region;
  c.distance_mm = vertex_displacements(upper, region, pose_b, pose_a);
  c.statistics = summarise_distances(c.distance_mm);
  return c;
}

OcclusionComparison compare_occlusions(const DistanceField& upper, const DistanceField& lower,
                                       const Eigen::Isometry3d& pose_a, const Eigen::Isometry3d& pose_b,
                                       double roi_mm) {
  return compare_poses(upper.mesh(), occlusal_region(upper, lower, pose_a, roi_mm), pose_a, pose_b);
}

}  // namespace maxillo::occlusion
