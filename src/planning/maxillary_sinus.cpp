#include "planning/maxillary_sinus.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "planning/distractor_checks.h"
#include "planning/voxel_components.h"

namespace maxillo::planning {
namespace {

using Eigen::Vector3d;

constexpr int kMaxOpenSides = 1;

double enclosed_air_cm3(const LabelVolume& labels, const PlanningFrame& frame, const AnatomyLabels& anatomy, Side side,
                        const SinusBox& box) {
  const VolumeGeometry& g = labels.geometry;
  int64_t count = 0;
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i)
        if (is_labelled(anatomy.sinus_air, labels.labels[g.index(i, j, k)]) &&
            box.contains(g.world(Vector3d(i, j, k)), frame, side))
          ++count;
  return count * g.spacing.prod() / 1000;
}

// A wall met within kWallReachMm from `p` along `direction`: anything but the outside's air.
// Bone alone would not do: a sinus wall thinner than the voxels (the cadaver head's anterior
// and medial walls at 2 mm slices) reads as soft tissue.
bool wall_within_reach(const LabelVolume& labels, const AnatomyLabels& anatomy, const Vector3d& p,
                       const Vector3d& direction) {
  const VolumeGeometry& g = labels.geometry;
  const double step = 0.5 * g.spacing.minCoeff();
  for (double s = step; s <= kWallReachMm; s += step) {
    const Vector3d c = g.continuous_index(p + s * direction);
    const int i = static_cast<int>(std::lround(c.x())), j = static_cast<int>(std::lround(c.y())),
              k = static_cast<int>(std::lround(c.z()));
    if (!g.contains(i, j, k)) return false;
    if (!is_labelled(anatomy.open_air, labels.labels[g.index(i, j, k)])) return true;
  }
  return false;
}

// Open air of the side's box that lies lateral to the nasal cavity, walled in front (where the
// distractor enters; air in front of the face is open there) and on three at least of the four
// other sides: the candidates for the sinus (1 per voxel of the whole grid). One side may be
// open: a foramen, a canal, or a wall the scan did not resolve.
std::vector<uint8_t> walled_open_air(const LabelVolume& labels, const PlanningFrame& frame,
                                     const AnatomyLabels& anatomy, Side side, const SinusBox& box) {
  const VolumeGeometry& g = labels.geometry;
  const Vector3d lateral = outward_sign(side) * frame.left;
  const Vector3d other_sides[] = {lateral, -frame.anterior, frame.superior, -frame.superior};
  std::vector<uint8_t> mask(labels.labels.size(), 0);
  for (int k = 0; k < g.size.z(); ++k)
    for (int j = 0; j < g.size.y(); ++j)
      for (int i = 0; i < g.size.x(); ++i) {
        const size_t index = g.index(i, j, k);
        if (!is_labelled(anatomy.open_air, labels.labels[index])) continue;
        const Vector3d p = g.world(Vector3d(i, j, k));
        if (!box.contains(p, frame, side) || (p - frame.origin).dot(lateral) < kNasalHalfWidthMm) continue;
        if (!wall_within_reach(labels, anatomy, p, frame.anterior)) continue;
        int open_sides = 0;
        for (const Vector3d& d : other_sides) open_sides += wall_within_reach(labels, anatomy, p, d) ? 0 : 1;
        mask[index] = open_sides <= kMaxOpenSides ? 1 : 0;
      }
  return mask;
}

std::string cm3(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f cm3", value);
  return text;
}

}  // namespace

bool SinusBox::contains(const Vector3d& p, const PlanningFrame& frame, Side side) const {
  return outward_sign(side) * (p - frame.origin).dot(frame.left) > 0 && height.contains(p.dot(frame.superior)) &&
         depth.contains(p.dot(frame.anterior));
}

SinusBox sinus_box(const PlanningFrame& frame, const LandmarkSet& landmarks) {
  SinusBox box;
  const auto ans = find_landmark(landmarks, "ANS"), pns = find_landmark(landmarks, "PNS");
  if (ans && pns) {
    box.height.low = std::min(ans->dot(frame.superior), pns->dot(frame.superior)) - 5;
    box.depth = {pns->dot(frame.anterior) - 5, ans->dot(frame.anterior) + 5};
  }
  for (const char* label : {"OrR", "OrL", "Or"})
    if (auto o = find_landmark(landmarks, label))
      box.height.high =
          std::isinf(box.height.high) ? o->dot(frame.superior) : std::max(box.height.high, o->dot(frame.superior));
  return box;
}

LabelVolume with_open_sinus_air(const LabelVolume& labels, const PlanningFrame& frame, const AnatomyLabels& anatomy,
                                const LandmarkSet& landmarks, SinusAirReading& reading) {
  const SinusBox box = sinus_box(frame, landmarks);
  if (!box.bounded() || anatomy.sinus_air.empty()) return labels;
  LabelVolume result = labels;
  for (Side side : {Side::Right, Side::Left}) {
    if (enclosed_air_cm3(labels, frame, anatomy, side, box) >= kMinEnclosedSinusCm3) continue;
    const std::vector<uint8_t> candidates = walled_open_air(labels, frame, anatomy, side, box);
    const VoxelComponents components = voxel_components(candidates, labels.geometry.size);
    if (components.count == 0) continue;
    const auto largest = static_cast<int32_t>(std::max_element(components.sizes.begin(), components.sizes.end()) -
                                              components.sizes.begin());
    for (size_t v = 0; v < components.id.size(); ++v)
      if (components.id[v] == largest) result.labels[v] = anatomy.sinus_air.front();
    const double volume = components.sizes[largest] * labels.geometry.spacing.prod() / 1000;
    char reach[16];
    std::snprintf(reach, sizeof reach, "%.0f mm", kNasalHalfWidthMm);
    reading.notes.push_back(std::string(side_name(side)) + " maxillary sinus open to the nasal cavity at this " +
                            "scan's resolution: its air taken lateral to " + reach +
                            " from the midsagittal plane, walled by tissue (" + cm3(volume) + ")");
  }
  return result;
}

}  // namespace maxillo::planning
