#include "planning/anatomical_moves.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "ceph/cephalometric_measures.h"
#include "ceph/landmark_frame.h"

namespace maxillo::planning {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Rotation in frame coordinates (x = anterior, y = left, z = superior), see the header.
Matrix3d frame_rotation(const FrameMove& move) {
  using Eigen::AngleAxisd;
  return (AngleAxisd(radians(move.yaw_deg), Vector3d::UnitZ()) *
          AngleAxisd(radians(-move.pitch_deg), Vector3d::UnitY()) *
          AngleAxisd(radians(move.roll_deg), Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

Matrix3d PlanningFrame::basis() const {
  Matrix3d b;
  b.col(0) = anterior;
  b.col(1) = left;
  b.col(2) = superior;
  return b;
}

PlanningFrame planning_frame(const LandmarkSet& landmarks) {
  const AnatomicalFrame frankfort = anatomical_frame(landmarks);
  PlanningFrame frame;
  frame.origin = frankfort.origin;
  frame.anterior = frankfort.anterior;
  frame.left = frankfort.left;
  frame.superior = frankfort.superior;
  frame.source = frankfort.source == FrameSource::Frankfort ? "Frankfort" : "patient axes";

  const auto s = find_landmark(landmarks, "S");
  const auto n = find_landmark(landmarks, "N");
  if (!s || !n) return frame;
  // S->N in the mid-sagittal plane (perpendicular to the transverse axis).
  Vector3d sn = *n - *s;
  sn -= sn.dot(frame.left) * frame.left;
  if (sn.norm() < 10) return frame;  // S and N (nearly) coincide: keep Frankfort
  sn.normalize();
  // Rotating about +left by +angle turns anterior towards inferior (anterior end down).
  const Vector3d anterior = Eigen::AngleAxisd(radians(ceph::kNasionFrameRotationDeg), frame.left) * sn;
  frame.anterior = anterior.normalized();
  frame.superior = frame.anterior.cross(frame.left).normalized();
  frame.origin = *n;
  frame.source = "nasion";
  return frame;
}

Eigen::Isometry3d to_transform(const PlanningFrame& frame, const FrameMove& move, const Vector3d& pivot) {
  const Matrix3d basis = frame.basis();
  const Matrix3d rotation = basis * frame_rotation(move) * basis.transpose();
  const Vector3d translation =
      move.advancement_mm * frame.anterior - move.vertical_mm * frame.superior + move.lateral_mm * frame.left;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = rotation;
  transform.translation() = pivot + translation - rotation * pivot;
  return transform;
}

FrameMove from_transform(const PlanningFrame& frame, const Eigen::Isometry3d& transform, const Vector3d& pivot) {
  const Matrix3d basis = frame.basis();
  const Matrix3d r = basis.transpose() * transform.linear() * basis;  // frame coordinates
  // R = Rz(yaw) Ry(b) Rx(roll) with b = -pitch: r(2,0) = -sin(b) = sin(pitch).
  FrameMove move;
  move.pitch_deg = degrees(std::asin(std::clamp(r(2, 0), -1.0, 1.0)));
  move.yaw_deg = degrees(std::atan2(r(1, 0), r(0, 0)));
  move.roll_deg = degrees(std::atan2(r(2, 1), r(2, 2)));
  const Vector3d t = displacement_in_frame(frame, transform * pivot - pivot);
  move.advancement_mm = t.x();
  move.vertical_mm = t.y();
  move.lateral_mm = t.z();
  return move;
}

Vector3d displacement_in_frame(const PlanningFrame& frame, const Vector3d& displacement) {
  return {displacement.dot(frame.anterior), -displacement.dot(frame.superior), displacement.dot(frame.left)};
}

}  // namespace maxillo::planning
