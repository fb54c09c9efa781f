#include "landmarking/midline_landmarks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "landmarking/landmark_template.h"
#include "landmarking/profile.h"

namespace maxillo::landmarking {
namespace {

constexpr double kMidlineSlabMm = 1.5;         // bone profiles: the most anterior bone within this of x = 0
constexpr double kForeheadAboveNasionMm = 10;  // scanned this far above a nasion, or it is absent
// Crowns against lips and air: low enough to keep a thin incisal edge that the partial volume
// has faded (the edge itself is placed at the half maximum, first_edge).
constexpr double kToothSurfaceHu = 500;
// The anterior nasal spine thins to a tip of a millimetre or two, faded by the partial volume.
constexpr double kSpineHu = 150;

Eigen::Vector3d midline_point(const ProfilePoint& p) { return {0, p.y, p.z}; }

// Whether profile[i] is at least as extreme in y (sign -1: minimum = most anterior, +1: maximum =
// most posterior) as every sample within `reach_mm` above and below, and not within `reach_mm`
// of the profile's ends.
bool is_local_extremum(const Profile& profile, int i, int sign, double reach_mm) {
  const double z = profile[size_t(i)].z;
  if (std::abs(z - profile.front().z) < reach_mm || std::abs(z - profile.back().z) < reach_mm) return false;
  for (const auto& other : profile)
    if (std::abs(other.z - z) <= reach_mm && sign * (other.y - profile[size_t(i)].y) > 0) return false;
  return true;
}

// Index of the lowest local extremum (the first met reading the profile from its bottom); -1 if none.
int lowest_local_extremum(const Profile& profile, int sign, double reach_mm) {
  for (int i = int(profile.size()) - 1; i >= 0; --i)
    if (is_local_extremum(profile, i, sign, reach_mm)) return i;
  return -1;
}

// Index of the most extreme of the local extrema; -1 if none.
int strongest_local_extremum(const Profile& profile, int sign, double reach_mm) {
  int best = -1;
  for (int i = 0; i < int(profile.size()); ++i)
    if (is_local_extremum(profile, i, sign, reach_mm) &&
        (best < 0 || sign * (profile[size_t(i)].y - profile[size_t(best)].y) > 0))
      best = i;
  return best;
}

// The profile's extreme sample in y (sign -1 most anterior, +1 most posterior), refined.
std::optional<ProfilePoint> extreme(const Profile& profile, int sign) {
  if (profile.size() < 3) return std::nullopt;
  const int i = sign < 0 ? most_anterior(profile) : most_posterior(profile);
  return refined_extremum(profile, i, 4);  // the extremes of a face are flat: a wide fit
}

// Whether the tissue behind a profile point is a crown (enamel/dentine) rather than bone.
// Enamel is above 2200 HU; the densest cortical bone of a mandible stays below it.
bool is_tooth(const HeadVolume& v, const ProfilePoint& p) { return v.hu({p.x, p.y + 0.75, p.z}) >= 2200; }

// The first forward extremum reading the profile downwards (the upper lip's before the lower
// lip's, whichever of the two stands further forward), refined; the most anterior point when the
// profile holds no extremum 2 mm from its ends.
std::optional<ProfilePoint> first_forward_extremum(const Profile& profile) {
  if (profile.size() < 3) return std::nullopt;
  for (int i = 0; i < int(profile.size()); ++i)
    if (is_local_extremum(profile, i, -1, 2)) return refined_extremum(profile, i, 4);  // lips are flat: a wide fit
  return extreme(profile, -1);
}

// The profile point farthest behind the profile's anterior hull (for a concave stretch, the
// line joining its ends), refined; nullopt for fewer than three points.
std::optional<ProfilePoint> deepest_behind_line(const Profile& profile) {
  if (profile.size() < 3) return std::nullopt;
  const auto depth = depth_behind_hull(profile);
  const int deepest = int(std::max_element(depth.begin(), depth.end()) - depth.begin());
  return refined_peak(profile, depth, deepest);
}

}  // namespace

RuleFinding find_nasion(const HeadVolume& v, const Eigen::Vector3d& expected) {
  const Profile forehead_to_nose =
      until_jump(anterior_profile(v, expected.z() + 22, expected.z() - 20, expected.y() - 30, expected.y() + 30,
                                  kBoneHu, 0, kMidlineSlabMm),
                 6);
  if (forehead_to_nose.size() < 20) return RuleFinding::absent("no frontal and nasal bone in front of the skull base");
  const auto depth = depth_behind_hull(forehead_to_nose);
  int deepest = 0;
  for (size_t i = 0; i < depth.size(); ++i)
    if (depth[i] > depth[size_t(deepest)]) deepest = int(i);
  const ProfilePoint n = refined_peak(forehead_to_nose, depth, deepest);
  // The concavity is the frontonasal one only if the forehead above it was scanned: a field cut
  // just above the nose makes its own "deepest point" at the edge.
  if (!v.scanned(midline_point(n) + Eigen::Vector3d(0, 0, kForeheadAboveNasionMm)))
    return RuleFinding::absent("the forehead above the nasion lies outside the scanned field");
  return RuleFinding::found(midline_point(n), evidence_between(depth[size_t(deepest)], 0.3, 2.5),
                            depth[size_t(deepest)] < 1 ? "a shallow frontonasal concavity" : "");
}

constexpr double kSpineBumpReachMm = 1.5;
constexpr double kSpineBumpAheadMm = 0.2;
constexpr double kSpineAsABumpVoxelMm = 1.0;

// The sample `dz` mm above (dz > 0) or below profile[i], the nearest in height within 0.2 mm, or
// nullopt.
std::optional<ProfilePoint> sample_at(const Profile& profile, int i, double dz) {
  const double z = profile[size_t(i)].z + dz;
  std::optional<ProfilePoint> best;
  for (const auto& p : profile)
    if (std::abs(p.z - z) < 0.2 && (!best || std::abs(p.z - z) < std::abs(best->z - z))) best = p;
  return best;
}

// A bump on a slope: the most anterior sample within 0.5 mm, standing at least
// kSpineBumpAheadMm ahead of the chord joining the samples kSpineBumpReachMm above and below.
bool is_bump_on_slope(const Profile& profile, int i) {
  if (!is_local_extremum(profile, i, -1, 0.5)) return false;
  const auto above = sample_at(profile, i, kSpineBumpReachMm), below = sample_at(profile, i, -kSpineBumpReachMm);
  if (!above || !below) return false;
  return (above->y + below->y) / 2 - profile[size_t(i)].y >= kSpineBumpAheadMm;
}

void find_maxillary_midline(const HeadVolume& v, double scale, Findings& found) {
  const Eigen::Vector3d ans = expected_position("ANS", scale), a = expected_position("A", scale);
  const Eigen::Vector3d u1 = expected_position("U1", scale);
  const Profile upper =
      anterior_profile(v, ans.z() + 12, u1.z() + 2, ans.y() - 30, ans.y() + 40, kSpineHu, 0, kMidlineSlabMm);
  // ANS: the spine's tip, a forward extremum above A (the alveolus below A comes forward again
  // and must not be taken for it). The spine is thin and the partial volume shortens it, so of
  // the forward extrema within 2 mm of the most anterior one the lowest is taken: the spine
  // projects from the nasal floor, below the rim of the aperture. At voxels of 1.2 mm and more
  // the spine is a bump of a few tenths of a millimetre on the bone's front below that rim, which
  // stands further forward: a bump counts when it leads the profile 1.5 mm above and below, or,
  // where the front slopes back from the rim, when it stands ahead of the slope (BENCH-002 at
  // 1.2 mm: a bump 0.3 mm ahead of the slope 4 mm below the rim, which had been taken: 3.3 mm off).
  const Profile spine_zone = between_heights(upper, a.z() - 4, ans.z() + 12);
  const int strongest = strongest_local_extremum(spine_zone, -1, 3);
  // Finer voxels resolve the spine's own tip; there, a bump on the slope is the bone's texture
  // (BENCH-024 at 0.6 mm: its ANS was taken from such a bump and flagged).
  const bool coarse_voxels = v.scan_voxel_mm() >= kSpineAsABumpVoxelMm;
  int tip = strongest;
  for (int i = 0; strongest >= 0 && i < int(spine_zone.size()); ++i)
    if ((is_local_extremum(spine_zone, i, -1, kSpineBumpReachMm) ||
         (coarse_voxels && is_bump_on_slope(spine_zone, i))) &&
        spine_zone[size_t(i)].y < spine_zone[size_t(strongest)].y + 2 &&
        spine_zone[size_t(i)].z < spine_zone[size_t(tip)].z)
      tip = i;
  if (tip < 0) {
    found["ANS"] = RuleFinding::absent("no anterior nasal spine: the nasal floor has no forward tip");
    found["A"] = RuleFinding::absent("needs ANS");
    found["PNS"] = RuleFinding::absent("needs ANS");
    return;
  }
  const ProfilePoint ans_point = refined_extremum(spine_zone, tip, 1.5);
  found["ANS"] = RuleFinding::found(midline_point(ans_point), 1);
  // A: the most posterior bone point between ANS and prosthion (where the crowns begin).
  Profile alveolus;
  for (const auto& p : between_heights(upper, u1.z() - 2, ans_point.z - 1.5)) {
    if (is_tooth(v, p)) break;
    alveolus.push_back(p);
  }
  if (const auto deepest = extreme(alveolus, +1)) {
    const double depth = deepest->y - std::min(ans_point.y, alveolus.back().y);
    found["A"] = RuleFinding::found(midline_point(*deepest), evidence_between(depth, 0.3, 2));
  } else {
    found["A"] = RuleFinding::absent("no alveolar bone below ANS");
  }
  // PNS: the posterior end of the bone plate that runs back from ANS (the hard palate), traced
  // as the bone connected to the spine within a band around its height.
  const double step = 0.25;
  const double y0 = ans_point.y, z_top = ans_point.z + 3, z_bottom = ans_point.z - 8;
  const int columns = int(95 * scale / step), rows = int((z_top - z_bottom) / step) + 1;
  std::vector<uint8_t> bone(size_t(columns * rows), 0), reached(size_t(columns * rows), 0);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c)
      bone[size_t(r * columns + c)] = v.hu({0, y0 + c * step, z_top - r * step}) >= kBoneHu;
  std::vector<int> queue;
  for (int r = 0; r < rows; ++r) {
    const int start = r * columns + int(2 / step);  // 2 mm behind the tip, inside the spine's base
    if (bone[size_t(start)]) {
      reached[size_t(start)] = 1;
      queue.push_back(start);
    }
  }
  int back = -1;
  for (size_t next = 0; next < queue.size(); ++next) {
    const int c = queue[next] % columns, r = queue[next] / columns;
    if (back < 0 || c > back % columns) back = queue[next];
    const int around[4][2] = {{c - 1, r}, {c + 1, r}, {c, r - 1}, {c, r + 1}};
    for (const auto& n : around) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= columns || n[1] >= rows) continue;
      const int index = n[1] * columns + n[0];
      if (bone[size_t(index)] && !reached[size_t(index)]) {
        reached[size_t(index)] = 1;
        queue.push_back(index);
      }
    }
  }
  if (back < 0) {
    found["PNS"] = RuleFinding::absent("no hard palate behind ANS");
    return;
  }
  // The palate's end: the mean height of its last column, then the exact end along that row.
  const int last = back % columns;
  double z_sum = 0;
  int z_count = 0;
  for (int r = 0; r < rows; ++r)
    if (reached[size_t(r * columns + last)]) {
      z_sum += z_top - r * step;
      ++z_count;
    }
  const double z = z_sum / z_count;
  const auto end = first_drop(v, {0, y0 + (last - 2) * step, z}, {0, 1, 0}, 4, kBoneHu, 0.1);
  const double y = end ? end->y() : y0 + last * step;
  const double length = y - ans_point.y;
  found["PNS"] = RuleFinding::found({0, y, z}, evidence_between(length, 30 * scale, 42 * scale),
                                    length < 42 * scale ? "a short hard palate" : "");
}

