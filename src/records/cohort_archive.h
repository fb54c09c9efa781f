#pragma once
// A follow-up cohort kept in the archive. Each cohort case becomes a case labelled
// "cohort:NAME" of the patient whose Patient ID is the cohort CSV's `case` column (patient and
// case created when missing, without images: Archive::ensure_case), and each of its time points a
// landmark set attached with its label and date (case_landmarks.h). Re-importing the same cohort
// stores nothing new: a time point whose newest stored set has the same date, frame and points is
// left alone; a changed one is stored as a newer version (the history keeps both).
#include <cstdint>
#include <string>
#include <vector>

#include "archive/archive.h"
#include "ceph/follow_up.h"
#include "records/case_landmarks.h"

namespace maxillo::records {

std::string cohort_case_label(const std::string& cohort_name);  // "cohort:" + name

struct CohortImportReport {
  int cases = 0;
  int sets_stored = 0;     // new time points or changed sets
  int sets_unchanged = 0;  // already archived as they are
};

// `frame` says how the coordinates are read; kAuto is resolved per set (cephalogram when every z
// is 0, else LPS) so the archive records what was meant. Error(kBadValue) for an empty name.
CohortImportReport import_cohort(Archive& archive, const std::vector<ceph::CohortCase>& cohort,
                                 const std::string& cohort_name, const LandmarkFrame& frame, const std::string& source);

// Attaches one cohort case's time points to an existing case (e.g. a scanned patient's own
// case), skipping those already archived as they are; counts into `report`. `origin`: kReference
// for a phantom cohort's known landmarks (the case's CT then never works with them).
void attach_cohort_time_points(Archive& archive, int64_t case_id, const ceph::CohortCase& cohort_case,
                               const LandmarkFrame& frame, const std::string& source, CohortImportReport& report,
                               LandmarkOrigin origin = LandmarkOrigin::kGiven);

// The cohort's cases in import order, named by Patient ID, each time point's newest set (by date).
// Error(kNotFound, name) when the archive holds no case of this cohort.
std::vector<ceph::CohortCase> archived_cohort(const Archive& archive, const std::string& cohort_name);

// A case's analysis per time point, each set read in the frame it was stored with.
ceph::CaseFollowUp archived_case_follow_up(const Archive& archive, int64_t case_id, const std::string& name,
                                           ceph::Sex sex = ceph::Sex::kUnknown);
// The same for every case of the cohort.
std::vector<ceph::CaseFollowUp> archived_cohort_follow_up(const Archive& archive, const std::string& cohort_name,
                                                          ceph::Sex sex = ceph::Sex::kUnknown);

}  // namespace maxillo::records
