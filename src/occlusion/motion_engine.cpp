#include "occlusion/motion_engine.h"

#include <algorithm>
#include <cmath>

namespace maxillo::occlusion {

MotionEngine::MotionEngine(const DistanceField& upper_field, const DistanceField& lower_field,
                           const Eigen::Isometry3d& start_pose, const MotionOptions& options)
    : upper_(upper_field), lower_(lower_field), pose_(start_pose), options_(options) {
  const TriangleMesh& upper = upper_field.mesh();
  if (upper.vertex_count() > 0) upper_centre_ = upper.vertices.colwise().mean().transpose();
  for (Eigen::Index v = 0; v < upper.vertex_count(); ++v)
    upper_radius_ = std::max(upper_radius_, (upper.vertices.row(v).transpose() - upper_centre_).norm());
  // The band must reach the start pose's deepest vertices: widen until it does.
  double band = options_.contact_band_mm;
  double depth = assess_contacts(upper_, lower_, pose_, band).max_penetration_mm;
  while (depth > band - 2 * options_.max_substep_mm && band < 64) {
    band *= 2;
    depth = assess_contacts(upper_, lower_, pose_, band).max_penetration_mm;
  }
  allowed_penetration_mm_ = depth + options_.penetration_tolerance_mm;
}

double MotionEngine::penetration_at(const Eigen::Isometry3d& pose) const {
  return assess_contacts(upper_, lower_, pose, band_mm()).max_penetration_mm;
}

// Bound over the upper arch: |R x + t - x| <= |(R - I)(x - c)| + |(R - I) c + t| <= |R - I|_2 r + |motion(c) - c|.
double MotionEngine::max_displacement_mm(const Eigen::Isometry3d& motion) const {
  const Eigen::Vector3d centre = pose_ * upper_centre_;
  const double angle = Eigen::AngleAxisd(motion.linear()).angle();
  return 2 * std::sin(angle / 2) * upper_radius_ + (motion * centre - centre).norm();
}

StepReport MotionEngine::move(const Eigen::Isometry3d& motion) {
  const int substeps = std::max(1, int(std::ceil(max_displacement_mm(motion) / options_.max_substep_mm)));
  const Eigen::AngleAxisd rotation(motion.linear());
  const Eigen::Vector3d centre = pose_ * upper_centre_;
  const Eigen::Vector3d centre_shift = motion * centre - centre;
  for (int s = 1; s <= substeps; ++s) {
    const double f = double(s) / substeps;
    // Rotation about the arch centre by a fraction of the angle, plus a fraction of its shift.
    Eigen::Isometry3d partial = Eigen::Isometry3d::Identity();
    partial.translate(centre + f * centre_shift)
        .rotate(Eigen::AngleAxisd(f * rotation.angle(), rotation.axis()))
        .translate(-centre);
    const double depth = penetration_at(partial * pose_);
    if (depth > allowed_penetration_mm_) return {StepOutcome::CancelledByCollision, penetration_at(pose_)};
  }
  pose_ = motion * pose_;
  return {StepOutcome::Moved, penetration_at(pose_)};
}

StepReport MotionEngine::translate(const Eigen::Vector3d& offset_mm) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translate(offset_mm);
  return move(motion);
}

StepReport MotionEngine::rotate(const Eigen::Vector3d& axis, double angle_deg, const Eigen::Vector3d& pivot_mm) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translate(pivot_mm)
      .rotate(Eigen::AngleAxisd(angle_deg * M_PI / 180.0, axis.normalized()))
      .translate(-pivot_mm);
  return move(motion);
}

}  // namespace maxillo::occlusion
