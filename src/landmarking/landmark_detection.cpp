#include "landmarking/landmark_detection.h"

#include <cmath>
#include <numbers>

#include "core/angles.h"
#include "core/error.h"
#include "imaging/hounsfield_reading.h"
#include "landmarking/bone_surface.h"
#include "landmarking/dental_landmarks.h"
#include "landmarking/ear_orbit_frame.h"
#include "landmarking/head_volume.h"
#include "landmarking/landmark_template.h"
#include "landmarking/lateral_landmarks.h"
#include "landmarking/mandible_landmarks.h"
#include "landmarking/midline_landmarks.h"
#include "landmarking/profile.h"
#include "landmarking/sella.h"

namespace maxillo::landmarking {
namespace {

// The second start (landmark_checks.h): every rule again with its window placed for a head 4 %
// larger, so each window starts 4 % farther from sella (a few millimetres at the face).
constexpr double kSecondStartScale = 1.04;

constexpr double kSnAboveFrankfortDeg = 7;      // adult mean: S-N rises this much anteriorly over Frankfort
constexpr double kSurfaceSpacingMm = 1.5;       // the symmetry search's grid
constexpr double kCoarseSpacingMm = 1.0;        // the frame-finding head volumes
constexpr double kNasionSpacingMm = 0.5;        // the nasion's when it sets the head's size
constexpr double kMinBoneCm3 = 40;              // less is not a skull
constexpr double kMinSnMm = 56, kMaxSnMm = 91;  // the scales the detector accepts (0.8-1.3) times 70 mm
constexpr double kFieldEdgeMarginMm = 3;        // a landmark needs the field around it this far
constexpr double kSellaBehindFrontMm = 115;     // the front's most anterior bone to sella, a large head's and more
constexpr double kSizeChangeToRefind = 0.03;  // S-N found again longer or shorter than this share: the first was wrong
constexpr const char* kSellaCutByTheField = "the scanned field's top edge cuts the sella turcica's walls";

// A frame (frame -> LPS) with the given axes (columns) and origin.
Eigen::Isometry3d frame_of(const Eigen::Vector3d& x, const Eigen::Vector3d& y, const Eigen::Vector3d& origin) {
  Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
  f.linear().col(0) = x.normalized();
  f.linear().col(1) = (y - y.dot(f.linear().col(0)) * f.linear().col(0)).normalized();
  f.linear().col(2) = f.linear().col(0).cross(f.linear().col(1));
  f.translation() = origin;
  return f;
}

// The frame turned about its x axis (the midsagittal normal) so that `direction` (frame
// coordinates, in the sagittal plane) points anterior and `rise_deg` above the horizontal.
Eigen::Isometry3d pitched(const Eigen::Isometry3d& frame, const Eigen::Vector3d& direction, double rise_deg,
                          const Eigen::Vector3d& new_origin) {
  const double current = std::atan2(direction.z(), -direction.y());
  // The new axes are the old ones turned by rise - current about x: a vector's angle above the
  // anterior horizontal then grows by that much. Points keep their LPS place.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(rise_deg * kDeg - current, Eigen::Vector3d::UnitX()).toRotationMatrix();
  Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
  f.linear() = frame.linear() * turn;
  f.translation() = frame * new_origin;
  return f;
}

// The head's box in a frame whose origin is sella (mm, for S-N = 70 mm, scaled).
FrameBox head_box(double scale) {
  return {scale * Eigen::Vector3d(-82, -128, -140), scale * Eigen::Vector3d(82, 62, 48)};
}

void require_a_head(const Volume& ct, const std::string& subject) {
  const auto& g = ct.geometry;
  const Eigen::Vector3d extent = g.spacing.cwiseProduct((g.size.array() - 1).cast<double>().matrix());
  if (g.size.minCoeff() < 16 || extent.minCoeff() < 60)
    throw Error(ErrorCode::kBadValue, subject,
                "the volume is too small to hold a head (" + std::to_string(int(extent.x())) + " x " +
                    std::to_string(int(extent.y())) + " x " + std::to_string(int(extent.z())) +
                    " mm; landmarks need the skull from the orbits to the chin)");
}

struct Frames {
  Plane midsagittal;
  double asymmetry = 0;
  Eigen::Isometry3d sagittal;  // P: x = midsagittal normal, y = the scan's posterior in the plane
};

Frames sagittal_frame(const Volume& ct, const GreyCalibration& grey, const std::string& subject) {
  const BoneSurface bone = sample_bone_surface(ct, grey.from_hu(kBoneHu + 100), kSurfaceSpacingMm);
  if (bone.bone_cm3 < kMinBoneCm3 || bone.points.size() < 200)
    throw Error(ErrorCode::kBadValue, subject,
                "no bone found (" + std::to_string(int(bone.bone_cm3)) + " cm3 above " +
                    std::to_string(int(kBoneHu + 100)) + " HU, as the grey values were read: " + grey.describe() +
                    "): not a head CT, or a scan without its skull");
  Plane initial{{1, 0, 0}, bone.bone_centre.x()};
  const SymmetryPlane symmetry = find_symmetry_plane(bone.points, *bone.distance, initial);
  Frames f;
  f.midsagittal = refine_on_grey_values(ct, grey, bone.points, symmetry.plane);
  if (f.midsagittal.normal.x() < 0) f.midsagittal = {-f.midsagittal.normal, -f.midsagittal.offset};
  f.asymmetry = symmetry.mean_distance_mm;
  const Eigen::Vector3d on_plane =
      bone.bone_centre - f.midsagittal.signed_distance(bone.bone_centre) * f.midsagittal.normal;
  f.sagittal = frame_of(f.midsagittal.normal, Eigen::Vector3d::UnitY(), on_plane);
  return f;
}

}  // namespace

bool DetectedLandmark::flagged() const {
  if (!position) return false;
  if (confidence < 0.5) return true;
  for (const auto& c : checks)
    if (!c.passed) return true;
  return false;
}

LandmarkSet LandmarkDetection::present() const {
  LandmarkSet set;
  for (const auto& l : landmarks)
    if (l.position) set.push_back({l.label, *l.position});
  return set;
}

const DetectedLandmark* LandmarkDetection::find(const std::string& label) const {
  for (const auto& l : landmarks)
    if (l.label == label) return &l;
  return nullptr;
}

namespace {

// The skull's extent in the sagittal frame P, from a midline head volume.
MidlineExtent midline_extent(const HeadVolume& midline, const std::string& subject) {
  const FrameBox& wide = midline.box();
  MidlineExtent e{1e9, -1e9, -1e9};
  double y_top = 0;
  for (double z = wide.lo.z(); z <= wide.hi.z(); z += midline.spacing())
    for (double y = wide.lo.y(); y <= wide.hi.y(); y += midline.spacing())
      if (midline.hu({0, y, z}) >= kBoneHu) {
        e.y_front = std::min(e.y_front, y);
        e.y_back = std::max(e.y_back, y);
        if (z > e.z_top) e.z_top = z, y_top = y;
      }
  if (e.y_back - e.y_front < 60) throw Error(ErrorCode::kBadValue, subject, "no skull in the midsagittal plane");
  e.vertex_scanned = midline.scanned({0, y_top, e.z_top + 6});
  return e;
}

// Sella and nasion in the sagittal frame P, where the pitch is still the scan's: sella's window
// from the bone's extent, nasion's from sella.
struct SellaNasion {
  Eigen::Vector3d s, n;  // P frame
};

std::optional<SellaNasion> find_sella_and_nasion(const Volume& ct, const GreyCalibration& grey,
                                                 const Eigen::Isometry3d& p_frame, const MidlineExtent& e,
                                                 std::string& why) {
  const double length = e.y_back - e.y_front;
  const FrameBox box{{-15, e.y_front - 35, e.z_top - 170}, {15, e.y_back + 5, e.z_top + 5}};
  const HeadVolume section(ct, grey, p_frame, box, kCoarseSpacingMm);
  // The sella lies 55-135 mm below the vertex. A field that ends at the skull's top (a cone-beam
  // scan cut above the orbits) shows no vertex: the sella, if scanned, lies within 70 mm of the
  // field's edge (a window 135 mm below the edge would reach the neck, whose recesses then pass
  // for a fossa). A head without it gets its frame from the ears and orbits. Front to back, the
  // sella lies within the middle of the skull's length, or, where a cone-beam field's cylinder
  // cuts the back of the skull off (the midline 130 mm long instead of 180), within
  // kSellaBehindFrontMm of its front: the fraction of a cut length says nothing.
  auto window_below_top = [&](double nearest, double farthest) {
    return FrameBox{{0, e.y_front + 0.2 * length, e.z_top - farthest},
                    {0, e.y_front + std::max(0.7 * length, kSellaBehindFrontMm), e.z_top - nearest}};
  };
  bool cut = false;
  const auto sella = e.vertex_scanned ? find_sella(section, window_below_top(55, 135), &cut)
                                      : find_sella(section, window_below_top(2, 70), &cut);
  if (!sella) {
    why = cut ? kSellaCutByTheField : "no sella turcica in the midsagittal plane";
    return std::nullopt;
  }
  // Nasion: S-N is about 70 mm and rises 7 degrees; the scan's pitch may add +-20 degrees.
  const RuleFinding n = find_nasion(section, sella->centre + Eigen::Vector3d(0, -68, 8.5));
  if (!n.position) {
    why = "no nasion in front of the sella: " + n.note;
    return std::nullopt;
  }
  const double length_sn = (*n.position - sella->centre).norm();
  if (length_sn < kMinSnMm || length_sn > kMaxSnMm) {
    why = "the sella and nasion found lie " + std::to_string(int(std::lround(length_sn))) + " mm apart, no adult's S-N";
    return std::nullopt;
  }
  return SellaNasion{sella->centre, *n.position};
}

// Nasion was first sought with the scan's pitch unknown (a window wide enough for +-20 degrees),
// where a head tilted far enough shows another concavity of the midline profile deeper than the
// frontonasal one, and the head's size follows from it. In the provisional frame the pitch is
// known, so both points are sought once more in their own windows; when the S-N length found
// there differs by more than kSizeChangeToRefind, the first pair was wrong and the frame and
// size are taken from the second. (A difference below it is the resampling's: the first pair
// stands, so a head whose first pass was right is read exactly as before.)
Eigen::Isometry3d with_sella_and_nasion_found_again(const Volume& ct, const GreyCalibration& grey,
                                                    const Eigen::Isometry3d& frame, double& scale) {
  const HeadVolume coarse(ct, grey, frame, head_box(scale), kCoarseSpacingMm);
  const auto s = find_sella(coarse, {{0, -14, -14}, {0, 14, 14}});
  const RuleFinding n = find_nasion(coarse, expected_position("N", scale));
  if (!s || !n.position) return frame;
  const double length = (*n.position - s->centre).norm();
  if (std::abs(length / (70.0 * scale) - 1) <= kSizeChangeToRefind) return frame;
  scale = std::clamp(length / 70.0, 0.8, 1.3);
  return pitched(frame, *n.position - s->centre, kSnAboveFrankfortDeg, s->centre);
}

// A frame from the ears and orbits has its origin where the template puts sella over the
// porions, and its size from their distance or from where the orbits lie, which a porion read at
// a cone-beam field's wall (or mirrored from the other side) misplaces by several millimetres.
// When the field holds the sella, the frame is moved onto it, so that every landmark's window is
// placed from the real one; when it holds the nasion too (in the frame, where the forehead above
// it is sought along the head's own axis, not the scan's), S-N gives the size.
Eigen::Isometry3d centred_on_sella(const Volume& ct, const GreyCalibration& grey, const Eigen::Isometry3d& frame,
                                   double& scale) {
  const HeadVolume coarse(ct, grey, frame, head_box(scale), kCoarseSpacingMm);
  const auto s = find_sella(coarse, {{0, -14, -14}, {0, 14, 14}});
  if (!s) return frame;
  Eigen::Isometry3d moved = frame;
  moved.translation() = frame * s->centre;
  // The nasion at the fine spacing, in a box around it: its rule counts samples of the profile,
  // of which a forehead cut by the field's top leaves too few at a coarse one.
  const Eigen::Vector3d expected_n = s->centre + expected_position("N", scale);
  const Eigen::Vector3d reach(15, 45, 35);
  const HeadVolume around_nasion(ct, grey, frame, {expected_n - reach, expected_n + reach}, kNasionSpacingMm);
  const RuleFinding n = find_nasion(around_nasion, expected_n);
  if (n.position) scale = std::clamp((*n.position - s->centre).norm() / 70.0, 0.8, 1.3);
  return moved;
}

// A point whose surroundings the field's edge cuts (the chin at a cone-beam field's floor, a
// porion at its cylinder's wall) cannot be told from the cut: the bone's extreme may be the
// edge's. Such a point is reported absent rather than invented.
void leave_out_points_at_the_field_edge(const HeadVolume& head, Findings& found) {
  for (auto& [label, f] : found) {
    if (!f.position) continue;
    bool inside = head.scanned(*f.position);
    for (int axis = 0; axis < 3 && inside; ++axis)
      for (double d : {-kFieldEdgeMarginMm, kFieldEdgeMarginMm})
        inside = inside && head.scanned(*f.position + d * Eigen::Vector3d::Unit(axis));
    if (!inside) f = RuleFinding::absent("at the edge of the scanned field: the anatomy around it was not scanned");
  }
}

// Sella, sought around the head frame's origin: its window does not depend on the head's size,
// so a second start would find it again to the bit (it is not run twice).
RuleFinding find_sella_in_frame(const HeadVolume& head) {
  bool cut = false;
  if (auto s = find_sella(head, {{0, -14, -14}, {0, 14, 14}}, &cut))
    return RuleFinding::found(s->centre, evidence_between(1.5 - s->fit_rms_mm, 0, 1));
  if (!head.scanned(Eigen::Vector3d::Zero())) return RuleFinding::absent("the sella lies outside the scanned field");
  return RuleFinding::absent(cut ? kSellaCutByTheField : "no sella turcica in the head frame");
}

// Every rule but sella's in the head volume at the fine spacing, its windows placed for a head of
// `scale` (S-N / 70 mm); points where the field's edge cuts their surroundings are left out.
Findings find_every_landmark(const HeadVolume& head, double scale, const RuleFinding& sella) {
  Findings found;
  found["S"] = sella;
  found["N"] = find_nasion(head, expected_position("N", scale));
  for (int side : {-1, 1}) {
    const std::string suffix = side > 0 ? "L" : "R";
    found["Po" + suffix] = find_porion(head, expected_position("Po" + suffix, scale), side);
    found["Or" + suffix] = find_orbitale(head, expected_position("Or" + suffix, scale), side, OrbitSearch::kWidening);
  }
  find_maxillary_midline(head, scale, found);
  find_incisors(head, scale, found);
  find_symphysis(head, scale, found);  // its window follows the lower incisor
  for (int side : {-1, 1}) find_ramus_landmarks(head, scale, side, found);
  for (int side : {-1, 1}) find_first_molars(head, scale, side, found);
  find_soft_tissue_profile(head, scale, found);
  leave_out_points_at_the_field_edge(head, found);
  return found;
}

// The head frame before Frankfort is measured in it: origin at sella and S-N rising 7 degrees,
// or, when the field holds no sella or no nasion, Frankfort from the ear canals and orbits.
// Sets the result's scale and frame source.
Eigen::Isometry3d provisional_frame(const Volume& ct, const GreyCalibration& grey, const Eigen::Isometry3d& sagittal,
                                    const std::string& subject, LandmarkDetection& result) {
  const HeadVolume midline(ct, grey, sagittal, {{-12, -160, -170}, {12, 160, 170}}, 2.0);
  const MidlineExtent extent = midline_extent(midline, subject);
  std::string no_sella_nasion, no_frankfort;
  if (const auto sn = find_sella_and_nasion(ct, grey, sagittal, extent, no_sella_nasion)) {
    result.scale = std::clamp((sn->n - sn->s).norm() / 70.0, 0.8, 1.3);
    const Eigen::Isometry3d frame = pitched(sagittal, sn->n - sn->s, kSnAboveFrankfortDeg, sn->s);
    result.frame_source = "S-N rising 7 degrees over Frankfort (porion or orbitale missing)";
    return with_sella_and_nasion_found_again(ct, grey, frame, result.scale);
  }
  if (const auto eo = frame_from_ears_and_orbits(ct, grey, sagittal, extent, no_frankfort)) {
    result.scale = eo->scale;
    result.frame_source = no_sella_nasion;
    return eo->frame;
  }
  throw Error(ErrorCode::kBadValue, subject,
              "no head frame: " + no_sella_nasion + ", and " + no_frankfort +
                  ": not a head CT, or a field of view without the cranial base and the ears (landmarks need one "
                  "of them to set the head's frame)");
}

}  // namespace

LandmarkDetection detect_landmarks(const Volume& scan, const std::string& subject, const DetectionOptions& options) {
  require_a_head(scan, subject);
  LandmarkDetection result;
  // A cone-beam scan's values lose more towards its axis: undone first, or the thresholds that
  // hold at the rim do not hold in the middle (imaging/hounsfield_reading.h). A CT is read as it is.
  Volume uncupped;
  result.reading = read_grey_values(scan, &uncupped);
  const GreyCalibration& grey = result.reading.grey;
  const Volume& ct = uncupped.hu.empty() ? scan : uncupped;
  const Frames frames = sagittal_frame(ct, grey, subject);
  result.midsagittal = frames.midsagittal;
  result.asymmetry_mm = frames.asymmetry;
  Eigen::Isometry3d frame = provisional_frame(ct, grey, frames.sagittal, subject, result);
  const bool origin_at_sella = result.frame_source.starts_with("S-N");
  // Frankfort from porion and orbitale, found in the provisional frame.
  {
    const HeadVolume coarse(ct, grey, frame, head_box(result.scale), kCoarseSpacingMm);
    Eigen::Vector3d po = Eigen::Vector3d::Zero(), orb = Eigen::Vector3d::Zero();
    int po_count = 0, or_count = 0;
    for (int side : {-1, 1}) {
      const std::string suffix = side > 0 ? "L" : "R";
      const RuleFinding p = find_porion(coarse, expected_position("Po" + suffix, result.scale), side, kPorionReachMm,
                                        PorionAxis::kCanalCentre);
      const RuleFinding o = find_orbitale(coarse, expected_position("Or" + suffix, result.scale), side);
      if (p.position) po += *p.position, ++po_count;
      if (o.position) orb += *o.position, ++or_count;
    }
    if (po_count && or_count) {
      const Eigen::Vector3d forward = orb / or_count - po / po_count;
      frame = pitched(frame, Eigen::Vector3d(0, forward.y(), forward.z()), 0, Eigen::Vector3d::Zero());
      const bool sella_nasion_frame = result.frame_source.starts_with("S-N");
      result.frame_source = sella_nasion_frame ? "Frankfort horizontal (porion and orbitale)"
                                               : "Frankfort horizontal (porion and orbitale, found without sella "
                                                 "and nasion: " +
                                                     result.frame_source + ")";
    }
  }
  if (!origin_at_sella) frame = centred_on_sella(ct, grey, frame, result.scale);
  result.head_frame = frame;
  // Every landmark, read in the head volume at the fine spacing, and again from a second start.
  const HeadVolume head(ct, grey, frame, head_box(result.scale), options.fine_spacing_mm);
  const RuleFinding sella = find_sella_in_frame(head);
  Findings found = find_every_landmark(head, result.scale, sella);
  const Findings again = find_every_landmark(head, result.scale * kSecondStartScale, sella);
  FramePoints points;
  for (const auto& [label, f] : found)
    if (f.position) points[label] = *f.position;
  auto checks = check_landmarks(points, result.scale);
  for (const auto& [label, point] : points) {
    if (label == "S") continue;  // the same window from both starts
    const auto second = again.find(label);
    checks[label].push_back(second_start_check(point, second == again.end() ? std::nullopt : second->second.position));
  }
  for (const auto& label : detected_labels()) {
    DetectedLandmark l;
    l.label = label;
    const auto it = found.find(label);
    if (it == found.end()) {
      l.note = "not detected by this version of the method";
    } else {
      l.note = it->second.note;
      if (it->second.position) l.position = head.to_lps(*it->second.position);
      l.confidence = it->second.evidence;
    }
    if (auto c = checks.find(label); c != checks.end()) l.checks = c->second;
    for (const auto& c : l.checks)
      if (!c.passed) l.confidence = std::min(l.confidence, 0.3);
    result.landmarks.push_back(std::move(l));
  }
  return result;
}

}  // namespace maxillo::landmarking
