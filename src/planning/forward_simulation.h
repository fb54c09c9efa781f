#pragma once
// Forward simulation of a distraction: move the maxilla as the two distractors move it and
// compare the result with the target move at chosen landmarks (ANS, PNS, U1).
//
// What the distractors decide: each moves its entry point by activation x axis. Two points fix
// a rigid move up to a turn about the line through them, which runs transversely through the
// two sinuses: so the devices fix advancement, vertical and lateral translation, roll, yaw and
// (with a midline split) the widening, but not the pitch. The pitch is what the source saw
// drift: a clockwise rotation during distraction (ch. 4b). The simulation therefore takes the
// pitch as planned minus the expected clockwise drift, and solves the six other values (and the
// widening) so that the simulated entry points land where the distractors put them
// (Gauss-Newton on the 6 x 6 system, to 1e-9 mm).
//
// Points within 1 mm of the mid-sagittal plane (ANS, PNS) move with the common move; the others
// with their half (U1, the right central incisor, with the right half).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "ceph/landmark.h"
#include "planning/distraction_vectors.h"

namespace maxillo::planning {

struct SimulatedPoint {
  std::string label;
  Eigen::Vector3d before = Eigen::Vector3d::Zero();
  Eigen::Vector3d target = Eigen::Vector3d::Zero();     // where the plan wants it
  Eigen::Vector3d simulated = Eigen::Vector3d::Zero();  // where the distractors take it
  double error_mm = 0;
};

struct ForwardSimulation {
  FrameMove achieved;  // the common move the distractors make (frame values about the pivot)
  double achieved_widening_mm = 0;
  std::vector<SimulatedPoint> points;
  double max_error_mm = 0;
};

// `points`: the landmarks to compare (e.g. ANS, PNS, U1; those absent are skipped).
ForwardSimulation simulate_distraction(const PlanningFrame& frame, const MaxillaryTarget& target,
                                       const MaxillaryReference& ref, const DistractionVectors& vectors,
                                       const LandmarkSet& points, double expected_clockwise_rotation_deg = 0);

}  // namespace maxillo::planning
