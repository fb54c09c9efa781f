#include "planning/plan.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>

#include "core/error.h"
#include "core/json_input.h"
#include "core/json_reader.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

// A reader of one object of a plan file: failures name the file and the key path, "plan" at the top.
JsonReader reader(const Json& json, const std::string& path, const std::string& source) {
  return JsonReader(json, path, source, ErrorCode::kBadValue, "plan");
}

constexpr double kMaxMoveMm = 60;
constexpr double kMaxAngleDeg = 45;

CutSpec read_cut(JsonReader& parent, const std::string& key, const std::string& source) {
  const Json& v = parent.at(key);
  const std::string name = parent.field(key);
  CutSpec cut;
  if (v.is_string()) {
    const std::string text = v.get<std::string>();
    if (text == "default" || text == "default-high") return cut;
    if (text == "default-low" && key == "le_fort_i") {
      cut.variant = LeFortVariant::Low;
      return cut;
    }
    parent.fail(name, "\"" + text + "\" is not a cut: use \"default\"" +
                          std::string(key == "le_fort_i" ? ", \"default-high\", \"default-low\"" : "") +
                          ", {\"point\": [x, y, z], \"normal\": [x, y, z]} or {\"points\": [three points]}");
  }
  JsonReader r = reader(v, name, source);
  if (r.has("points")) {
    const Json& points = r.at("points");
    if (!points.is_array() || points.size() != 3) r.fail(name + ".points", "must be three points [[x, y, z], ...]");
    cut.kind = CutSpec::Kind::Points;
    for (size_t i = 0; i < 3; ++i) cut.points[i] = r.point_of(points[i], name + ".points[" + std::to_string(i) + "]");
    if ((cut.points[1] - cut.points[0]).cross(cut.points[2] - cut.points[0]).norm() < 1.0)
      r.fail(name + ".points", "the three points lie (nearly) on one line: they do not define a plane");
    r.refuse_unknown_keys();
    return cut;
  }
  cut.kind = CutSpec::Kind::Plane;
  const auto point = r.point("point");
  const auto normal = r.point("normal");
  if (!point) r.fail(name + ".point", "missing");
  if (!normal) r.fail(name + ".normal", "missing");
  if (normal->norm() < 1e-9) r.fail(name + ".normal", "must not be zero");
  cut.plane.point = *point;
  cut.plane.normal = normal->normalized();
  r.refuse_unknown_keys();
  return cut;
}

PlanOsteotomies read_osteotomies(const Json& json, const std::string& source) {
  JsonReader r = reader(json, "osteotomies", source);
  PlanOsteotomies o;
  const std::vector<std::pair<const char*, std::optional<CutSpec>*>> cuts{{"le_fort_i", &o.le_fort_i},
                                                                          {"pterygomaxillary", &o.pterygomaxillary},
                                                                          {"bsso_right", &o.bsso_right},
                                                                          {"bsso_left", &o.bsso_left},
                                                                          {"genioplasty", &o.genioplasty}};
  for (const auto& [key, slot] : cuts)
    if (r.has(key)) *slot = read_cut(r, key, source);
  r.refuse_unknown_keys();
  if (bool(o.bsso_right) != bool(o.bsso_left))
    r.fail("osteotomies.bsso_right/bsso_left", "a bilateral sagittal split needs both sides");
  return o;
}

FrameMove read_frame_move(JsonReader& r) {
  FrameMove m;
  r.number("advancement_mm", m.advancement_mm, -kMaxMoveMm, kMaxMoveMm);
  r.number("vertical_mm", m.vertical_mm, -kMaxMoveMm, kMaxMoveMm);
  r.number("lateral_mm", m.lateral_mm, -kMaxMoveMm, kMaxMoveMm);
  r.number("pitch_deg", m.pitch_deg, -kMaxAngleDeg, kMaxAngleDeg);
  r.number("roll_deg", m.roll_deg, -kMaxAngleDeg, kMaxAngleDeg);
  r.number("yaw_deg", m.yaw_deg, -kMaxAngleDeg, kMaxAngleDeg);
  return m;
}

