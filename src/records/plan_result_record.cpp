#include "records/plan_result_record.h"

#include "core/error.h"
#include "core/json_reader.h"

namespace maxillo::records {
namespace {

using Record = PlanResultRecord;

int days(JsonReader& r, const std::string& key) { return int(r.required_integer(key, 0, 100000)); }

Record::Vector read_vector(JsonReader r) {
  return {r.required_point("entry"), r.required_number("outward_deg"), r.required_number("elevation_deg"),
          r.required_number("activation_mm")};
}

Record::ScheduleSide read_schedule_side(JsonReader r) {
  Record::ScheduleSide s;
  s.activation_mm = r.required_number("activation_mm");
  s.turns = r.required_number("turns");
  s.delivered_mm = r.required_number("delivered_mm");
  s.first_day = days(r, "first_day");
  s.last_day = days(r, "last_day");
  s.distraction_days = days(r, "distraction_days");
  return s;
}

Record::Schedule read_schedule(JsonReader r) {
  Record::Schedule s;
  s.latency_days = days(r, "latency_days");
  s.rate_mm_per_day = r.required_number("rate_mm_per_day");
  s.activations_per_day = int(r.required_integer("activations_per_day", 0, 1000));
  s.mm_per_turn = r.required_number("mm_per_turn");
  s.turns_per_activation = r.required_number("turns_per_activation");
  s.right = read_schedule_side(r.object("right"));
  s.left = read_schedule_side(r.object("left"));
  s.distraction_end_day = days(r, "distraction_end_day");
  s.consolidation_end_day = days(r, "consolidation_end_day");
  return s;
}

Record::Distraction read_distraction(JsonReader r) {
  Record::Distraction d;
  JsonReader vectors = r.object("vectors");
  d.right = read_vector(vectors.object("right"));
  d.left = read_vector(vectors.object("left"));
  d.divergence_deg = vectors.required_number("divergence_deg");
  d.angle_deg = vectors.required_number("angle_deg");
  const Json& checks = r.required_array("checks");
  for (size_t i = 0; i < checks.size(); ++i) {
    JsonReader c = r.element(checks, "checks", i);
    d.checks.push_back({c.required_text("side"), c.required_text("name"), c.required_text("status"),
                        c.required_text("reason"), c.required_number("value_mm"), c.required_number("limit_mm")});
  }
  d.schedule = read_schedule(r.object("schedule"));
  JsonReader simulation = r.object("forward_simulation");
  const Json& points = simulation.required_array("points");
  for (size_t i = 0; i < points.size(); ++i) {
    JsonReader p = simulation.element(points, "points", i);
    d.simulation.push_back({p.required_text("label"), p.required_point("target"), p.required_point("simulated"),
                            p.required_number("error_mm")});
  }
  d.max_error_mm = simulation.required_number("max_error_mm");
  // Results stored before the open-sinus reading have no notes: both sinuses were closed air.
  if (r.has("sinus_notes")) d.sinus_notes = r.required_texts("sinus_notes");
  return d;
}

Record::Osteotomy read_osteotomy(JsonReader r) {
  Record::Osteotomy o;
  const Json& segments = r.required_array("segments");
  for (size_t i = 0; i < segments.size(); ++i) {
    JsonReader s = r.element(segments, "segments", i);
    o.segments.push_back({s.required_text("segment"), s.required_integer("voxels", 0), s.required_number("volume_ml")});
  }
  o.bone_voxels = r.required_integer("bone_voxels", 0);
  if (r.has("transfer_model")) {
    JsonReader m = r.object("transfer_model");
    o.transfer_model = Record::TransferModel{m.required_bool("watertight"), m.required_integer("triangles", 0),
                                             m.required_number("volume_ml")};
  }
  return o;
}

std::vector<std::pair<std::string, std::filesystem::path>> read_files(JsonReader& r) {
  const Json& files = r.at("files");
  if (!files.is_object()) r.fail("files", "must be an object of label: path");
  std::vector<std::pair<std::string, std::filesystem::path>> read;
  for (auto it = files.begin(); it != files.end(); ++it) {
    if (!it.value().is_string()) r.fail("files." + it.key(), "must be a path");
    read.emplace_back(it.key(), it.value().get<std::string>());
  }
  return read;
}

// The plan inside the result, parsed by the plan's own strict reader; its errors become the
// record's (a damaged archive, not a bad file a person gave us).
planning::Plan read_plan(const Json& json, const std::string& source) {
  try {
    return planning::plan_from_json(json, source + " plan");
  } catch (const Error& e) {
    throw Error(ErrorCode::kArchiveCorrupt, "", e.what());
  }
}

}  // namespace

Json plan_result_record_json(const planning::PlanResult& result, Json osteotomy) {
  Json json = planning::plan_result_json(result);
  json["osteotomy"] = std::move(osteotomy);
  json["format_version"] = PlanResultRecord::kFormatVersion;
  return json;
}

PlanResultRecord read_plan_result_record(const Json& json, const std::string& source) {
  JsonReader r(json, "", source, ErrorCode::kArchiveCorrupt, "plan result");
  Record record;
  record.format_version = r.format_version(Record::kFormatVersion);
  record.plan = read_plan(r.at("plan"), source);
  record.frame_source = r.object("frame").required_text("source");
  record.feasible = r.required_bool("feasible");
  record.refusals = r.required_texts("refusals");
  record.moves = planning::planned_moves_from_json(json, source);
  if (r.has("distraction")) record.distraction = read_distraction(r.object("distraction"));
  record.files = read_files(r);
  if (r.has("osteotomy")) record.osteotomy = read_osteotomy(r.object("osteotomy"));
  return record;
}

}  // namespace maxillo::records
