#include "landmarking/dental_landmarks.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "landmarking/landmark_template.h"
#include "landmarking/profile.h"

namespace maxillo::landmarking {
namespace {

constexpr double kStep = 0.5;        // the dental grid (mm)
constexpr double kCrownHu = 2000;    // enamel: above any bone
constexpr double kSurfaceHu = 1400;  // halfway between enamel and the soft tissue or air around it
constexpr double kMolarMinLengthMm = 8.5;
constexpr double kMolarMaxLengthMm = 12.5;  // longer: two teeth whose contact did not show
// How far a first molar's cusp may lie from the template's: a varied phantom's lower molar lay
// 6.3 mm from it, and the second start (landmark_checks.h) moves the template 2 mm more; the
// canine lies 10 mm and more in front of the first molar, the second molar as far behind.
constexpr double kMolarSearchMm = 10;

// Crown voxels of a box beside the arch on one side, counted per height and per position along
// y (the posterior teeth stand nearly in a line along y).
class DentalBox {
 public:
  DentalBox(const HeadVolume& v, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) : lo_(grid_corner(lo, kStep)) {
    for (int a = 0; a < 3; ++a) n_[a] = int((hi[a] - lo_[a]) / kStep) + 1;
    crown_.resize(size_t(n_[0]) * n_[1] * n_[2]);
    for (int k = 0; k < n_[2]; ++k)
      for (int j = 0; j < n_[1]; ++j)
        for (int i = 0; i < n_[0]; ++i) crown_[index(i, j, k)] = v.hu(at(i, j, k)) >= kCrownHu;
  }
  int size(int axis) const { return n_[axis]; }
  double y(int j) const { return lo_.y() + j * kStep; }
  double z(int k) const { return lo_.z() + k * kStep; }
  double x(int i) const { return lo_.x() + i * kStep; }
  bool crown(int i, int j, int k) const { return crown_[index(i, j, k)] != 0; }
  // Crown voxels in the slab of rows [j0, j1) at height k.
  int count_at(int k, int j0, int j1) const {
    int count = 0;
    for (int j = std::max(0, j0); j < std::min(n_[1], j1); ++j)
      for (int i = 0; i < n_[0]; ++i) count += crown(i, j, k);
    return count;
  }

