#include "landmarking/sella.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "landmarking/profile.h"

namespace maxillo::landmarking {
namespace {

constexpr double kWallReachMm = 10;  // bone this close in front, behind and below: inside a pocket
// The fossa's walls are thin (the dorsum sellae a millimetre or two): in a scan of 1-2 mm
// voxels they stay well below cortical values, so the walls are bone above this.
constexpr double kWallHu = 150;
constexpr double kMinPocketMm2 = 12, kMaxPocketMm2 = 400;
constexpr double kOpenAboveMm = 30;  // the fossa opens to the brain: no bone this far above it
// A cone-beam field may end a little above the fossa: the brain seen up to the field's edge,
// at least this far above the pocket's top, is open too (what lies beyond was not scanned, not
// bone). A fossa whose walls the edge cuts has pocket pixels up to the edge itself (0-0.5 mm of
// brain above them, on BENCH-006 and 027); a whole fossa ends where its walls end, below the
// edge (1.5-3.5 mm above it on BENCH-009 and 018, which 6 mm here once refused).
constexpr double kOpenToFieldEdgeMm = 1;

// The section's pixels: rows along z (downwards), columns along y.
struct Section {
  double y0, z0, step;
  int columns, rows;
  Eigen::Vector3d at(int c, int r) const { return {0, y0 + c * step, z0 - r * step}; }
};

bool soft(double hu) { return hu < kWallHu && hu >= -300; }

// Where the soft tissue ends along the direction within `reach`, to 0.05 mm: bone, or air behind
// a wall too thin to show as bone (the sella's floor over a large sphenoid sinus).
std::optional<Eigen::Vector3d> wall_along(const HeadVolume& v, const Eigen::Vector3d& p,
                                          const Eigen::Vector3d& direction, double reach) {
  for (double t = 0.25; t <= reach; t += 0.25) {
    if (soft(v.hu(p + t * direction))) continue;
    double lo = t - 0.25, hi = t;
    while (hi - lo > 0.05) {
      const double mid = (lo + hi) / 2;
      (soft(v.hu(p + mid * direction)) ? lo : hi) = mid;
    }
    return p + hi * direction;
  }
  return std::nullopt;
}

bool wall_within(const HeadVolume& v, const Eigen::Vector3d& p, const Eigen::Vector3d& direction) {
  return wall_along(v, p, direction, kWallReachMm).has_value();
}

bool in_pocket(const HeadVolume& v, const Eigen::Vector3d& p) {
  const double hu = v.hu(p);
  if (!soft(hu)) return false;  // bone, or air (the sphenoid sinus below)
  return wall_within(v, p, {0, 0, -1}) && wall_within(v, p, {0, -1, 0}) && wall_within(v, p, {0, 1, 0});
}

// Connected regions (4-neighbours) of the marked pixels, as pixel lists.
std::vector<std::vector<int>> regions(const std::vector<uint8_t>& marked, const Section& s) {
  std::vector<int> label(marked.size(), -1);
  std::vector<std::vector<int>> result;
  for (int start = 0; start < int(marked.size()); ++start) {
    if (!marked[size_t(start)] || label[size_t(start)] >= 0) continue;
    std::vector<int> pixels{start};
    label[size_t(start)] = int(result.size());
    for (size_t next = 0; next < pixels.size(); ++next) {
      const int c = pixels[next] % s.columns, r = pixels[next] / s.columns;
      const int around[4][2] = {{c - 1, r}, {c + 1, r}, {c, r - 1}, {c, r + 1}};
      for (const auto& n : around) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= s.columns || n[1] >= s.rows) continue;
        const int index = n[1] * s.columns + n[0];
        if (marked[size_t(index)] && label[size_t(index)] < 0) {
          label[size_t(index)] = int(result.size());
          pixels.push_back(index);
        }
      }
    }
    result.push_back(std::move(pixels));
  }
  return result;
}

// Algebraic (Kasa) circle fit: centre and radius in the (y, z) plane.
bool fit_circle(const std::vector<Eigen::Vector2d>& points, Eigen::Vector2d& centre, double& radius) {
  if (points.size() < 6) return false;
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    a.row(Eigen::Index(i)) << 2 * points[i].x(), 2 * points[i].y(), 1;
    b[Eigen::Index(i)] = points[i].squaredNorm();
  }
  const Eigen::Vector3d solution = a.colPivHouseholderQr().solve(b);
  centre = solution.head<2>();
  const double r2 = solution[2] + centre.squaredNorm();
  if (!(r2 > 0)) return false;
  radius = std::sqrt(r2);
  return true;
}