namespace {

// The chin's own middle (x in the head frame): a chin deviated to one side (an asymmetric
// mandible) has its midsagittal points off the skull's midline. At Pog's height and 3 mm above
// and below, a ray from either side 3 mm behind the chin's front meets the symphysis' outer
// cortex; the middle of each pair, the median of the three. 0 (the skull's midline) when a ray
// misses or the middle lies within kChinMiddleToleranceMm of it.
constexpr double kChinRaysBehindFrontMm = 3, kChinRayReachMm = 40, kChinMiddleToleranceMm = 0.25;
double symphysis_middle_x(const HeadVolume& v, const ProfilePoint& pog) {
  std::vector<double> middles;
  for (double dz : {-3.0, 0.0, 3.0}) {
    const double y = pog.y + kChinRaysBehindFrontMm, z = pog.z + dz;
    const auto right = first_edge(v, {-kChinRayReachMm, y, z}, {1, 0, 0}, kChinRayReachMm, kBoneHu);
    const auto left = first_edge(v, {kChinRayReachMm, y, z}, {-1, 0, 0}, kChinRayReachMm, kBoneHu);
    if (!right || !left || left->x() <= right->x()) return 0;
    middles.push_back((right->x() + left->x()) / 2);
  }
  std::sort(middles.begin(), middles.end());
  return std::abs(middles[1]) < kChinMiddleToleranceMm ? 0 : middles[1];
}

// Whether the field's floor cuts the symphysis below a chin point `pog`: a sample inside the
// symphysis, kSymphysisBehindFrontMm behind its front, unscanned between Pog and the expected
// menton's height (less kBelowMentonMm). A cone-beam field cut through the chin leaves the
// alveolar bulge over the incisors' roots as the lowest forward extremum, which reads as a
// chin; without its lower border it cannot be told from one, so it is not reported.
constexpr double kSymphysisBehindFrontMm = 5, kBelowMentonMm = 5;
bool chin_cut_by_the_field(const HeadVolume& v, const Eigen::Vector3d& pog, double expected_menton_z) {
  for (double z = pog.z(); z >= expected_menton_z - kBelowMentonMm; z -= v.spacing())
    if (!v.scanned({pog.x(), pog.y() + kSymphysisBehindFrontMm, z})) return true;
  return false;
}

constexpr double kAlveolarGapMm = 1;

// The alveolar front read upwards (`upwards`), cut at infradentale: its most anterior point above
// `chin_z` halfway to its top. Above it the alveolar crest curls back towards the crowns (which
// is_tooth leaves out), and its top would pass for the deepest point of the concavity.
Profile up_to_infradentale(const Profile& upwards, double chin_z) {
  if (upwards.empty()) return upwards;
  // The front ends first where samples go missing over more than a millimetre: the crowns.
  size_t end = 1;
  while (end < upwards.size() && upwards[end].z - upwards[end - 1].z <= kAlveolarGapMm) ++end;
  const double halfway = (chin_z + upwards[end - 1].z) / 2;
  size_t id = end - 1;
  for (size_t i = 0; i < end; ++i)
    if (upwards[i].z >= halfway && upwards[i].y < upwards[id].y) id = i;
  return Profile(upwards.begin(), upwards.begin() + std::ptrdiff_t(id + 1));
}

// A chin too flat to have its extremes in the head frame: the forward bulge and the concavity
// above it differ by less than this (a frame pitched a few degrees moves them that much).
constexpr double kFlatChinMm = 1;

}  // namespace

