#include "validation/face_regions.h"

#include <cmath>

namespace maxillo::validation {

std::string_view region_name(FaceRegion region) {
  switch (region) {
    case FaceRegion::kNose: return "nose";
    case FaceRegion::kUpperLip: return "upper lip";
    case FaceRegion::kLowerLip: return "lower lip";
    case FaceRegion::kChin: return "chin";
    case FaceRegion::kCheeks: return "cheeks";
    case FaceRegion::kOutside: break;
  }
  return "outside";
}

namespace {

// A point's coordinates along the frame's axes, relative to subnasale.
struct FramePoint {
  double anterior, superior,
      lateral;  // lateral: distance from the midline through subnasale
};

FramePoint in_frame(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, const FaceAxes& axes) {
  const Eigen::Vector3d d = p - origin;
  return {d.dot(axes.anterior), d.dot(axes.superior), std::abs(d.dot(axes.left))};
}

}  // namespace

std::vector<FaceRegion> classify_face_regions(const VertexMatrix& points, const FaceLandmarks& l, const FaceAxes& axes,
                                              const FaceRegionOptions& o) {
  const Eigen::Vector3d& origin = l.subnasale;
  auto frame = [&](const Eigen::Vector3d& p) { return in_frame(p, origin, axes); };
  const double orbit_level = frame(l.orbitale).superior;
  const double ear_front = frame(l.porion).anterior + o.ear_margin_mm;
  const FramePoint menton = frame(l.menton);
  const double lips_meet = 0.5 * (frame(l.labrale_superius).superior + frame(l.labrale_inferius).superior);
  const double chin_top = 0.5 * (frame(l.labrale_inferius).superior + frame(l.soft_pogonion).superior);

  std::vector<FaceRegion> regions(size_t(points.rows()), FaceRegion::kOutside);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const FramePoint p = frame(points.row(i).transpose());
    const bool eyes_or_above = p.superior > orbit_level;
    const bool behind_face = p.anterior < ear_front;
    const bool below_chin = p.superior < menton.superior - o.chin_margin_mm;
    const bool neck = p.superior < menton.superior && p.anterior < menton.anterior - o.neck_depth_mm;
    if (eyes_or_above || behind_face || below_chin || neck) continue;

    FaceRegion& r = regions[size_t(i)];
    if (p.superior >= 0) {  // at or above subnasale
      const bool nose = p.lateral <= o.nose_half_width_mm && p.anterior >= -o.nose_depth_mm;
      r = nose ? FaceRegion::kNose : FaceRegion::kCheeks;
    } else if (p.lateral > o.lip_half_width_mm) {
      r = FaceRegion::kCheeks;
    } else if (p.superior >= lips_meet) {
      r = FaceRegion::kUpperLip;
    } else if (p.superior >= chin_top) {
      r = FaceRegion::kLowerLip;
    } else {
      r = FaceRegion::kChin;
    }
  }
  return regions;
}

std::vector<bool> region_mask(const std::vector<FaceRegion>& regions, FaceRegion region) {
  std::vector<bool> mask(regions.size());
  for (size_t i = 0; i < regions.size(); ++i)
    mask[i] = region == FaceRegion::kOutside ? regions[i] != FaceRegion::kOutside : regions[i] == region;
  return mask;
}

}  // namespace maxillo::validation
