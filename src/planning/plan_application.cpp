#include "planning/plan_application.h"

#include <cmath>

#include "core/error.h"
#include "core/json_reader.h"
#include "planning/maxillary_sinus.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

Vector3d pivot_of(const Pivot& pivot, const LandmarkSet& landmarks, const std::string& field) {
  return pivot.point ? *pivot.point : require_landmark(landmarks, pivot.landmark, field);
}

DistractionResult plan_distraction(const DistractionSpec& spec, const PlanningFrame& frame, const LabelVolume& labels,
                                   const LandmarkSet& landmarks, const AnatomyLabels& anatomy) {
  DistractionResult result;
  result.target = spec.target;
  result.reference.pivot = require_landmark(landmarks, "PNS", "distraction");
  result.reference.incisor = require_landmark(landmarks, "U1", "distraction");
  SinusAirReading sinus_reading;
  const LabelVolume with_sinuses = with_open_sinus_air(labels, frame, anatomy, landmarks, sinus_reading);
  result.sinus_notes = sinus_reading.notes;
  EntryPoints entries = find_entry_points(with_sinuses, frame, anatomy, landmarks);
  if (spec.entry_right) entries.right = *spec.entry_right;
  if (spec.entry_left) entries.left = *spec.entry_left;
  result.vectors = distraction_vectors(frame, spec.target, result.reference, entries.right, entries.left);
  result.checks = check_distractors(with_sinuses, result.vectors, landmarks, frame, anatomy, spec.device, spec.limits);
  result.schedule =
      activation_schedule(result.vectors.right.activation_mm, result.vectors.left.activation_mm, spec.schedule);
  LandmarkSet points;
  for (const char* label : {"ANS", "PNS", "U1"})
    if (auto p = find_landmark(landmarks, label)) points.push_back({label, *p});
  result.simulation = simulate_distraction(frame, spec.target, result.reference, result.vectors, points,
                                           spec.expected_clockwise_rotation_deg);
  return result;
}

Json move_json(const FrameMove& m) {
  return {{"advancement_mm", m.advancement_mm}, {"vertical_mm", m.vertical_mm}, {"lateral_mm", m.lateral_mm},
          {"pitch_deg", m.pitch_deg},           {"roll_deg", m.roll_deg},       {"yaw_deg", m.yaw_deg}};
}

Json vector_json(const DistractionVector& v) {
  return {{"side", side_name(v.side)},        {"entry", point_json(v.entry)}, {"axis", point_json(v.axis)},
          {"activation_mm", v.activation_mm}, {"outward_deg", v.outward_deg}, {"elevation_deg", v.elevation_deg}};
}

Json schedule_side_json(const SideSchedule& s) {
  return {{"side", side_name(s.side)},      {"activation_mm", s.activation_mm},       {"turns", s.turns},
          {"delivered_mm", s.delivered_mm}, {"distraction_days", s.distraction_days}, {"first_day", s.first_day},
          {"last_day", s.last_day}};
}

}  // namespace

PlanResult apply_plan(const Plan& plan, const LabelVolume& labels, const LandmarkSet& landmarks,
                      const AnatomyLabels& anatomy) {
  PlanResult result;
  result.plan = plan;
  result.frame = planning_frame(landmarks);
  for (size_t i = 0; i < plan.moves.size(); ++i) {
    const SegmentMove& m = plan.moves[i];
    PlannedMove planned;
    planned.segment = m.segment;
    planned.pivot = pivot_of(m.pivot, landmarks, "moves[" + std::to_string(i) + "].pivot");
    planned.move = m.move;
    planned.transform = to_transform(result.frame, m.move, planned.pivot);
    result.moves.push_back(planned);
  }
  if (plan.distraction) {
    result.distraction = plan_distraction(*plan.distraction, result.frame, labels, landmarks, anatomy);
    for (const DistractorCheck& c : result.distraction->checks)
      if (c.status == CheckStatus::Fail)
        result.refusals.push_back(std::string(side_name(c.side)) + " " + c.name + ": " + c.reason);
    result.feasible = result.refusals.empty();
  }
  return result;
}