std::optional<ChinReading> chin_from_nasion(const Profile& alveolar_front, const Eigen::Vector3d& nasion,
                                            double lowest_chin_z) {
  if (alveolar_front.size() < 8) return std::nullopt;
  const ProfilePoint id = alveolar_front.back();
  const Profile chin = between_heights(alveolar_front, lowest_chin_z, (id.z + lowest_chin_z) / 2);
  if (chin.size() < 5) return std::nullopt;
  std::vector<double> forwardness(chin.size());  // the slope of the line from nasion, forward positive
  for (size_t i = 0; i < chin.size(); ++i) forwardness[i] = (nasion.y() - chin[i].y) / (nasion.z() - chin[i].z);
  const int touch = int(std::max_element(forwardness.begin(), forwardness.end()) - forwardness.begin());
  const ProfilePoint pog = refined_peak(chin, forwardness, touch, 5);
  const Profile concavity = between_heights(alveolar_front, pog.z + 1, id.z - 1);
  if (concavity.size() < 5) return std::nullopt;
  const Eigen::Vector2d along = Eigen::Vector2d(id.y - pog.y, id.z - pog.z).normalized();
  std::vector<double> depth(concavity.size());  // behind the chord, posterior positive
  for (size_t i = 0; i < concavity.size(); ++i)
    depth[i] = along.y() * (concavity[i].y - pog.y) - along.x() * (concavity[i].z - pog.z);
  const int deepest = int(std::max_element(depth.begin(), depth.end()) - depth.begin());
  return ChinReading{pog, refined_peak(concavity, depth, deepest, 4), depth[size_t(deepest)]};
}

