#pragma once
// The Wits appraisal over months, one line per patient (the source's Fig. 10), as a PNG chart for
// the consultation report (one patient) and the cohort follow-up report. Months as in
// ceph/follow_up_months.h: since the end of distraction ("post"), else since the first dated time
// point; the x axis title says which. A grey line marks Wits = 0 mm (a normal sagittal relation).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "archive/archive.h"
#include "ceph/follow_up.h"
#include "render/chart.h"

namespace maxillo::sections {

// A case can be charted when it has two or more dated time points with a Wits value.
bool has_wits_chart(const ceph::CaseFollowUp& follow_up);

// The chart's data: one series per chartable case (others left out), named by the case.
// Error(kEmptyResult) when no case is chartable; Error(kBadValue) for a malformed date.
render::LineChart wits_line_chart(const std::vector<ceph::CaseFollowUp>& cohort);

// Renders the chart to `png` (rendered afresh each time: it takes ~0.1 s).
void write_wits_chart(const std::vector<ceph::CaseFollowUp>& cohort, const std::filesystem::path& png);

// One case's chart stored as a "chart-wits" artefact of the case, reused while its Wits values,
// dates and labels are unchanged; the stored object's path (read-only). nullopt when the case
// cannot be charted.
std::optional<std::filesystem::path> case_wits_chart(Archive& archive, int64_t case_id,
                                                     const ceph::CaseFollowUp& follow_up);

}  // namespace maxillo::sections
