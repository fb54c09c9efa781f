#pragma once
// `maxillo plan apply` for an archived case: the newest plan of the case applied to its CT
// (segmented: enclosed air = sinus air, bone, teeth) and its newest landmarks. Writes
// DIR/plan-result.json and stores the result in the archive (plan_archive.h), where the
// consultation report finds it.
#include <cstdint>
#include <filesystem>

#include "archive/archive.h"
#include "planning/plan_application.h"
#include "casework/surfaces/case_tissues.h"
#include "records/plan_archive.h"

namespace maxillo::casework {

struct CasePlanResult {
  records::StoredPlan plan;
  planning::PlanResult result;
  std::filesystem::path result_json;  // DIR/plan-result.json
  CaseTissues tissues;                // the segmented CT the plan was applied to (for simulate_case)
};

// Error(kNotFound) when the case has no plan or no landmarks; what volume loading, segmentation
// and apply_plan throw otherwise. An infeasible plan is not an error here: result.feasible says.
// `tissues`, when given, are the case's CT segmented for its newest landmarks (load_case_tissues),
// made earlier; the CT is then not loaded and segmented again.
// The landmarks are the case's (casework/landmarks/automatic_landmarks.h: detected and stored when none were
// attached); flagged automatic ones refuse the plan (Error kBadValue naming them) unless
// `accept_flagged`.
CasePlanResult apply_case_plan(Archive& archive, int64_t case_id, const std::filesystem::path& out_dir,
                               const CaseTissues* tissues = nullptr, bool accept_flagged = false);

}  // namespace maxillo::casework