void find_symphysis(const HeadVolume& v, double scale, Findings& found) {
  // The template's window, carried with the lower incisor when it was found: faces differ in
  // height far more than a lower incisor differs from its symphysis.
  const auto l1_found = found.find("L1");
  const Eigen::Vector3d l1_template = expected_position("L1", scale);
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  if (l1_found != found.end() && l1_found->second.position)
    shift = Eigen::Vector3d(0, 1, 1).cwiseProduct(*l1_found->second.position - l1_template);
  const Eigen::Vector3d b = expected_position("B", scale) + shift, me = expected_position("Me", scale) + shift;
  const Eigen::Vector3d l1 = l1_template + shift;
  // The symphysis' front below the crowns of the lower incisors, read in a slab about x = middle.
  auto bone_front_at = [&](double middle) {
    Profile bone_front;
    for (const auto& p :
         anterior_profile(v, l1.z() - 2, me.z() - 8, b.y() - 30, b.y() + 45, kBoneHu, middle, kMidlineSlabMm))
      if (!is_tooth(v, p)) bone_front.push_back(p);
    return bone_front;
  };
  // Pog: the lowest forward extremum (the chin); B: the deepest point above it, below the crowns.
  // Read first in the skull's midline, then again in the chin's own (a chin to one side).
  Profile bone_front = bone_front_at(0);
  int pog = lowest_local_extremum(bone_front, -1, 4);
  const double middle = pog < 0 ? 0 : symphysis_middle_x(v, refined_extremum(bone_front, pog, 5));
  if (middle != 0) {
    bone_front = bone_front_at(middle);
    pog = lowest_local_extremum(bone_front, -1, 4);
    find_lower_incisor(v, scale, middle, found);  // the lower arch goes with its chin
  }
  if (pog < 0) {
    for (const char* label : {"Pog", "B", "Me", "Gn"})
      found[label] = RuleFinding::absent("no bony chin in the midline");
    return;
  }
  auto chin_point = [middle](const ProfilePoint& p) { return Eigen::Vector3d(middle, p.y, p.z); };
  ProfilePoint pog_point = refined_extremum(bone_front, pog, 5);
  // Read upwards from below Pog, the alveolar front continues to the crowns; where it jumps
  // (into the mouth between the teeth, onto a crown) the symphysis has ended, and infradentale,
  // where it stands furthest forward near its top, ends the search for B.
  const double lowest_chin_z = pog_point.z - 10;
  Profile upwards = between_heights(bone_front, lowest_chin_z, bone_front.front().z);
  std::reverse(upwards.begin(), upwards.end());
  const Profile alveolar_front = up_to_infradentale(until_jump(upwards, 3), pog_point.z);
  const Profile above = between_heights(alveolar_front, pog_point.z + 1, bone_front.front().z);
  const auto deepest = extreme(above, +1);
  const auto nasion = found.find("N");
  bool flat_chin = false;
  if (deepest && deepest->y - pog_point.y < kFlatChinMm && nasion != found.end() && nasion->second.position) {
    if (const auto flat = chin_from_nasion(alveolar_front, *nasion->second.position, lowest_chin_z)) {
      found["Pog"] = RuleFinding::found(chin_point(flat->pog), 1, "a flat chin: read on the line from nasion");
      found["B"] = RuleFinding::found(chin_point(flat->b), evidence_between(flat->b_depth, 0.5, 3),
                                      "a flat chin: the deepest point behind the line from infradentale to Pog");
      pog_point = flat->pog;
      flat_chin = true;
    }
  }
  if (!flat_chin) {
    found["Pog"] = RuleFinding::found(chin_point(pog_point), 1);
    if (deepest)
      found["B"] = RuleFinding::found(chin_point(*deepest), evidence_between(deepest->y - pog_point.y, 0.5, 3));
    else
      found["B"] = RuleFinding::absent("no alveolar bone above the chin");
  }
  // Me: the lowest point of the symphysis, from rays up through the chin's underside.
  Profile underside;  // (z, y) swapped roles: here "y" holds the height of the hit, "z" the column
  for (double y = pog_point.y - 4; y <= pog_point.y + 25 * scale; y += 0.25)
    if (auto hit = first_edge(v, {middle, y, me.z() - 25}, {0, 0, 1}, 35, kBoneHu))
      underside.push_back({y, hit->z(), middle});
  if (underside.size() < 5) {
    if (chin_cut_by_the_field(v, {middle, pog_point.y, pog_point.z}, me.z())) {
      for (const char* label : {"Pog", "B", "Me", "Gn"})
        found[label] = RuleFinding::absent("the chin's lower border lies outside the scanned field");
      return;
    }
    found["Me"] = found["Gn"] = RuleFinding::absent("no lower border of the symphysis");
    return;
  }
  const ProfilePoint lowest = refined_extremum(underside, most_anterior(underside), 5);
  found["Me"] = RuleFinding::found({middle, lowest.z, lowest.y}, 1);
  // Gn: the chin's support point along the antero-inferior bisector.
  const Eigen::Vector3d d = Eigen::Vector3d(0, 1, 1).normalized(), across(0, 1, -1);
  const Eigen::Vector3d centre(middle, pog_point.y + 8, lowest.y + 12);
  Profile support;  // z holds the offset across, y the distance along d
  for (double s = -14; s <= 14; s += 0.25)
    if (auto hit = first_edge(v, centre - 40 * d + s * across.normalized(), d, 45, kBoneHu))
      support.push_back({s, d.dot(*hit - centre), 0});
  if (support.size() < 5) {
    found["Gn"] = RuleFinding::absent("no chin outline between Pog and Me");
    return;
  }
  const ProfilePoint gn = refined_extremum(support, most_anterior(support), 4);
  found["Gn"] = RuleFinding::found(centre + gn.y * d + gn.z * across.normalized(), 1);
}