enum class Above { kOpen, kClosed, kCutByTheField };

// kOpen: soft tissue (the brain) straight above `p` for kOpenAboveMm, or up to the scanned
// field's edge when that lies at least kOpenToFieldEdgeMm above. kCutByTheField: the edge
// comes sooner, so the pocket below may be a fossa whose walls were not scanned whole.
Above what_lies_above(const HeadVolume& v, const Eigen::Vector3d& p) {
  for (double t = 0; t <= kOpenAboveMm; t += 0.5) {
    const Eigen::Vector3d q = p + Eigen::Vector3d(0, 0, t);
    // The voxel above too: the interpolation mixes in the unscanned air beyond the edge.
    if (!v.scanned(q + Eigen::Vector3d(0, 0, v.spacing())))
      return t >= kOpenToFieldEdgeMm ? Above::kOpen : Above::kCutByTheField;
    if (!soft(v.hu(q))) return Above::kClosed;
  }
  return Above::kOpen;
}

}  // namespace

std::optional<SellaFinding> find_sella(const HeadVolume& v, const FrameBox& window, bool* cut_by_the_field) {
  Section s;
  s.step = std::max(0.5, v.spacing());
  s.y0 = window.lo.y();
  s.z0 = window.hi.z();
  s.columns = int((window.hi.y() - window.lo.y()) / s.step) + 1;
  s.rows = int((window.hi.z() - window.lo.z()) / s.step) + 1;
  std::vector<uint8_t> marked(size_t(s.columns * s.rows), 0);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.columns; ++c) marked[size_t(r * s.columns + c)] = in_pocket(v, s.at(c, r));
  // The pocket: a region of a fossa's size that opens upwards into the cranial cavity (soft
  // tissue for 30 mm above its top: the brain), unlike the recesses of the nasal cavity.
  const std::vector<std::vector<int>> pockets = regions(marked, s);
  const std::vector<int>* best = nullptr;
  double best_top = 0;
  bool a_pocket_was_cut = false;
  for (const auto& region : pockets) {
    const double area = double(region.size()) * s.step * s.step;
    if (area < kMinPocketMm2 || area > kMaxPocketMm2) continue;
    double y_sum = 0, z_top = -1e9;
    for (int index : region) {
      const Eigen::Vector3d p = s.at(index % s.columns, index / s.columns);
      y_sum += p.y();
      z_top = std::max(z_top, p.z());
    }
    const Eigen::Vector3d above(0, y_sum / double(region.size()), z_top + s.step);
    const Above what = what_lies_above(v, above);
    a_pocket_was_cut = a_pocket_was_cut || what == Above::kCutByTheField;
    if (what != Above::kOpen) continue;
    // Of the pockets that open into the cranial cavity, the sella is the lowest: the deepest
    // point of the central skull base (the olfactory recess in front of it lies higher).
    if (!best || z_top < best_top) {
      best = &region;
      best_top = z_top;
    }
  }
  if (cut_by_the_field) *cut_by_the_field = !best && a_pocket_was_cut;
  if (!best) return std::nullopt;
  // Its bony wall: pocket pixels next to bone; the wall point itself where the bone begins.
  std::vector<Eigen::Vector2d> wall;
  const Eigen::Vector3d directions[3] = {{0, 0, -1}, {0, -1, 0}, {0, 1, 0}};
  for (int index : *best) {
    const Eigen::Vector3d p = s.at(index % s.columns, index / s.columns);
    for (const auto& d : directions)
      if (auto hit = wall_along(v, p, d, 1.5 * s.step)) wall.emplace_back(hit->y(), hit->z());
  }
  SellaFinding finding;
  finding.pocket_mm2 = double(best->size()) * s.step * s.step;
  // S: the pocket's centroid, the geometric centre of the fossa in the midsagittal section.
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int index : *best) {
    const Eigen::Vector3d p = s.at(index % s.columns, index / s.columns);
    centroid += Eigen::Vector2d(p.y(), p.z());
  }
  centroid /= double(best->size());
  finding.centre = {0, centroid.x(), centroid.y()};
  // How round its bony outline is: the evidence that the pocket is a fossa.
  Eigen::Vector2d centre;
  if (!fit_circle(wall, centre, finding.radius_mm) || finding.radius_mm > 12) {
    finding.radius_mm = 0;
    finding.fit_rms_mm = 1.5;
    return finding;
  }
  double sum = 0;
  for (const auto& w : wall) sum += std::pow((w - centre).norm() - finding.radius_mm, 2);
  finding.fit_rms_mm = std::sqrt(sum / double(wall.size()));
  return finding;
}

}  // namespace maxillo::landmarking
