#include "followup/ceph_sample_cohort.h"

#include <charconv>

#include "sample/phantom.h"

namespace maxillo::followup {
namespace {

struct Visit {
  const char* label;
  const char* date_suffix;  // month-day within the patient's treatment year pattern
  int months_after_post;    // -1 = pre, 0 = post
};

LandmarkSet phantom_at(const SamplePatient& p, int months_after_post) {
  PhantomSpec spec = phantom_spec_for_class(SkeletalClass::III);
  spec.spacing_mm = 4;  // landmarks only (analytic): no volume is voxelised
  if (months_after_post >= 0) {
    spec.maxillary_advancement_mm += p.advancement_mm - (months_after_post >= 6 ? p.relapse_mm : 0);
    spec.mandibular_protrusion_mm += p.mandibular_growth_mm_per_year * months_after_post / 12.0;
  }
  return make_phantom_landmarks(spec);
}

// Shortest text that reads back to the same double.
std::string number(double v) {
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, v == 0 ? 0.0 : v);
  return std::string(buffer, result.ptr);
}

}  // namespace

std::vector<SamplePatient> sample_cohort_patients() {
  return {{"P01", 8, 0.3, 0}, {"P02", 10, 0.5, 0}, {"P03", 12, 0.2, 2.5},
          {"P04", 9, 0.8, 0}, {"P05", 11, 0.4, 3}, {"P06", 13, 0.6, 0}};
}

ceph::CohortCase sample_patient_follow_up(const SamplePatient& patient, int first_year) {
  // pre, end of distraction (2 months later), then 6, 12 and 24 months after it.
  const Visit visits[] = {
      {"pre", "01-15", -1}, {"post", "03-15", 0}, {"6M", "09-15", 6}, {"12M", "03-15", 12}, {"24M", "03-15", 24}};
  ceph::CohortCase c{patient.name, {}};
  for (const auto& v : visits) {
    int visit_year = first_year + (v.months_after_post >= 12 ? v.months_after_post / 12 : 0);
    c.time_points.push_back(
        {v.label, std::to_string(visit_year) + "-" + v.date_suffix, phantom_at(patient, v.months_after_post)});
  }
  return c;
}

std::vector<ceph::CohortCase> sample_cohort() {
  std::vector<ceph::CohortCase> cohort;
  int year = 2001;
  for (const auto& patient : sample_cohort_patients()) cohort.push_back(sample_patient_follow_up(patient, year++));
  return cohort;
}

std::string format_cohort_csv(const std::vector<ceph::CohortCase>& cohort) {
  std::string out = "case,time_point,date,label,x,y,z\n";
  for (const auto& c : cohort)
    for (const auto& tp : c.time_points)
      for (const auto& lm : tp.landmarks)
        out += c.name + "," + tp.label + "," + tp.date + "," + lm.label + "," + number(lm.position.x()) + "," +
               number(lm.position.y()) + "," + number(lm.position.z()) + "\n";
  return out;
}

}  // namespace maxillo::followup
