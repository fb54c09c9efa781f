#include "landmarking/lateral_landmarks.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/QR>

#include "landmarking/profile.h"

namespace maxillo::landmarking {
namespace {

constexpr double kCanalAirHu = -200;  // the canal's air, partial volume included
constexpr double kCanalWallReachMm = 7;

struct Grid3 {
  Eigen::Vector3d lo;
  double step;
  int nx, ny, nz;
  Eigen::Vector3d at(int i, int j, int k) const { return lo + step * Eigen::Vector3d(i, j, k); }
  Eigen::Vector3d at(int index) const { return at(index % nx, (index / nx) % ny, index / (nx * ny)); }
  int index(int i, int j, int k) const { return i + nx * (j + ny * k); }
};

// The 6-connected regions of marked voxels, in the order of their first voxel.
std::vector<std::vector<int>> regions_of(const std::vector<uint8_t>& marked, const Grid3& g) {
  std::vector<uint8_t> seen(marked.size(), 0);
  std::vector<std::vector<int>> regions;
  for (int start = 0; start < int(marked.size()); ++start) {
    if (!marked[size_t(start)] || seen[size_t(start)]) continue;
    std::vector<int> region{start};
    seen[size_t(start)] = 1;
    for (size_t next = 0; next < region.size(); ++next) {
      const int i = region[next] % g.nx, j = (region[next] / g.nx) % g.ny, k = region[next] / (g.nx * g.ny);
      const int around[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                                {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
      for (const auto& n : around) {
        if (n[0] < 0 || n[1] < 0 || n[2] < 0 || n[0] >= g.nx || n[1] >= g.ny || n[2] >= g.nz) continue;
        const int index = g.index(n[0], n[1], n[2]);
        if (marked[size_t(index)] && !seen[size_t(index)]) {
          seen[size_t(index)] = 1;
          region.push_back(index);
        }
      }
    }
    regions.push_back(std::move(region));
  }
  return regions;
}

// The external acoustic meatus among the air spaces inside the temporal bone: the one that
// opens at the bone's lateral surface (no bone for 12 mm lateral to its outermost voxel), the
// most lateral of them; the middle ear and the mastoid cells lie deeper and stay closed.
std::vector<int> outer_canal(const HeadVolume& v, const std::vector<uint8_t>& canal, const Grid3& g, int side) {
  std::vector<int> best;
  double best_outer = -1e9;
  for (auto& region : regions_of(canal, g)) {
    if (double(region.size()) * std::pow(g.step, 3) < 4) continue;
    int outermost = region.front();
    for (int index : region)
      if (side * g.at(index).x() > side * g.at(outermost).x()) outermost = index;
    const Eigen::Vector3d p = g.at(outermost);
    if (first_crossing(v, p + Eigen::Vector3d(side * g.step, 0, 0), {double(side), 0, 0}, 12, kBoneHu, 0.5))
      continue;  // bone lateral to it: a closed space
    if (side * p.x() > best_outer) {
      best_outer = side * p.x();
      best = std::move(region);
    }
  }
  return best;
}

// The canal's voxels between `near_mm` and `far_mm` inside its lateral opening (`outer`, the
// opening's lateral coordinate times `side`).
std::vector<Eigen::Vector3d> voxels_between(const std::vector<int>& region, const Grid3& g, int side, double outer,
                                            double near_mm, double far_mm) {
  std::vector<Eigen::Vector3d> voxels;
  for (int index : region) {
    const Eigen::Vector3d p = g.at(index);
    const double depth = outer - side * p.x();
    if (depth >= near_mm && depth <= far_mm) voxels.push_back(p);
  }
  return voxels;
}

// The canal's axis, `depth_mm` inside its opening: a least-squares line (y and z over x)
// through its voxels 3-15 mm inside. Each cross-section of a cylinder is centred on its axis, so
// the line runs along the axis however oblique the canal; the whole region's centre did not:
// where the canal's air joins the middle ear's through a voxel or two (the cadaver head turned
// by 12 degrees), the region took in twice the voxels and its centre lay 6 mm deeper, which moved
// porion 0.9 mm along the canal's oblique axis. Deeper than 15 mm the canal may have joined the
// middle ear; nearer than 3 mm its opening flares.
constexpr double kAxisFromOpeningMm[2] = {3, 15};
Eigen::Vector3d canal_axis_at(const std::vector<int>& region, const Grid3& g, int side, double outer, double depth_mm) {
  std::vector<Eigen::Vector3d> voxels =
      voxels_between(region, g, side, outer, kAxisFromOpeningMm[0], kAxisFromOpeningMm[1]);
  if (voxels.size() < 8) voxels = voxels_between(region, g, side, outer, 0, 1e9);  // a short canal
  const double x_at = side * (outer - depth_mm);
  Eigen::MatrixXd design(voxels.size(), 2);
  Eigen::MatrixXd yz(voxels.size(), 2);
  for (size_t i = 0; i < voxels.size(); ++i) {
    design.row(Eigen::Index(i)) << 1, voxels[i].x() - x_at;
    yz.row(Eigen::Index(i)) << voxels[i].y(), voxels[i].z();
  }
  // A canal seen in one sagittal slab only has no slope to fit: its centre then.
  const bool one_slab = (design.col(1).array() - design(0, 1)).abs().maxCoeff() < 1e-9;
  if (one_slab) return {x_at, yz.col(0).mean(), yz.col(1).mean()};
  const Eigen::MatrixXd line = design.colPivHouseholderQr().solve(yz);
  return {x_at, line(0, 0), line(0, 1)};
}

// The whole air region's centre, carried out to `depth_mm` inside the opening (PorionAxis).
Eigen::Vector3d canal_centre_at(const std::vector<int>& region, const Grid3& g, int side, double outer,
                                double depth_mm) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int index : region) centre += g.at(index);
  centre /= double(region.size());
  return {side * (outer - depth_mm), centre.y(), centre.z()};
}
}  // namespace

RuleFinding find_porion(const HeadVolume& v, const Eigen::Vector3d& expected, int side, const Eigen::Vector2d& reach,
                        PorionAxis axis) {
  Grid3 g;
  g.step = std::max(0.5, v.spacing());
  const double lateral = std::abs(expected.x());
  const double x_near = lateral - 30, x_far = lateral + 15;
  g.lo = {side > 0 ? x_near : -x_far, expected.y() - reach.x(), expected.z() - reach.y()};
  g.nx = int((x_far - x_near) / g.step) + 1;
  g.ny = int(2 * reach.x() / g.step) + 1;
  g.nz = int(2 * reach.y() / g.step) + 1;
  std::vector<uint8_t> canal(size_t(g.nx * g.ny * g.nz), 0);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Eigen::Vector3d p = g.at(i, j, k);
        if (v.hu(p) >= kCanalAirHu) continue;
        canal[size_t(g.index(i, j, k))] =
            first_crossing(v, p, {0, 0, 1}, kCanalWallReachMm, kBoneHu, 0.5).has_value() &&
            first_crossing(v, p, {0, 0, -1}, kCanalWallReachMm, kBoneHu, 0.5).has_value();
      }
  const std::vector<int> region = outer_canal(v, canal, g, side);
  if (region.empty())
    return RuleFinding::absent(v.scanned(expected) ? "no ear canal inside the temporal bone"
                                                   : "the ear canal lies outside the scanned field");
  // The lateral opening: the region's outermost voxels.
  double outer = -1e9;
  for (int index : region) outer = std::max(outer, side * g.at(index).x());
  const double extent = outer - (side > 0 ? g.lo.x() : -(g.lo.x() + (g.nx - 1) * g.step));
  // The canal's roof above its axis, 1.5 mm inside the opening; then the bone's lateral surface
  // along the roof's line.
  const Eigen::Vector3d inside = axis == PorionAxis::kAtOpening ? canal_axis_at(region, g, side, outer, 1.5)
                                                                : canal_centre_at(region, g, side, outer, 1.5);
  const auto roof = first_edge(v, inside, {0, 0, 1}, kCanalWallReachMm, kBoneHu);
  if (!roof) return RuleFinding::absent("the ear canal has no bony roof");
  // (0.6 mm above the roof: inside its bone, whatever the voxel size, so that the ray cannot run
  // along the canal itself.)
  const Eigen::Vector3d outside(side * (outer + 15), inside.y(), roof->z() + 0.6);
  const auto surface = first_edge(v, outside, {-double(side), 0, 0}, 25, kBoneHu);
  if (!surface) return RuleFinding::absent("no bone lateral to the ear canal");
  return RuleFinding::found({surface->x(), inside.y(), roof->z()}, evidence_between(extent, 4, 12),
                            extent < 12 ? "a short bony ear canal" : "");
}

