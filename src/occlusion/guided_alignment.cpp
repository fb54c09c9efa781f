#include "occlusion/guided_alignment.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "geometry/rigid_fit.h"

namespace maxillo::occlusion {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

constexpr double kTrustRegionMm = 0.5;     // largest vertex displacement per iteration
constexpr double kStallMm = 1e-4;          // a step this small ends the iteration
constexpr double kConstraintWeight = 1e4;  // penalty weight of an active contact, relative to one spring
constexpr double kSettledSpringMm = 0.15;  // springs this short need no tapping (contact pairs are up to 0.1 mm apart)
constexpr double kTapLiftsMm[] = {0.25, 0.5, 1.0};  // lifts tried, in order, when a cusp holds the arch

Matrix3d skew(const Vector3d& v) {
  Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// The motion x -> R(w)(x - c) + c + t for the twist (t, w) about centre c.
Eigen::Isometry3d twist_motion(const Vector6d& twist, const Vector3d& centre) {
  const Vector3d w = twist.tail<3>();
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.translate(centre + twist.head<3>());
  if (w.norm() > 0) motion.rotate(Eigen::AngleAxisd(w.norm(), w.normalized()));
  motion.translate(-centre);
  return motion;
}

double spring_energy(const Eigen::Isometry3d& pose, const std::vector<SpringPair>& pairs) {
  double energy = 0;
  for (const SpringPair& p : pairs) energy += (pose * p.upper - p.lower).squaredNorm();
  return energy;
}

// Gauss-Newton step for the springs, with linearised contact constraints
// gap + J_c twist >= -allowed added as stiff penalties while the prediction violates them.
Vector6d constrained_step(const Eigen::Isometry3d& pose, const std::vector<SpringPair>& pairs,
                          const ContactState& contacts, double allowed, const Vector3d& centre) {
  Matrix6d h = Matrix6d::Identity() * 1e-9;
  Vector6d g = Vector6d::Zero();
  for (const SpringPair& p : pairs) {
    const Vector3d x = pose * p.upper;
    Eigen::Matrix<double, 3, 6> j;
    j << Matrix3d::Identity(), -skew(x - centre);
    h += j.transpose() * j;
    g += j.transpose() * (x - p.lower);
  }
  std::vector<Vector6d> rows(contacts.contacts.size());
  for (size_t k = 0; k < rows.size(); ++k) {
    const ArchContact& c = contacts.contacts[k];
    rows[k] << c.direction, (c.anchor - centre).cross(c.direction);
  }
  const double weight = kConstraintWeight * double(pairs.size());
  // Active set of one-sided constraints held by stiff penalties: a contact joins when the step
  // would push it deeper than allowed, and leaves when its penalty would pull it (a contact may
  // push, never hold).
  std::vector<char> active(rows.size(), 0);
  Vector6d twist = h.ldlt().solve(-g);
  for (int round = 0; round < 20; ++round) {
    bool changed = false;
    for (size_t k = 0; k < rows.size(); ++k) {
      const double predicted = contacts.contacts[k].gap_mm + rows[k].dot(twist);
      if (!active[k] && predicted < -allowed)
        active[k] = 1, changed = true;
      else if (active[k] && predicted > -allowed + 1e-6)
        active[k] = 0, changed = true;
    }
    if (!changed) break;
    Matrix6d hc = h;
    Vector6d gc = g;
    for (size_t k = 0; k < rows.size(); ++k)
      if (active[k]) {
        hc += weight * rows[k] * rows[k].transpose();
        gc += weight * rows[k] * (contacts.contacts[k].gap_mm + allowed);
      }
    twist = hc.ldlt().solve(-gc);
  }
  return twist;
}

// SeparateAlignClose: returns the lift used, 0 when the arch stayed where it was.
double separate_and_align(MotionEngine& engine, const std::vector<SpringPair>& pairs) {
  const Eigen::Isometry3d target = best_fit_transform(pairs);
  if (engine.max_displacement_mm(target * engine.pose().inverse()) < 0.5) return 0;
  const Vector3d upper_centre = engine.pose() * Vector3d(engine.upper().mesh().vertices.colwise().mean().transpose());
  const Vector3d lower_centre = engine.lower().mesh().vertices.colwise().mean().transpose();
  const Vector3d away = (upper_centre - lower_centre).normalized();
  const Eigen::Isometry3d start = engine.pose();
  for (double lift : {2.0, 4.0, 8.0, 16.0}) {
    Eigen::Isometry3d raise = Eigen::Isometry3d::Identity();
    raise.translate(lift * away);
    if (engine.move(raise).outcome != StepOutcome::Moved) continue;
    if (engine.move(raise * target * engine.pose().inverse()).outcome == StepOutcome::Moved) return lift;
    engine.set_pose(start);  // back along the checked lift
  }
  return 0;
}

}  // namespace

Eigen::Isometry3d best_fit_transform(const std::vector<SpringPair>& pairs) {
  assert(pairs.size() >= 3 && "best_fit_transform needs at least three pairs");
  std::vector<Vector3d> upper, lower;
  for (const SpringPair& p : pairs) upper.push_back(p.upper), lower.push_back(p.lower);
  return best_rigid_transform(upper, lower);
}

namespace {

// Gauss-Newton iterations from the engine's pose until the step stalls. Returns the iterations
// used and whether it converged (false: the iteration budget ran out).
std::pair<int, bool> settle(MotionEngine& engine, const std::vector<SpringPair>& pairs, int max_iterations) {
  const double tolerance = engine.options().penetration_tolerance_mm;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    const Eigen::Isometry3d pose = engine.pose();
    Vector3d centre = Vector3d::Zero();
    for (const SpringPair& p : pairs) centre += pose * p.upper;
    centre /= double(pairs.size());
    const ContactState contacts = engine.contacts();
    const double energy = spring_energy(pose, pairs);
    // The linearised contacts keep half the tolerance in reserve for curvature; when no step
    // along that direction is admissible, retry once keeping the whole tolerance in reserve.
    bool accepted = false, stalled = false;
    for (double reserve : {0.5 * tolerance, tolerance}) {
      const double allowed = engine.allowed_penetration_mm() - reserve;
      Vector6d twist = constrained_step(pose, pairs, contacts, allowed, centre);
      double reach = engine.max_displacement_mm(twist_motion(twist, centre));
      if (reach > kTrustRegionMm) twist *= kTrustRegionMm / reach, reach = kTrustRegionMm;
      stalled = reach < kStallMm;
      for (double scale = 1.0; scale * reach > kStallMm && !accepted; scale *= 0.5) {
        const Eigen::Isometry3d candidate = twist_motion(scale * twist, centre) * pose;
        if (spring_energy(candidate, pairs) < energy && engine.admissible(candidate)) {
          engine.set_pose(candidate);
          accepted = true;
        }
      }
      if (accepted || stalled) break;
    }
    if (!accepted || stalled) return {iteration + 1, true};
  }
  return {max_iterations, false};
}

double longest_spring(const Eigen::Isometry3d& pose, const std::vector<SpringPair>& pairs) {
  double longest = 0;
  for (const SpringPair& p : pairs) longest = std::max(longest, (pose * p.upper - p.lower).norm());
  return longest;
}

// A cusp can catch the arch on a slope short of the springs' rest position (a local minimum,
// as with plaster casts). Like a user tapping the cast, lift it slightly along the line between
// the arches and let the springs close it again; keep the result only when the springs are
// shorter. Deterministic.
int tap_and_resettle(MotionEngine& engine, const std::vector<SpringPair>& pairs, int iteration_budget) {
  int used = 0;
  for (double lift : kTapLiftsMm) {
    if (longest_spring(engine.pose(), pairs) <= kSettledSpringMm || used >= iteration_budget) break;
    const Eigen::Isometry3d before = engine.pose();
    const double energy = spring_energy(before, pairs);
    const Vector3d upper_centre = before * Vector3d(engine.upper().mesh().vertices.colwise().mean().transpose());
    const Vector3d lower_centre = engine.lower().mesh().vertices.colwise().mean().transpose();
    Eigen::Isometry3d raise = Eigen::Isometry3d::Identity();
    raise.translate(lift * (upper_centre - lower_centre).normalized());
    if (engine.move(raise).outcome != StepOutcome::Moved) continue;
    used += settle(engine, pairs, iteration_budget - used).first;
    if (spring_energy(engine.pose(), pairs) >= energy) engine.set_pose(before);
  }
  return used;
}

}  // namespace

AlignmentResult align_guided(MotionEngine& engine, const std::vector<SpringPair>& pairs, Approach approach) {
  assert(pairs.size() >= 3 && "guided alignment needs at least three point pairs");
  AlignmentResult result;
  if (approach == Approach::SeparateAlignClose) result.lift_mm = separate_and_align(engine, pairs);
  const int budget = engine.options().max_iterations;
  const auto [iterations, converged] = settle(engine, pairs, budget);
  result.iterations = iterations;
  result.status = converged ? AlignmentStatus::Converged : AlignmentStatus::IterationLimit;
  if (converged) result.iterations += tap_and_resettle(engine, pairs, budget - iterations);
  result.pose = engine.pose();
  for (const SpringPair& p : pairs) result.residual_spring_mm.push_back((result.pose * p.upper - p.lower).norm());
  result.penetration_mm = engine.penetration_at(result.pose);
  return result;
}

}  // namespace maxillo::occlusion
