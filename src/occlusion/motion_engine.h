#pragma once
// The rigid motion engine of the virtual occlusion (thesis ch. 7): the lower arch is fixed, the
// upper arch moves rigidly and may never penetrate the lower one by more than
// penetration_tolerance_mm beyond the deepest penetration of the pose it started from
// (scanned arches in natural occlusion already overlap by a few tenths of a millimetre).
// Poses map upper-file coordinates to lower-file coordinates (mm).
#include <Eigen/Geometry>
#include <vector>

#include "occlusion/arch_contacts.h"

namespace maxillo::occlusion {

struct MotionOptions {
  double penetration_tolerance_mm = 0.05;  // allowed extra penetration beyond the start pose's
  double contact_band_mm = 1.0;            // vertices this close to the other arch are contacts
  double max_substep_mm = 0.25;            // no vertex moves further per checked substep (no tunnelling)
  int max_iterations = 150;                // guided alignment
};

enum class StepOutcome { Moved, CancelledByCollision };

struct StepReport {
  StepOutcome outcome = StepOutcome::Moved;
  double penetration_mm = 0;  // at the pose kept (the new one, or the old one when cancelled)
};

class MotionEngine {
 public:
  // Both distance fields (built once per arch) must outlive the engine. `start_pose` sets the
  // allowed penetration.
  MotionEngine(const DistanceField& upper, const DistanceField& lower, const Eigen::Isometry3d& start_pose,
               const MotionOptions& options = {});

  const Eigen::Isometry3d& pose() const { return pose_; }
  double allowed_penetration_mm() const { return allowed_penetration_mm_; }
  const DistanceField& upper() const { return upper_; }
  const DistanceField& lower() const { return lower_; }
  const MotionOptions& options() const { return options_; }
  ContactState contacts() const { return assess_contacts(upper_, lower_, pose_, band_mm()); }

  // Free-hand steps (lower frame): the whole step is cancelled, and reported, if any substep
  // along it would penetrate beyond the allowance.
  StepReport translate(const Eigen::Vector3d& offset_mm);
  StepReport rotate(const Eigen::Vector3d& axis, double angle_deg, const Eigen::Vector3d& pivot_mm);
  // Applies `motion` (lower frame, left-multiplied onto the pose) with the same rule.
  StepReport move(const Eigen::Isometry3d& motion);

  // Penetration of a candidate pose (mm), and whether the engine would accept it.
  double penetration_at(const Eigen::Isometry3d& pose) const;
  bool admissible(const Eigen::Isometry3d& pose) const { return penetration_at(pose) <= allowed_penetration_mm_; }
  // Sets the pose without checks (the guided solver checks every pose it accepts itself).
  void set_pose(const Eigen::Isometry3d& pose) { pose_ = pose; }

  double band_mm() const {
    return std::max(options_.contact_band_mm, allowed_penetration_mm_ + 2 * options_.max_substep_mm);
  }
  // Largest displacement of any upper vertex under `motion` (lower frame) from the current pose.
  double max_displacement_mm(const Eigen::Isometry3d& motion) const;

 private:
  const DistanceField& upper_;
  const DistanceField& lower_;
  Eigen::Isometry3d pose_;
  MotionOptions options_;
  double allowed_penetration_mm_ = 0;
  Eigen::Vector3d upper_centre_ = Eigen::Vector3d::Zero();  // upper file frame
  double upper_radius_ = 0;                                 // bounding sphere about the centre
};

}  // namespace maxillo::occlusion
