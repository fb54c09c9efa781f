#include "landmarking/detection_files.h"

#include <cstdio>

#include "ceph/landmark_io.h"
#include "core/atomic_file.h"
#include "core/error.h"

namespace maxillo::landmarking {
namespace {

std::string number(double value, const char* format = "%.3f") {
  char text[48];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// What a person reads beside the point: confidence, status, the failed checks or the reason.
std::string description(const DetectedLandmark& l) {
  if (!l.position) return "absent: " + l.note;
  std::string text = "automatic, confidence " + number(l.confidence, "%.2f");
  const std::string failed = failed_checks(l);
  if (!failed.empty()) text += "; FLAGGED: " + failed;
  if (!l.note.empty() && failed.find(l.note) == std::string::npos) text += "; " + l.note;
  return text;
}

}  // namespace

std::string status_of(const DetectedLandmark& l) {
  if (!l.position) return "absent";
  return l.flagged() ? "flagged" : "ok";
}

std::string failed_checks(const DetectedLandmark& l) {
  std::string text;
  for (const auto& c : l.checks)
    if (!c.passed) text += (text.empty() ? "" : "; ") + c.name + ": " + c.detail;
  if (l.position && l.confidence < 0.5 && text.empty())
    text = l.note.empty() ? "weak evidence" : "weak evidence: " + l.note;
  return text;
}

std::string format_detection_csv(const LandmarkDetection& d) {
  std::string text = "label,x,y,z,confidence,status,checks_passed,checks_failed,note\n";
  for (const auto& l : d.landmarks) {
    int passed = 0;
    for (const auto& c : l.checks) passed += c.passed;
    text += l.label + ",";
    text += l.position ? number(l.position->x()) + "," + number(l.position->y()) + "," + number(l.position->z())
                       : std::string(",,");
    text += "," + number(l.confidence, "%.2f") + "," + status_of(l) + "," + std::to_string(passed) + "," +
            csv_field(failed_checks(l)) + "," + csv_field(l.note) + "\n";
  }
  return text;
}

std::string format_detection_markups(const LandmarkDetection& d) {
  std::vector<MarkupPoint> points;
  for (const auto& l : d.landmarks) points.push_back({l.label, l.position, description(l), !l.flagged()});
  return format_markup_points(points);
}

Json detection_json(const LandmarkDetection& d) {
  Json landmarks = Json::array();
  for (const auto& l : d.landmarks) {
    Json checks = Json::array();
    for (const auto& c : l.checks) checks.push_back({{"check", c.name}, {"passed", c.passed}, {"detail", c.detail}});
    Json entry = {{"label", l.label}, {"status", status_of(l)}, {"confidence", l.confidence}, {"checks", checks}};
    entry["position"] = l.position ? Json::array({l.position->x(), l.position->y(), l.position->z()}) : Json();
    if (!l.note.empty()) entry["note"] = l.note;
    landmarks.push_back(entry);
  }
  const auto& n = d.midsagittal.normal;
  return {{"method", kMethodVersion},
          {"frame", d.frame_source},
          {"midsagittal_plane", {{"normal", {n.x(), n.y(), n.z()}}, {"offset_mm", d.midsagittal.offset}}},
          {"asymmetry_mm", d.asymmetry_mm},
          {"scale", d.scale},
          {"grey_values", d.reading.grey.describe()},
          {"cone_beam_cupping_undone", d.reading.cupping_depth},
          {"landmarks", landmarks}};
}

void write_detection(const std::filesystem::path& path, const LandmarkDetection& detection) {
  const std::string name = path.filename().string();
  auto ends_with = [&](const std::string& suffix) {
    return name.size() >= suffix.size() &&
           std::equal(suffix.rbegin(), suffix.rend(), name.rbegin(),
                      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
  };
  if (ends_with(".csv"))
    write_file_atomically(path, format_detection_csv(detection));
  else if (ends_with(".json"))
    write_file_atomically(path, format_detection_markups(detection));
  else
    throw Error(ErrorCode::kBadValue, path.string(), "landmark files are .csv or .mrk.json");
}

}  // namespace maxillo::landmarking
