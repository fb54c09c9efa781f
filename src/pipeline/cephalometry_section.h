#pragma once
// The "cephalometry" section of the consultation report: the cephalometric table of the newest
// landmark set (value, norm mean ± SD, deviation flag, the frame it was measured in) and, when
// the case has landmark sets at two or more time points, the follow-up table over time points
// (the source's chapter 5 measurements, with the Wits appraisal). The Wits chart is not drawn yet.
#include <cstdint>
#include <optional>
#include <string>

#include "archive/archive.h"
#include "ceph/follow_up.h"
#include "report/report_model.h"

namespace maxillo::pipeline {

// From analyses already made: `current` is the set shown in the cephalometric table (nullopt =
// no landmarks), `follow_up` may have no time points.
report::Section cephalometry_section(const std::optional<ceph::CephalometricAnalysis>& current,
                                     const std::string& current_label, const ceph::CaseFollowUp& follow_up);

// Everything from the archive: the time points of the case (case_landmarks.h), the newest one
// (or the newest untimed set when there are none) in the cephalometric table.
report::Section case_cephalometry_section(const Archive& archive, int64_t case_id, ceph::Sex sex = ceph::Sex::kUnknown);

// A cohort's follow-up (section id "cephalometry"): per pair (from, to) of time points the change
// table of the source's Tables II/III (nasion-frame X/Y of PNS, Si, ANS and alpha, then SNA, SNB,
// ANB, Wits: mean ± SD, n), and the Wits appraisal per patient and time point (Fig. 10's data).
report::Section cohort_follow_up_section(const std::vector<ceph::CaseFollowUp>& cohort,
                                         const std::vector<std::pair<std::string, std::string>>& changes);

}  // namespace maxillo::pipeline