SegmentMove read_move(const Json& json, const std::string& path, const std::string& source) {
  JsonReader r = reader(json, path, source);
  SegmentMove move;
  if (!r.has("segment") || !r.at("segment").is_string())
    r.fail(r.field("segment"), "missing (a segment name such as \"maxilla\")");
  const std::string name = r.at("segment").get<std::string>();
  const auto segment = parse_segment(name);
  if (!segment || *segment == Segment::kNone) r.fail(r.field("segment"), "unknown segment \"" + name + "\"");
  move.segment = *segment;
  if (r.has("pivot")) {
    const Json& p = r.at("pivot");
    if (p.is_string())
      move.pivot.landmark = p.get<std::string>();
    else
      move.pivot.point = r.point_of(p, r.field("pivot"));
  }
  move.move = read_frame_move(r);
  r.refuse_unknown_keys();
  return move;
}

MaxillaryTarget read_target(const Json& json, const std::string& source) {
  JsonReader r = reader(json, "distraction.target", source);
  MaxillaryTarget t;
  r.number("advancement_mm", t.advancement_mm, -kMaxMoveMm, kMaxMoveMm);
  r.number("vertical_mm", t.vertical_mm, -kMaxMoveMm, kMaxMoveMm);
  r.number("widening_mm", t.widening_mm, 0, 30);
  r.number("midline_shift_mm", t.midline_shift_mm, -15, 15);
  r.number("rotation_deg", t.rotation_deg, -kMaxAngleDeg, kMaxAngleDeg);
  r.number("counter_rotation_deg", t.counter_rotation_deg, -kMaxAngleDeg, kMaxAngleDeg);
  r.refuse_unknown_keys();
  return t;
}

DistractionSpec read_distraction(const Json& json, const std::string& source) {
  JsonReader r = reader(json, "distraction", source);
  DistractionSpec d;
  if (r.has("target")) d.target = read_target(r.at("target"), source);
  r.number("expected_clockwise_rotation_deg", d.expected_clockwise_rotation_deg, -kMaxAngleDeg, kMaxAngleDeg);
  if (r.has("device")) {
    JsonReader dev = reader(r.at("device"), "distraction.device", source);
    dev.number("screw_length_mm", d.device.screw_length_mm, 5, 80);
    dev.number("screw_diameter_mm", d.device.screw_diameter_mm, 0.5, 10);
    dev.number("engagement_mm", d.device.engagement_mm, 0, 40);
    dev.refuse_unknown_keys();
  }
  if (r.has("limits")) {
    JsonReader lim = reader(r.at("limits"), "distraction.limits", source);
    lim.number("sinus_clearance_mm", d.limits.sinus_clearance_mm, 0, 10);
    lim.number("tooth_distance_mm", d.limits.tooth_distance_mm, 0, 20);
    lim.number("nerve_distance_mm", d.limits.nerve_distance_mm, 0, 30);
    lim.number("foramen_below_orbitale_mm", d.limits.foramen_below_orbitale_mm, 0, 20);
    lim.refuse_unknown_keys();
  }
  if (r.has("schedule")) {
    JsonReader s = reader(r.at("schedule"), "distraction.schedule", source);
    s.integer("latency_days", d.schedule.latency_days, 0, 60);
    s.number("rate_mm_per_day", d.schedule.rate_mm_per_day, 0.05, 5);
    s.integer("activations_per_day", d.schedule.activations_per_day, 1, 12);
    s.number("mm_per_turn", d.schedule.mm_per_turn, 0.05, 5);
    s.integer("consolidation_days", d.schedule.consolidation_days, 0, 365);
    s.refuse_unknown_keys();
  }
  d.entry_right = r.point("entry_right");
  d.entry_left = r.point("entry_left");
  r.refuse_unknown_keys();
  return d;
}

OcclusionReference read_occlusion(const Json& json, const std::string& source) {
  JsonReader r = reader(json, "occlusion", source);
  OcclusionReference o;
  r.text("reference", o.reference);
  r.text("pairs_file", o.pairs_file);
  r.refuse_unknown_keys();
  if (o.reference != "preoperative" && o.reference != "pairs")
    r.fail("occlusion.reference", "must be \"preoperative\" or \"pairs\", got \"" + o.reference + "\"");
  if (o.reference == "pairs" && o.pairs_file.empty()) r.fail("occlusion.pairs_file", "needed with reference \"pairs\"");
  return o;
}

