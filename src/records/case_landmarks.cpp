#include "records/case_landmarks.h"

#include <algorithm>
#include <map>

#include "archive/artefact_kind.h"
#include "ceph/landmark_io.h"
#include "core/error.h"
#include "core/json.h"
#include "core/json_reader.h"
#include "core/sha256.h"
#include "records/stored_artefact.h"

namespace maxillo::records {
namespace {
const std::string kLandmarksKind = kind_name(ArtefactKind::kLandmarks);

Json frame_json(const LandmarkFrame& frame) {
  if (frame.geometry != LandmarkGeometry::kCephalogram) return "LPS";
  return Json{{"cephalogram",
               {{"pixel_spacing_mm", frame.axes.pixel_spacing_mm},
                {"image_y", frame.axes.vertical == ImageVerticalAxis::kDown ? "down" : "up"},
                {"face", frame.axes.facing == FacingDirection::kPlusX ? "+x" : "-x"}}}};
}

// The frame frame_json wrote: "LPS", or a cephalogram's pixel spacing and image axes. Anything
// else fails naming the key: a cephalogram read with a default spacing would give every
// measurement at the wrong scale.
LandmarkFrame read_frame(JsonReader& parameters) {
  LandmarkFrame frame;
  const Json& value = parameters.at("frame");
  if (value == Json("LPS")) return frame;
  JsonReader r = parameters.object("frame");
  JsonReader c = r.object("cephalogram");
  frame.geometry = LandmarkGeometry::kCephalogram;
  frame.axes.pixel_spacing_mm = c.required_number("pixel_spacing_mm", 1e-6, 1e3);
  const std::string image_y = c.required_text("image_y"), face = c.required_text("face");
  if (image_y != "up" && image_y != "down") c.fail(c.field("image_y"), "must be \"up\" or \"down\"");
  if (face != "+x" && face != "-x") c.fail(c.field("face"), "must be \"+x\" or \"-x\"");
  frame.axes.vertical = image_y == "down" ? ImageVerticalAxis::kDown : ImageVerticalAxis::kUp;
  frame.axes.facing = face == "-x" ? FacingDirection::kMinusX : FacingDirection::kPlusX;
  return frame;
}

// A stored set's facts, from its artefact's parameters (what attach_landmarks wrote): the
// source, the frame, and the time point and date when it has one.
StoredLandmarks read_landmark_record(const ArtefactRecord& record) {
  const std::string source = artefact_source(record);
  Json parameters = Json::parse(record.parameters_json, nullptr, /*allow_exceptions=*/false);
  if (parameters.is_discarded()) parameters = nullptr;  // not JSON: refused below as not an object
  JsonReader r(parameters, "", source, ErrorCode::kArchiveCorrupt, "parameters");
  StoredLandmarks stored;
  stored.artefact_id = record.id;
  stored.source = r.required_text("source");
  stored.frame = read_frame(r);
  if (r.has("time_point") || r.has("date")) {
    stored.time_point = {r.required_text("time_point"), r.required_text("date")};
    if (!stored.time_point.date.empty() && !is_iso_date(stored.time_point.date))
      r.fail("date", "must be YYYY-MM-DD or empty");
  }
  stored.created_at = record.created_at;
  stored.reference = r.has("reference") && r.at("reference") == Json(true);
  if (r.has("automatic")) {
    JsonReader a = r.object("automatic");
    AutomaticFacts facts;
    facts.method = a.required_text("method");
    for (const auto& [label, value] : a.at("confidence").items())
      facts.confidence[label] = value.is_number() ? value.get<double>() : 0.0;
    for (const auto& [label, value] : a.at("flagged").items())
      facts.flagged[label] = value.is_string() ? value.get<std::string>() : std::string();
    for (const auto& [label, value] : a.at("absent").items())
      facts.absent[label] = value.is_string() ? value.get<std::string>() : std::string();
    stored.automatic = std::move(facts);
  }
  return stored;
}

// The newest landmark artefact given by hand, else the newest automatic one; never a reference.
const ArtefactRecord* preferred_record(const std::vector<ArtefactRecord>& artefacts) {
  const ArtefactRecord* by_hand = nullptr;
  const ArtefactRecord* automatic = nullptr;
  for (const auto& record : artefacts) {
    if (record.kind != kLandmarksKind) continue;
    const Json parameters = Json::parse(record.parameters_json, nullptr, /*allow_exceptions=*/false);
    const bool is_object = parameters.is_object();
    if (is_object && parameters.contains("reference") && parameters.at("reference") == Json(true)) continue;
    const bool detected = is_object && parameters.contains("automatic");
    const ArtefactRecord*& newest = detected ? automatic : by_hand;
    if (!newest || record.id > newest->id) newest = &record;
  }
  return by_hand ? by_hand : automatic;
}

LandmarkSet read_set(const Archive& archive, const ArtefactRecord& record) {
  return parse_landmarks(artefact_text(archive, record), LandmarkFormat::kSlicerMarkupsJson,
                         "archive object " + record.object_sha256);
}

}  // namespace

bool is_iso_date(const std::string& text) {
  if (text.size() != 10 || text[4] != '-' || text[7] != '-') return false;
  for (size_t i : {0, 1, 2, 3, 5, 6, 8, 9})
    if (text[i] < '0' || text[i] > '9') return false;
  int month = std::stoi(text.substr(5, 2)), day = std::stoi(text.substr(8, 2));
  return month >= 1 && month <= 12 && day >= 1 && day <= 31;
}

void attach_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& landmarks, const std::string& source) {
  attach_landmarks(archive, case_id, landmarks, source, TimePoint{});
}

