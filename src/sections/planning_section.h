#pragma once
// The "planning" section of the consultation report (template heading "Surgical plan"), built
// from a stored plan result (plan_result_record.h, as `maxillo plan apply` stores it): the
// planned moves in the anatomical frame, the distraction vectors, their checks, the activation
// schedule, the forward simulation, the renders listed in the result's files (PNG) and the
// osteotomy outputs.
#include "records/plan_archive.h"
#include "records/plan_result_record.h"
#include "report/report_model.h"

namespace maxillo::sections {

report::Section planning_section(const records::PlanResultRecord& plan_result);

// The section for a plan stored but not applied yet (`maxillo plan create` without `plan apply`):
// its target and how to apply it; `flagged` lists the automatic landmarks that would refuse it
// until confirmed or accepted (casework::flagged_for_planning).
report::Section unapplied_plan_section(const records::StoredPlan& plan, int64_t case_id,
                                       const std::vector<std::string>& flagged);

}  // namespace maxillo::sections