Json cut_json(const CutSpec& cut, bool le_fort) {
  if (cut.kind == CutSpec::Kind::Points)
    return Json{
        {"points", Json::array({point_json(cut.points[0]), point_json(cut.points[1]), point_json(cut.points[2])})}};
  if (cut.kind == CutSpec::Kind::Default) {
    if (!le_fort) return "default";
    return cut.variant == LeFortVariant::Low ? "default-low" : "default-high";
  }
  return Json{{"point", point_json(cut.plane.point)}, {"normal", point_json(cut.plane.normal)}};
}

bool differ(double a, double b) { return std::abs(a - b) > 1e-6; }

// Every field read and range-checked; how the fields fit together is validate_plan's.
Plan read_plan_fields(const Json& json, const std::string& source) {
  JsonReader r = reader(json, "", source);
  Plan plan;
  if (!r.has("format_version")) r.fail("format_version", "missing");
  r.integer("format_version", plan.format_version, 1, 1000000);
  if (plan.format_version > kPlanFormatVersion)
    r.fail("format_version", std::to_string(plan.format_version) + " is newer than this program's " +
                                 std::to_string(kPlanFormatVersion) + ": update maxillo");
  r.text("description", plan.description);
  if (r.has("osteotomies")) plan.osteotomies = read_osteotomies(r.at("osteotomies"), source);
  if (r.has("moves")) {
    const Json& moves = r.at("moves");
    if (!moves.is_array()) r.fail("moves", "must be an array");
    for (size_t i = 0; i < moves.size(); ++i)
      plan.moves.push_back(read_move(moves[i], "moves[" + std::to_string(i) + "]", source));
  }
  if (r.has("distraction")) plan.distraction = read_distraction(r.at("distraction"), source);
  if (r.has("occlusion")) plan.occlusion = read_occlusion(r.at("occlusion"), source);
  r.refuse_unknown_keys();
  return plan;
}

void check_consistency(const Plan& plan, const std::string& source);

}  // namespace

Plan plan_from_json(const Json& json, const std::string& source) {
  Plan plan = read_plan_fields(json, source);
  check_consistency(plan, source);
  return plan;
}

Plan parse_plan(std::string_view text, const std::string& source) {
  return plan_from_json(parse_json_input(text, source), source);
}

// A plan made in code (from command-line options) passes the same range checks as a plan read
// from a file, by reading back its own JSON: one set of limits, NaN and infinities refused.
void validate_plan(const Plan& plan, const std::string& source) {
  read_plan_fields(plan_to_json(plan), source);
  check_consistency(plan, source);
}

namespace {

void check_consistency(const Plan& plan, const std::string& source) {
  auto fail = [&](const std::string& field, const std::string& reason) {
    throw Error(ErrorCode::kBadValue, source, field + ": " + reason);
  };
  std::set<Segment> seen;
  for (size_t i = 0; i < plan.moves.size(); ++i) {
    const SegmentMove& m = plan.moves[i];
    const std::string field = "moves[" + std::to_string(i) + "]";
    if (m.segment == Segment::kCranium) fail(field + ".segment", "the cranium is the fixed reference and cannot move");
    if (!seen.insert(m.segment).second)
      fail(field + ".segment", "\"" + std::string(segment_name(m.segment)) + "\" moves twice");
    if (!m.pivot.point && m.pivot.landmark.empty()) fail(field + ".pivot", "empty landmark label");
    if (m.segment == Segment::kMaxilla && plan.distraction) {
      const MaxillaryTarget& t = plan.distraction->target;
      if (differ(m.move.advancement_mm, t.advancement_mm) || differ(m.move.vertical_mm, t.vertical_mm) ||
          differ(m.move.pitch_deg, t.rotation_deg))
        fail(field,
             "the maxilla's advancement, vertical change and pitch must equal distraction.target's "
             "(the distraction makes this move)");
    }
  }
  if (plan.distraction) validate(plan.distraction->schedule);
}

}  // namespace

