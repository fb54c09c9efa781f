#pragma once
// The surgical plan as a versioned JSON document (issue #4 §3). Example (format_version 1):
//
// {
//   "format_version": 1,
//   "description": "10 mm advancement, 6 mm widening",
//   "osteotomies": {
//     "le_fort_i": "default-high",                 // or "default-low", or a plane:
//     "pterygomaxillary": "default",               //   {"point": [x, y, z], "normal": [x, y, z]}
//     "genioplasty": {"point": [0, -20, -80], "normal": [0, -0.5, -0.87]}
//   },
//   "moves": [ {"segment": "maxilla", "pivot": "PNS",   // a landmark label or [x, y, z] (LPS mm)
//               "advancement_mm": 10, "vertical_mm": 0, "lateral_mm": 0,
//               "pitch_deg": 0, "roll_deg": 0, "yaw_deg": 0} ],
//   "distraction": {
//     "target": {"advancement_mm": 10, "vertical_mm": 0, "widening_mm": 6, "midline_shift_mm": 0,
//                "rotation_deg": 0, "counter_rotation_deg": 0},
//     "expected_clockwise_rotation_deg": 0,
//     "device": {"screw_length_mm": 25, "screw_diameter_mm": 3, "engagement_mm": 5},
//     "limits": {"sinus_clearance_mm": 1, "tooth_distance_mm": 2, "nerve_distance_mm": 5,
//                "foramen_below_orbitale_mm": 7},
//     "schedule": {"latency_days": 5, "rate_mm_per_day": 1, "activations_per_day": 2,
//                  "mm_per_turn": 0.5, "consolidation_days": 84},
//     "entry_right": [x, y, z], "entry_left": [x, y, z]      // optional: override the placement
//   },
//   "occlusion": {"reference": "preoperative"}   // or {"reference": "pairs", "pairs_file": "pairs.csv"}
// }
//
// Moves and angles are in the planning frame (anatomical_moves.h) with its signs. Every key is
// optional except format_version; unknown keys are refused (a typo must not silently drop a
// move). A plan of a newer format_version than this program's is refused. Segment names are
// osteotomy.h's segment_name values; the cranium is the fixed reference and cannot move.
// With both a maxilla move and a distraction, their advancement, vertical change and pitch
// must agree (the distraction is how the move is made).
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/json.h"
#include "planning/activation_schedule.h"
#include "planning/anatomical_moves.h"
#include "planning/distraction_vectors.h"
#include "planning/distractor_checks.h"
#include "planning/osteotomy.h"

namespace maxillo::planning {

inline constexpr int kPlanFormatVersion = 1;

struct CutSpec {
  // Default: from the landmarks (osteotomy.h). Plane: a point and the normal towards the part
  // that is cut off. Points: three points on the cut (e.g. picked on the bone surface); the
  // side that moves is the one holding the segment's reference landmark (resolve_osteotomies).
  enum class Kind { Default, Plane, Points };
  Kind kind = Kind::Default;
  LeFortVariant variant = LeFortVariant::High;  // for a default Le Fort I
  CutPlane plane;                               // for Kind::Plane (normal unit)
  // For Kind::Points, not collinear (zero otherwise: Eigen leaves a vector uninitialised).
  std::array<Eigen::Vector3d, 3> points{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
};

struct PlanOsteotomies {
  std::optional<CutSpec> le_fort_i, pterygomaxillary, bsso_right, bsso_left, genioplasty;
};

struct Pivot {
  std::string landmark = "PNS";          // used when point is empty
  std::optional<Eigen::Vector3d> point;  // LPS mm
};

struct SegmentMove {
  Segment segment = Segment::kMaxilla;
  Pivot pivot;
  FrameMove move;
};

struct DistractionSpec {
  MaxillaryTarget target;
  double expected_clockwise_rotation_deg = 0;
  DistractorDevice device;
  CheckLimits limits;
  ScheduleSettings schedule;
  std::optional<Eigen::Vector3d> entry_right, entry_left;
};

struct OcclusionReference {
  std::string reference = "preoperative";  // "preoperative" or "pairs"
  std::string pairs_file;                  // with "pairs": upper/lower point pairs (maxillo occlude)
};

struct Plan {
  int format_version = kPlanFormatVersion;
  std::string description;
  PlanOsteotomies osteotomies;
  std::vector<SegmentMove> moves;
  std::optional<DistractionSpec> distraction;
  OcclusionReference occlusion;
};

// Parses and validates. Error(kBadValue, source, "<field path>: <reason>").
Plan parse_plan(std::string_view text, const std::string& source);
Plan plan_from_json(const Json& json, const std::string& source);
// Error(kBadValue, source, "<field>: <reason>") for a plan that is well-formed but inconsistent.
void validate_plan(const Plan& plan, const std::string& source);
Json plan_to_json(const Plan& plan);
// A point as plans and their results write it: [x, y, z].
inline Json point_json(const Eigen::Vector3d& p) { return Json::array({p.x(), p.y(), p.z()}); }
std::string serialise_plan(const Plan& plan);  // indented JSON text, newline-terminated

// The plan `maxillo plan create` makes for a distraction: default high Le Fort I and
// pterygomaxillary cuts, the maxilla's common move about PNS, and the distraction. Without a
// description, the target's in one line ("TS-MD distraction: 6 mm advancement").
Plan distraction_plan(const MaxillaryTarget& target, const std::string& description = "");

// Osteotomy cut planes of the plan, defaults resolved from the landmarks.
Osteotomies resolve_osteotomies(const PlanOsteotomies& spec, const LandmarkSet& landmarks);

}  // namespace maxillo::planning
