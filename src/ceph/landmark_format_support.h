#pragma once
// Internal to ceph/landmark_*.cpp: text helpers shared by the landmark file formats and the
// parsers/formatters of each format (the public entry points are in landmark_io.h).
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "ceph/landmark.h"
#include <Eigen/Core>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "core/error.h"

namespace maxillo::landmark_format {

enum class Frame { kLps, kRas };

inline Eigen::Vector3d to_lps(const Eigen::Vector3d& p, Frame frame) {
  return frame == Frame::kRas ? Eigen::Vector3d(-p.x(), -p.y(), p.z()) : p;
}

inline std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

inline std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  for (size_t i = 0; i <= line.size(); ++i)
    if (i == line.size() || line[i] == separator) {
      fields.push_back(trim(line.substr(start, i - start)));
      start = i + 1;
    }
  return fields;
}

inline std::string number(double v) {
  if (v == 0) v = 0;  // no "-0"
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, v);  // shortest exact round trip
  return std::string(buffer, result.ptr);
}

// Collects landmarks, rejecting empty and duplicate labels.
class Collector {
 public:
  explicit Collector(std::string source) : source_(std::move(source)) {}
  [[noreturn]] void fail(const std::string& where, const std::string& reason) const {
    throw Error(ErrorCode::kBadValue, source_, where + ": " + reason);
  }
  double parse_number(std::string_view field, const char* axis, const std::string& where) const {
    double value = 0;
    auto result = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size() || !std::isfinite(value))
      fail(where, std::string("coordinate ") + axis + " is not a number: '" + std::string(field) + "'");
    return value;
  }
  void add(std::string label, const Eigen::Vector3d& lps, const std::string& where) {
    if (label.empty()) fail(where, "empty label");
    if (!labels_.insert(label).second) fail(where, "duplicate label '" + label + "'");
    set_.push_back({std::move(label), lps});
  }
  LandmarkSet take() { return std::move(set_); }

 private:
  std::string source_;
  std::set<std::string> labels_;
  LandmarkSet set_;
};

inline std::string line_name(size_t number) { return "line " + std::to_string(number); }

LandmarkSet parse_csv(std::string_view text, const std::string& source);
LandmarkSet parse_fcsv(std::string_view text, const std::string& source);
LandmarkSet parse_markups_json(std::string_view text, const std::string& source);
std::string format_csv(const LandmarkSet& set);
std::string format_fcsv(const LandmarkSet& set);
std::string format_markups_json(const LandmarkSet& set);

}  // namespace maxillo::landmark_format
