#include "records/cohort_archive.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace maxillo::records {
namespace {

// Positions survive the markups JSON exactly; the tolerance only guards against printing noise.
constexpr double kSamePositionMm = 1e-9;

bool same_points(const LandmarkSet& a, const LandmarkSet& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].label != b[i].label || (a[i].position - b[i].position).cwiseAbs().maxCoeff() > kSamePositionMm)
      return false;
  return true;
}

bool same_frame(const LandmarkFrame& a, const LandmarkFrame& b) {
  if (a.geometry != b.geometry) return false;
  if (a.geometry != LandmarkGeometry::kCephalogram) return true;
  return a.axes.pixel_spacing_mm == b.axes.pixel_spacing_mm && a.axes.vertical == b.axes.vertical &&
         a.axes.facing == b.axes.facing;
}

LandmarkFrame resolved(const LandmarkFrame& frame, const LandmarkSet& landmarks) {
  if (frame.geometry != LandmarkGeometry::kAuto) return frame;
  const bool flat =
      std::all_of(landmarks.begin(), landmarks.end(), [](const Landmark& l) { return l.position.z() == 0; });
  return {flat ? LandmarkGeometry::kCephalogram : LandmarkGeometry::kVolumeLps, frame.axes};
}

bool already_stored(const std::vector<StoredLandmarks>& stored, const ceph::TimePointSet& tp,
                    const LandmarkFrame& frame) {
  for (const auto& s : stored)
    if (s.time_point.label == tp.label)
      return s.time_point.date == tp.date && same_frame(s.frame, frame) && same_points(s.landmarks, tp.landmarks);
  return false;
}

std::vector<CaseRecord> cohort_cases(const Archive& archive, const std::string& cohort_name) {
  std::vector<CaseRecord> cases;
  for (const auto& c : archive.cases())
    if (c.label == cohort_case_label(cohort_name)) cases.push_back(c);
  std::sort(cases.begin(), cases.end(), [](const CaseRecord& a, const CaseRecord& b) { return a.id < b.id; });
  if (cases.empty())
    throw Error(ErrorCode::kNotFound, cohort_name,
                "no cohort of this name in the archive (maxillo followup --import-cohort)");
  return cases;
}

std::string patient_id_of(const Archive& archive, const CaseRecord& c) {
  auto patient = archive.patient(c.patient);
  return patient ? patient->patient_id : "case " + std::to_string(c.id);
}

}  // namespace

std::string cohort_case_label(const std::string& cohort_name) { return "cohort:" + cohort_name; }

CohortImportReport import_cohort(Archive& archive, const std::vector<ceph::CohortCase>& cohort,
                                 const std::string& cohort_name, const LandmarkFrame& frame,
                                 const std::string& source) {
  if (cohort_name.empty()) throw Error(ErrorCode::kBadValue, source, "empty cohort name");
  CohortImportReport report;
  for (const auto& c : cohort)
    attach_cohort_time_points(archive, archive.ensure_case(c.name, cohort_case_label(cohort_name)), c, frame, source,
                              report);
  return report;
}

void attach_cohort_time_points(Archive& archive, int64_t case_id, const ceph::CohortCase& cohort_case,
                               const LandmarkFrame& frame, const std::string& source, CohortImportReport& report,
                               LandmarkOrigin origin) {
  const auto stored = landmark_time_points(archive, case_id);
  for (const auto& tp : cohort_case.time_points) {
    const LandmarkFrame set_frame = resolved(frame, tp.landmarks);
    if (already_stored(stored, tp, set_frame)) {
      ++report.sets_unchanged;
      continue;
    }
    attach_landmarks(archive, case_id, tp.landmarks, source, {tp.label, tp.date}, set_frame, origin);
    ++report.sets_stored;
  }
  ++report.cases;
}

std::vector<ceph::CohortCase> archived_cohort(const Archive& archive, const std::string& cohort_name) {
  std::vector<ceph::CohortCase> cohort;
  for (const auto& c : cohort_cases(archive, cohort_name)) {
    ceph::CohortCase out{patient_id_of(archive, c), {}};
    for (auto& stored : landmark_time_points(archive, c.id))
      out.time_points.push_back({stored.time_point.label, stored.time_point.date, std::move(stored.landmarks)});
    cohort.push_back(std::move(out));
  }
  return cohort;
}

ceph::CaseFollowUp archived_case_follow_up(const Archive& archive, int64_t case_id, const std::string& name,
                                           ceph::Sex sex) {
  std::vector<ceph::TimePointAnalysis> analyses;
  for (const auto& stored : landmark_time_points(archive, case_id)) {
    auto sagittal = to_sagittal(stored.landmarks, stored.frame.geometry, stored.frame.axes,
                                "case " + std::to_string(case_id) + " time point " + stored.time_point.label);
    analyses.push_back({stored.time_point.label, stored.time_point.date, ceph::analyse(sagittal, sex)});
  }
  return ceph::make_follow_up(name, std::move(analyses));
}

std::vector<ceph::CaseFollowUp> archived_cohort_follow_up(const Archive& archive, const std::string& cohort_name,
                                                          ceph::Sex sex) {
  std::vector<ceph::CaseFollowUp> cohort;
  for (const auto& c : cohort_cases(archive, cohort_name))
    cohort.push_back(archived_case_follow_up(archive, c.id, patient_id_of(archive, c), sex));
  return cohort;
}

}  // namespace maxillo::records
