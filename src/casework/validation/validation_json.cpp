#include "casework/validation/validation_json.h"

#include "occlusion/occlusion_files.h"
#include "records/derivation.h"
#include "records/validation_record.h"
#include "planning/osteotomy.h"

namespace maxillo::casework {
namespace {

Json segment_json(const SegmentOutcome& s) {
  const Eigen::AngleAxisd turn((s.planned.rotation().transpose() * s.actual.rotation()));
  return Json{{"segment", planning::segment_name(planning::Segment(s.segment))},
              {"planned", occlusion::transform_to_json(s.planned)},
              {"actual", occlusion::transform_to_json(s.actual)},
              {"icp_rms_mm", s.icp_rms_mm},
              {"mean_difference_mm", s.mean_difference_mm},
              {"max_difference_mm", s.max_difference_mm},
              {"rotation_difference_deg", turn.angle() * 180 / M_PI}};
}

}  // namespace

Json to_json(const validation::DistanceStatistics& s) {
  return Json{{"count", s.count},
              {"mean_absolute", s.mean_absolute},
              {"mean_signed", s.mean_signed},
              {"sd", s.standard_deviation},
              {"p5", s.p5},
              {"p25", s.p25},
              {"p50", s.p50},
              {"p75", s.p75},
              {"p90", s.p90},
              {"p95", s.p95},
              {"max_absolute", s.max_absolute},
              {"within_tolerance_percent", s.within_tolerance_percent}};
}

Json validation_json(const CaseValidation& v, const CaseContents& contents) {
  Json segments = Json::array();
  for (const auto& s : v.segments) segments.push_back(segment_json(s));
  Json regions = Json::array();
  for (const auto& r : v.statistics)
    regions.push_back({{"region", r.region},
                       {"closest", to_json(r.closest)},
                       {"corresponding", r.corresponding.count ? to_json(r.corresponding) : Json(nullptr)}});
  return Json{{"format_version", records::ValidationRecord::kFormatVersion},
              {"case", v.case_id},
              {"case_label", contents.record.label},
              {"preop_series", v.preop_series},
              {"postop_series", v.postop_series},
              {"preop_date", records::study_date_of(contents, v.preop_series)},
              {"postop_date", records::study_date_of(contents, v.postop_series)},
              {"inputs_hash", v.inputs_hash},
              {"registration",
               {{"moving_to_fixed", occlusion::transform_to_json(v.registration.moving_to_fixed)},
                {"metric", v.registration.metric},
                {"iterations", v.registration.iterations},
                {"seconds", v.registration.seconds},
                {"cranium_icp_rms_mm", v.cranium_icp_rms_mm}}},
              {"segments", segments},
              {"regions", regions},
              {"seconds", v.seconds}};
}

records::ValidationToStore validation_to_store(const CaseValidation& validation) {
  records::ValidationToStore stored;
  stored.case_id = validation.case_id;
  stored.inputs_hash = validation.inputs_hash;
  stored.summary = validation.summary;
  stored.pictures = validation.error_maps;
  stored.pictures.push_back(validation.profile_png);
  stored.face_closest_mm = validation.closest_mm;
  for (const auto region : validation.regions) stored.face_regions.emplace_back(validation::region_name(region));
  return stored;
}

}  // namespace maxillo::casework
