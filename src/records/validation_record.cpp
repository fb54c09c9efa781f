#include "records/validation_record.h"

#include "core/error.h"
#include "core/json_reader.h"

namespace maxillo::records {
namespace {

validation::DistanceStatistics read_statistics(JsonReader r) {
  validation::DistanceStatistics s;
  s.count = int(r.required_integer("count", 0, std::numeric_limits<int>::max()));
  s.mean_absolute = r.required_number("mean_absolute");
  s.mean_signed = r.required_number("mean_signed");
  s.standard_deviation = r.required_number("sd");
  s.p5 = r.required_number("p5");
  s.p25 = r.required_number("p25");
  s.p50 = r.required_number("p50");
  s.p75 = r.required_number("p75");
  s.p90 = r.required_number("p90");
  s.p95 = r.required_number("p95");
  s.max_absolute = r.required_number("max_absolute");
  s.within_tolerance_percent = r.required_number("within_tolerance_percent", 0, 100);
  return s;
}

ValidationRecord::Registration read_registration(JsonReader r) {
  ValidationRecord::Registration g;
  g.moving_to_fixed = r.required_rigid_transform("moving_to_fixed");
  g.metric = r.required_number("metric");
  g.iterations = int(r.required_integer("iterations", 0, 1000000));
  g.seconds = r.required_number("seconds", 0);
  g.cranium_icp_rms_mm = r.required_number("cranium_icp_rms_mm", 0);
  return g;
}

ValidationRecord::Segment read_segment(JsonReader r) {
  ValidationRecord::Segment s;
  s.segment = r.required_text("segment");
  s.planned = r.required_rigid_transform("planned");
  s.actual = r.required_rigid_transform("actual");
  s.icp_rms_mm = r.required_number("icp_rms_mm", 0);
  s.mean_difference_mm = r.required_number("mean_difference_mm", 0);
  s.max_difference_mm = r.required_number("max_difference_mm", 0);
  s.rotation_difference_deg = r.required_number("rotation_difference_deg", 0);
  return s;
}

ValidationRecord::Region read_region(JsonReader r) {
  ValidationRecord::Region region;
  region.region = r.required_text("region");
  region.closest = read_statistics(r.object("closest"));
  if (!r.at("corresponding").is_null()) region.corresponding = read_statistics(r.object("corresponding"));
  return region;
}

}  // namespace

ValidationRecord read_validation_record(const Json& json, const std::string& source) {
  JsonReader r(json, "", source, ErrorCode::kArchiveCorrupt, "validation");
  ValidationRecord v;
  v.format_version = r.format_version(ValidationRecord::kFormatVersion);
  v.case_id = r.required_integer("case", 1);
  v.case_label = r.required_text("case_label");
  v.preop_series = r.required_integer("preop_series", 1);
  v.postop_series = r.required_integer("postop_series", 1);
  v.preop_date = r.required_text("preop_date");
  v.postop_date = r.required_text("postop_date");
  v.inputs_hash = r.required_text("inputs_hash");
  v.registration = read_registration(r.object("registration"));
  const Json& segments = r.required_array("segments");
  for (size_t i = 0; i < segments.size(); ++i) v.segments.push_back(read_segment(r.element(segments, "segments", i)));
  const Json& regions = r.required_array("regions");
  for (size_t i = 0; i < regions.size(); ++i) v.regions.push_back(read_region(r.element(regions, "regions", i)));
  if (v.regions.empty()) r.fail("regions", "must hold the face's statistics at least");
  v.seconds = r.required_number("seconds", 0);
  return v;
}

}  // namespace maxillo::records
