#pragma once
// The stored result of applying a plan (the "plan-result" artefact, DIR/plan-result.json): one
// struct, read back strictly. The writer is planning::plan_result_json plus the osteotomy
// outputs (plan_outputs_json) under "osteotomy", as `plan apply` stores them.
//
// Every field the consultation report shows is required: a missing or mistyped one is
// Error(kArchiveCorrupt) naming the artefact and the key path ("distraction.checks[3].limit_mm:
// missing"), never a zero or an empty cell in the report, and never a plan read as feasible
// without its flag. `format_version` is absent in results stored before it existed; those have
// this same layout (version 1). A newer version is refused: a newer program wrote it.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/json.h"
#include "planning/plan.h"
#include "planning/plan_application.h"

namespace maxillo::records {

struct PlanResultRecord {
  static constexpr int kFormatVersion = 1;

  struct Vector {                                     // one distractor's vector
    Eigen::Vector3d entry = Eigen::Vector3d::Zero();  // LPS mm
    double outward_deg = 0, elevation_deg = 0, activation_mm = 0;
  };
  struct Check {
    std::string side, name, status, reason;
    double value_mm = 0, limit_mm = 0;
  };
  struct ScheduleSide {
    double activation_mm = 0, turns = 0, delivered_mm = 0;
    int first_day = 0, last_day = 0, distraction_days = 0;
  };
  struct Schedule {
    int latency_days = 0, activations_per_day = 0, distraction_end_day = 0, consolidation_end_day = 0;
    double rate_mm_per_day = 0, mm_per_turn = 0, turns_per_activation = 0;
    ScheduleSide right, left;
  };
  struct SimulatedPoint {
    std::string label;
    Eigen::Vector3d target = Eigen::Vector3d::Zero(), simulated = Eigen::Vector3d::Zero();  // LPS mm
    double error_mm = 0;
  };
  struct Distraction {
    Vector right, left;
    double divergence_deg = 0, angle_deg = 0;
    std::vector<Check> checks;
    Schedule schedule;
    std::vector<SimulatedPoint> simulation;
    double max_error_mm = 0;
    std::vector<std::string> sinus_notes;  // a sinus taken open to the nose (planning/maxillary_sinus.h)
  };
  struct Segment {
    std::string segment;
    int64_t voxels = 0;
    double volume_ml = 0;
  };
  struct TransferModel {
    bool watertight = false;
    int64_t triangles = 0;
    double volume_ml = 0;
  };
  struct Osteotomy {
    std::vector<Segment> segments;
    int64_t bone_voxels = 0;
    std::optional<TransferModel> transfer_model;
  };

  int format_version = kFormatVersion;
  planning::Plan plan;
  std::string frame_source;  // "nasion frame", "Frankfort", "patient axes"
  bool feasible = false;
  std::vector<std::string> refusals;
  std::vector<planning::PlannedMove> moves;
  std::optional<Distraction> distraction;
  std::vector<std::pair<std::string, std::filesystem::path>> files;  // label -> path
  std::optional<Osteotomy> osteotomy;
};

// The stored document: planning::plan_result_json, the osteotomy outputs (plan_outputs_json of
// plan_outputs.h) under "osteotomy" and "format_version" (kFormatVersion).
Json plan_result_record_json(const planning::PlanResult& result, Json osteotomy);

// Reads a stored plan result; `source` names it in errors ("artefact 12 (plan result)").
PlanResultRecord read_plan_result_record(const Json& json, const std::string& source);

}  // namespace maxillo::records
