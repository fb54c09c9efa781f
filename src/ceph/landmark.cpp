#include "ceph/landmark.h"

#include "core/error.h"

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

}  // namespace maxillo
