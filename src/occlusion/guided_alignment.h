#pragma once
// Guided movement (thesis ch. 7): corresponding point pairs act as springs pulling the upper
// arch towards the lower one; contacts push back. Each iteration solves a constrained
// Gauss-Newton step on the 6-dof pose (spring energy, with the contacts within the band
// linearised as constraints "gap >= -allowed penetration" enforced by an active-set penalty),
// limited to a trust region, then halves the step until the engine accepts the pose (never an
// interpenetrating one). Stops when the step stalls; if a spring is then still longer than
// 0.15 mm (a cusp holds the arch on a slope), the arch is lifted 0.25, 0.5 or 1 mm and closed
// again, keeping only a result with shorter springs. Deterministic.
#include <Eigen/Geometry>
#include <vector>

#include "occlusion/motion_engine.h"

namespace maxillo::occlusion {

struct SpringPair {
  Eigen::Vector3d upper;  // upper file coordinates, mm (moves with the arch)
  Eigen::Vector3d lower;  // lower file coordinates, mm
};

enum class AlignmentStatus {
  Converged,       // the step became negligible
  IterationLimit,  // still moving after max_iterations
};

struct AlignmentResult {
  AlignmentStatus status = AlignmentStatus::Converged;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // upper -> lower frame
  int iterations = 0;
  double lift_mm = 0;                      // SeparateAlignClose: the lift used (0: none)
  std::vector<double> residual_spring_mm;  // |pose * upper - lower| per pair
  double penetration_mm = 0;               // at the final pose
};

enum class Approach {
  // Springs act from the start pose. Cusps met on the way can hold the arch in a wrong
  // interlocking (a local minimum), as they would hold a plaster cast.
  Direct,
  // When the start is more than 0.5 mm from the springs' best fit: lift the upper arch away from
  // the lower one (2, 4, 8 or 16 mm, along the line between the arches' centroids), carry it over
  // the best-fit pose, both as checked free-hand steps, then let the springs close it from there.
  // What a user does with the free-hand tool before the guided one (thesis ch. 7).
  SeparateAlignClose,
};

// Needs at least three pairs (asserted). Moves `engine` to the final pose.
AlignmentResult align_guided(MotionEngine& engine, const std::vector<SpringPair>& pairs,
                             Approach approach = Approach::SeparateAlignClose);

// The rigid transform minimising the spring energy alone (Kabsch), for the unconstrained case.
Eigen::Isometry3d best_fit_transform(const std::vector<SpringPair>& pairs);

}  // namespace maxillo::occlusion
