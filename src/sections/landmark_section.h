#pragma once
// The "landmarks" section of the consultation report: every landmark the case works with, so a
// surgeon can check them at a glance: label, position (LPS mm), where it came from (a file or
// the automatic detection), the detection's confidence and status (flagged ones with their
// failed checks; absent ones with the reason).
#include <optional>

#include "records/case_landmarks.h"
#include "report/report_model.h"

namespace maxillo::sections {

// nullopt: the case has no landmarks (the section is left out; the summary says why).
std::optional<report::Section> landmark_section(const std::optional<records::StoredLandmarks>& stored);

}  // namespace maxillo::sections
