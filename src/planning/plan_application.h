#pragma once
// Applying a plan to a case: the moves in the planning frame as transforms, and for a
// distraction the entry points, vectors, checks, activation schedule and the forward
// simulation at ANS, PNS and U1. Pure computation on a label volume and landmarks; the command
// (cli/cmd_plan.cpp) loads the case and writes the files.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/json.h"
#include "core/volume.h"
#include "planning/forward_simulation.h"
#include "planning/plan.h"

namespace maxillo::planning {

struct PlannedMove {
  Segment segment = Segment::kMaxilla;
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  FrameMove move;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();  // LPS
};

struct DistractionResult {
  MaxillaryTarget target;
  MaxillaryReference reference;
  DistractionVectors vectors;
  std::vector<DistractorCheck> checks;
  ActivationSchedule schedule;
  ForwardSimulation simulation;
  // A side whose sinus the scan shows open into the nasal cavity (maxillary_sinus.h): how its
  // air was taken. Empty when both sinuses are closed air.
  std::vector<std::string> sinus_notes;
};

struct PlanResult {
  Plan plan;
  PlanningFrame frame;
  std::vector<PlannedMove> moves;
  std::optional<DistractionResult> distraction;
  bool feasible = true;               // every check passed (or was not checked)
  std::vector<std::string> refusals;  // one line per failed check: "<side> <check>: <reason>"
  // Files written for this result by later steps (osteotomy segments, the STL transfer model,
  // renders): label -> path. plan_result_json lists them.
  std::vector<std::pair<std::string, std::filesystem::path>> files;
};

// Error(kBadValue, "moves[i].pivot", ...) for a pivot landmark the case lacks; Error(kUnsafePlan)
// when a side has no sinus to house a distractor (find_entry_points).
PlanResult apply_plan(const Plan& plan, const LabelVolume& labels, const LandmarkSet& landmarks,
                      const AnatomyLabels& anatomy = {});

Json plan_result_json(const PlanResult& result);

// The moves of a stored plan result (plan_result_json's "moves"), read back exactly: each
// segment, pivot, frame move and LPS transform. Anything missing, mistyped or not a rigid
// transform is Error(`code`, source, "<key path>: <reason>"); a stored result is never read as a
// default.
std::vector<PlannedMove> planned_moves_from_json(const Json& result, const std::string& source,
                                                 ErrorCode code = ErrorCode::kArchiveCorrupt);

}  // namespace maxillo::planning