namespace {

// The middle of the right central incisor's width (x) 1 mm inside its edge: between its distal
// end and its mesial one, which is its contact with the left central incisor at the arch's
// midline (`midline_x`: 0 in the head frame, the chin's middle for a lower arch to one side)
// unless a gap shows within 1.5 mm of it. Neighbouring incisors touch, often with no gap a scan
// resolves (the lower ones nearly always), and near the thin edge a ray may leave the crown
// early: a distal end that makes the crown narrower than 0.8 or wider than 1.2 times its mean
// `width` is not the crown's, and the middle is then half the mean width from the mesial end.
double crown_middle_x(const HeadVolume& v, const Eigen::Vector3d& edge, double rootward, double width,
                      double midline_x = 0) {
  const Eigen::Vector3d inside(midline_x - 2.5, edge.y(), edge.z() + rootward);
  const auto distal = first_drop(v, inside, {-1, 0, 0}, 9, kToothSurfaceHu, 0.1);
  const auto mesial = first_drop(v, inside, {1, 0, 0}, 4, kToothSurfaceHu, 0.1);
  const double mesial_x = mesial && std::abs(mesial->x() - midline_x) < 1.5 ? mesial->x() : midline_x;
  if (distal && std::abs(mesial_x - distal->x() - width) <= 0.2 * width) return (distal->x() + mesial_x) / 2;
  return mesial_x - width / 2;
}

// The upper incisor's incisal edge centre from the lowest point of its labial face: centred in
// the edge's thickness (front to back), at the edge's lowest point there, centred in its width.
Eigen::Vector3d upper_incisal_edge_centre(const HeadVolume& v, const ProfilePoint& tip) {
  const auto lingual = first_drop(v, {tip.x, tip.y + 0.1, tip.z + 0.6}, {0, 1, 0}, 4, kToothSurfaceHu, 0.1);
  const double y = lingual ? (tip.y + lingual->y()) / 2 : tip.y + 0.6;
  const auto edge = first_edge(v, {tip.x, y, tip.z - 3}, {0, 0, 1}, 5, kToothSurfaceHu);
  const double z = edge ? edge->z() : tip.z;
  return {crown_middle_x(v, {tip.x, y, z}, +1, kUpperCentralWidthMm), y, z};
}

// The upper incisor's labial face read downwards until the profile jumps back to the lower
// incisor (or ends): the last point before the jump. A jump back by more than 1.2 mm, or, where
// the point seen first moves sideways by more than kOtherToothSideMm at once (another tooth: the
// lower incisors, or the lateral incisor at the slab's side), by more than kOtherToothStepMm: with
// a small overjet the lower incisor's labial face stands barely a millimetre behind the edge (a
// varied phantom's, 1.19 mm, was missed).
constexpr double kOtherToothStepMm = 0.5, kOtherToothSideMm = 2.0;
constexpr size_t kShortestFaceRows = 8;  // 2 mm of labial face at least, or no crown was read
std::optional<ProfilePoint> upper_incisor_tip(const Profile& profile) {
  for (size_t i = 1; i < profile.size(); ++i) {
    const bool gap = std::abs(profile[i].z - profile[i - 1].z) > 0.6;
    const double back = profile[i].y - profile[i - 1].y;
    if (gap || back > 1.2 ||
        (back > kOtherToothStepMm && std::abs(profile[i].x - profile[i - 1].x) > kOtherToothSideMm))
      return i >= kShortestFaceRows ? std::optional<ProfilePoint>(profile[i - 1]) : std::nullopt;
  }
  return std::nullopt;
}

// The upper incisor's tip where the slab's profile shows none: the slab is 5 mm wide, and in a
// Class III bite a lower lateral incisor standing forward at the slab's side takes the profile
// over below the upper central's edge without a jump back (the phantom's Class III patients, whose
// lower centrals alone are tipped back, lost U1 on 6 of 30 bench scans). Each column of the slab
// is then read on its own, up to a jump forward (a tooth standing in front of the face: in that
// column the edge is hidden from the front), and the tip is the lowest of the columns' tips. In
// the upper central's own columns the lower central, tipped back against the upper's lingual face,
// continues the profile 2 mm behind it, and the blur joins the two faces with a slope instead of a
// jump: a step back is also the face receding by more than kStepBackMm within kStepRows rows and
// staying back (a face of kStepRows rows behind), and the tip is the last point before it.
constexpr double kForwardJumpMm = 1.2, kStepBackMm = 1.2, kFaceBehindMm = 0.5;
constexpr size_t kStepRows = 4;         // 1 mm
constexpr double kProfileRowMm = 0.25;  // anterior_profile's and column_profiles' default rows
Profile until_jump_forward(const Profile& face) {
  Profile kept;
  for (const auto& point : face) {
    if (!kept.empty() && kept.back().y - point.y > kForwardJumpMm) break;
    kept.push_back(point);
  }
  return kept;
}
bool stays_back(const Profile& column, size_t from, double y) {
  for (size_t i = from; i < from + kStepRows; ++i)
    if (i >= column.size() || column[i].y - y < kStepBackMm - kFaceBehindMm) return false;
  return true;
}
std::optional<ProfilePoint> tip_before_a_step_back(const Profile& column) {
  for (size_t i = kShortestFaceRows; i + 1 < column.size(); ++i)
    for (size_t k = 1; k <= kStepRows && i + k < column.size(); ++k) {
      if (column[i].z - column[i + k].z > (double(k) + 0.5) * kProfileRowMm) break;  // rows left out: a gap
      if (column[i + k].y - column[i].y > kStepBackMm && stays_back(column, i + k, column[i].y)) return column[i];
    }
  return std::nullopt;
}
std::optional<ProfilePoint> upper_incisor_tip_in_columns(const HeadVolume& v, const Eigen::Vector3d& u1) {
  std::optional<ProfilePoint> lowest;
  for (const Profile& column :
       column_profiles(v, u1.z() + 8, u1.z() - 12, u1.y() - 20, u1.y() + 20, kToothSurfaceHu, u1.x(), 2.5)) {
    const Profile face = until_jump_forward(column);
    auto tip = upper_incisor_tip(face);
    if (const auto stepped = tip_before_a_step_back(face); stepped && (!tip || stepped->z > tip->z)) tip = stepped;
    if (tip && (!lowest || tip->z < lowest->z)) lowest = tip;
  }
  return lowest;
}

// Where a lower incisor's lingual profile (read upwards, rays from behind) leaves the lower tip for
// the upper incisor standing in front: the first sample kOverjetJumpMm or more in front of the one
// below it, within kCrownBandMm of the template's height (lower down the rays cross bone and gum,
// whose steps are no tip), from a point that lies behind the found upper edge by no more than the
// largest overjet and a crown (kLargestOverjetMm, scaled) and that ends a face read without a gap
// or a jump over the kFaceBelowJumpMm below it (a lone hit on the alveolar bone after a gap, 3 mm
// behind the crown, once made a jump 7 mm below the tip), the two samples in neighbouring rows
// (across rows where no ray met the face, the step is no jump). -1 if none.
constexpr double kOverjetJumpMm = 0.8, kCrownBandMm = 6.0, kLargestOverjetMm = 16.0, kFaceBelowJumpMm = 1.0;
constexpr double kLingualRowMm = 0.25;  // the lower lingual profile's rows
bool neighbouring_rows(const ProfilePoint& below, const ProfilePoint& above) {
  return above.z - below.z < 1.5 * kLingualRowMm;
}
bool a_face_ends_at(const Profile& lingual, size_t top) {
  const size_t samples = size_t(kFaceBelowJumpMm / kLingualRowMm);
  if (top < samples) return false;
  for (size_t i = top - samples + 1; i <= top; ++i)
    if (!neighbouring_rows(lingual[i - 1], lingual[i]) || std::abs(lingual[i].y - lingual[i - 1].y) >= kOverjetJumpMm)
      return false;
  return true;
}
int overjet_jump(const Profile& lingual, const Eigen::Vector3d& upper_edge, double template_z, double scale) {
  for (size_t i = 1; i < lingual.size(); ++i) {
    const ProfilePoint& below = lingual[i - 1];
    if (std::abs(below.z - template_z) > kCrownBandMm || below.y - lingual[i].y < kOverjetJumpMm) continue;
    if (!neighbouring_rows(below, lingual[i]) || !a_face_ends_at(lingual, i - 1)) continue;
    const double behind_upper = below.y - upper_edge.y();
    if (behind_upper > 0 && behind_upper <= kLargestOverjetMm * scale) return int(i);
  }
  return -1;
}

}  // namespace

