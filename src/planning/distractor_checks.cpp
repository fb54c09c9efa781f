#include "planning/distractor_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

#include "core/error.h"
#include "planning/maxillary_sinus.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

constexpr double kStepMm = 0.5;    // sampling step along the screw
constexpr double kMaxWallMm = 10;  // the axis must reach sinus air this close to the entry
constexpr int kRingSamples = 12;
// The first millimetres behind the anterior wall are the entry hole's rim, where the screw
// crosses the curved front of the sinus: the clearance ring is checked from there on.
constexpr double kEntryZoneMm = 5;

std::string mm(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f mm", value);
  return text;
}

// Label of the voxel nearest to p; 0 outside the grid.
uint8_t label_at(const LabelVolume& volume, const Vector3d& p) {
  const Vector3d c = volume.geometry.continuous_index(p);
  const int i = static_cast<int>(std::lround(c.x()));
  const int j = static_cast<int>(std::lround(c.y()));
  const int k = static_cast<int>(std::lround(c.z()));
  if (!volume.geometry.contains(i, j, k)) return 0;
  return volume.labels[volume.geometry.index(i, j, k)];
}

std::optional<Vector3d> sinus_centroid(const LabelVolume& volume, const PlanningFrame& frame,
                                       const AnatomyLabels& anatomy, Side side, const SinusBox& box) {
  const VolumeGeometry& g = volume.geometry;
  Vector3d sum = Vector3d::Zero();
  int64_t count = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        if (!is_labelled(anatomy.sinus_air, volume.labels[g.index(i, j, k)])) continue;
        const Vector3d p = g.world(Vector3d(i, j, k));
        if (!box.contains(p, frame, side)) continue;
        sum += p;
        ++count;
      }
  if (count == 0) return std::nullopt;
  return sum / static_cast<double>(count);
}

// From inside the sinus along `direction`: through the air, then through the wall's bone; the
// entry point is the first sample beyond both.
Vector3d exit_point(const LabelVolume& volume, const AnatomyLabels& anatomy, const Vector3d& start,
                    const Vector3d& direction) {
  const double step = 0.25;
  Vector3d p = start;
  for (int n = 0; n < 400 && is_labelled(anatomy.sinus_air, label_at(volume, p)); ++n) p += step * direction;
  for (int n = 0; n < 80; ++n) {
    const uint8_t label = label_at(volume, p);
    if (!is_labelled(anatomy.bone, label) && !is_labelled(anatomy.teeth, label)) break;
    p += step * direction;
  }
  return p;
}

// Distance from the entry point, backwards along the axis, to the first sinus air sample; and
// the length of the air run from there. nullopt when no air within kMaxWallMm.
struct AxisProfile {
  double wall_mm = 0;
  double depth_mm = 0;
};
std::optional<AxisProfile> axis_profile(const LabelVolume& volume, const AnatomyLabels& anatomy,
                                        const DistractionVector& v) {
  const double step = 0.25;
  AxisProfile profile;
  double s = 0;
  while (s <= kMaxWallMm && !is_labelled(anatomy.sinus_air, label_at(volume, v.entry - s * v.axis))) s += step;
  if (s > kMaxWallMm) return std::nullopt;
  profile.wall_mm = s;
  while (s < 200 && is_labelled(anatomy.sinus_air, label_at(volume, v.entry - s * v.axis))) s += step;
  profile.depth_mm = s - profile.wall_mm;
  return profile;
}

