#pragma once
// Plans of a case in the archive, with their history: every saved plan is a new "plan"
// artefact (the plan's JSON text as an object, media type application/json); nothing is
// overwritten, so the newest is the current plan and the older ones its history. Applying a
// plan stores its result (vectors, checks, schedule, forward simulation) as a "plan-result"
// artefact made from that plan; the consultation report shows the newest result.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "core/json.h"
#include "ceph/landmark.h"
#include "planning/plan.h"
#include "records/plan_result_record.h"
#include "planning/plan_application.h"

namespace maxillo::records {

struct StoredPlan {
  int64_t artefact_id = 0;
  int version = 1;  // 1 = the case's first plan, 2 = the next saved one, ...
  std::string created_at;
  std::string program_version;
  std::string sha256;  // of the plan's text
  planning::Plan plan;
};

// Stores the plan as the case's newest version; returns it as stored.
StoredPlan store_plan(Archive& archive, int64_t case_id, const planning::Plan& plan);
// Every stored plan of the case, oldest first. A stored plan that no longer parses (written
// by a newer program) throws Error naming the artefact.
std::vector<StoredPlan> plan_history(const Archive& archive, int64_t case_id);
std::optional<StoredPlan> latest_plan(const Archive& archive, int64_t case_id);
// The newest stored plan's object name, from the index alone (what derivation keys need; the
// nightly scan asks it of every case).
std::optional<std::string> latest_plan_sha256(const std::vector<ArtefactRecord>& case_artefacts);

// The key a plan's result is filed under: what its moves depend on, the plan's text (by its
// SHA-256, StoredPlan::sha256) and the landmarks, which place the frame and the pivots.
std::string plan_application_key(const std::string& plan_sha256, const LandmarkSet& landmarks);

// Stores the result of `plan` applied with `landmarks` (plan_result_json's document).
void store_plan_result(Archive& archive, int64_t case_id, const StoredPlan& plan, const LandmarkSet& landmarks,
                       const Json& result);
// The moves of the newest stored result of the plan with this text applied with these
// landmarks, so that simulate and validate reuse `plan apply`'s work instead of applying the
// plan again; none when it was not applied with them. A stored result whose moves do not read
// back is Error(kArchiveCorrupt) naming the artefact and the key, never a re-application.
std::optional<std::vector<planning::PlannedMove>> stored_plan_moves(const Archive& archive, int64_t case_id,
                                                                    const std::string& plan_sha256,
                                                                    const LandmarkSet& landmarks);
// The newest stored plan result of the case, if any. One that does not read back (not JSON, a
// key missing or mistyped, a newer format) is Error(kArchiveCorrupt) naming the artefact.
std::optional<PlanResultRecord> latest_plan_result(const Archive& archive, int64_t case_id);

}  // namespace maxillo::records
