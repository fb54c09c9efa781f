#include "planning/forward_simulation.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// The unknowns: advancement, vertical, lateral, roll, yaw (of the common move) and widening.
struct Pose {
  FrameMove move;
  double widening_mm = 0;
};

Pose pose_of(const Vector6d& q, double pitch_deg) {
  Pose pose;
  pose.move.advancement_mm = q[0];
  pose.move.vertical_mm = q[1];
  pose.move.lateral_mm = q[2];
  pose.move.roll_deg = q[3];
  pose.move.yaw_deg = q[4];
  pose.move.pitch_deg = pitch_deg;
  pose.widening_mm = q[5];
  return pose;
}

Vector3d moved(const PlanningFrame& frame, const Pose& pose, const Vector3d& pivot, const Vector3d& p,
               std::optional<Side> half) {
  Vector3d q = to_transform(frame, pose.move, pivot) * p;
  if (half) q += outward_sign(*half) * pose.widening_mm / 2 * frame.left;
  return q;
}

// Which half carries p: none (common move) within 1 mm of the mid-sagittal plane.
std::optional<Side> half_of(const PlanningFrame& frame, const Vector3d& p) {
  const double lateral = (p - frame.origin).dot(frame.left);
  if (std::abs(lateral) < 1) return std::nullopt;
  return lateral > 0 ? Side::Left : Side::Right;
}

Vector6d residual(const PlanningFrame& frame, const Vector6d& q, double pitch_deg, const Vector3d& pivot,
                  const DistractionVectors& vectors) {
  const Pose pose = pose_of(q, pitch_deg);
  Vector6d r;
  for (const DistractionVector* v : {&vectors.right, &vectors.left}) {
    const Vector3d wanted = v->entry + v->activation_mm * v->axis;
    const Vector3d got = moved(frame, pose, pivot, v->entry, v->side);
    r.segment<3>(v->side == Side::Right ? 0 : 3) = got - wanted;
  }
  return r;
}

Vector6d solve_pose(const PlanningFrame& frame, double pitch_deg, const Vector3d& pivot,
                    const DistractionVectors& vectors) {
  Vector6d q = Vector6d::Zero();
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Vector6d r = residual(frame, q, pitch_deg, pivot, vectors);
    if (r.norm() < 1e-9) return q;
    Matrix6d jacobian;
    const double h = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Vector6d dq = q;
      dq[k] += h;
      jacobian.col(k) = (residual(frame, dq, pitch_deg, pivot, vectors) - r) / h;
    }
    q -= jacobian.colPivHouseholderQr().solve(r);
  }
  const double left_over = residual(frame, q, pitch_deg, pivot, vectors).norm();
  if (left_over > 1e-6)
    throw Error(
        ErrorCode::kProcessing, "forward simulation",
        "no rigid move of the maxilla matches both distractors (residual " + std::to_string(left_over) + " mm)");
  return q;
}

}  // namespace

ForwardSimulation simulate_distraction(const PlanningFrame& frame, const MaxillaryTarget& target,
                                       const MaxillaryReference& ref, const DistractionVectors& vectors,
                                       const LandmarkSet& points, double expected_clockwise_rotation_deg) {
  // Clockwise (anterior end down) is negative pitch.
  const double pitch_deg = target.rotation_deg - expected_clockwise_rotation_deg;
  const Vector6d q = solve_pose(frame, pitch_deg, ref.pivot, vectors);
  const Pose pose = pose_of(q, pitch_deg);

  ForwardSimulation result;
  result.achieved = pose.move;
  result.achieved_widening_mm = pose.widening_mm;
  const Eigen::Isometry3d common = common_move(frame, target, ref);
  for (const Landmark& landmark : points) {
    const std::optional<Side> half = half_of(frame, landmark.position);
    SimulatedPoint point;
    point.label = landmark.label;
    point.before = landmark.position;
    point.target = half ? half_move(frame, target, ref, *half) * landmark.position : common * landmark.position;
    point.simulated = moved(frame, pose, ref.pivot, landmark.position, half);
    point.error_mm = (point.simulated - point.target).norm();
    result.max_error_mm = std::max(result.max_error_mm, point.error_mm);
    result.points.push_back(point);
  }
  return result;
}

}  // namespace maxillo::planning
