#pragma once
// The "planning" section of the consultation report (template heading "Surgical plan"), built
// from a plan result (planning::plan_result_json, as `maxillo plan apply` stores it): the
// planned moves in the anatomical frame, the distraction vectors, their checks, the activation
// schedule, the forward simulation, and the renders listed in the result's files (PNG).
#include "core/json.h"
#include "report/report_model.h"

namespace maxillo::pipeline {

report::Section planning_section(const Json& plan_result);

}  // namespace maxillo::pipeline
