#include "ceph/landmark.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "core/error.h"
#include "core/sha256.h"

namespace maxillo {

std::optional<Eigen::Vector3d> find_landmark(const LandmarkSet& set, const std::string& label) {
  for (const auto& landmark : set)
    if (landmark.label == label) return landmark.position;
  return std::nullopt;
}

Eigen::Vector3d require_landmark(const LandmarkSet& set, const std::string& label, const std::string& subject) {
  if (auto p = find_landmark(set, label)) return *p;
  throw Error(ErrorCode::kBadValue, subject, "needs the landmark " + label);
}

std::optional<Eigen::Vector3d> bilateral_mean(const LandmarkSet& set, const std::string& label) {
  auto right = find_landmark(set, label + "R"), left = find_landmark(set, label + "L");
  if (right && left) return 0.5 * (*right + *left);
  if (auto single = find_landmark(set, label)) return single;
  return right ? right : left;
}

bool is_bilateral_base(const std::string& label) {
  static constexpr std::array kBilateralBases = {"Or", "Po", "Go", "Ar", "Co", "U6", "L6", "U5", "L5", "U4", "L4"};
  return std::find(kBilateralBases.begin(), kBilateralBases.end(), label) != kBilateralBases.end();
}

std::optional<std::string> bilateral_base(const std::string& label) {
  if (label.size() < 2 || (label.back() != 'R' && label.back() != 'L')) return std::nullopt;
  std::string base = label.substr(0, label.size() - 1);
  if (!is_bilateral_base(base)) return std::nullopt;
  return base;
}

std::string landmarks_hash(const LandmarkSet& set) {
  Sha256 hash;
  char line[160];
  for (const auto& l : set) {
    std::snprintf(line, sizeof line, "%s %.6f %.6f %.6f\n", l.label.c_str(), l.position.x(), l.position.y(),
                  l.position.z());
    hash.update(line);
  }
  return hash.hex_digest();
}

}  // namespace maxillo
