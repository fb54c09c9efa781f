#include "imaging/head_orientation.h"

#include <cmath>
#include <cstdio>

#include "core/parallel_slabs.h"

namespace maxillo {
namespace {

constexpr int kSlabs = 16;  // fixed parts of the slices, joined in order

// The sums over the volume, in fixed slabs of slices joined in order: the same answer
// whatever the threads (core/parallel_slabs.h).
struct DenseSums {
  Eigen::Vector3d teeth_sum{0, 0, 0};
  int64_t teeth = 0;
  int64_t bone = 0;
};

// Thresholds in the scan's own grey values.
struct Thresholds {
  double bone, dense;
};

DenseSums locate_teeth(const Volume& ct, const Thresholds& options) {
  const auto& g = ct.geometry;
  std::vector<DenseSums> parts(kSlabs);
  for_each_part(kSlabs, [&](int part) {
    DenseSums& sums = parts[size_t(part)];
    const PartRange slices = part_range(g.size.z(), part, kSlabs);
    for (int64_t k = slices.begin; k < slices.end; ++k)
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          const int16_t hu = ct.hu[size_t(g.index(i, j, int(k)))];
          if (hu < options.bone) continue;
          ++sums.bone;
          if (hu < options.dense) continue;
          ++sums.teeth;
          sums.teeth_sum += g.world(Eigen::Vector3d(i, j, double(k)));
        }
  });
  DenseSums total;
  for (const auto& part : parts) {
    total.teeth_sum += part.teeth_sum;
    total.teeth += part.teeth;
    total.bone += part.bone;
  }
  return total;
}

// Bone beyond the plane through `centre` across each patient axis: (+ side - side) / all.
Eigen::Vector3d bone_imbalance(const Volume& ct, const Eigen::Vector3d& centre, double bone_hu) {
  const auto& g = ct.geometry;
  std::vector<Eigen::Vector3d> parts(kSlabs, Eigen::Vector3d::Zero());
  std::vector<int64_t> counts(kSlabs, 0);
  for_each_part(kSlabs, [&](int part) {
    const PartRange slices = part_range(g.size.z(), part, kSlabs);
    for (int64_t k = slices.begin; k < slices.end; ++k)
      for (int j = 0; j < g.size.y(); ++j)
        for (int i = 0; i < g.size.x(); ++i) {
          if (ct.hu[size_t(g.index(i, j, int(k)))] < bone_hu) continue;
          const Eigen::Vector3d offset = g.world(Eigen::Vector3d(i, j, double(k))) - centre;
          for (int a = 0; a < 3; ++a) parts[size_t(part)][a] += offset[a] > 0 ? 1 : -1;
          ++counts[size_t(part)];
        }
  });
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int64_t count = 0;
  for (int part = 0; part < kSlabs; ++part) {
    sum += parts[size_t(part)];
    count += counts[size_t(part)];
  }
  return count ? Eigen::Vector3d(sum / double(count)) : Eigen::Vector3d::Zero();
}

AxisVerdict verdict_of(double imbalance, double needed) {
  if (imbalance >= needed) return AxisVerdict::kAsTheHeaderSays;
  if (imbalance <= -needed) return AxisVerdict::kReversed;
  return AxisVerdict::kUndetermined;
}

}  // namespace

HeadOrientation check_head_orientation(const Volume& ct, const HeadOrientationOptions& options) {
  HeadOrientation result;
  const double voxel_cm3 = ct.geometry.spacing.prod() / 1000.0;
  result.grey = estimate_grey_calibration(ct);
  const Thresholds grey{result.grey.from_hu(options.bone_hu), result.grey.from_hu(options.dense_hu)};
  const DenseSums sums = locate_teeth(ct, grey);
  result.teeth_cm3 = double(sums.teeth) * voxel_cm3;
  result.bone_cm3 = double(sums.bone) * voxel_cm3;
  if (result.teeth_cm3 < options.min_teeth_cm3) return result;  // nothing to stand on
  result.teeth_centre = sums.teeth_sum / double(sums.teeth);
  result.imbalance = bone_imbalance(ct, result.teeth_centre, grey.bone);
  // Posterior is +y in LPS: bone behind the teeth makes the y imbalance positive.
  result.face = verdict_of(result.imbalance.y(), options.face_imbalance);
  result.vertex = verdict_of(result.imbalance.z(), options.vertex_imbalance);
  result.sideways = std::abs(result.imbalance.x()) >= options.face_imbalance &&
                    std::abs(result.imbalance.x()) > std::abs(result.imbalance.y());
  return result;
}

std::string HeadOrientation::finding() const {
  char figures[160];
  std::snprintf(figures, sizeof figures,
                " (bone imbalance about the teeth: x %+.2f, y %+.2f, z %+.2f; %.1f cm3 of teeth)", imbalance.x(),
                imbalance.y(), imbalance.z(), teeth_cm3);
  if (teeth_cm3 == 0 && bone_cm3 == 0) return "no bone in the volume: the orientation cannot be checked";
  if (imbalance.isZero())
    return "no teeth found (enamel or restorations): the orientation could not be checked from the anatomy";
  std::string text;
  if (sideways)
    text = std::string("the face points ") + (imbalance.x() > 0 ? "right" : "left") +
           " in the patient frame, not anterior";
  else if (face == AxisVerdict::kReversed)
    text = "the face points posterior (+y) in the patient frame";
  if (vertex == AxisVerdict::kReversed)
    text += std::string(text.empty() ? "" : ", and ") + "the vertex points inferior (-z)";
  if (!text.empty())
    return "the header contradicts the anatomy: " + text +
           ". The volume is rotated or mirrored, so left and right cannot be trusted either" + figures;
  if (face == AxisVerdict::kAsTheHeaderSays && vertex == AxisVerdict::kAsTheHeaderSays)
    return std::string("the header agrees with the anatomy: the face points anterior and the vertex superior") +
           figures;
  return std::string("the anatomy confirms only part of the header (") +
         (face == AxisVerdict::kAsTheHeaderSays ? "the face points anterior; " : "front and back undetermined; ") +
         (vertex == AxisVerdict::kAsTheHeaderSays ? "the vertex points superior" : "up and down undetermined") +
         "): the field of view may not hold the whole skull" + figures;
}

}  // namespace maxillo