Json plan_result_json(const PlanResult& r) {
  Json json{{"plan", plan_to_json(r.plan)},
            {"frame",
             {{"source", r.frame.source},
              {"origin", point_json(r.frame.origin)},
              {"anterior", point_json(r.frame.anterior)},
              {"left", point_json(r.frame.left)},
              {"superior", point_json(r.frame.superior)}}},
            {"feasible", r.feasible},
            {"refusals", r.refusals}};
  Json moves = Json::array();
  for (const PlannedMove& m : r.moves) {
    Json t = Json::array();
    for (int i = 0; i < 4; ++i)
      t.push_back(Json::array({m.transform.matrix()(i, 0), m.transform.matrix()(i, 1), m.transform.matrix()(i, 2),
                               m.transform.matrix()(i, 3)}));
    moves.push_back({{"segment", std::string(segment_name(m.segment))},
                     {"pivot", point_json(m.pivot)},
                     {"move", move_json(m.move)},
                     {"transform_lps", t}});
  }
  json["moves"] = moves;
  if (r.distraction) {
    const DistractionResult& d = *r.distraction;
    Json checks = Json::array();
    for (const DistractorCheck& c : d.checks)
      checks.push_back({{"name", c.name},
                        {"side", side_name(c.side)},
                        {"status", status_name(c.status)},
                        {"value_mm", c.value},
                        {"limit_mm", c.limit},
                        {"reason", c.reason}});
    Json points = Json::array();
    for (const SimulatedPoint& p : d.simulation.points)
      points.push_back({{"label", p.label},
                        {"before", point_json(p.before)},
                        {"target", point_json(p.target)},
                        {"simulated", point_json(p.simulated)},
                        {"error_mm", p.error_mm}});
    json["distraction"] = {{"vectors",
                            {{"right", vector_json(d.vectors.right)},
                             {"left", vector_json(d.vectors.left)},
                             {"divergence_deg", d.vectors.divergence_deg},
                             {"angle_deg", d.vectors.angle_deg}}},
                           {"checks", checks},
                           {"sinus_notes", d.sinus_notes},
                           {"schedule",
                            {{"latency_days", d.schedule.settings.latency_days},
                             {"rate_mm_per_day", d.schedule.settings.rate_mm_per_day},
                             {"activations_per_day", d.schedule.settings.activations_per_day},
                             {"mm_per_turn", d.schedule.settings.mm_per_turn},
                             {"turns_per_activation", d.schedule.turns_per_activation},
                             {"right", schedule_side_json(d.schedule.right)},
                             {"left", schedule_side_json(d.schedule.left)},
                             {"distraction_end_day", d.schedule.distraction_end_day},
                             {"consolidation_end_day", d.schedule.consolidation_end_day}}},
                           {"forward_simulation",
                            {{"achieved", move_json(d.simulation.achieved)},
                             {"achieved_widening_mm", d.simulation.achieved_widening_mm},
                             {"points", points},
                             {"max_error_mm", d.simulation.max_error_mm}}}};
  }
  Json files = Json::object();
  for (const auto& [label, path] : r.files) files[label] = path.string();
  json["files"] = files;
  return json;
}

namespace {

FrameMove read_stored_frame_move(JsonReader r) {
  FrameMove m;
  m.advancement_mm = r.required_number("advancement_mm");
  m.vertical_mm = r.required_number("vertical_mm");
  m.lateral_mm = r.required_number("lateral_mm");
  m.pitch_deg = r.required_number("pitch_deg");
  m.roll_deg = r.required_number("roll_deg");
  m.yaw_deg = r.required_number("yaw_deg");
  r.refuse_unknown_keys();
  return m;
}

}  // namespace

std::vector<PlannedMove> planned_moves_from_json(const Json& result, const std::string& source, ErrorCode code) {
  JsonReader r(result, "", source, code, "plan result");
  const Json& moves = r.required_array("moves");
  std::vector<PlannedMove> read;
  for (size_t i = 0; i < moves.size(); ++i) {
    JsonReader m = r.element(moves, "moves", i);
    PlannedMove move;
    const std::string name = m.required_text("segment");
    const auto segment = parse_segment(name);
    if (!segment || *segment == Segment::kNone) m.fail(m.field("segment"), "unknown segment \"" + name + "\"");
    move.segment = *segment;
    move.pivot = m.required_point("pivot");
    move.move = read_stored_frame_move(m.object("move"));
    move.transform = m.required_rigid_transform("transform_lps");
    m.refuse_unknown_keys();
    read.push_back(move);
  }
  return read;
}

}  // namespace maxillo::planning
