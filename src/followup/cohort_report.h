#pragma once
// The cohort follow-up report (`maxillo followup --cohort ... --pdf`, and the demo's
// cohort-followup.pdf): the change tables of the source's Tables II/III (mean ± SD, n), the
// stability from the end of distraction to 6 months, the Wits table and the Wits chart with one
// line per patient (Fig. 10), laid out with the consultation template's look.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "ceph/follow_up.h"
#include "records/case_landmarks.h"

namespace maxillo::followup {

// Every case's time points analysed, the coordinates read per `frame` (kAuto: cephalogram when
// every z is 0). `source` names the data in errors.
std::vector<ceph::CaseFollowUp> analyse_cohort(const std::vector<ceph::CohortCase>& cohort,
                                               const records::LandmarkFrame& frame, ceph::Sex sex,
                                               const std::string& source);

// Time point labels in order of first appearance over the cases (each case ordered by date).
std::vector<std::string> cohort_time_point_labels(const std::vector<ceph::CaseFollowUp>& cohort);
// Every consecutive pair of those labels: (pre, post), (post, 6M), ...
std::vector<std::pair<std::string, std::string>> consecutive_pairs(const std::vector<std::string>& labels);

// Writes the PDF; the chart is drawn when a case has two dated time points. Returns the page count.
int write_cohort_report(const std::vector<ceph::CaseFollowUp>& cohort,
                        const std::vector<std::pair<std::string, std::string>>& changes, const std::string& title,
                        const std::filesystem::path& pdf);

}  // namespace maxillo::followup
