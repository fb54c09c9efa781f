#pragma once
// The "cephalometry" section of the consultation report: the cephalometric table of the newest
// landmark set (value, norm mean ± SD, deviation flag, the frame it was measured in) and, when
// the case has landmark sets at two or more time points, the follow-up table over time points
// (the source's chapter 5 measurements, with the Wits appraisal) and, with two or more dated
// time points, the Wits appraisal over months as a chart (pipeline/wits_chart.h).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "archive/archive.h"
#include "ceph/follow_up.h"
#include "report/report_model.h"

namespace maxillo::sections {

// From analyses already made: `current` is the set shown in the cephalometric table (nullopt =
// no landmarks), `follow_up` may have no time points; `wits_chart` a PNG shown after the follow-up table.
report::Section cephalometry_section(const std::optional<ceph::CephalometricAnalysis>& current,
                                     const std::string& current_label, const ceph::CaseFollowUp& follow_up,
                                     const std::optional<std::filesystem::path>& wits_chart = std::nullopt);

// Everything from the archive: the time points of the case (case_landmarks.h), the newest one
// (or the newest untimed set when there are none) in the cephalometric table; the Wits chart is
// made (or reused) as a "chart-wits" artefact of the case.
report::Section case_cephalometry_section(Archive& archive, int64_t case_id, ceph::Sex sex = ceph::Sex::kUnknown);

// A cohort's follow-up (section id "cephalometry"): per pair (from, to) of time points the change
// table of the source's Tables II/III (nasion-frame X/Y of PNS, Si, ANS and alpha, then SNA, SNB,
// ANB, Wits: mean ± SD, n), the stability from the end of distraction to 6 months when the cohort
// has both, the Wits appraisal per patient and time point (Fig. 10's data) and `wits_chart` (a PNG).
report::Section cohort_follow_up_section(const std::vector<ceph::CaseFollowUp>& cohort,
                                         const std::vector<std::pair<std::string, std::string>>& changes,
                                         const std::optional<std::filesystem::path>& wits_chart = std::nullopt);

// "Stable" between two time points: every change of the Tables II/III measurements has a mean of
// at most 1 mm (positions) or 1 degree (alpha) in magnitude. The sentence says the largest ones.
std::string stability_summary(const std::vector<ceph::CaseFollowUp>& cohort, const std::string& from,
                              const std::string& to);

}  // namespace maxillo::sections