// The lower incisor's edge is thin: 1.5 mm below its tip a crown is 2-2.5 mm thick. A labial face
// read farther than this in front of the lingual tip is the upper incisor's, standing against the
// lower crown with a tight overjet: the reading ran on through both crowns (6.3-6.4 mm on two
// bench patients, whose L1 it put 2.6 mm too far forward). Over the bench's 30 patients the
// readings fell at 1.3-2.8 mm or at 5.0-6.9 mm, none between. The edge's centre is then taken
// half a thin edge in front of the lingual tip, as when no labial face is read.
constexpr double kThickestLowerEdgeMm = 4.0;

void find_lower_incisor(const HeadVolume& v, double scale, double midline_x, Findings& found) {
  const Eigen::Vector3d l1 = expected_position("L1", scale) + Eigen::Vector3d(midline_x, 0, 0);
  // The lower incisor's lingual face, from inside the mouth, bottom up.
  Profile lower_lingual;
  // A ray that starts in bone (the symphysis of a lower jaw set back) sees no lingual face: its
  // hit at the start once made a jump forward to the crown, taken for the tip 7 mm low.
  const double ray_start_y = l1.y() + 16;
  for (double z = l1.z() - 12; z <= l1.z() + 8; z += kLingualRowMm) {
    std::optional<ProfilePoint> best;
    for (double x = l1.x() - 2; x <= l1.x() + 2.01; x += 0.5)
      if (auto hit = first_crossing(v, {x, ray_start_y, z}, {0, -1, 0}, 26, kToothSurfaceHu))
        if (hit->y() < ray_start_y - 0.5 && (!best || hit->y() > best->y)) best = ProfilePoint{z, hit->y(), x};
    if (best) lower_lingual.push_back(*best);
  }
  // Read upwards, the lower incisor's lingual face leans forward to its tip; above the tip the
  // rays meet the upper incisor's lingual face, which leans back: the tip is the most anterior
  // point of this profile. With a large overjet the upper incisor stands millimetres in front
  // of the lower one and the rays above the tip reach it at once (a jump forward), so its
  // lingual face would be taken for the tip: then the tip is the last point before the jump.
  // Its centre lies half the edge's thickness labially.
  const auto upper = found.find("U1");
  const int jump = upper != found.end() && upper->second.position
                       ? overjet_jump(lower_lingual, *upper->second.position, l1.z(), scale)
                       : -1;
  const int tip = jump > 0 ? jump - 1 : strongest_local_extremum(lower_lingual, -1, 2.5);
  if (tip < 0) {
    found["L1"] = RuleFinding::absent("no lower incisor crown behind the upper incisor");
    return;
  }
  const ProfilePoint lingual_tip = jump > 0 ? lower_lingual[size_t(tip)] : refined_extremum(lower_lingual, tip, 1.5);
  auto labial =
      first_drop(v, {lingual_tip.x, lingual_tip.y - 0.1, lingual_tip.z - 1.5}, {0, -1, 0}, 7, kToothSurfaceHu, 0.1);
  if (labial && lingual_tip.y - labial->y() > kThickestLowerEdgeMm) labial.reset();  // the upper incisor's
  const double y = labial ? (lingual_tip.y + labial->y()) / 2 : lingual_tip.y - 0.6;
  const double x = crown_middle_x(v, {lingual_tip.x, y, lingual_tip.z}, -1, kLowerCentralWidthMm, midline_x);
  found["L1"] = RuleFinding::found({x, y, lingual_tip.z}, labial ? 1 : 0.6);
}

