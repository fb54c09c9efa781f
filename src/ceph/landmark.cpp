#include "ceph/landmark.h"

namespace maxillo {

std::optional<Eigen::Vector3d> find_landmark(const LandmarkSet& set, const std::string& label) {
  for (const auto& landmark : set)
    if (landmark.label == label) return landmark.position;
  return std::nullopt;
}

}  // namespace maxillo
