#include "casework/landmarks/case_reorientation.h"

#include "casework/landmarks/automatic_landmarks.h"
#include "casework/landmarks/case_orientation.h"
#include "core/error.h"
#include "core/log.h"
#include "core/temporary_folder.h"
#include "dicom/dicom_series_writer.h"
#include "dicom/dicom_uid.h"
#include "imaging/axis_flip.h"
#include "imaging/head_orientation.h"
#include "landmarking/landmark_detection.h"
#include "records/archived_series.h"
#include "records/case_landmarks.h"
#include "records/derivation.h"

namespace maxillo::casework {
namespace {

std::string case_name(int64_t case_id) { return "case:" + std::to_string(case_id); }

std::string axes_text(const Eigen::Matrix3d& flip) {
  if (flip(1, 1) < 0 && flip(2, 2) < 0) return "y and z";
  return flip(1, 1) < 0 ? "y" : "z";
}

// Throws when the check on the original gives no axis flip to undo.
Eigen::Matrix3d required_correction(const HeadOrientation& found, int64_t case_id) {
  if (auto flip = axis_flip_correction(found)) return *flip;
  std::string why = found.finding();
  if (found.sideways)
    why +=
        ". A face pointing sideways is not an axis flip: correct the scan (or its conversion) and import it again, "
        "or confirm the volume as it is with --confirm";
  else
    why += ": there is no flipped axis to undo";
  throw Error(ErrorCode::kBadValue, case_name(case_id), "cannot reorient: " + why);
}

// The original series' patient and study, a derived UID and a description saying what was done.
SeriesMetadata corrected_metadata(const CaseContents& contents, int64_t series, const std::string& axes) {
  SeriesMetadata m;
  m.patient_name = contents.patient.name;
  m.patient_id = contents.patient.patient_id;
  m.patient_birth_date = contents.patient.birth_date;
  m.patient_sex = contents.patient.sex;
  for (const auto& entry : contents.series) {
    if (entry.series.id != series) continue;
    m.series_description = entry.series.description + " (reoriented: " + axes + " flipped back)";
    m.series_number = entry.series.number.value_or(1);
    m.modality = entry.series.modality;
    m.series_instance_uid = derived_uid("maxillo reoriented " + entry.series.series_uid + " " + axes);
    for (const auto& study : contents.studies)
      if (study.id == entry.series.study) {
        m.study_instance_uid = study.study_uid;
        m.study_date = study.date;
        m.study_time = study.time.empty() ? m.study_time : study.time;
        m.study_description = study.description;
        m.accession_number = study.accession;
      }
  }
  return m;
}

int64_t import_corrected(Archive& archive, int64_t case_id, const Volume& corrected, const SeriesMetadata& metadata) {
  TemporaryFolder scratch("maxillo-reorient");
  const auto written = write_ct_series(corrected, metadata, scratch.path());
  const auto report = archive.import_paths({scratch.path()});
  if (!report.all_ok())
    throw Error(ErrorCode::kBatchPartlyFailed, case_name(case_id), "the corrected series did not import cleanly");
  return archive.resolve_series(written.series_instance_uid);
}

// A set given by hand on the flipped volume, mapped to the corrected one; else a new detection.
void carry_landmarks(Archive& archive, int64_t case_id, const Volume& corrected, const Eigen::Vector3d& centre,
                     ReorientedCase& result) {
  const auto preferred = records::preferred_landmarks(archive, case_id);
  if (preferred && !preferred->automatic && preferred->frame.geometry != LandmarkGeometry::kCephalogram) {
    LandmarkSet mapped = preferred->landmarks;
    for (auto& l : mapped) l.position = centre + result.flip * (l.position - centre);
    records::attach_landmarks(archive, case_id, mapped, preferred->source + ", mapped with the reoriented CT",
                              preferred->time_point, preferred->frame);
    result.landmarks_mapped = true;
  } else if (preferred) {
    const auto detection = landmarking::detect_landmarks(corrected, case_name(case_id));
    records::attach_automatic_landmarks(archive, case_id, detection.present(), automatic_facts(detection));
    result.landmarks_detected = true;
  }
}

}  // namespace

ReorientedCase reorient_case(Archive& archive, int64_t case_id) {
  const auto contents = archive.case_contents(case_id);
  ReorientedCase result;
  result.original_series = records::primary_series(contents);
  Volume ct = records::load_archived_series(archive, result.original_series);
  result.flip = required_correction(check_head_orientation(ct), case_id);
  result.flipped_axes = axes_text(result.flip);

  const Eigen::Vector3d centre = grid_centre(ct.geometry);
  ct.geometry = flipped_about_centre(ct.geometry, result.flip);
  result.corrected_series =
      import_corrected(archive, case_id, ct, corrected_metadata(contents, result.original_series, result.flipped_axes));
  if (result.corrected_series != result.original_series) {
    archive.set_series_role(case_id, result.original_series, "unassigned");
    archive.set_series_role(case_id, result.corrected_series, "preop");
  }
  carry_landmarks(archive, case_id, ct, centre, result);
  result.record = case_orientation(archive, case_id);
  log::debug(case_name(case_id), ": reoriented (", result.flipped_axes, " flipped back); ", result.record.finding);
  return result;
}

}  // namespace maxillo::casework