// Two unit vectors perpendicular to `axis`.
std::pair<Vector3d, Vector3d> perpendiculars(const Vector3d& axis) {
  const Vector3d helper = std::abs(axis.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  const Vector3d u = axis.cross(helper).normalized();
  return {u, axis.cross(u).normalized()};
}

double point_segment_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

DistractorCheck make_check(std::string name, Side side, double value, double limit) {
  DistractorCheck check;
  check.name = std::move(name);
  check.side = side;
  check.value = value;
  check.limit = limit;
  return check;
}

DistractorCheck fail(DistractorCheck check, std::string reason) {
  check.status = CheckStatus::Fail;
  check.reason = std::move(reason);
  return check;
}

std::string tissue_word(const AnatomyLabels& anatomy, uint8_t label) {
  if (is_labelled(anatomy.teeth, label)) return "a tooth";
  if (is_labelled(anatomy.bone, label)) return "bone";
  return "soft tissue or air outside the sinus";
}

// Screw body inside the sinus air with clearance; the first sample that is not tells why.
DistractorCheck check_in_sinus(const LabelVolume& volume, const AnatomyLabels& anatomy, const DistractionVector& v,
                               const AxisProfile& profile, const DistractorDevice& device, const CheckLimits& limits) {
  const double ring = device.screw_diameter_mm / 2 + limits.sinus_clearance_mm;
  const auto [u, w] = perpendiculars(v.axis);
  DistractorCheck check = make_check("screw in sinus", v.side, device.screw_length_mm, device.screw_length_mm);
  for (double s = profile.wall_mm; s <= device.screw_length_mm + 1e-9; s += kStepMm) {
    const Vector3d centre = v.entry - s * v.axis;
    std::vector<Vector3d> samples{centre};
    if (s >= profile.wall_mm + kEntryZoneMm)
      for (int n = 0; n < kRingSamples; ++n) {
        const double angle = 2 * std::numbers::pi * n / kRingSamples;
        samples.push_back(centre + ring * (std::cos(angle) * u + std::sin(angle) * w));
      }
    for (const Vector3d& p : samples) {
      const uint8_t label = label_at(volume, p);
      if (is_labelled(anatomy.sinus_air, label)) continue;
      check.value = s;
      return fail(check, "the screw body (with " + mm(limits.sinus_clearance_mm) + " clearance) leaves the sinus air " +
                             mm(s) + " behind the entry point and meets " + tissue_word(anatomy, label));
    }
  }
  return check;
}

DistractorCheck check_depth(const DistractionVector& v, const AxisProfile& profile, const DistractorDevice& device,
                            const CheckLimits& limits) {
  const double needed = device.screw_length_mm - profile.wall_mm + limits.sinus_clearance_mm;
  DistractorCheck check = make_check("sinus depth", v.side, profile.depth_mm, needed);
  if (profile.depth_mm < needed)
    return fail(check, "the sinus is " + mm(profile.depth_mm) + " deep along the screw axis; the " +
                           mm(device.screw_length_mm) + " screw needs " + mm(needed));
  return check;
}

DistractorCheck check_travel(const DistractionVector& v, const DistractorDevice& device) {
  const double travel = device.screw_length_mm - device.engagement_mm;
  DistractorCheck check = make_check("screw travel", v.side, v.activation_mm, travel);
  if (v.activation_mm > travel)
    return fail(check, "activation " + mm(v.activation_mm) + " exceeds the screw's travel " + mm(travel));
  return check;
}

DistractorCheck check_teeth(const LabelVolume& volume, const AnatomyLabels& anatomy, const DistractionVector& v,
                            const DistractorDevice& device, const CheckLimits& limits) {
  const Vector3d a = v.entry;
  const Vector3d b = v.entry - device.screw_length_mm * v.axis;
  const double reach = device.screw_diameter_mm / 2 + limits.tooth_distance_mm + 20;
  const VolumeGeometry& g = volume.geometry;
  // Search the voxels of the segment's bounding box grown by `reach` only.
  Vector3d lo = a.cwiseMin(b).array() - reach, hi = a.cwiseMax(b).array() + reach;
  Eigen::Vector3d c0 = g.continuous_index(lo), c1 = g.continuous_index(hi);
  const Eigen::Vector3i from = c0.cwiseMin(c1).array().floor().cast<int>().max(0);
  const Eigen::Vector3i to = c0.cwiseMax(c1).array().ceil().cast<int>().min((g.size.array() - 1));
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = from.z(); k <= to.z(); ++k)
    for (int j = from.y(); j <= to.y(); ++j)
      for (int i = from.x(); i <= to.x(); ++i)
        if (is_labelled(anatomy.teeth, volume.labels[g.index(i, j, k)]))
          nearest = std::min(nearest, point_segment_distance(g.world(Vector3d(i, j, k)), a, b));
  const double clearance = nearest - device.screw_diameter_mm / 2;
  DistractorCheck check = make_check("tooth distance", v.side, clearance, limits.tooth_distance_mm);
  if (clearance < limits.tooth_distance_mm)
    return fail(check, "the screw passes " + mm(std::max(clearance, 0.0)) + " from a tooth root or bud; at least " +
                           mm(limits.tooth_distance_mm) + " needed");
  return check;
}

