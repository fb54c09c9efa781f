#pragma once
// Mandibular autorotation (issue 6 item 6): after a maxillary impaction the mandible closes by
// rotating about the condylar hinge axis until the lower teeth first meet the upper ones. The
// lower arch turns about the axis through two points (e.g. the condyles, lower file frame, mm)
// in the closing direction (the one that carries the lower arch towards the upper one), in steps
// that move no vertex by more than max_substep_mm (no tunnelling through a cusp), until the
// exact triangle test finds contact; the angle is then bisected to tolerance_deg.
#include <Eigen/Geometry>

#include "geometry/signed_distance.h"

namespace maxillo::occlusion {

struct HingeAxis {
  Eigen::Vector3d first = Eigen::Vector3d::Zero(), second = Eigen::Vector3d::UnitX();  // e.g. right, left condyle
};

struct AutorotationOptions {
  double max_angle_deg = 30;     // give up (no contact) beyond this
  double tolerance_deg = 0.01;   // bisection stops when the bracket is this narrow
  double max_substep_mm = 0.25;  // largest vertex motion between two collision checks
};

struct AutorotationResult {
  bool contact = false;  // false: no contact within max_angle_deg (or in contact already: angle 0)
  bool already_in_contact = false;
  double angle_deg = 0;  // the closing rotation, >= 0 (last contact-free angle of the bracket)
  Eigen::Isometry3d lower_motion = Eigen::Isometry3d::Identity();   // applied to the lower arch (lower frame)
  Eigen::Vector3d pogonion_displacement = Eigen::Vector3d::Zero();  // mm, lower frame
  double pogonion_mm = 0;                                           // its length
};

// Rotation of the lower arch by angle_deg about the hinge axis (right-hand rule about first->second).
Eigen::Isometry3d hinge_rotation(const HingeAxis& hinge, double angle_deg);

// `upper_pose` places the upper arch in the lower frame (fixed during the rotation); `pogonion`
// is a point of the mandible in the lower frame whose displacement is reported.
AutorotationResult autorotate_mandible(const DistanceField& upper, const DistanceField& lower,
                                       const Eigen::Isometry3d& upper_pose, const HingeAxis& hinge,
                                       const Eigen::Vector3d& pogonion, const AutorotationOptions& options = {});

}  // namespace maxillo::occlusion
