#pragma once
// A synthetic follow-up cohort made of phantoms, in the cohort CSV format (ceph/follow_up.h):
// Class III patients treated by maxillary distraction, measured before (pre), at the end of
// distraction (post) and 6, 12 and 24 months later. Each patient's maxilla advances by a known
// amount at "post", relapses slightly by 6 months, and in the "growing" patients the mandible
// keeps growing forward afterwards (the Wits appraisal falls again, as in the source's Fig. 10).
// Landmarks are the phantom's analytic 3D landmarks (LPS mm). Deterministic.
#include <string>
#include <vector>

#include "ceph/follow_up.h"

namespace maxillo::followup {

struct SamplePatient {
  std::string name;
  double advancement_mm;                 // maxillary advancement at the end of distraction
  double relapse_mm;                     // maxillary setback between post and 6 months
  double mandibular_growth_mm_per_year;  // forward growth of the mandible after distraction
};
// The six patients of the sample cohort.
std::vector<SamplePatient> sample_cohort_patients();

std::vector<ceph::CohortCase> sample_cohort();
// One patient's visits (pre, post, 6M, 12M, 24M), dated from January of `first_year`, as in the
// cohort (patient i of sample_cohort() starts in 2001 + i).
ceph::CohortCase sample_patient_follow_up(const SamplePatient& patient, int first_year);
// The cohort as CSV text (header case,time_point,date,label,x,y,z).
std::string format_cohort_csv(const std::vector<ceph::CohortCase>& cohort);

}  // namespace maxillo::followup
