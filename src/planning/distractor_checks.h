#pragma once
// Where the distractors go and whether they are safe (thesis ch. 2, 4a, 5), on a tissue label
// volume: the maxillary sinus air, the teeth (erupted and buds) and the bone.
//
// Entry points: from the centroid of the side's sinus air straight forwards (the frame's anterior
// axis) through the sinus and the anterior maxillary wall; the entry point is where that line
// leaves the bone. It lies medial to the infraorbital foramen, below it by about half the
// sinus height (the source drilled the hole at the medial part of the anterior wall, ch. 2).
// The screw body runs from the entry point backwards, -axis, for the screw length: with
// divergent vectors it turns medially inside the sinus, away from the lateral wall.
//
// Checks, each per side with its measured value, its limit and a reason when it fails:
//   screw in sinus  every sample of the screw body beyond the anterior wall (axis and a ring at
//                   screw radius + clearance, every 0.5 mm) is sinus air; the ring starts 5 mm
//                   behind the wall's inner surface (the entry hole's rim at the sinus's front).
//   sinus depth     sinus air along the axis from the wall backwards >= the screw's length in
//                   the sinus + clearance (the source: 34-38 mm ventrodorsal at age 8, enough
//                   from that age on).
//   screw travel    activation <= screw length - engagement (the thread that stays in the cylinder).
//   tooth distance  screw body (a cylinder) to the nearest tooth voxel (roots and buds) >= limit.
//   infraorbital nerve  screw body to the infraorbital foramen, taken 7 mm below the orbitale of
//                   that side (OrR/OrL, else Or mirrored), >= limit; not checked without orbitales.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "ceph/landmark.h"
#include "core/volume.h"
#include "planning/distraction_vectors.h"

namespace maxillo::planning {

// Which labels are which tissue. Defaults: the phantom's Tissue values (sample/phantom.h).
// For imaging/segmentation.h's TissueLabel use segmentation_anatomy_labels().
struct AnatomyLabels {
  std::vector<uint8_t> sinus_air{4};
  std::vector<uint8_t> teeth{3};
  std::vector<uint8_t> bone{2};
  std::vector<uint8_t> open_air{0};  // the outside's air and the airways open to it
};
AnatomyLabels segmentation_anatomy_labels();  // enclosed air 2, bone 3, teeth 4

// Whether `label` is one of `set` (one of AnatomyLabels' lists).
bool is_labelled(const std::vector<uint8_t>& set, uint8_t label);

struct DistractorDevice {
  double screw_length_mm = 25;
  double screw_diameter_mm = 3;
  double engagement_mm = 5;
};

struct CheckLimits {
  double sinus_clearance_mm = 1;
  double tooth_distance_mm = 2;
  double nerve_distance_mm = 5;
  double foramen_below_orbitale_mm = 7;
};

enum class CheckStatus { Pass, Fail, NotChecked };
std::string_view status_name(CheckStatus status);  // "pass", "FAIL", "not checked"

struct DistractorCheck {
  std::string name;  // "screw in sinus", "sinus depth", "screw travel", "tooth distance", "infraorbital nerve"
  Side side = Side::Right;
  CheckStatus status = CheckStatus::Pass;
  double value = 0;    // the measured quantity (mm)
  double limit = 0;    // what it is compared with (mm)
  std::string reason;  // why it failed or was not checked; empty when passed
};

struct EntryPoints {
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  Eigen::Vector3d left = Eigen::Vector3d::Zero();
};

// Error(kUnsafePlan, "<side> maxillary sinus", reason) when a side has no sinus air. With
// landmarks, only air between the palatal plane (ANS/PNS) and the orbitales (Or*) counts, so
// other closed air cells of a segmented CT (frontal sinus, mastoid) do not pull the centroid.
EntryPoints find_entry_points(const LabelVolume& labels, const PlanningFrame& frame, const AnatomyLabels& anatomy,
                              const LandmarkSet& landmarks = {});

std::vector<DistractorCheck> check_distractors(const LabelVolume& labels, const DistractionVectors& vectors,
                                               const LandmarkSet& landmarks, const PlanningFrame& frame,
                                               const AnatomyLabels& anatomy = {}, const DistractorDevice& device = {},
                                               const CheckLimits& limits = {});

bool all_passed(const std::vector<DistractorCheck>& checks);  // NotChecked counts as passed

}  // namespace maxillo::planning
