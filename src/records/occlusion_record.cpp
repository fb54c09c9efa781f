#include "records/occlusion_record.h"

#include <limits>

#include "core/error.h"
#include "core/json_reader.h"
#include "occlusion/occlusion_files.h"

namespace maxillo::records {
namespace {

using Record = OcclusionRecord;

constexpr int kMaxCount = std::numeric_limits<int>::max();

int count(JsonReader& r, const std::string& key) { return int(r.required_integer(key, 0, kMaxCount)); }

Json arch_json(const Record::Arch& arch) {
  Json teeth = Json::array();
  for (const occlusion::ToothContacts& t : arch.teeth)
    teeth.push_back({{"component", t.component},
                     {"vertices", t.vertices},
                     {"contact_vertices", t.contact_vertices},
                     {"contact_area_mm2", t.contact_area_mm2},
                     {"min_distance_mm", t.min_distance_mm}});
  return {{"contact_vertices", arch.contact_vertices}, {"contact_area_mm2", arch.contact_area_mm2}, {"teeth", teeth}};
}

Json repair_json(const occlusion::ArchRepairReport& r) {
  return {{"shells", r.shells},
          {"shells_flipped", r.shells_flipped},
          {"degenerate_faces_removed", r.degenerate_faces_removed},
          {"open_edges", r.open_edges},
          {"notes", r.notes}};
}

Json splint_json(const Record& record) {
  if (!record.splint_error.empty()) return {{"error", record.splint_error}};
  if (!record.splint) return nullptr;
  const Record::Splint& s = *record.splint;
  return {{"file", s.file},
          {"minimum_thickness_mm", s.minimum_thickness_mm},
          {"imprint_depth_mm", s.imprint_depth_mm},
          {"clearance_mm", s.clearance_mm},
          {"voxel_mm", s.voxel_mm},
          {"thickness_mm", s.thickness_mm},
          {"thickness_columns", s.thickness_columns},
          {"volume_mm3", s.volume_mm3},
          {"triangles", s.triangles},
          {"watertight", s.watertight},
          {"components", s.components},
          {"min_distance_upper_mm", s.min_distance_upper_mm},
          {"min_distance_lower_mm", s.min_distance_lower_mm},
          {"intersecting_pairs_upper", s.intersecting_pairs_upper},
          {"intersecting_pairs_lower", s.intersecting_pairs_lower},
          {"seconds", s.seconds}};
}

Record::Arch read_arch(JsonReader r) {
  Record::Arch arch;
  arch.contact_vertices = count(r, "contact_vertices");
  arch.contact_area_mm2 = r.required_number("contact_area_mm2", 0);
  const Json& teeth = r.required_array("teeth");
  for (size_t i = 0; i < teeth.size(); ++i) {
    JsonReader t = r.element(teeth, "teeth", i);
    occlusion::ToothContacts tooth;
    tooth.component = count(t, "component");
    tooth.vertices = count(t, "vertices");
    tooth.contact_vertices = count(t, "contact_vertices");
    tooth.contact_area_mm2 = t.required_number("contact_area_mm2", 0);
    tooth.min_distance_mm = t.required_number("min_distance_mm");
    arch.teeth.push_back(tooth);
  }
  return arch;
}

occlusion::ArchRepairReport read_repair(JsonReader r) {
  occlusion::ArchRepairReport repair;
  repair.shells = count(r, "shells");
  repair.shells_flipped = count(r, "shells_flipped");
  repair.degenerate_faces_removed = count(r, "degenerate_faces_removed");
  repair.open_edges = count(r, "open_edges");
  repair.notes = r.required_texts("notes");
  return repair;
}

Record::Splint read_splint(JsonReader r) {
  Record::Splint s;
  s.file = r.required_text("file");
  s.minimum_thickness_mm = r.required_number("minimum_thickness_mm", 0);
  s.imprint_depth_mm = r.required_number("imprint_depth_mm", 0);
  s.clearance_mm = r.required_number("clearance_mm", 0);
  s.voxel_mm = r.required_number("voxel_mm", 0);
  s.thickness_mm = r.required_number("thickness_mm", 0);
  s.thickness_columns = count(r, "thickness_columns");
  s.volume_mm3 = r.required_number("volume_mm3", 0);
  s.triangles = r.required_integer("triangles", 0);
  s.watertight = r.required_bool("watertight");
  s.components = count(r, "components");
  s.min_distance_upper_mm = r.required_number("min_distance_upper_mm");
  s.min_distance_lower_mm = r.required_number("min_distance_lower_mm");
  s.intersecting_pairs_upper = r.required_integer("intersecting_pairs_upper", 0);
  s.intersecting_pairs_lower = r.required_integer("intersecting_pairs_lower", 0);
  s.seconds = r.required_number("seconds", 0);
  return s;
}

void read_splint_field(JsonReader& r, Record& record) {
  const Json& splint = r.at("splint");
  if (splint.is_null()) return;  // none asked for
  if (!splint.is_object()) r.fail("splint", "must be an object or null");
  JsonReader s = r.object("splint");
  if (s.has("error"))
    record.splint_error = s.required_text("error");
  else
    record.splint = read_splint(s);
}

}  // namespace

Json to_json(const OcclusionRecord& record) {
  Json residuals = Json::array();
  for (double r : record.residual_spring_mm) residuals.push_back(r);
  Json json{{"format_version", record.format_version},
            {"upper_file", record.upper_file},
            {"lower_file", record.lower_file},
            {"frame", record.frame},
            {"upper_transform", occlusion::transform_to_json(record.upper_transform)},
            {"start_transform", occlusion::transform_to_json(record.start_transform)},
            {"status", record.converged ? "converged" : "iteration_limit"},
            {"iterations", record.iterations},
            {"residual_spring_mm", residuals},
            {"penetration_mm", record.penetration_mm},
            {"allowed_penetration_mm", record.allowed_penetration_mm},
            {"intersecting_triangle_pairs", record.intersecting_triangle_pairs},
            {"contact_threshold_mm", record.contact_threshold_mm},
            {"upper", arch_json(record.upper)},
            {"lower", arch_json(record.lower)},
            {"repairs", {{"upper", repair_json(record.upper_repair)}, {"lower", repair_json(record.lower_repair)}}},
            {"splint", splint_json(record)},
            {"files", record.files}};
  if (record.upper_centroid)
    json["upper_centroid"] = {record.upper_centroid->x(), record.upper_centroid->y(), record.upper_centroid->z()};
  return json;
}

OcclusionRecord read_occlusion_record(const Json& json, const std::string& source) {
  JsonReader r(json, "", source, ErrorCode::kArchiveCorrupt, "occlusion result");
  Record record;
  record.format_version = r.format_version(Record::kFormatVersion);
  record.upper_file = r.required_text("upper_file");
  record.lower_file = r.required_text("lower_file");
  record.frame = r.required_text("frame");
  record.upper_transform = r.required_rigid_transform("upper_transform");
  record.start_transform = r.required_rigid_transform("start_transform");
  if (record.format_version >= 2) record.upper_centroid = r.required_point("upper_centroid");
  const std::string status = r.required_text("status");
  if (status != "converged" && status != "iteration_limit")
    r.fail("status", "must be \"converged\" or \"iteration_limit\"");
  record.converged = status == "converged";
  record.iterations = count(r, "iterations");
  const Json& residuals = r.required_array("residual_spring_mm");
  for (size_t i = 0; i < residuals.size(); ++i) {
    if (!residuals[i].is_number()) r.fail("residual_spring_mm[" + std::to_string(i) + "]", "must be a number");
    record.residual_spring_mm.push_back(residuals[i].get<double>());
  }
  record.penetration_mm = r.required_number("penetration_mm");
  record.allowed_penetration_mm = r.required_number("allowed_penetration_mm", 0);
  record.intersecting_triangle_pairs = r.required_integer("intersecting_triangle_pairs", 0);
  record.contact_threshold_mm = r.required_number("contact_threshold_mm", 0);
  record.upper = read_arch(r.object("upper"));
  record.lower = read_arch(r.object("lower"));
  JsonReader repairs = r.object("repairs");
  record.upper_repair = read_repair(repairs.object("upper"));
  record.lower_repair = read_repair(repairs.object("lower"));
  read_splint_field(r, record);
  record.files = r.required_texts("files");
  return record;
}

}  // namespace maxillo::records
