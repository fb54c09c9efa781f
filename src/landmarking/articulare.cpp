#include "landmarking/articulare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "landmarking/landmark_template.h"

namespace maxillo::landmarking {
namespace {

// The underside of the cranial base at the midline, at depth y: read downwards from the height
// of the sella, through the brain, into the base (the clivus behind the sphenoid) and out of it.
// nullopt where no bone lies below within reach (a field that ends above the base).
constexpr double kBaseReachMm = 70;
std::optional<double> cranial_base_underside(const HeadVolume& v, double y, double scale) {
  const Eigen::Vector3d down(0, 0, -1);
  const Eigen::Vector3d start(0, y, expected_position("S", scale).z());
  const auto top =
      v.hu(start) >= kBoneHu ? std::optional(start) : first_crossing(v, start, down, kBaseReachMm, kBoneHu);
  if (!top) return std::nullopt;
  const auto below = first_drop(v, *top, down, kBaseReachMm, kBoneHu);
  if (!below) return std::nullopt;
  // The threshold's crossing lies in the blur below the bone: the half-maximum edge, read upwards.
  constexpr double kBlurMm = 3;
  const auto edge = first_edge(v, *below + kBlurMm * down, -down, 2 * kBlurMm, kBoneHu);
  return (edge ? *edge : *below).z();
}

// The border's points within `length_mm` below its top, extended upwards by `extension_mm` at
// `step_mm`: y along a straight line (least squares against z), x at their mean (the ramus's
// middle is too noisy from one height to the next to extrapolate a slope).
Profile extended_upwards(const Profile& border, double length_mm, double extension_mm, double step_mm) {
  const double top = border.back().z;
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Vector2d sum_y = Eigen::Vector2d::Zero();
  double sum_x = 0;
  for (const auto& p : border) {
    if (p.z < top - length_mm) continue;
    const double dz = p.z - top;
    normal += Eigen::Vector2d(1, dz) * Eigen::RowVector2d(1, dz);
    sum_y += p.y * Eigen::Vector2d(1, dz);
    sum_x += p.x;
  }
  if (std::abs(normal.determinant()) < 1e-9) return {};
  const Eigen::Vector2d fit_y = normal.inverse() * sum_y;
  const double mean_x = sum_x / normal(0, 0);
  Profile extension;
  for (double dz = step_mm; dz <= extension_mm + 1e-9; dz += step_mm)
    extension.push_back({top + dz, fit_y(0) + fit_y(1) * dz, mean_x});
  return extension;
}

// Where the border (ascending heights) rises to the underside of the cranial base at the same
// depth, interpolated between the last border point below the base and the first at or above it.
// The border is followed while it stays on one bone: consecutive heights (0.5 mm apart) no more
// than kBorderStepMm apart in depth and kBorderSideStepMm across (the ramus's middle is noisier).
// Where the condyle comes so close to the bone behind it (the temporal bone at the joint) that
// the traced border ends short of the base, its last kFitMm go on in a straight line for up to
// kExtensionMm. nullopt if the border never gets there.
constexpr double kFitMm = 3, kExtensionMm = 4, kBorderStepMm = 1, kBorderSideStepMm = 4;
constexpr double kExtendedBorderEvidence = 0.8;
struct BaseCrossing {
  ProfilePoint point;
  double beyond_border_mm = 0;  // how far above the traced border's top (0: on it)
};
std::optional<BaseCrossing> border_meets_cranial_base(const HeadVolume& v, Profile border, double scale) {
  for (size_t i = 1; i < border.size(); ++i)
    if (std::abs(border[i].y - border[i - 1].y) > kBorderStepMm ||
        std::abs(border[i].x - border[i - 1].x) > kBorderSideStepMm) {
      border.resize(i);
      break;
    }
  if (border.empty()) return std::nullopt;
  const double top = border.back().z;
  const Profile extension = extended_upwards(border, kFitMm, kExtensionMm, 0.25);
  border.insert(border.end(), extension.begin(), extension.end());
  std::optional<std::pair<ProfilePoint, double>> below;  // a border point and how far below the base
  for (const auto& p : border) {
    const auto base = cranial_base_underside(v, p.y, scale);
    if (!base) continue;
    const double under = *base - p.z;
    if (under > 0) {
      below = std::pair{p, under};
      continue;
    }
    ProfilePoint crossing = p;
    if (below) {
      const double f = below->second / (below->second - under);
      const ProfilePoint& q = below->first;
      crossing = {q.z + f * (p.z - q.z), q.y + f * (p.y - q.y), q.x + f * (p.x - q.x)};
    }
    return BaseCrossing{crossing, std::max(0.0, crossing.z - top)};
  }
  return std::nullopt;
}

// Articulare from the crossing, with its evidence. The crossing's height is only as sure as the
// base is level there: where the underside slopes (a clivus at 60 degrees: the real cadaver head),
// a small error in depth moves the crossing by the slope times as much in height, and the same
// head in another pose gave a point 2 mm away. Full evidence up to a slope of kLevelSlope (1 mm
// per mm), none at kSteepSlope; met on the border extended beyond its traced top, at most
// kExtendedBorderEvidence.
constexpr double kLevelSlope = 1, kSteepSlope = 2.5, kSlopeSpanMm = 1;
RuleFinding articulare_finding(const HeadVolume& v, const BaseCrossing& crossing, double scale) {
  const ProfilePoint& at = crossing.point;
  const auto behind = cranial_base_underside(v, at.y + kSlopeSpanMm, scale);
  const auto in_front = cranial_base_underside(v, at.y - kSlopeSpanMm, scale);
  const double slope = behind && in_front ? std::abs(*behind - *in_front) / (2 * kSlopeSpanMm) : kSteepSlope;
  double evidence = evidence_between(slope, kSteepSlope, kLevelSlope);
  std::string note;
  char text[120];
  if (slope > kLevelSlope) {
    std::snprintf(text, sizeof text, "the cranial base slopes %.1f mm per mm where the border meets it", slope);
    note = text;
  }
  if (crossing.beyond_border_mm > 0) {
    evidence = std::min(evidence, kExtendedBorderEvidence);
    std::snprintf(text, sizeof text, "the border extended %.1f mm above its traced top", crossing.beyond_border_mm);
    note += (note.empty() ? "" : "; ") + std::string(text);
  }
  return RuleFinding::found({at.x, at.y, at.z}, evidence, note);
}

}  // namespace

RuleFinding find_articulare(const HeadVolume& v, const Profile& border, double scale) {
  const auto crossing = border_meets_cranial_base(v, border, scale);
  return crossing ? articulare_finding(v, *crossing, scale)
                  : RuleFinding::absent("the posterior border does not reach the cranial base's underside");
}

}  // namespace maxillo::landmarking