void find_incisors(const HeadVolume& v, double scale, Findings& found) {
  const Eigen::Vector3d u1 = expected_position("U1", scale);
  // The patient's right central incisors (x < 0), as the phantom and most analyses take them.
  const Profile upper_labial =
      anterior_profile(v, u1.z() + 8, u1.z() - 12, u1.y() - 20, u1.y() + 20, kToothSurfaceHu, u1.x(), 2.5);
  auto tip = upper_incisor_tip(upper_labial);
  if (!tip) tip = upper_incisor_tip_in_columns(v, u1);
  if (tip)
    found["U1"] = RuleFinding::found(upper_incisal_edge_centre(v, *tip), 1);
  else
    found["U1"] = RuleFinding::absent("no upper incisor crown ending above the lower arch");
  find_lower_incisor(v, scale, 0, found);
}

namespace {

// Skin points this much less deep than the deepest are as deep, for the soft-tissue nasion: its
// concavity is broad and shallow, and at coarse voxels the noise decides between its parts.
constexpr double kNasionConcavityTieMm = 0.5;

// The soft-tissue nasion in the skin profile `zone` around nasion's height `nasion_z`: the
// deepest point of the concavity, and of the concavity's local bottoms as deep (within
// kNasionConcavityTieMm) the one nearest nasion's height, over which it lies. One scan at 1.5 mm
// voxels had two bottoms 6.5 mm apart 0.03 mm from each other in depth, and the upper was taken.
std::optional<ProfilePoint> soft_tissue_nasion(const Profile& zone, double nasion_z) {
  if (zone.size() < 3) return std::nullopt;
  int best = most_posterior(zone);
  const double deepest = zone[size_t(best)].y;
  for (int i = 0; i < int(zone.size()); ++i)
    if (zone[size_t(i)].y >= deepest - kNasionConcavityTieMm && is_local_extremum(zone, i, +1, 2) &&
        std::abs(zone[size_t(i)].z - nasion_z) < std::abs(zone[size_t(best)].z - nasion_z))
      best = i;
  return refined_extremum(zone, best, 4);  // a wide fit, as for the face's other extremes
}

}  // namespace

