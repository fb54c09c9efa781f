#pragma once
// What a landmark rule returns: the point (head frame, mm) or why there is none, and how sure
// the rule's own evidence makes it (the consistency checks come later, landmark_checks.h).
#include <map>
#include <optional>
#include <string>

#include <Eigen/Core>

namespace maxillo::landmarking {

struct RuleFinding {
  std::optional<Eigen::Vector3d> position;  // head frame mm; nullopt: absent
  double evidence = 0;                      // 0..1: how clearly the anatomy showed the point
  std::string note;                         // why absent, or what weakened the evidence

  static RuleFinding found(const Eigen::Vector3d& p, double evidence, std::string note = {}) {
    return {p, evidence, std::move(note)};
  }
  static RuleFinding absent(std::string reason) { return {std::nullopt, 0, std::move(reason)}; }
};

using Findings = std::map<std::string, RuleFinding>;

// Evidence that grows linearly from 0 at `none` to 1 at `full` (clamped).
inline double evidence_between(double value, double none, double full) {
  const double t = (value - none) / (full - none);
  return t < 0 ? 0 : t > 1 ? 1 : t;
}

}  // namespace maxillo::landmarking