void attach_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& landmarks, const std::string& source,
                      const TimePoint& time_point, const LandmarkFrame& frame, LandmarkOrigin origin) {
  if (!time_point.date.empty() && !is_iso_date(time_point.date))
    throw Error(ErrorCode::kBadValue, time_point.date, "date must be YYYY-MM-DD");
  auto text = format_landmarks(landmarks, LandmarkFormat::kSlicerMarkupsJson);
  auto sha = archive.store_object(text);
  Json parameters{{"source", source}, {"count", landmarks.size()}, {"frame", frame_json(frame)}};
  if (origin == LandmarkOrigin::kReference) parameters["reference"] = true;
  // The derivation key: the points, and the time point and the origin when they say more (a
  // reference set is not the same artefact as a given one with the same points).
  std::string inputs = sha;
  const bool for_a_time_point = !time_point.label.empty() || !time_point.date.empty();
  if (for_a_time_point || origin == LandmarkOrigin::kReference) {
    Sha256 hash;
    hash.update(sha);
    if (for_a_time_point) {
      parameters["time_point"] = time_point.label;
      parameters["date"] = time_point.date;
      hash.update("\n" + time_point.label + "\n" + time_point.date);
    }
    if (origin == LandmarkOrigin::kReference) hash.update("\nreference");
    inputs = hash.hex_digest();
  }
  archive.add_artefact(NewArtefact{case_id, kLandmarksKind, sha, "application/json", inputs, parameters.dump()});
}

LandmarkSet latest_landmarks(const Archive& archive, int64_t case_id) {
  return latest_landmarks(archive, archive.artefacts(case_id));
}

LandmarkSet latest_landmarks(const Archive& archive, const std::vector<ArtefactRecord>& artefacts) {
  const ArtefactRecord* preferred = preferred_record(artefacts);
  if (!preferred) return {};
  return read_set(archive, *preferred);
}

std::optional<StoredLandmarks> preferred_landmarks(const Archive& archive, int64_t case_id) {
  const auto artefacts = archive.artefacts(case_id);
  const ArtefactRecord* preferred = preferred_record(artefacts);
  if (!preferred) return std::nullopt;
  StoredLandmarks stored = read_landmark_record(*preferred);
  stored.landmarks = read_set(archive, *preferred);
  return stored;
}

std::optional<StoredLandmarks> newest_automatic_landmarks(const Archive& archive, int64_t case_id) {
  std::optional<StoredLandmarks> newest;
  for (auto& stored : landmark_history(archive, case_id))
    if (stored.automatic) newest = std::move(stored);
  return newest;
}

std::optional<StoredLandmarks> newest_reference_landmarks(const Archive& archive, int64_t case_id) {
  std::optional<StoredLandmarks> newest;
  for (auto& stored : landmark_history(archive, case_id))
    if (stored.reference && stored.time_point.label.empty() && stored.time_point.date.empty())
      newest = std::move(stored);
  return newest;
}

void attach_automatic_landmarks(Archive& archive, int64_t case_id, const LandmarkSet& present,
                                const AutomaticFacts& facts) {
  auto text = format_landmarks(present, LandmarkFormat::kSlicerMarkupsJson);
  auto sha = archive.store_object(text);
  const Json automatic{
      {"method", facts.method}, {"confidence", facts.confidence}, {"flagged", facts.flagged}, {"absent", facts.absent}};
  const Json parameters{{"source", "automatic (" + facts.method + ")"},
                        {"count", present.size()},
                        {"frame", frame_json({})},
                        {"automatic", automatic}};
  Sha256 inputs;
  inputs.update(sha);
  inputs.update("\nautomatic " + facts.method);
  archive.add_artefact(
      NewArtefact{case_id, kLandmarksKind, sha, "application/json", inputs.hex_digest(), parameters.dump()});
}

std::vector<StoredLandmarks> landmark_history(const Archive& archive, int64_t case_id) {
  auto artefacts = archive.artefacts(case_id);
  std::sort(artefacts.begin(), artefacts.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  std::vector<StoredLandmarks> history;
  std::map<std::string, int> versions;
  for (const auto& record : artefacts) {
    if (record.kind != kLandmarksKind) continue;
    StoredLandmarks stored = read_landmark_record(record);
    stored.version = ++versions[stored.time_point.label];
    stored.landmarks = read_set(archive, record);
    history.push_back(std::move(stored));
  }
  return history;
}

std::vector<StoredLandmarks> landmark_time_points(const Archive& archive, int64_t case_id) {
  std::map<std::string, StoredLandmarks> newest;
  for (auto& stored : landmark_history(archive, case_id))
    if (!stored.time_point.label.empty()) newest[stored.time_point.label] = std::move(stored);
  std::vector<StoredLandmarks> out;
  for (auto& [label, stored] : newest) out.push_back(std::move(stored));
  std::stable_sort(out.begin(), out.end(), [](const StoredLandmarks& a, const StoredLandmarks& b) {
    if (a.time_point.date.empty() != b.time_point.date.empty()) return b.time_point.date.empty();
    return a.time_point.date < b.time_point.date;
  });
  return out;
}

}  // namespace maxillo::records
