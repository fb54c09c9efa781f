#include "sections/planning_section.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "casework/plan/plan_outputs.h"
#include "report/number_text.h"

namespace maxillo::sections {
namespace {

using report::Align;

using report::fixed;

using Record = records::PlanResultRecord;

std::string degrees(double value) { return fixed(value, 1) + "\u00b0"; }
std::string millimetres(double value, int decimals = 1) { return fixed(value, decimals) + " mm"; }

// "(x, y, z)", one decimal.
std::string point(const Eigen::Vector3d& p) {
  return "(" + fixed(p.x(), 1) + ", " + fixed(p.y(), 1) + ", " + fixed(p.z(), 1) + ")";
}

// The planned moves in the planning frame, one row per segment.
report::Table moves_table(const std::vector<planning::PlannedMove>& moves) {
  report::Table table;
  table.columns = {{"Segment", 1.2},
                   {"Advance", 1, Align::Right},
                   {"Vertical (+down)", 1, Align::Right},
                   {"Lateral (+left)", 1, Align::Right},
                   {"Pitch", 0.8, Align::Right},
                   {"Roll", 0.8, Align::Right},
                   {"Yaw", 0.8, Align::Right}};
  for (const planning::PlannedMove& m : moves)
    table.rows.push_back({std::string(planning::segment_name(m.segment)), millimetres(m.move.advancement_mm),
                          millimetres(m.move.vertical_mm), millimetres(m.move.lateral_mm), degrees(m.move.pitch_deg),
                          degrees(m.move.roll_deg), degrees(m.move.yaw_deg)});
  return table;
}

report::Table vectors_table(const Record::Distraction& d) {
  report::Table table;
  table.columns = {{"Side", 0.8},
                   {"Entry point (LPS mm)", 2.2},
                   {"Outward", 1, Align::Right},
                   {"Elevation", 1, Align::Right},
                   {"Activation", 1.1, Align::Right},
                   {"Turns", 0.8, Align::Right},
                   {"Days", 0.7, Align::Right}};
  const std::pair<const char*, std::pair<const Record::Vector*, const Record::ScheduleSide*>> sides[] = {
      {"right", {&d.right, &d.schedule.right}}, {"left", {&d.left, &d.schedule.left}}};
  for (const auto& [side, parts] : sides) {
    const auto& [v, s] = parts;
    table.rows.push_back({side, point(v->entry), degrees(v->outward_deg), degrees(v->elevation_deg),
                          millimetres(v->activation_mm, 2), fixed(s->turns, 2), std::to_string(s->distraction_days)});
  }
  return table;
}

report::Table checks_table(const std::vector<Record::Check>& checks) {
  report::Table table;
  table.columns = {
      {"Side", 0.7}, {"Check", 1.5}, {"Result", 0.9}, {"Value", 0.9, Align::Right}, {"Limit", 0.9, Align::Right},
      {"Reason", 3}};
  for (const Record::Check& c : checks)
    table.rows.push_back({c.side, c.name, c.status, millimetres(c.value_mm), millimetres(c.limit_mm), c.reason});
  return table;
}

report::Table schedule_table(const Record::Schedule& schedule) {
  report::Table table;
  table.columns = {{"Side", 0.8},
                   {"Planned", 1, Align::Right},
                   {"Turns (360\u00b0)", 1.1, Align::Right},
                   {"Delivered", 1, Align::Right},
                   {"First day", 1, Align::Right},
                   {"Last day", 1, Align::Right},
                   {"Days", 0.8, Align::Right}};
  for (const auto& [side, s] : {std::pair{"right", &schedule.right}, std::pair{"left", &schedule.left}})
    table.rows.push_back({side, millimetres(s->activation_mm, 2), fixed(s->turns, 2), millimetres(s->delivered_mm, 2),
                          std::to_string(s->first_day), std::to_string(s->last_day),
                          std::to_string(s->distraction_days)});
  return table;
}

report::Table simulation_table(const std::vector<Record::SimulatedPoint>& points) {
  report::Table table;
  table.columns = {{"Point", 0.8}, {"Target (LPS mm)", 2}, {"Simulated (LPS mm)", 2}, {"Error", 0.9, Align::Right}};
  for (const Record::SimulatedPoint& p : points)
    table.rows.push_back({p.label, point(p.target), point(p.simulated), millimetres(p.error_mm, 2)});
  return table;
}

void add_distraction(report::Section& section, const Record::Distraction& d) {
  const Record::Schedule& schedule = d.schedule;
  section.blocks.push_back(report::Paragraph{"Distraction vectors (two trans-sinusal distractors)"});
  section.blocks.push_back(vectors_table(d));
  section.blocks.push_back(report::KeyValueBlock{{
      {"Vector divergence", degrees(d.divergence_deg)},
      {"Axis angle (3D)", degrees(d.angle_deg)},
  }});
  section.blocks.push_back(report::Paragraph{"Distractor checks"});
  section.blocks.push_back(checks_table(d.checks));
  for (const std::string& note : d.sinus_notes) section.blocks.push_back(report::Note{"The " + note + "."});
  section.blocks.push_back(report::Paragraph{"Activation schedule"});
  section.blocks.push_back(report::KeyValueBlock{{
      {"Latency", std::to_string(schedule.latency_days) + " days"},
      {"Rate", fixed(schedule.rate_mm_per_day, 2) + " mm/day in " + std::to_string(schedule.activations_per_day) +
                   " activations of " + fixed(schedule.turns_per_activation, 2) + " turn (" +
                   fixed(schedule.mm_per_turn, 2) + " mm per 360\u00b0 turn)"},
      {"Last activation", "day " + std::to_string(schedule.distraction_end_day)},
      {"End of consolidation", "day " + std::to_string(schedule.consolidation_end_day)},
  }});
  section.blocks.push_back(schedule_table(schedule));
  section.blocks.push_back(report::Paragraph{"Forward simulation"});
  section.blocks.push_back(simulation_table(d.simulation));
  section.blocks.push_back(report::Note{
      "The maxilla moved as the two distractors move their entry points, with the pitch the distractors do not "
      "control taken as planned minus the expected clockwise drift. Largest error " +
      millimetres(d.max_error_mm, 2) + "."});
}

void add_renders(report::Section& section, const std::vector<std::pair<std::string, std::filesystem::path>>& files) {
  report::ImageGrid grid;
  grid.per_row = 2;
  for (const auto& [label, path] : files)
    if (path.extension() == ".png" && std::filesystem::exists(path)) grid.figures.push_back({path, label});
  if (!grid.figures.empty()) section.blocks.push_back(grid);
}

report::KeyValueBlock target_block(const planning::MaxillaryTarget& t) {
  return report::KeyValueBlock{{
      {"Target advancement", millimetres(t.advancement_mm)},
      {"Target vertical change (+down)", millimetres(t.vertical_mm)},
      {"Target widening", millimetres(t.widening_mm)},
      {"Midline shift (+left)", millimetres(t.midline_shift_mm)},
      {"Rotation (+anterior up)", degrees(t.rotation_deg)},
      {"Counter-rotation of the vectors", degrees(t.counter_rotation_deg)},
  }};
}

}  // namespace

report::Section planning_section(const records::PlanResultRecord& result) {
  report::Section section{"planning", {}};
  const planning::Plan& plan = result.plan;
  if (!plan.description.empty()) section.blocks.push_back(report::Paragraph{plan.description});
  section.blocks.push_back(report::Paragraph{"Planned moves"});
  section.blocks.push_back(moves_table(result.moves));
  if (plan.distraction) section.blocks.push_back(target_block(plan.distraction->target));
  if (result.distraction) add_distraction(section, *result.distraction);
  if (result.feasible)
    section.blocks.push_back(report::Paragraph{"All distractor checks passed."});
  else {
    std::string text = "Plan refused:";
    for (const std::string& r : result.refusals) text += " " + r + ";";
    section.blocks.push_back(report::Paragraph{text});
  }
  add_renders(section, result.files);
  if (result.osteotomy)
    for (auto& block : casework::plan_output_blocks(*result.osteotomy)) section.blocks.push_back(std::move(block));
  section.blocks.push_back(report::Note{
      "Frame: " + result.frame_source +
      " (source ch. 5: origin N, X through N with SN rotated 6\u00b0, transverse axis from Frankfort). "
      "Advance + forward, vertical + down, lateral + patient's left; pitch + anterior end up, roll + left side up, "
      "yaw + anterior end to the left. Widening is the transverse expansion between the two maxillary halves."});
  return section;
}

report::Section unapplied_plan_section(const records::StoredPlan& stored, int64_t case_id,
                                       const std::vector<std::string>& flagged) {
  report::Section section{"planning", {}};
  const planning::Plan& plan = stored.plan;
  if (!plan.description.empty()) section.blocks.push_back(report::Paragraph{plan.description});
  if (plan.distraction) section.blocks.push_back(target_block(plan.distraction->target));
  const std::string apply = "maxillo plan apply " + std::to_string(case_id);
  section.blocks.push_back(report::Paragraph{
      "Plan version " + std::to_string(stored.version) + ", stored " + stored.created_at + ", not applied yet: `" +
      apply + "` computes the planned moves, the distractors' vectors and their checks, and the predicted face."});
  if (!flagged.empty()) {
    std::string text =
        "It will be refused until these automatic landmarks, which failed their checks, are confirmed by "
        "hand (`maxillo ceph add`) or accepted with `" +
        apply + " --accept-flagged`:";
    for (size_t i = 0; i < flagged.size(); ++i) text += (i ? "; " : " ") + flagged[i];
    section.blocks.push_back(report::Note{text + "."});
  }
  return section;
}

}  // namespace maxillo::sections