namespace {

// Where the rim, read from its lowest sample `lowest` in the direction `step` (+1 or -1 along
// x), has risen to `level` for good: its first crossing of the level, or the crossing after a
// second dip as deep as the bottom (within kSplitBottomMm) beyond it. Such a dip, 2-3 mm wide
// beyond a low bump towards the rim's lateral end (where the lateral rim rises to the zygoma),
// belongs to the bottom: with the first crossing the bottom's middle moved with the bump's height
// by 1.7 mm from one start to the other, or the dip was read as the bottom, 7-9 mm away. nullopt
// where the rim does not reach the level within the rim read.
constexpr double kSplitBottomMm = 0.5;
std::optional<double> rim_rise(const Profile& rim, int lowest, int step, double level) {
  const double bottom = rim[size_t(lowest)].y;
  std::optional<double> first, last;
  bool above = false;
  for (int i = lowest + step; i >= 0 && i < int(rim.size()); i += step) {
    const ProfilePoint &at = rim[size_t(i)], &before = rim[size_t(i - step)];
    if (!above && at.y >= level) {
      const double crossing = before.z + (level - before.y) / (at.y - before.y) * (at.z - before.z);
      if (!first) first = crossing;
      last = crossing;
      above = true;
    } else if (above && at.y < bottom + kSplitBottomMm) {
      above = false;  // a second dip of the bottom: the rise is still to come
    }
  }
  return above ? last : first;
}

RuleFinding orbitale_across(const HeadVolume& v, const Eigen::Vector3d& expected, int side, double half_width,
                            bool whole_ends) {
  // In each sagittal section across the orbit, rays from the front end on the face below the
  // rim and on the orbital floor above it; the floor lies far behind for a small rise, so where
  // the depth of the hit starts to grow faster than 2 mm per mm of height, the ray has passed the
  // rim. Or is the lowest rim point across the orbit's width.
  const std::string orbit = side > 0 ? "the left orbit" : "the right orbit";
  Profile rim;  // z holds x, y holds the rim's height; the rim's front is kept apart
  std::vector<double> rim_front;
  // (With `whole_ends`, 1 mm beyond the searched width on either side: those columns smooth the
  // width's ends, below.)
  const double reach = whole_ends ? half_width + 1.0 : half_width;
  for (double dx = -reach; dx <= reach + 0.01; dx += 0.5) {
    const double x = expected.x() + dx;
    Profile section = anterior_profile(v, expected.z() + 14, expected.z() - 12, expected.y() - 30, expected.y() + 40,
                                       kBoneHu, x, 0, 0.25);
    std::reverse(section.begin(), section.end());  // upwards
    for (size_t i = 2; i < section.size(); ++i) {
      const double rise = section[i].z - section[i - 2].z;
      if (rise > 0.75) continue;  // a gap in the section
      if ((section[i].y - section[i - 2].y) / rise > 2) {
        if (i > 4) {
          rim.push_back({x, (section[i].z + section[i - 2].z) / 2, 0});
          rim_front.push_back(section[i - 2].y);
        }
        break;
      }
    }
  }
  if (rim.size() < 8)
    return RuleFinding::absent(v.scanned(expected) ? "no inferior orbital rim in front of " + orbit
                                                   : orbit + " lies outside the scanned field");
  // The rim's heights smoothed across x (5 columns, 2 mm): the sections' steps are 0.25 mm. With
  // `whole_ends` the two columns at either end, beyond the searched width, have no smoothed
  // height and are dropped: left raw, a one-column dip at the search's lateral end was read as
  // the rim's bottom, 7 mm from its middle. Without, the ends stay raw (see find_orbitale).
  Profile smooth;
  std::vector<double> smooth_front;
  for (size_t i = 0; i < rim.size(); ++i) {
    const bool end = i < 2 || i + 2 >= rim.size();
    if (end && whole_ends) continue;
    smooth.push_back(
        end ? rim[i]
            : ProfilePoint{rim[i].z, (rim[i - 2].y + rim[i - 1].y + rim[i].y + rim[i + 1].y + rim[i + 2].y) / 5, 0});
    smooth_front.push_back(rim_front[i]);
  }
  rim = smooth;
  rim_front = smooth_front;
  const int lowest = most_anterior(rim);  // smallest "y": the lowest rim height
  // The rim's bottom is flat (an orbit's outline is close to an ellipse), so its lowest sample
  // says little about where across the orbit it lies: the bottom is placed midway between the
  // two places where the rim has risen 1.5 mm above it, and its height fitted there.
  const double level = rim[size_t(lowest)].y + 1.5;
  const std::optional<double> medial = rim_rise(rim, lowest, -1, level), lateral = rim_rise(rim, lowest, +1, level);
  const double x = medial && lateral ? (*medial + *lateral) / 2 : rim[size_t(lowest)].z;
  int nearest = lowest;
  for (int i = 0; i < int(rim.size()); ++i)
    if (std::abs(rim[size_t(i)].z - x) < std::abs(rim[size_t(nearest)].z - x)) nearest = i;
  const double z = refined_extremum(rim, nearest, 6).y;
  const auto front = first_crossing(v, {x, expected.y() - 30, z}, {0, 1, 0}, 70, kBoneHu);
  const bool at_end = !medial || !lateral;
  return RuleFinding::found(
      {x, front ? front->y() : rim_front[size_t(lowest)], z}, at_end ? 0.3 : 1,
      at_end ? "the rim does not rise on both sides of its lowest point within the searched width" : "");
}

constexpr double kOrbitHalfWidthMm = 12, kWideOrbitHalfWidthMm = 20;

// Orbitale is the rim's lowest point only where the rim is seen rising on both sides of it, a
// few millimetres above it: where the field's top cuts the rim that close (a cone-beam field cut
// at the orbits), the rule reads whatever bone the rays meet below the cut. Such a point is
// absent, as at any edge of the field (landmark_detection.cpp), but with the reach the rule needs.
constexpr double kRimRiseSeenMm = 5;
RuleFinding unless_the_rim_is_cut(const HeadVolume& v, RuleFinding found) {
  if (found.position && !v.scanned(*found.position + Eigen::Vector3d(0, 0, kRimRiseSeenMm)))
    return RuleFinding::absent("at the edge of the scanned field: the orbital rim above it was not scanned");
  return found;
}

}  // namespace

RuleFinding find_orbitale(const HeadVolume& v, const Eigen::Vector3d& expected, int side, OrbitSearch search) {
  const bool whole_ends = search == OrbitSearch::kWidening;
  RuleFinding narrow = unless_the_rim_is_cut(v, orbitale_across(v, expected, side, kOrbitHalfWidthMm, whole_ends));
  if (search == OrbitSearch::kNarrow || !narrow.position || narrow.evidence >= 1) return narrow;
  RuleFinding wide = unless_the_rim_is_cut(v, orbitale_across(v, expected, side, kWideOrbitHalfWidthMm, whole_ends));
  return wide.position && wide.evidence >= 1 ? wide : narrow;
}

}  // namespace maxillo::landmarking
