#pragma once
// The planning frame and rigid moves of a bone segment expressed in it (thesis ch. 5, Fig. 8).
//
// Frame (planning_frame): the source's nasion frame in 3D.
//   left      = the Frankfort frame's transverse axis (geometry/anatomical_frame.h: porions and
//               orbitales), which fixes the mid-sagittal plane far better than N and S;
//   anterior  = S->N projected on the mid-sagittal plane, rotated about `left` by
//               ceph::kNasionFrameRotationDeg (6 deg) so that its anterior end goes down: the
//               source's X axis, close to Frankfort horizontal;
//   superior  = anterior x left (right-handed, as AnatomicalFrame);
//   origin    = N.
//   Without S and N the Frankfort frame itself is used (source "Frankfort"), and without
//   porions/orbitales the scanner's patient axes (source "patient axes").
//
// A move of a segment about a pivot p is x' = R (x - p) + p + t (LPS, mm). Its frame values
// (FrameMove), with the signs of the source's Table II and III:
//   advancement_mm  t . anterior                        + advancement, - setback
//   vertical_mm     -t . superior                       + extrusion (down), - impaction (up)
//   lateral_mm      t . left                            + to the patient's left, - to the right
//   pitch_deg       rotation about the transverse axis  + anterior end up (counter-clockwise in
//                                                         the right profile view, like alpha)
//   roll_deg        rotation about the anterior axis    + patient's left side up
//   yaw_deg         rotation about the superior axis    + anterior end to the patient's left
// In frame coordinates (anterior, left, superior) the rotation is
//   R = Rz(yaw) * Ry(-pitch) * Rx(roll)      (yaw applied last, roll first),
// the usual z-y-x convention; the decomposition is unique for |pitch| < 90 deg.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "ceph/landmark.h"

namespace maxillo::planning {

struct PlanningFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d anterior = -Eigen::Vector3d::UnitY();
  Eigen::Vector3d left = Eigen::Vector3d::UnitX();
  Eigen::Vector3d superior = Eigen::Vector3d::UnitZ();
  std::string source = "patient axes";  // "nasion", "Frankfort" or "patient axes"

  // Columns anterior, left, superior: frame components -> LPS directions.
  Eigen::Matrix3d basis() const;
};

PlanningFrame planning_frame(const LandmarkSet& landmarks);

struct FrameMove {
  double advancement_mm = 0;
  double vertical_mm = 0;
  double lateral_mm = 0;
  double pitch_deg = 0;
  double roll_deg = 0;
  double yaw_deg = 0;
};

// Frame values -> the LPS rigid transform about `pivot`.
Eigen::Isometry3d to_transform(const PlanningFrame& frame, const FrameMove& move, const Eigen::Vector3d& pivot);
// The LPS rigid transform -> frame values about `pivot` (the rotation does not depend on the
// pivot; the translation is the pivot's displacement).
FrameMove from_transform(const PlanningFrame& frame, const Eigen::Isometry3d& transform, const Eigen::Vector3d& pivot);

// Displacement of a point in frame terms: (advancement, vertical (+ down), lateral (+ left)).
Eigen::Vector3d displacement_in_frame(const PlanningFrame& frame, const Eigen::Vector3d& displacement);

}  // namespace maxillo::planning