 private:
  size_t index(int i, int j, int k) const { return size_t(i) + size_t(n_[0]) * (size_t(j) + size_t(n_[1]) * k); }
  Eigen::Vector3d at(int i, int j, int k) const { return lo_ + kStep * Eigen::Vector3d(i, j, k); }
  Eigen::Vector3d lo_;
  int n_[3];
  std::vector<uint8_t> crown_;
};

// Each value the mean of itself and its two neighbours (the ends kept): one voxel's noise does
// not make a narrowing.
std::vector<double> three_sample_mean(const std::vector<double>& values) {
  std::vector<double> smooth = values;
  for (size_t i = 1; i + 1 < values.size(); ++i) smooth[i] = (values[i - 1] + values[i] + values[i + 1]) / 3;
  return smooth;
}

// The occlusal level in each band of 4 mm along y, from the crowns' cross-section per height.
// The upper crowns stand on the lower ones: counted per height, the enamel shows two plateaus
// (one per arch) and, where the cusp tips meet, a narrowing (the cusps taper to their tips and
// interdigitate) or, with the mouth open, a gap. The level is the narrowest height between the
// two plateaus' peaks (the middle of a gap); a band with one arch only has none.
std::optional<double> occlusal_level(const DentalBox& box, int j0, int j1) {
  const int heights = box.size(2);
  std::vector<double> count(size_t(heights), 0);
  for (int k = 0; k < heights; ++k) count[size_t(k)] = box.count_at(k, j0, j1);
  const std::vector<double> smooth = three_sample_mean(count);
  const auto highest = std::max_element(smooth.begin(), smooth.end());
  if (*highest <= 0) return std::nullopt;
  const int first = int(highest - smooth.begin());
  const int apart = int(4 / kStep);
  int second = -1;
  for (int k = 0; k < heights; ++k)
    if (std::abs(k - first) >= apart && (second < 0 || smooth[size_t(k)] > smooth[size_t(second)])) second = k;
  if (second < 0 || smooth[size_t(second)] < 0.25 * *highest) return std::nullopt;
  const int lo = std::min(first, second), hi = std::max(first, second);
  double least = *highest;
  for (int k = lo; k <= hi; ++k) least = std::min(least, smooth[size_t(k)]);
  // The middle of the run of heights at the least section (a gap, or a flat narrowing).
  int run_from = -1, best_from = lo, best_length = 0;
  for (int k = lo; k <= hi + 1; ++k) {
    const bool at_least = k <= hi && smooth[size_t(k)] <= least + 1e-9;
    if (at_least && run_from < 0) run_from = k;
    if (!at_least && run_from >= 0) {
      if (k - run_from > best_length) best_from = run_from, best_length = k - run_from;
      run_from = -1;
    }
  }
  return (box.z(best_from) + box.z(best_from + best_length - 1)) / 2;
}

std::vector<std::optional<double>> occlusal_levels(const DentalBox& box) {
  const int band = int(4 / kStep);
  std::vector<std::optional<double>> level(size_t(box.size(1)));
  for (int j0 = 0; j0 < box.size(1); j0 += band) {
    const auto at = occlusal_level(box, j0, j0 + band);
    for (int j = j0; j < std::min(box.size(1), j0 + band); ++j) level[size_t(j)] = at;
  }
  return level;
}

// The occlusal line along y: a least-squares line through the bands' levels (the occlusal plane
// slopes about 10 degrees from the Frankfort horizontal, down towards the front), so the crowns'
// heights are read from the plane they meet on, not from a single band's level.
struct OcclusalLine {
  double level_at_zero = 0, slope = 0;  // z = level_at_zero + slope * y
  double at(double y) const { return level_at_zero + slope * y; }
};

std::optional<OcclusalLine> occlusal_line(const DentalBox& box, const std::vector<std::optional<double>>& level) {
  double n = 0, sy = 0, sz = 0, syy = 0, syz = 0;
  for (int j = 0; j < box.size(1); ++j)
    if (level[size_t(j)]) {
      const double y = box.y(j), z = *level[size_t(j)];
      n += 1, sy += y, sz += z, syy += y * y, syz += y * z;
    }
  if (n < 2) return std::nullopt;
  const double spread = n * syy - sy * sy;
  if (spread <= 1e-9) return OcclusalLine{sz / n, 0};
  const double slope = (n * syz - sy * sz) / spread;
  return OcclusalLine{(sz - slope * sy) / n, slope};
}

struct ToothSpan {
  int front = 0, back = 0;  // rows along y
  double mass = 0;          // the crown's largest smoothed mass per row: its width across the arch
};

// The largest of values[from, to).
double largest_in(const std::vector<double>& values, int from, int to) {
  return *std::max_element(values.begin() + from, values.begin() + to);
}

// A run of crown rows longer than any tooth (kMolarMaxLengthMm) holds two or more: at 1 mm voxels
// a premolar's contact with the molar behind it keeps 87 % of the premolar's mass (a bench
// patient's lower first molar merged with both premolars into one 21.5 mm crown and was missed).
// It is split at its most marked narrowing (the lowest ratio of a local minimum's mass to the
// smaller of the highest masses on either side), and the parts in turn, until each fits a tooth
// or holds no narrowing.
void split_if_longer_than_a_tooth(const std::vector<double>& smooth, const ToothSpan& run,
                                  std::vector<ToothSpan>& teeth) {
  int contact = -1;
  double sharpest = 1;
  if ((run.back - run.front) * kStep > kMolarMaxLengthMm)
    for (int c = run.front + 2; c + 2 < run.back; ++c) {
      const double here = smooth[size_t(c)];
      if (here > smooth[size_t(c - 1)] || here > smooth[size_t(c + 1)]) continue;
      if (const double ratio = here / std::min(largest_in(smooth, run.front, c), largest_in(smooth, c + 1, run.back));
          ratio < sharpest)
        sharpest = ratio, contact = c;
    }
  if (contact < 0) {
    teeth.push_back(run);
    return;
  }
  split_if_longer_than_a_tooth(smooth, {run.front, contact, largest_in(smooth, run.front, contact)}, teeth);
  split_if_longer_than_a_tooth(smooth, {contact, run.back, largest_in(smooth, contact, run.back)}, teeth);
}

// The teeth along y of one arch: crown voxels 0.5-6 mm from the occlusal line on the arch's side,
// per row, smoothed over three rows. Crowns are the runs of rows above a quarter of the peak; a
// run splits where two crowns touch: at a row below 80 % of the highest rows on both sides of it
// within the run (the crowns narrow to their contact; at 1.4 mm voxels a contact keeps about
// 70 % of the crowns' mass, at 0.5 mm about half).
std::vector<ToothSpan> teeth_along_y(const DentalBox& box, const OcclusalLine& line, int up) {
  const int rows = box.size(1);
  std::vector<double> mass(size_t(rows), 0);
  for (int j = 0; j < rows; ++j)
    for (int k = 0; k < box.size(2); ++k) {
      const double h = up * (box.z(k) - line.at(box.y(j)));
      if (h < 0.5 || h > 6) continue;
      for (int i = 0; i < box.size(0); ++i) mass[size_t(j)] += box.crown(i, j, k);
    }
  const std::vector<double> smooth = three_sample_mean(mass);
  const double peak = *std::max_element(smooth.begin(), smooth.end());
  std::vector<ToothSpan> teeth;
  for (int j = 0; j < rows;) {
    if (smooth[size_t(j)] <= 0.25 * peak) {
      ++j;
      continue;
    }
    int end = j;
    while (end < rows && smooth[size_t(end)] > 0.25 * peak) ++end;
    // Contacts inside the run [j, end).
    int front = j;
    for (int c = j + 2; c + 2 < end; ++c) {
      const double here = smooth[size_t(c)];
      if (here > smooth[size_t(c - 1)] || here > smooth[size_t(c + 1)]) continue;
      const double before = largest_in(smooth, front, c);
      if (here < 0.8 * std::min(before, largest_in(smooth, c + 1, end))) {
        split_if_longer_than_a_tooth(smooth, {front, c, before}, teeth);
        front = c;
      }
    }
    split_if_longer_than_a_tooth(smooth, {front, end, largest_in(smooth, front, end)}, teeth);
    j = end;
  }
  return teeth;
}

// The mesio-buccal cusp tip of the tooth between rows [front, back). In occlusion the cusps rest
// on the opposing crowns, and at a scan's resolution two crowns in contact show as one, so the
// tip is placed from the crown's outline instead of its occlusal relief: a molar's mesio-buccal
// cusp stands about a quarter of the crown's length from its mesial face and a quarter of its
// width from its buccal face (first molars: 10-11 by 10-11.5 mm, the cusp tip 2.5-3 mm in from
// each). The outline is the crown's section 1.5-2.5 mm from the occlusal line, where upper and
// lower crowns are apart; the tip's height is where a ray from inside the crown towards the
// other arch leaves the enamel, or the occlusal line where it meets the opposing crown first.
std::optional<Eigen::Vector3d> mesiobuccal_cusp(const HeadVolume& v, const DentalBox& box, const ToothSpan& tooth,
                                                const OcclusalLine& line, int up, int side) {
  std::vector<double> xs;
  for (int j = tooth.front; j < tooth.back; ++j)
    for (int k = 0; k < box.size(2); ++k)
      if (const double h = up * (box.z(k) - line.at(box.y(j))); h >= 1.5 && h <= 2.5)
        for (int i = 0; i < box.size(0); ++i)
          if (box.crown(i, j, k)) xs.push_back(box.x(i));
  if (xs.size() < 20) return std::nullopt;
  // The crown's faces across x: the 2nd and 98th percentiles (a stray voxel does not move them).
  std::sort(xs.begin(), xs.end());
  const double x_low = xs[xs.size() / 50], x_high = xs[xs.size() - 1 - xs.size() / 50];
  const double buccal_face = side > 0 ? x_high : x_low;
  const double width = x_high - x_low, length = (tooth.back - tooth.front) * kStep;
  const double x = buccal_face - side * width / 4, y = box.y(tooth.front) + length / 4;
  constexpr double kStartMm = 3;
  const Eigen::Vector3d inside(x, y, line.at(y) + up * kStartMm);
  const auto surface = first_drop(v, inside, {0, 0, -double(up)}, kStartMm, kSurfaceHu, 0.05);
  return surface ? *surface : Eigen::Vector3d(x, y, line.at(y));
}

// The largest mass of the crowns of a tooth's length from `tooth` backwards: premolars are
// narrower than the molars behind them, and the canine in front, where the arch turns across the
// box, can pass for wider than any molar (a bench patient's upper first molar was refused beside
// a canine 33 % wider).
double widest_from(const std::vector<ToothSpan>& teeth, const ToothSpan& tooth) {
  double widest = 0;
  for (const auto& t : teeth)
    if (t.front >= tooth.front && (t.back - t.front) * kStep <= kMolarMaxLengthMm) widest = std::max(widest, t.mass);
  return widest;
}

// A crown with a molar's length and width. Premolars are 6.5-7.5 mm long, and where two of
// them touch without a visible contact they make one crown of a molar's length, but they are
// narrower across the arch (upper 9 mm, lower 7.5-8, against 10.5-11.5 for the molars), so their
// mass per row stays below 88 % of the molars' behind them. A crown cut by the box's front is
// not one (its length is unknown).
bool molar_shaped(const std::vector<ToothSpan>& teeth, const ToothSpan& t) {
  const double length = (t.back - t.front) * kStep;
  return t.front > 0 && length >= kMolarMinLengthMm && length <= kMolarMaxLengthMm &&
         t.mass >= 0.88 * widest_from(teeth, t);
}

// The first molar: the front one of the molars standing in a row with the molar-shaped crown
// whose mesio-buccal cusp (a quarter of its length behind its mesial face) lies nearest the
// template's. The template alone can be a tooth off: a bench patient's upper first molar cusp
// lay 8.5 mm in front of it and the second molar's 3 mm behind. The canine, where the arch
// turns, can pass for wide, but lies 10 mm and more in front of the first molar, beyond the
// kMolarSearchMm allowed around the template, with the premolars between.
const ToothSpan* first_molar(const DentalBox& box, const std::vector<ToothSpan>& teeth, double expected_cusp_y) {
  int nearest = -1;
  double nearest_mm = kMolarSearchMm;
  for (size_t i = 0; i < teeth.size(); ++i) {
    const ToothSpan& t = teeth[i];
    const double apart = std::abs(box.y(t.front) + (t.back - t.front) * kStep / 4 - expected_cusp_y);
    if (molar_shaped(teeth, t) && apart < nearest_mm) nearest = int(i), nearest_mm = apart;
  }
  if (nearest < 0) return nullptr;
  while (nearest > 0 && teeth[size_t(nearest - 1)].back == teeth[size_t(nearest)].front &&
         molar_shaped(teeth, teeth[size_t(nearest - 1)]))
    --nearest;
  return &teeth[size_t(nearest)];
}

}  // namespace

void find_first_molars(const HeadVolume& v, double scale, int side, Findings& found) {
  const std::string suffix = side > 0 ? "L" : "R";
  const Eigen::Vector3d upper = expected_position("U6" + suffix, scale),
                        lower = expected_position("L6" + suffix, scale);
  const Eigen::Vector3d centre = (upper + lower) / 2;
  const double x_mid = std::abs(centre.x());
  const Eigen::Vector3d lo(side > 0 ? x_mid - 14 : -x_mid - 12, centre.y() - 24, centre.z() - 14);
  const Eigen::Vector3d hi(side > 0 ? x_mid + 12 : -x_mid + 14, centre.y() + 22, centre.z() + 14);
  const DentalBox box(v, lo, hi);
  const auto level = occlusal_levels(box);
  const auto line = occlusal_line(box, level);
  for (int up : {+1, -1}) {
    const std::string label = (up > 0 ? "U6" : "L6") + suffix;
    if (!line) {
      found[label] = RuleFinding::absent(v.scanned(upper) ? "no upper and lower crowns meeting behind the canine"
                                                          : "the molars lie outside the scanned field");
      continue;
    }
    const auto teeth = teeth_along_y(box, *line, up);
    const ToothSpan* molar = first_molar(box, teeth, (up > 0 ? upper : lower).y());
    if (!molar) {
      found[label] = RuleFinding::absent("no first molar crown (8.5 to 12.5 mm long) behind the premolars");
      continue;
    }
    const auto cusp = mesiobuccal_cusp(v, box, *molar, *line, up, side);
    if (!cusp) {
      found[label] = RuleFinding::absent("no occlusal surface on the first molar's crown");
      continue;
    }
    const double length = (molar->back - molar->front) * kStep;
    found[label] = RuleFinding::found(*cusp, evidence_between(12.5 - std::abs(length - 10.5), 9, 10.5));
  }
}

}  // namespace maxillo::landmarking
