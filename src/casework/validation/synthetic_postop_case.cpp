#include "casework/validation/synthetic_postop_case.h"

#include "casework/validation/case_validation.h"
#include "casework/validation/validation_json.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "dicom/dicom_series_writer.h"
#include "dicom/dicom_uid.h"
#include "occlusion/occlusion_files.h"
#include "records/derivation.h"
#include "validation/region_statistics.h"

namespace maxillo::casework {
namespace {

std::string one_year_later(const std::string& dicom_date) {
  if (dicom_date.size() != 8) return "";
  return std::to_string(std::stoi(dicom_date.substr(0, 4)) + 1) + dicom_date.substr(4);
}

SeriesMetadata postop_metadata(const CaseContents& contents, int64_t preop_series, const std::string& study_date,
                               const Json& truth_parameters) {
  SeriesMetadata m;
  m.patient_name = contents.patient.name;
  m.patient_id = contents.patient.patient_id;
  m.patient_birth_date = contents.patient.birth_date;
  m.patient_sex = contents.patient.sex;
  m.study_date = study_date.empty() ? one_year_later(records::study_date_of(contents, preop_series)) : study_date;
  m.study_description = "Post-operative CT (synthetic)";
  m.series_description = "post-operative CT, synthetic: planned moves, predicted face + known error";
  m.series_number = 2;
  // UIDs derived from the pre-operative series and what was asked: the same request gives the same scan, so making it
  // again re-imports as "already archived" instead of a second series.
  std::string preop_uid;
  for (const auto& entry : contents.series)
    if (entry.series.id == preop_series) preop_uid = entry.series.series_uid;
  const std::string seed =
      "maxillo synthetic post-op of " + preop_uid + " " + truth_parameters.dump() + " " + m.study_date;
  m.study_instance_uid = derived_uid(seed + " study");
  m.series_instance_uid = derived_uid(seed + " series");
  return m;
}

// The answer: the known signed error per region, as the validation's statistics would give it.
Json truth_json(const SyntheticPostop& postop, const PlannedCase& planned, const SyntheticPostopOptions& options) {
  Json by_region = Json::array();
  const auto regions = face_regions_of(planned.skin, planned.landmarks);
  for (const auto& r : validation::statistics_by_region(postop.known_error_mm, regions))
    by_region.push_back({{"region", r.region}, {"known_error", to_json(r.statistics)}});
  return Json{
      {"postop_to_preop", occlusion::transform_to_json(postop.postop_to_preop)},
      {"error",
       {{"amplitude_mm", options.error_mm}, {"sigma_mm", options.error_sigma_mm}, {"centre", options.error_centre}}},
      {"regions", by_region}};
}

}  // namespace

SyntheticPostopCase make_synthetic_postop_case(Archive& archive, int64_t case_id, const SyntheticPostopOptions& options,
                                               const std::filesystem::path& out, bool import_into_archive,
                                               const std::string& study_date, const PlannedCase* given) {
  const PlannedCase loaded = given ? PlannedCase{} : load_planned_case(archive, case_id);
  const PlannedCase& planned = given ? *given : loaded;
  SyntheticPostopCase result;
  result.postop = make_synthetic_postop(planned, options);
  result.dicom_folder = out / "ct";
  const auto contents = archive.case_contents(case_id);
  const Json request{{"error_mm", options.error_mm},           {"sigma_mm", options.error_sigma_mm},
                     {"centre", options.error_centre},         {"reposition_deg", options.reposition_deg},
                     {"reposition_mm", options.reposition_mm}, {"plan", planned.plan.sha256}};
  std::filesystem::remove_all(result.dicom_folder);  // never a mix of two requests' slices
  const auto written = write_ct_series(
      result.postop.ct, postop_metadata(contents, planned.preop_series, study_date, request), result.dicom_folder);
  result.series_uid = written.series_instance_uid;
  result.truth = truth_json(result.postop, planned, options);
  result.truth["series_instance_uid"] = result.series_uid;
  result.truth_json = out / "truth.json";
  write_file_atomically(result.truth_json, result.truth.dump(2) + "\n");
  if (import_into_archive) {
    const auto report = archive.import_paths({result.dicom_folder});
    if (!report.all_ok())
      throw Error(ErrorCode::kBatchPartlyFailed, result.dicom_folder.string(),
                  "the synthetic series did not import cleanly");
    result.series = archive.resolve_series(result.series_uid);
    archive.set_series_role(case_id, *result.series, "postop");
  }
  return result;
}

}  // namespace maxillo::casework
