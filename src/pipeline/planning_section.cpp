#include "pipeline/planning_section.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "pipeline/plan_outputs.h"
#include "report/number_text.h"

namespace maxillo::pipeline {
namespace {

using report::Align;

using report::fixed;

// A number of a result JSON object as text (0 when absent).
std::string number(const Json& j, const char* key, int decimals = 1) { return fixed(j.value(key, 0.0), decimals); }

std::string degrees(const Json& j, const char* key) { return number(j, key, 1) + "\u00b0"; }

// "(x, y, z)" of a JSON array of three numbers, one decimal.
std::string point(const Json& p) {
  if (!p.is_array() || p.size() != 3) return "?";
  return "(" + fixed(p[0].get<double>(), 1) + ", " + fixed(p[1].get<double>(), 1) + ", " + fixed(p[2].get<double>(), 1) + ")";
}

// The planned moves in the planning frame, one row per segment.
report::Table moves_table(const Json& moves) {
  report::Table table;
  table.columns = {{"Segment", 1.2}, {"Advance", 1, Align::Right}, {"Vertical (+down)", 1, Align::Right},
                   {"Lateral (+left)", 1, Align::Right}, {"Pitch", 0.8, Align::Right}, {"Roll", 0.8, Align::Right},
                   {"Yaw", 0.8, Align::Right}};
  for (const Json& m : moves) {
    const Json& move = m["move"];
    table.rows.push_back({m.value("segment", ""), number(move, "advancement_mm") + " mm", number(move, "vertical_mm") + " mm",
                          number(move, "lateral_mm") + " mm", degrees(move, "pitch_deg"), degrees(move, "roll_deg"),
                          degrees(move, "yaw_deg")});
  }
  return table;
}

report::Table vectors_table(const Json& distraction) {
  const Json& vectors = distraction["vectors"];
  const Json& schedule = distraction["schedule"];
  report::Table table;
  table.columns = {{"Side", 0.8}, {"Entry point (LPS mm)", 2.2}, {"Outward", 1, Align::Right},
                   {"Elevation", 1, Align::Right}, {"Activation", 1.1, Align::Right}, {"Turns", 0.8, Align::Right},
                   {"Days", 0.7, Align::Right}};
  for (const char* side : {"right", "left"}) {
    const Json& v = vectors[side];
    const Json& s = schedule[side];
    table.rows.push_back({side, point(v["entry"]), degrees(v, "outward_deg"), degrees(v, "elevation_deg"),
                          number(v, "activation_mm", 2) + " mm", number(s, "turns", 2),
                          std::to_string(s.value("distraction_days", 0))});
  }
  return table;
}

report::Table checks_table(const Json& checks) {
  report::Table table;
  table.columns = {{"Side", 0.7}, {"Check", 1.5}, {"Result", 0.9}, {"Value", 0.9, Align::Right},
                   {"Limit", 0.9, Align::Right}, {"Reason", 3}};
  for (const Json& c : checks)
    table.rows.push_back({c.value("side", ""), c.value("name", ""), c.value("status", ""),
                          number(c, "value_mm") + " mm", number(c, "limit_mm") + " mm", c.value("reason", "")});
  return table;
}

report::Table schedule_table(const Json& schedule) {
  report::Table table;
  table.columns = {{"Side", 0.8}, {"Planned", 1, Align::Right}, {"Turns (360\u00b0)", 1.1, Align::Right},
                   {"Delivered", 1, Align::Right}, {"First day", 1, Align::Right}, {"Last day", 1, Align::Right},
                   {"Days", 0.8, Align::Right}};
  for (const char* side : {"right", "left"}) {
    const Json& s = schedule[side];
    table.rows.push_back({side, number(s, "activation_mm", 2) + " mm", number(s, "turns", 2),
                          number(s, "delivered_mm", 2) + " mm", std::to_string(s.value("first_day", 0)),
                          std::to_string(s.value("last_day", 0)), std::to_string(s.value("distraction_days", 0))});
  }
  return table;
}

report::Table simulation_table(const Json& simulation) {
  report::Table table;
  table.columns = {{"Point", 0.8}, {"Target (LPS mm)", 2}, {"Simulated (LPS mm)", 2}, {"Error", 0.9, Align::Right}};
  for (const Json& p : simulation["points"])
    table.rows.push_back({p.value("label", ""), point(p["target"]), point(p["simulated"]), number(p, "error_mm", 2) + " mm"});
  return table;
}

void add_distraction(report::Section& section, const Json& d) {
  const Json& vectors = d["vectors"];
  const Json& schedule = d["schedule"];
  section.blocks.push_back(report::Paragraph{"Distraction vectors (two trans-sinusal distractors)"});
  section.blocks.push_back(vectors_table(d));
  section.blocks.push_back(report::KeyValueBlock{{
      {"Vector divergence", degrees(vectors, "divergence_deg")},
      {"Axis angle (3D)", degrees(vectors, "angle_deg")},
  }});
  section.blocks.push_back(report::Paragraph{"Distractor checks"});
  section.blocks.push_back(checks_table(d["checks"]));
  section.blocks.push_back(report::Paragraph{"Activation schedule"});
  section.blocks.push_back(report::KeyValueBlock{{
      {"Latency", std::to_string(schedule.value("latency_days", 0)) + " days"},
      {"Rate", number(schedule, "rate_mm_per_day", 2) + " mm/day in " +
                   std::to_string(schedule.value("activations_per_day", 0)) + " activations of " +
                   number(schedule, "turns_per_activation", 2) + " turn (" + number(schedule, "mm_per_turn", 2) +
                   " mm per 360\u00b0 turn)"},
      {"Last activation", "day " + std::to_string(schedule.value("distraction_end_day", 0))},
      {"End of consolidation", "day " + std::to_string(schedule.value("consolidation_end_day", 0))},
  }});
  section.blocks.push_back(schedule_table(schedule));
  section.blocks.push_back(report::Paragraph{"Forward simulation"});
  section.blocks.push_back(simulation_table(d["forward_simulation"]));
  section.blocks.push_back(report::Note{
      "The maxilla moved as the two distractors move their entry points, with the pitch the distractors do not "
      "control taken as planned minus the expected clockwise drift. Largest error " +
      number(d["forward_simulation"], "max_error_mm", 2) + " mm."});
}

// Whether the stored plan result says the plan passed its checks. A result without the flag is
// damaged: reading it as feasible would report a plan nobody checked as safe (issue 17).
bool plan_feasible(const Json& result) {
  const auto flag = result.find("feasible");
  if (flag == result.end() || !flag->is_boolean())
    throw Error(ErrorCode::kArchiveCorrupt, "plan result",
                "no true/false \"feasible\": it cannot say whether the plan passed its checks");
  return flag->get<bool>();
}

void add_renders(report::Section& section, const Json& files) {
  report::ImageGrid grid;
  grid.per_row = 2;
  for (auto it = files.begin(); it != files.end(); ++it) {
    if (!it.value().is_string()) continue;
    const std::filesystem::path path = it.value().get<std::string>();
    if (path.extension() == ".png" && std::filesystem::exists(path)) grid.figures.push_back({path, it.key()});
  }
  if (!grid.figures.empty()) section.blocks.push_back(grid);
}

}  // namespace

report::Section planning_section(const Json& result) {
  report::Section section{"planning", {}};
  const Json& plan = result["plan"];
  if (!plan.value("description", "").empty()) section.blocks.push_back(report::Paragraph{plan.value("description", "")});
  section.blocks.push_back(report::Paragraph{"Planned moves"});
  section.blocks.push_back(moves_table(result["moves"]));
  if (plan.contains("distraction")) {
    const Json& t = plan["distraction"]["target"];
    section.blocks.push_back(report::KeyValueBlock{{
        {"Target advancement", number(t, "advancement_mm") + " mm"},
        {"Target vertical change (+down)", number(t, "vertical_mm") + " mm"},
        {"Target widening", number(t, "widening_mm") + " mm"},
        {"Midline shift (+left)", number(t, "midline_shift_mm") + " mm"},
        {"Rotation (+anterior up)", degrees(t, "rotation_deg")},
        {"Counter-rotation of the vectors", degrees(t, "counter_rotation_deg")},
    }});
  }
  if (result.contains("distraction")) add_distraction(section, result["distraction"]);
  if (plan_feasible(result))
    section.blocks.push_back(report::Paragraph{"All distractor checks passed."});
  else {
    std::string text = "Plan refused:";
    for (const Json& r : result["refusals"]) text += " " + r.get<std::string>() + ";";
    section.blocks.push_back(report::Paragraph{text});
  }
  if (result.contains("files")) add_renders(section, result["files"]);
  if (result.contains("osteotomy"))
    for (auto& block : plan_output_blocks(result["osteotomy"])) section.blocks.push_back(std::move(block));
  const Json& frame = result["frame"];
  section.blocks.push_back(report::Note{
      "Frame: " + frame.value("source", std::string("?")) +
      " (source ch. 5: origin N, X through N with SN rotated 6\u00b0, transverse axis from Frankfort). "
      "Advance + forward, vertical + down, lateral + patient's left; pitch + anterior end up, roll + left side up, "
      "yaw + anterior end to the left. Widening is the transverse expansion between the two maxillary halves."});
  return section;
}

}  // namespace maxillo::pipeline