std::optional<Vector3d> orbitale_of(const LandmarkSet& landmarks, const PlanningFrame& frame, Side side) {
  if (auto p = find_landmark(landmarks, side == Side::Right ? "OrR" : "OrL")) return p;
  const auto single = find_landmark(landmarks, "Or");
  if (!single) return std::nullopt;
  // One orbitale (a profile tracing): mirror it to the requested side of the mid-sagittal plane.
  const double lateral = (*single - frame.origin).dot(frame.left);
  if (lateral * outward_sign(side) >= 0) return single;
  return Vector3d(*single - 2 * lateral * frame.left);
}

DistractorCheck check_nerve(const DistractionVector& v, const LandmarkSet& landmarks, const PlanningFrame& frame,
                            const DistractorDevice& device, const CheckLimits& limits) {
  DistractorCheck check = make_check("infraorbital nerve", v.side, 0, limits.nerve_distance_mm);
  const auto orbitale = orbitale_of(landmarks, frame, v.side);
  if (!orbitale) {
    check.status = CheckStatus::NotChecked;
    check.reason = "no orbitale landmark (OrR, OrL or Or)";
    return check;
  }
  const Vector3d foramen = *orbitale - limits.foramen_below_orbitale_mm * frame.superior;
  const double distance = point_segment_distance(foramen, v.entry, v.entry - device.screw_length_mm * v.axis) -
                          device.screw_diameter_mm / 2;
  check.value = distance;
  if (distance < limits.nerve_distance_mm)
    return fail(check, "the screw passes " + mm(std::max(distance, 0.0)) + " from the infraorbital foramen; at least " +
                           mm(limits.nerve_distance_mm) + " needed");
  return check;
}

}  // namespace

bool is_labelled(const std::vector<uint8_t>& set, uint8_t label) {
  return std::find(set.begin(), set.end(), label) != set.end();
}

AnatomyLabels segmentation_anatomy_labels() { return AnatomyLabels{{2}, {4}, {3}}; }

std::string_view status_name(CheckStatus status) {
  switch (status) {
    case CheckStatus::Pass: return "pass";
    case CheckStatus::Fail: return "FAIL";
    case CheckStatus::NotChecked: return "not checked";
  }
  return "?";
}

EntryPoints find_entry_points(const LabelVolume& labels, const PlanningFrame& frame, const AnatomyLabels& anatomy,
                              const LandmarkSet& landmarks) {
  EntryPoints entries;
  const SinusBox box = sinus_box(frame, landmarks);
  for (Side side : {Side::Right, Side::Left}) {
    const auto centroid = sinus_centroid(labels, frame, anatomy, side, box);
    if (!centroid)
      throw Error(ErrorCode::kUnsafePlan, std::string(side_name(side)) + " maxillary sinus",
                  "no sinus air in the label volume to house the distraction screw");
    (side == Side::Right ? entries.right : entries.left) = exit_point(labels, anatomy, *centroid, frame.anterior);
  }
  return entries;
}

std::vector<DistractorCheck> check_distractors(const LabelVolume& labels, const DistractionVectors& vectors,
                                               const LandmarkSet& landmarks, const PlanningFrame& frame,
                                               const AnatomyLabels& anatomy, const DistractorDevice& device,
                                               const CheckLimits& limits) {
  std::vector<DistractorCheck> checks;
  for (const DistractionVector* v : {&vectors.right, &vectors.left}) {
    if (v->activation_mm <= 0) continue;  // nothing to place on this side
    const auto profile = axis_profile(labels, anatomy, *v);
    if (!profile) {
      checks.push_back(fail(make_check("screw in sinus", v->side, 0, kMaxWallMm),
                            "the screw axis meets no sinus air within " + mm(kMaxWallMm) + " of the entry point"));
      checks.push_back(
          fail(make_check("sinus depth", v->side, 0, device.screw_length_mm), "no sinus along the screw axis"));
    } else {
      checks.push_back(check_in_sinus(labels, anatomy, *v, *profile, device, limits));
      checks.push_back(check_depth(*v, *profile, device, limits));
    }
    checks.push_back(check_travel(*v, device));
    checks.push_back(check_teeth(labels, anatomy, *v, device, limits));
    checks.push_back(check_nerve(*v, landmarks, frame, device, limits));
  }
  return checks;
}

bool all_passed(const std::vector<DistractorCheck>& checks) {
  return std::none_of(checks.begin(), checks.end(),
                      [](const DistractorCheck& c) { return c.status == CheckStatus::Fail; });
}

}  // namespace maxillo::planning