void find_soft_tissue_profile(const HeadVolume& v, double scale, Findings& found) {
  auto position_or = [&](const char* label) {
    const auto it = found.find(label);
    return it != found.end() && it->second.position ? *it->second.position : expected_position(label, scale);
  };
  const Eigen::Vector3d n = position_or("N"), me = position_or("Me");
  const Profile skin =
      anterior_profile(v, n.z() + 20, me.z() - 8, v.box().lo.y() + 0.5, n.y() + 40, kSkinHu, 0, 0, 0.25);
  auto extreme_between = [&](double z_low, double z_high, int sign) {
    return extreme(between_heights(skin, z_low, z_high), sign);
  };
  auto record = [&](const char* label, const std::optional<ProfilePoint>& p, const char* what) {
    found[label] = p ? RuleFinding::found(midline_point(*p), 1) : RuleFinding::absent(what);
  };
  // The soft-tissue nasion overlies the frontonasal suture: without a nasion (a field cut above
  // the nose) its concavity is not known to be there.
  if (found.count("N") && found.at("N").position)
    record("NS", soft_tissue_nasion(between_heights(skin, n.z() - 10, n.z() + 12), n.z()),
           "no skin in front of nasion");
  else
    found["NS"] = RuleFinding::absent("needs the nasion");
  const Eigen::Vector3d prn_expected = expected_position("Prn", scale);
  const auto prn = extreme_between(prn_expected.z() - 15, prn_expected.z() + 15, -1);
  record("Prn", prn, "no nose in the scanned field");
  if (!prn) return;
  // The deepest skin below the nose, from which the upper lip is sought.
  const auto below_nose = extreme_between(prn->z - 22 * scale, prn->z - 1, +1);
  if (!below_nose) record("Sn", below_nose, "no skin below the nose");
  if (!below_nose) return;
  const auto ls = first_forward_extremum(between_heights(skin, below_nose->z - 25 * scale, below_nose->z - 1));
  record("Ls", ls, "no upper lip");
  // Sn, where the columella meets the lip: the bottom of the concavity between Prn and Ls,
  // measured behind the line that joins them. The lip below it is nearly upright, so the
  // deepest point along the frame's anterior axis slides down the lip with a degree of pitch;
  // the depth behind that line does not.
  record("Sn", ls ? deepest_behind_line(between_heights(skin, ls->z, prn->z)) : below_nose, "no skin below the nose");
  if (!ls) return;
  const auto stomion = extreme_between(ls->z - 14 * scale, ls->z - 1, +1);
  if (!stomion) return;
  const auto li = first_forward_extremum(between_heights(skin, stomion->z - 16 * scale, stomion->z - 1));
  record("Li", li, "no lower lip");
  if (!li) return;
  const auto fold = extreme_between(li->z - 22 * scale, li->z - 1, +1);
  if (!fold) return;
  record("PogS", extreme_between(me.z(), fold->z - 1, -1), "no soft-tissue chin");
}

}  // namespace maxillo::landmarking
