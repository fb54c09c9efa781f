#include "landmarking/ear_orbit_frame.h"

#include <cmath>

#include "core/angles.h"
#include "landmarking/head_volume.h"
#include "landmarking/landmark_template.h"
#include "landmarking/lateral_landmarks.h"

namespace maxillo::landmarking {
namespace {

constexpr double kSpacingMm = 1.0;
constexpr double kPitchReachDeg = 30, kPitchStepDeg = 5;
constexpr double kMaxCanalMismatchMm = 15;  // the two canals' heights and depths differ by less
constexpr double kMaxMisplacementMm = 5;    // an orbitale this far from where its pitch put it is another edge
// The sizes tried when the canals' distance gives none: steps of 6 mm in the porion-orbitale
// distance, so that with the pitch's step an orbitale lies within kMaxMisplacementMm of one try.
constexpr double kMinScale = 0.8, kMaxScale = 1.3, kScaleStep = 0.08;

struct Porions {
  Eigen::Vector3d left, right;
  Eigen::Vector3d middle() const { return (left + right) / 2; }
};

// Both ear canals, each sought over its side's lateral third from 40 to 150 mm behind the
// skull's front and over 130 mm below its top. A cone-beam field's cylinder, off the head's
// centre, may cut one canal: the other one mirrored across the midsagittal plane (x = 0 in the
// sagittal frame) stands in for it, for the frame only (the canal is not reported).
std::optional<Porions> find_porions_anywhere(const HeadVolume& v, const MidlineExtent& extent, std::string& why) {
  const double y_centre = extent.y_front + 95, z_centre = extent.z_top - 65;
  std::optional<Eigen::Vector3d> found[2];
  std::string missing;
  for (int side : {-1, 1}) {
    const RuleFinding f = find_porion(v, {side * 62.0, y_centre, z_centre}, side, {55, 65}, PorionAxis::kCanalCentre);
    if (f.position)
      found[side > 0] = *f.position;
    else
      missing += std::string(missing.empty() ? "" : ", and ") + "no " + (side > 0 ? "left" : "right") +
                 " ear canal: " + f.note;
  }
  if (!found[0] && !found[1]) {
    why = missing;
    return std::nullopt;
  }
  const auto mirrored = [](const Eigen::Vector3d& p) { return Eigen::Vector3d(-p.x(), p.y(), p.z()); };
  Porions p;
  p.left = found[1] ? *found[1] : mirrored(*found[0]);
  p.right = found[0] ? *found[0] : mirrored(*found[1]);
  if ((p.left - p.right).tail<2>().norm() > kMaxCanalMismatchMm) {
    why = "the two ear canals found do not face each other across the midsagittal plane";
    return std::nullopt;
  }
  return p;
}

// Frankfort's forward direction in the sagittal frame rising `pitch_deg` anteriorly.
Eigen::Vector3d forward_at(double pitch_deg) { return {0, -std::cos(pitch_deg * kDeg), std::sin(pitch_deg * kDeg)}; }

struct Orbitales {
  Eigen::Vector3d middle{0, 0, 0};  // of the rims found
  int found = 0;                    // 1 when one orbit lies at the field's edge
  double misplacement_mm = 0;       // mean distance from where the pitch put them

