#include "planning/distraction_vectors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "core/error.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

DistractionVector vector_of(const PlanningFrame& frame, const MaxillaryTarget& target, const MaxillaryReference& ref,
                            Side side, const Vector3d& entry) {
  DistractionVector v;
  v.side = side;
  v.entry = entry;
  const Vector3d displacement = half_move(frame, target, ref, side) * entry - entry;
  v.activation_mm = displacement.norm();
  if (v.activation_mm < 1e-9) return v;  // no move: no axis
  Vector3d axis = displacement / v.activation_mm;
  // The source's remedy for the clockwise rotation: tilt the axis anterior-end-up. A positive
  // right-handed rotation about -left turns anterior towards superior.
  axis = Eigen::AngleAxisd(radians(target.counter_rotation_deg), -frame.left) * axis;
  v.axis = axis.normalized();
  const Vector3d f = displacement_in_frame(frame, v.axis);  // (anterior, down, left)
  v.outward_deg = degrees(std::atan2(outward_sign(side) * f.z(), f.x()));
  v.elevation_deg = degrees(std::atan2(-f.y(), std::hypot(f.x(), f.z())));
  return v;
}

}  // namespace

std::string_view side_name(Side side) { return side == Side::Right ? "right" : "left"; }

double midline_yaw_deg(const PlanningFrame& frame, const MaxillaryTarget& target, const MaxillaryReference& ref) {
  if (target.midline_shift_mm == 0) return 0;
  const double lever = (ref.incisor - ref.pivot).dot(frame.anterior);
  if (lever <= std::abs(target.midline_shift_mm))
    throw Error(ErrorCode::kBadValue, "midline_shift_mm",
                "a midline shift of " + std::to_string(target.midline_shift_mm) +
                    " mm cannot be made by turning the maxilla about a pivot " + std::to_string(lever) +
                    " mm behind the incisor");
  // A yaw psi about the pivot moves the incisor sideways by lever * sin(psi); + yaw = to the left.
  return degrees(std::asin(target.midline_shift_mm / lever));
}

Eigen::Isometry3d common_move(const PlanningFrame& frame, const MaxillaryTarget& target,
                              const MaxillaryReference& ref) {
  FrameMove move;
  move.advancement_mm = target.advancement_mm;
  move.vertical_mm = target.vertical_mm;
  move.pitch_deg = target.rotation_deg;
  move.yaw_deg = midline_yaw_deg(frame, target, ref);
  return to_transform(frame, move, ref.pivot);
}

Eigen::Isometry3d half_move(const PlanningFrame& frame, const MaxillaryTarget& target, const MaxillaryReference& ref,
                            Side side) {
  Eigen::Isometry3d widen = Eigen::Isometry3d::Identity();
  widen.translation() = outward_sign(side) * target.widening_mm / 2 * frame.left;
  return widen * common_move(frame, target, ref);
}

DistractionVectors distraction_vectors(const PlanningFrame& frame, const MaxillaryTarget& target,
                                       const MaxillaryReference& ref, const Vector3d& entry_right,
                                       const Vector3d& entry_left) {
  DistractionVectors vectors;
  vectors.right = vector_of(frame, target, ref, Side::Right, entry_right);
  vectors.left = vector_of(frame, target, ref, Side::Left, entry_left);
  const Vector3d& a = vectors.right.axis;
  const Vector3d& b = vectors.left.axis;
  vectors.divergence_deg = vectors.right.outward_deg + vectors.left.outward_deg;
  if (a.norm() > 0 && b.norm() > 0) {
    vectors.angle_deg = degrees(std::acos(std::clamp(a.dot(b), -1.0, 1.0)));
  }
  return vectors;
}

double divergence_for_widening_deg(double advancement_mm, double widening_mm) {
  return 2 * degrees(std::atan2(widening_mm / 2, advancement_mm));
}

}  // namespace maxillo::planning
