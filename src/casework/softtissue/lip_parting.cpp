#include "casework/softtissue/lip_parting.h"

#include <algorithm>
#include <cmath>

#include "ceph/landmark_frame.h"

namespace maxillo::casework {
namespace {

constexpr double kMouthHalfWidthMm = 25;  // the corners of an adult's mouth from the midline
constexpr double kBehindIncisorMm = 1;    // the lips reach this far behind the incisor's tip
constexpr double kArchFallMm = 50;        // the arch falls back as x^2 / kArchFallMm
constexpr double kLipHalfHeightMm = 10;
constexpr double kAcrossStepMm = 2.5;
constexpr double kStepMm = 0.25;
constexpr double kSearchInFrontMm = 15;  // where the search for the lips' front starts, in front of Ls and Li

bool is_soft(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels, const Eigen::Vector3d& p) {
  const Eigen::Vector3d ijk = tissues.geometry.continuous_index(p);
  const int i = int(std::lround(ijk.x())), j = int(std::lround(ijk.y())), k = int(std::lround(ijk.z()));
  if (!tissues.geometry.contains(i, j, k)) return false;
  const uint8_t label = tissues.labels[size_t(tissues.geometry.index(i, j, k))];
  return std::find(soft_labels.begin(), soft_labels.end(), label) != soft_labels.end();
}

// The face's frame at the mouth: the midline point between Ls and Li, and how far the dental
// arch's front lies in front of it at a lateral offset.
struct Mouth {
  AnatomicalFrame frame;
  Eigen::Vector3d middle;
  double low = 0, high = 0;  // the heights of Li and Ls above `middle`
  double front = 0;          // where the search for the lips starts, in front of `middle`
  double incisor = 0;        // the arch's front on the midline, in front of `middle`
  double arch_front(double lateral) const { return incisor - lateral * lateral / kArchFallMm; }
  Eigen::Vector3d at(double lateral, double up, double forward) const {
    return middle + lateral * frame.left + up * frame.superior + forward * frame.anterior;
  }
};

// The cleft's height at `lateral`: of the heights between Li and Ls, where the soft tissue's front
// lies furthest back, or where none stands in front of the arch (the lips apart); the middle of
// those heights. nullopt when no height has tissue in front of the arch.
std::optional<double> cleft_height(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels, const Mouth& m,
                                   double lateral) {
  const double arch = m.arch_front(lateral);
  double deepest = INFINITY, first = 0, last = 0;
  bool tissue_seen = false;
  for (double h = m.low; h <= m.high; h += kStepMm) {
    double front = arch;  // no tissue in front of the arch: open down to it
    for (double a = m.front; a >= arch; a -= kStepMm)
      if (is_soft(tissues, soft_labels, m.at(lateral, h, a))) {
        front = a;
        tissue_seen = true;
        break;
      }
    if (front < deepest - 1e-9)
      deepest = front, first = last = h;
    else if (front < deepest + 1e-9)
      last = h;
  }
  if (!tissue_seen) return std::nullopt;
  return (first + last) / 2;
}

// The cleft's height at `lateral`, linear between its samples, the end samples' beyond them.
double height_at(const std::vector<std::pair<double, double>>& cleft, double lateral) {
  if (lateral <= cleft.front().first) return cleft.front().second;
  if (lateral >= cleft.back().first) return cleft.back().second;
  const auto after = std::lower_bound(cleft.begin(), cleft.end(), std::pair<double, double>{lateral, -INFINITY});
  const auto before = after - 1;
  const double t = (lateral - before->first) / (after->first - before->first);
  return before->second + t * (after->second - before->second);
}

}  // namespace

std::optional<LipParting> lip_parting(const LabelVolume& tissues, const std::vector<uint8_t>& soft_labels,
                                      const LandmarkSet& landmarks) {
  const auto ls = find_landmark(landmarks, "Ls"), li = find_landmark(landmarks, "Li");
  auto incisor = find_landmark(landmarks, "U1");
  if (!incisor) incisor = find_landmark(landmarks, "L1");
  if (!ls || !li || !incisor) return std::nullopt;
  Mouth m;
  m.frame = anatomical_frame(landmarks);
  m.middle = (*ls + *li) / 2;
  m.low = m.frame.superior.dot(*li - m.middle);
  m.high = m.frame.superior.dot(*ls - m.middle);
  m.front = std::max(m.frame.anterior.dot(*ls - m.middle), m.frame.anterior.dot(*li - m.middle)) + kSearchInFrontMm;
  m.incisor = m.frame.anterior.dot(*incisor - m.middle) - kBehindIncisorMm;

  LipParting parting;
  for (double lateral = -kMouthHalfWidthMm; lateral <= kMouthHalfWidthMm + 1e-9; lateral += kAcrossStepMm)
    if (const auto h = cleft_height(tissues, soft_labels, m, lateral)) parting.cleft.emplace_back(lateral, *h);
  if (parting.cleft.empty()) return std::nullopt;
  parting.stomion = m.at(0, height_at(parting.cleft, 0), 0);
  parting.side = [m, cleft = parting.cleft](const Eigen::Vector3d& p) {
    const Eigen::Vector3d d = p - m.middle;
    const double lateral = m.frame.left.dot(d), up = m.frame.superior.dot(d) - height_at(cleft, lateral);
    if (std::abs(lateral) > kMouthHalfWidthMm || std::abs(up) > kLipHalfHeightMm) return 0;
    if (m.frame.anterior.dot(d) < m.arch_front(lateral)) return 0;
    return up > 0 ? 1 : -1;
  };
  return parting;
}

}  // namespace maxillo::casework