  // Two rims beat one; then the nearer to where they were expected.
  bool better_than(const Orbitales& other) const {
    return found != other.found ? found > other.found : misplacement_mm < other.misplacement_mm;
  }
};

// The orbitales where Frankfort rising `pitch_deg` from the porions would put them: those found
// with full evidence within kMaxMisplacementMm of that place (a pitch 2.5 degrees off, half the
// search's step, moves them 3.4 mm; farther, the rule has read another edge of the face).
std::optional<Orbitales> orbitales_at_pitch(const HeadVolume& v, const Porions& po, double scale, double pitch_deg) {
  // The template's orbitale lies level with the porion, 77 mm in front and 29 mm nearer the midline.
  const Eigen::Vector3d to_orbitale = expected_position("OrL", scale) - expected_position("PoL", scale);
  Orbitales o;
  for (int side : {-1, 1}) {
    const Eigen::Vector3d porion = side > 0 ? po.left : po.right;
    Eigen::Vector3d expected = porion + std::abs(to_orbitale.y()) * forward_at(pitch_deg);
    expected.x() = side * std::abs(expected_position("OrL", scale).x());
    const RuleFinding f = find_orbitale(v, expected, side);
    if (!f.position || f.evidence < 0.5) continue;
    const double misplacement = (*f.position - expected).tail<2>().norm();
    if (misplacement > kMaxMisplacementMm) continue;
    o.middle += *f.position;
    o.misplacement_mm += misplacement;
    ++o.found;
  }
  if (o.found == 0) return std::nullopt;
  o.middle /= o.found;
  o.misplacement_mm /= o.found;
  return o;
}

// The orbitales over every pitch within +-kPitchReachDeg, for a head of `scale`: the best found.
std::optional<Orbitales> orbitales_over_pitches(const HeadVolume& v, const Porions& po, double scale) {
  std::optional<Orbitales> best;
  for (double pitch = -kPitchReachDeg; pitch <= kPitchReachDeg + 1e-9; pitch += kPitchStepDeg) {
    const auto o = orbitales_at_pitch(v, po, scale, pitch);
    if (o && (!best || o->better_than(*best))) best = o;
  }
  return best;
}

}  // namespace

std::optional<EarOrbitFrame> frame_from_ears_and_orbits(const Volume& ct, const GreyCalibration& grey,
                                                        const Eigen::Isometry3d& sagittal, const MidlineExtent& extent,
                                                        std::string& why) {
  const FrameBox box{{-85, extent.y_front - 20, extent.z_top - 150}, {85, extent.y_front + 160, extent.z_top + 2}};
  const HeadVolume v(ct, grey, sagittal, box, kSpacingMm);
  const auto po = find_porions_anywhere(v, extent, why);
  if (!po) return std::nullopt;
  const double width = 2 * expected_position("PoL", 1).x();
  double scale = std::clamp((po->left - po->right).norm() / width, 0.8, 1.3);
  std::optional<Orbitales> best = orbitales_over_pitches(v, *po, scale);
  // The canals' distance gives no size when a canal's lateral opening lies at the field's wall
  // (read too medial) or was mirrored from the other side: the sizes the detector accepts are
  // tried in turn, each placing the rims at its distance in front of the porions; the size whose
  // rims are found nearest to where it put them wins.
  if (!best)
    for (double size = kMinScale; size <= kMaxScale + 1e-9; size += kScaleStep) {
      const auto o = orbitales_over_pitches(v, *po, size);
      if (o && (!best || o->better_than(*best))) best = o, scale = size;
    }
  if (!best) {
    why = "no inferior orbital rims in front of the ear canals";
    return std::nullopt;
  }
  // Frankfort: x the midsagittal normal, y posterior along porion-orbitale, z superior.
  Eigen::Vector3d forward = best->middle - po->middle();
  forward.x() = 0;
  forward.normalize();
  Eigen::Matrix3d axes;
  axes.col(0) = Eigen::Vector3d::UnitX();
  axes.col(1) = -forward;
  axes.col(2) = axes.col(0).cross(axes.col(1));
  // The origin where the template's sella lies over the porions' midpoint.
  const Eigen::Vector3d sella_from_porion = -expected_position("PoL", scale);
  Eigen::Vector3d origin = po->middle() + axes.col(1) * sella_from_porion.y() + axes.col(2) * sella_from_porion.z();
  origin.x() = 0;
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  local.linear() = axes;
  local.translation() = origin;
  return EarOrbitFrame{sagittal * local, scale};
}

}  // namespace maxillo::landmarking