Json plan_to_json(const Plan& plan) {
  Json json{{"format_version", plan.format_version}, {"description", plan.description}};
  Json cuts = Json::object();
  const PlanOsteotomies& o = plan.osteotomies;
  if (o.le_fort_i) cuts["le_fort_i"] = cut_json(*o.le_fort_i, true);
  if (o.pterygomaxillary) cuts["pterygomaxillary"] = cut_json(*o.pterygomaxillary, false);
  if (o.bsso_right) cuts["bsso_right"] = cut_json(*o.bsso_right, false);
  if (o.bsso_left) cuts["bsso_left"] = cut_json(*o.bsso_left, false);
  if (o.genioplasty) cuts["genioplasty"] = cut_json(*o.genioplasty, false);
  json["osteotomies"] = cuts;
  Json moves = Json::array();
  for (const SegmentMove& m : plan.moves)
    moves.push_back({{"segment", std::string(segment_name(m.segment))},
                     {"pivot", m.pivot.point ? point_json(*m.pivot.point) : Json(m.pivot.landmark)},
                     {"advancement_mm", m.move.advancement_mm},
                     {"vertical_mm", m.move.vertical_mm},
                     {"lateral_mm", m.move.lateral_mm},
                     {"pitch_deg", m.move.pitch_deg},
                     {"roll_deg", m.move.roll_deg},
                     {"yaw_deg", m.move.yaw_deg}});
  json["moves"] = moves;
  if (plan.distraction) {
    const DistractionSpec& d = *plan.distraction;
    Json dj{{"target",
             {{"advancement_mm", d.target.advancement_mm},
              {"vertical_mm", d.target.vertical_mm},
              {"widening_mm", d.target.widening_mm},
              {"midline_shift_mm", d.target.midline_shift_mm},
              {"rotation_deg", d.target.rotation_deg},
              {"counter_rotation_deg", d.target.counter_rotation_deg}}},
            {"expected_clockwise_rotation_deg", d.expected_clockwise_rotation_deg},
            {"device",
             {{"screw_length_mm", d.device.screw_length_mm},
              {"screw_diameter_mm", d.device.screw_diameter_mm},
              {"engagement_mm", d.device.engagement_mm}}},
            {"limits",
             {{"sinus_clearance_mm", d.limits.sinus_clearance_mm},
              {"tooth_distance_mm", d.limits.tooth_distance_mm},
              {"nerve_distance_mm", d.limits.nerve_distance_mm},
              {"foramen_below_orbitale_mm", d.limits.foramen_below_orbitale_mm}}},
            {"schedule",
             {{"latency_days", d.schedule.latency_days},
              {"rate_mm_per_day", d.schedule.rate_mm_per_day},
              {"activations_per_day", d.schedule.activations_per_day},
              {"mm_per_turn", d.schedule.mm_per_turn},
              {"consolidation_days", d.schedule.consolidation_days}}}};
    if (d.entry_right) dj["entry_right"] = point_json(*d.entry_right);
    if (d.entry_left) dj["entry_left"] = point_json(*d.entry_left);
    json["distraction"] = dj;
  }
  Json occlusion{{"reference", plan.occlusion.reference}};
  if (!plan.occlusion.pairs_file.empty()) occlusion["pairs_file"] = plan.occlusion.pairs_file;
  json["occlusion"] = occlusion;
  return json;
}

std::string serialise_plan(const Plan& plan) { return plan_to_json(plan).dump(2) + "\n"; }

namespace {

// The target in one line, for a plan created without a description of its own.
std::string target_text(const MaxillaryTarget& target) {
  std::string text = "TS-MD distraction";
  const char* separator = ": ";
  auto add = [&](double value, const char* what, const char* unit) {
    if (value == 0) return;
    char part[64];
    std::snprintf(part, sizeof part, "%s%g %s %s", separator, value, unit, what);
    text += part;
    separator = ", ";
  };
  add(target.advancement_mm, "advancement", "mm");
  add(target.vertical_mm, "vertical move", "mm");
  add(target.widening_mm, "widening", "mm");
  add(target.midline_shift_mm, "midline shift", "mm");
  add(target.rotation_deg, "rotation", "degrees");
  add(target.counter_rotation_deg, "counter-rotation", "degrees");
  return text;
}

}  // namespace

Plan distraction_plan(const MaxillaryTarget& target, const std::string& description) {
  Plan plan;
  plan.description = description.empty() ? target_text(target) : description;
  plan.osteotomies.le_fort_i = CutSpec{};  // default, high: the source's TS-MD cases (ch. 4a, 4b)
  plan.osteotomies.pterygomaxillary = CutSpec{};
  SegmentMove maxilla;
  maxilla.segment = Segment::kMaxilla;
  maxilla.move.advancement_mm = target.advancement_mm;
  maxilla.move.vertical_mm = target.vertical_mm;
  maxilla.move.pitch_deg = target.rotation_deg;
  plan.moves.push_back(maxilla);
  plan.distraction = DistractionSpec{};
  plan.distraction->target = target;
  return plan;
}

}  // namespace maxillo::planning
