#include "occlusion/mandibular_autorotation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace maxillo::occlusion {
namespace {

constexpr double kDegree = M_PI / 180.0;

Eigen::Vector3d centroid(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  return pose * Eigen::Vector3d(mesh.vertices.colwise().mean().transpose());
}

// Farthest distance of a lower vertex from the axis: a rotation by a radians moves no vertex
// further than radius * a.
double radius_about(const TriangleMesh& mesh, const HingeAxis& hinge) {
  const Eigen::Vector3d direction = (hinge.second - hinge.first).normalized();
  double radius = 0;
  for (Eigen::Index v = 0; v < mesh.vertex_count(); ++v) {
    const Eigen::Vector3d r = mesh.vertices.row(v).transpose() - hinge.first;
    radius = std::max(radius, (r - r.dot(direction) * direction).norm());
  }
  return radius;
}

}  // namespace

Eigen::Isometry3d hinge_rotation(const HingeAxis& hinge, double angle_deg) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translate(hinge.first)
      .rotate(Eigen::AngleAxisd(angle_deg * kDegree, (hinge.second - hinge.first).normalized()))
      .translate(-hinge.first);
  return motion;
}

AutorotationResult autorotate_mandible(const DistanceField& upper, const DistanceField& lower,
                                       const Eigen::Isometry3d& upper_pose, const HingeAxis& hinge,
                                       const Eigen::Vector3d& pogonion, const AutorotationOptions& options) {
  assert((hinge.second - hinge.first).norm() > 1e-9 && "the hinge axis needs two distinct points");
  // Closing: the sign of the rotation whose first-order motion of the lower centroid points
  // towards the upper arch.
  const Eigen::Vector3d axis = (hinge.second - hinge.first).normalized();
  const Eigen::Vector3d lower_centre = centroid(lower.mesh(), Eigen::Isometry3d::Identity());
  const Eigen::Vector3d towards_upper = centroid(upper.mesh(), upper_pose) - lower_centre;
  const double sign = axis.cross(lower_centre - hinge.first).dot(towards_upper) >= 0 ? 1.0 : -1.0;

  // Rotating the lower arch by M is, relative to it, moving the upper arch by M^-1.
  const auto in_contact = [&](double angle_deg) {
    const Eigen::Isometry3d motion = hinge_rotation(hinge, sign * angle_deg);
    return !lower.tree().intersecting_faces(upper.tree(), motion.inverse() * upper_pose).empty();
  };
  AutorotationResult result;
  const auto finish = [&](double angle_deg) {
    result.angle_deg = angle_deg;
    result.lower_motion = hinge_rotation(hinge, sign * angle_deg);
    result.pogonion_displacement = result.lower_motion * pogonion - pogonion;
    result.pogonion_mm = result.pogonion_displacement.norm();
    return result;
  };
  if (in_contact(0)) {
    result.contact = result.already_in_contact = true;
    return finish(0);
  }
  const double radius = std::max(radius_about(lower.mesh(), hinge), 1e-9);
  const double step_deg = std::min(options.max_substep_mm / radius / kDegree, 1.0);
  double free = 0, blocked = -1;
  for (double angle = step_deg; free < options.max_angle_deg;
       angle = std::min(angle + step_deg, options.max_angle_deg)) {
    if (in_contact(angle)) {
      blocked = angle;
      break;
    }
    free = angle;
  }
  if (blocked < 0) return finish(free);  // no contact within the limit
  while (blocked - free > options.tolerance_deg) {
    const double middle = 0.5 * (free + blocked);
    (in_contact(middle) ? blocked : free) = middle;
  }
  result.contact = true;
  return finish(free);
}

}  // namespace maxillo::occlusion
