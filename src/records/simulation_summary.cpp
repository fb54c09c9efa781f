#include "records/simulation_summary.h"

#include <limits>

#include "core/error.h"
#include "core/json_reader.h"
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
  const Json& runs = r.required_array("runs");
  for (size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i].is_string()) r.fail(r.field("runs") + "[" + std::to_string(i) + "]", "must be a string");
    band.runs.push_back(runs[i].get<std::string>());
  }
  band.p95_mm = r.required_number("p95_mm", 0);
  band.max_mm = r.required_number("max_mm", 0);
  return band;
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
  return s;
}

}  // namespace maxillo::records
