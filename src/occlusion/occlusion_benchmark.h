#pragma once
// Pieces of the occlusion benchmark (issue 6 item 9): arches scanned in natural occlusion are
// displaced to random starting poses and the guided alignment must bring the upper arch back.
// All poses map upper file coordinates to lower file coordinates (mm).
#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "occlusion/guided_alignment.h"

namespace maxillo::occlusion {

// `count` spring pairs where the arches touch at `pose`: upper vertices within max_gap_mm of the
// lower surface, spread by farthest-point sampling (deterministic, starting from the contact
// farthest from the contacts' centroid); each lower point is the nearest lower surface point.
// Fewer pairs are returned when fewer contacts exist.
std::vector<SpringPair> contact_spring_pairs(const DistanceField& upper, const DistanceField& lower,
                                             const Eigen::Isometry3d& pose, int count, double max_gap_mm);

// Upper vertices within region_mm of the lower arch at `pose`: the region of interest around the
// occlusal plane where poses are compared (thesis ch. 7, Fig. 6a).
std::vector<int> occlusal_region(const DistanceField& upper, const DistanceField& lower, const Eigen::Isometry3d& pose,
                                 double region_mm);

// |a * v - b * v| for the given upper vertices.
std::vector<double> vertex_displacements(const TriangleMesh& upper, const std::vector<int>& vertices,
                                         const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

// Linear-interpolated percentile (0..100) of the values; 0 for none.
double percentile(std::vector<double> values, double percent);

// A rigid motion about `centre`: a rotation by an angle uniform in [0, max_deg] about a uniformly
// random axis, then a translation uniform in the ball of radius max_mm.
Eigen::Isometry3d random_displacement(std::mt19937& rng, const Eigen::Vector3d& centre, double max_mm, double max_deg);

// Moves the upper arch along z (superior in LPS, away from the lower arch) until its penetration
// of the lower arch is just at or below target_penetration_mm (bisection to 0.01 mm), as a user
// brings the casts into contact before starting. Returns the placed pose.
Eigen::Isometry3d place_in_contact(const DistanceField& upper, const DistanceField& lower,
                                   const Eigen::Isometry3d& pose, double target_penetration_mm);

}  // namespace maxillo::occlusion
