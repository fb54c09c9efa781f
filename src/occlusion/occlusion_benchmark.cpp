#include "occlusion/occlusion_benchmark.h"

#include <algorithm>
#include <cmath>

#include "occlusion/arch_contacts.h"

namespace maxillo::occlusion {

std::vector<SpringPair> contact_spring_pairs(const DistanceField& upper, const DistanceField& lower,
                                             const Eigen::Isometry3d& pose, int count, double max_gap_mm) {
  std::vector<SpringPair> candidates;
  for (const ArchContact& c : assess_contacts(upper, lower, pose, max_gap_mm).contacts) {
    if (c.side != ContactSide::UpperVertex || std::abs(c.gap_mm) > max_gap_mm) continue;
    const Eigen::Vector3d u = upper.mesh().vertices.row(c.vertex).transpose();
    candidates.push_back({u, lower.signed_distance(pose * u, 2 * max_gap_mm + 1).point});
  }
  std::vector<SpringPair> chosen;
  if (candidates.empty()) return chosen;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const SpringPair& c : candidates) centroid += c.lower;
  centroid /= double(candidates.size());
  std::vector<double> nearest(candidates.size(), 1e300);
  size_t next = 0;
  for (size_t i = 0; i < candidates.size(); ++i)
    if ((candidates[i].lower - centroid).norm() > (candidates[next].lower - centroid).norm()) next = i;
  while (int(chosen.size()) < count && int(chosen.size()) < int(candidates.size())) {
    chosen.push_back(candidates[next]);
    for (size_t i = 0; i < candidates.size(); ++i)
      nearest[i] = std::min(nearest[i], (candidates[i].lower - candidates[next].lower).norm());
    next = size_t(std::max_element(nearest.begin(), nearest.end()) - nearest.begin());
  }
  return chosen;
}

std::vector<int> occlusal_region(const DistanceField& upper, const DistanceField& lower, const Eigen::Isometry3d& pose,
                                 double region_mm) {
  std::vector<int> vertices;
  for (Eigen::Index v = 0; v < upper.mesh().vertex_count(); ++v)
    if (lower.signed_distance(pose * Eigen::Vector3d(upper.mesh().vertices.row(v).transpose()), region_mm).found)
      vertices.push_back(int(v));
  return vertices;
}

std::vector<double> vertex_displacements(const TriangleMesh& upper, const std::vector<int>& vertices,
                                         const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  std::vector<double> d;
  d.reserve(vertices.size());
  for (int v : vertices) {
    const Eigen::Vector3d x = upper.vertices.row(v).transpose();
    d.push_back((a * x - b * x).norm());
  }
  return d;
}

double percentile(std::vector<double> values, double percent) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const double position = percent / 100.0 * double(values.size() - 1);
  const size_t below = size_t(std::floor(position));
  const size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - double(below)) * (values[above] - values[below]);
}

Eigen::Isometry3d random_displacement(std::mt19937& rng, const Eigen::Vector3d& centre, double max_mm, double max_deg) {
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> unit(0, 1);
  const Eigen::Vector3d axis = Eigen::Vector3d(gaussian(rng), gaussian(rng), gaussian(rng)).normalized();
  const double angle = max_deg * unit(rng) * M_PI / 180.0;
  const Eigen::Vector3d direction = Eigen::Vector3d(gaussian(rng), gaussian(rng), gaussian(rng)).normalized();
  const double distance = max_mm * std::cbrt(unit(rng));
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translate(centre + distance * direction).rotate(Eigen::AngleAxisd(angle, axis)).translate(-centre);
  return motion;
}

Eigen::Isometry3d place_in_contact(const DistanceField& upper, const DistanceField& lower,
                                   const Eigen::Isometry3d& pose, double target_penetration_mm) {
  constexpr double kBandMm = 3.0;  // penetrations deeper than this are not met: the start is at most ~3 mm off
  const auto raised = [&](double z) {
    Eigen::Isometry3d moved = pose;
    moved.pretranslate(Eigen::Vector3d(0, 0, z));
    return moved;
  };
  const auto too_deep = [&](double z) {
    return assess_contacts(upper, lower, raised(z), kBandMm).max_penetration_mm > target_penetration_mm;
  };
  double low = 0, high = 0;  // too deep at `low`, not at `high`
  if (too_deep(0)) {
    high = 0.5;
    for (int k = 0; k < 6 && too_deep(high); ++k) low = high, high *= 2;
  } else {
    low = -0.5;
    for (int k = 0; k < 6 && !too_deep(low); ++k) high = low, low *= 2;
  }
  while (high - low > 0.01) {
    const double middle = 0.5 * (low + high);
    (too_deep(middle) ? low : high) = middle;
  }
  return raised(high);
}

}  // namespace maxillo::occlusion
