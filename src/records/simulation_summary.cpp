#include "records/simulation_summary.h"

#include <limits>

#include "core/error.h"
#include "core/json_reader.h"
#include "softtissue/bone_attachment.h"
#include "softtissue/soft_tissue_model.h"

namespace maxillo::records {
namespace {

constexpr int kMaxCount = std::numeric_limits<int>::max();

int count(JsonReader& r, const std::string& key) { return int(r.required_integer(key, 0, kMaxCount)); }

SoftTissueTimings read_seconds(JsonReader r) {
  SoftTissueTimings s;
  s.region = r.required_number("region", 0);
  s.meshing = r.required_number("meshing", 0);
  s.attachment = r.required_number("attachment", 0);
  s.assembly = r.required_number("assembly", 0);
  s.solve = r.required_number("solve", 0);
  s.mapping = r.required_number("mapping", 0);
  return s;
}

SimulationSummary::UncertaintyBand read_band(JsonReader r) {
  SimulationSummary::UncertaintyBand band;
  band.runs = r.required_texts("runs");
  band.p95_mm = r.required_number("p95_mm", 0);
  band.max_mm = r.required_number("max_mm", 0);
  return band;
}

SimulationSummary::LandmarkMove read_landmark_move(JsonReader r) {
  SimulationSummary::LandmarkMove move;
  move.label = r.required_text("label");
  move.forward_mm = r.required_number("forward_mm");
  move.up_mm = r.required_number("up_mm");
  move.left_mm = r.required_number("left_mm");
  move.total_mm = r.required_number("total_mm", 0);
  return move;
}

// The fields version 2 added: required from version 2 on.
void read_report_facts(JsonReader& r, SimulationSummary& s) {
  s.plan_text = r.required_text("plan_text");
  s.meshing_attempts = count(r, "meshing_attempts");
  s.mean_aspect_ratio = r.required_number("mean_aspect_ratio", 0);
  const Json& landmarks = r.required_array("soft_landmarks");
  for (size_t i = 0; i < landmarks.size(); ++i)
    s.soft_landmarks.push_back(read_landmark_move(r.element(landmarks, "soft_landmarks", i)));
}

std::optional<double> optional_fraction(JsonReader& r, const std::string& key) {
  if (r.at(key).is_null()) return std::nullopt;
  return r.required_number(key);
}

SimulationSummary::ProfilePoint read_profile_point(JsonReader r) {
  SimulationSummary::ProfilePoint point;
  point.label = r.required_text("label");
  point.present = r.required_bool("present");
  point.forward_mm = r.required_number("forward_mm");
  point.ratio = r.required_number("ratio");
  point.published = r.required_text("published");
  point.source = r.required_text("source");
  point.plausible_low = optional_fraction(r, "plausible_low");
  point.plausible_high = optional_fraction(r, "plausible_high");
  return point;
}

SimulationSummary::ProfileResponse read_profile_response(JsonReader r) {
  SimulationSummary::ProfileResponse response;
  response.advancement_mm = r.required_number("advancement_mm");
  response.reference = r.required_text("reference");
  response.other_segments_moved = r.required_bool("other_segments_moved");
  response.gradient_p999 = r.required_number("gradient_p999", 0);
  response.gradient_max = r.required_number("gradient_max", 0);
  response.steepest_near = r.required_text("steepest_near");
  response.steepest_near_mm = r.required_number("steepest_near_mm", 0);
  const Json& points = r.required_array("points");
  for (size_t i = 0; i < points.size(); ++i)
    response.points.push_back(read_profile_point(r.element(points, "points", i)));
  return response;
}

Json optional_json(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

Json profile_response_json(const SimulationSummary::ProfileResponse& response) {
  Json points = Json::array();
  for (const auto& p : response.points)
    points.push_back({{"label", p.label},
                      {"present", p.present},
                      {"forward_mm", p.forward_mm},
                      {"ratio", p.ratio},
                      {"published", p.published},
                      {"source", p.source},
                      {"plausible_low", optional_json(p.plausible_low)},
                      {"plausible_high", optional_json(p.plausible_high)}});
  return {{"advancement_mm", response.advancement_mm},
          {"reference", response.reference},
          {"other_segments_moved", response.other_segments_moved},
          {"gradient_p999", response.gradient_p999},
          {"gradient_max", response.gradient_max},
          {"steepest_near", response.steepest_near},
          {"steepest_near_mm", response.steepest_near_mm},
          {"points", points}};
}

}  // namespace

Json to_json(const SimulationSummary& s) {
  Json json{{"format_version", s.format_version},
            {"model", s.model},
            {"plan_application", s.plan_application_stored ? "stored" : "applied"},
            {"poisson_ratio", s.poisson_ratio},
            {"tetrahedra", s.tetrahedra},
            {"nodes", s.nodes},
            {"cell_size_mm", s.cell_size_mm},
            {"tet_budget", s.tet_budget},
            {"over_tet_budget", s.over_tet_budget},
            {"min_dihedral_deg", s.min_dihedral_deg},
            {"max_aspect_ratio", s.max_aspect_ratio},
            {"prescribed_nodes", s.prescribed_nodes},
            {"fixed_nodes", s.fixed_nodes},
            {"free_nodes", s.free_nodes},
            {"iterations", s.iterations},
            {"max_skin_displacement_mm", s.max_skin_displacement_mm},
            {"seconds",
             {{"region", s.seconds.region},
              {"meshing", s.seconds.meshing},
              {"attachment", s.seconds.attachment},
              {"assembly", s.seconds.assembly},
              {"solve", s.seconds.solve},
              {"mapping", s.seconds.mapping}}}};
  if (s.format_version >= 2) {
    json["plan_text"] = s.plan_text;
    json["meshing_attempts"] = s.meshing_attempts;
    json["mean_aspect_ratio"] = s.mean_aspect_ratio;
    Json landmarks = Json::array();
    for (const auto& m : s.soft_landmarks)
      landmarks.push_back({{"label", m.label},
                           {"forward_mm", m.forward_mm},
                           {"up_mm", m.up_mm},
                           {"left_mm", m.left_mm},
                           {"total_mm", m.total_mm}});
    json["soft_landmarks"] = landmarks;
  }
  if (s.format_version >= 3) {
    json["profile_response"] = s.profile_response ? profile_response_json(*s.profile_response) : Json(nullptr);
    Json boundary = Json::array();
    for (const auto& b : s.boundary_moves)
      boundary.push_back({{"where", b.where}, {"largest_move_mm", b.largest_move_mm}});
    json["boundary_moves"] = boundary;
  }
  if (s.format_version >= 4) {
    json["nose_tets"] = s.nose_tets;
    json["nose_stiffness"] = s.nose_stiffness;
    json["model_fallback"] =
        s.model_fallback ? Json{{"requested", s.model_fallback->requested}, {"reason", s.model_fallback->reason}}
                         : Json(nullptr);
  }
  if (s.format_version >= 5) {
    json["sliding_nodes"] = s.sliding_nodes;
    json["bone_contact"] = s.bone_contact;
  }
  if (s.format_version >= 6) json["nose_nodes_uncarried"] = s.nose_nodes_uncarried;
  if (s.format_version >= 7) {
    json["squeezed_nodes_freed"] = s.squeezed_nodes_freed;
    json["enclosed_voxels_left_out"] = s.enclosed_voxels_left_out;
  }
  if (s.uncertainty)
    json["uncertainty"] = {
        {"runs", s.uncertainty->runs}, {"p95_mm", s.uncertainty->p95_mm}, {"max_mm", s.uncertainty->max_mm}};
  return json;
}

SimulationSummary read_simulation_summary(const Json& json, const std::string& source) {
  JsonReader r(json, "", source, ErrorCode::kArchiveCorrupt, "simulation summary");
  SimulationSummary s;
  s.format_version = r.format_version(SimulationSummary::kFormatVersion);
  s.model = r.required_text("model");
  if (!softtissue::parse_model(s.model)) r.fail("model", "unknown model \"" + s.model + "\"");
  const std::string application = r.required_text("plan_application");
  if (application != "stored" && application != "applied")
    r.fail("plan_application", "must be \"stored\" or \"applied\"");
  s.plan_application_stored = application == "stored";
  s.poisson_ratio = r.required_number("poisson_ratio", 0, 0.5);
  s.tetrahedra = count(r, "tetrahedra");
  s.nodes = count(r, "nodes");
  s.cell_size_mm = r.required_number("cell_size_mm", 0);
  s.tet_budget = count(r, "tet_budget");
  s.over_tet_budget = r.required_bool("over_tet_budget");
  s.min_dihedral_deg = r.required_number("min_dihedral_deg", 0, 180);
  s.max_aspect_ratio = r.required_number("max_aspect_ratio", 0);
  s.prescribed_nodes = count(r, "prescribed_nodes");
  s.fixed_nodes = count(r, "fixed_nodes");
  s.free_nodes = count(r, "free_nodes");
  s.iterations = count(r, "iterations");
  s.max_skin_displacement_mm = r.required_number("max_skin_displacement_mm", 0);
  s.seconds = read_seconds(r.object("seconds"));
  if (r.has("uncertainty")) s.uncertainty = read_band(r.object("uncertainty"));
  if (s.format_version >= 2) read_report_facts(r, s);
  if (s.format_version >= 3) {
    if (!r.at("profile_response").is_null()) s.profile_response = read_profile_response(r.object("profile_response"));
    const Json& boundary = r.required_array("boundary_moves");
    for (size_t i = 0; i < boundary.size(); ++i) {
      JsonReader b = r.element(boundary, "boundary_moves", i);
      s.boundary_moves.push_back({b.required_text("where"), b.required_number("largest_move_mm", 0)});
    }
  }
  if (s.format_version >= 4) {
    s.nose_tets = count(r, "nose_tets");
    s.nose_stiffness = r.required_number("nose_stiffness", 1);
    if (!r.at("model_fallback").is_null()) {
      JsonReader fallback = r.object("model_fallback");
      s.model_fallback = {fallback.required_text("requested"), fallback.required_text("reason")};
      if (!softtissue::parse_model(s.model_fallback->requested))
        fallback.fail(fallback.field("requested"), "unknown model \"" + s.model_fallback->requested + "\"");
    }
  }
  if (s.format_version >= 5) {
    s.sliding_nodes = count(r, "sliding_nodes");
    s.bone_contact = r.required_text("bone_contact");
    if (!softtissue::contact_named(s.bone_contact))
      r.fail("bone_contact", "unknown contact \"" + s.bone_contact + "\"");
  }
  if (s.format_version >= 6) s.nose_nodes_uncarried = count(r, "nose_nodes_uncarried");
  if (s.format_version >= 7) {
    s.squeezed_nodes_freed = count(r, "squeezed_nodes_freed");
    s.enclosed_voxels_left_out = count(r, "enclosed_voxels_left_out");
  }
  return s;
}

}  // namespace maxillo::records
