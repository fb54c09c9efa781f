#pragma once
// The CT resampled in a head frame, in Hounsfield units: the frame where every landmark rule is
// written. Its axes are the patient's once the head is set straight: x towards the patient's
// left (the midsagittal plane's normal), y posterior, z superior (normal to the Frankfort
// horizontal in the final frame); millimetres from the frame's origin. Rules then read "most
// anterior" as "smallest y" whatever the pose the scan was taken in.
#include <Eigen/Geometry>

#include "core/volume.h"
#include "imaging/grey_calibration.h"

namespace maxillo::landmarking {

// A box of the head frame (mm).
struct FrameBox {
  Eigen::Vector3d lo, hi;
};

// The corner of a rule's sampling grid of `step_mm`, moved down to the nearest multiple of the
// step in the head frame: the grids of two windows that overlap (a rule run from a second start,
// landmark_checks.h) then sample the same points and see the same outline.
inline Eigen::Vector3d grid_corner(const Eigen::Vector3d& lo, double step_mm) {
  return (lo / step_mm).array().floor().matrix() * step_mm;
}

class HeadVolume {
 public:
  // `ct` read through `grey` (its values as HU), sampled with trilinear interpolation on a grid
  // of `spacing_mm` covering `box` of the frame `frame_to_lps`. Outside the scan: air.
  HeadVolume(const Volume& ct, const GreyCalibration& grey, const Eigen::Isometry3d& frame_to_lps, const FrameBox& box,
             double spacing_mm);

  // HU at a point of the frame (trilinear; outside the box: -1000).
  double hu(const Eigen::Vector3d& p) const;
  // Whether the point lies inside the scanned field (not padded with air by the resampling, nor
  // the scanner's padding value: GreyCalibration::padding).
  bool scanned(const Eigen::Vector3d& p) const;
  Eigen::Vector3d to_lps(const Eigen::Vector3d& p) const { return frame_to_lps_ * p; }
  const Eigen::Isometry3d& frame_to_lps() const { return frame_to_lps_; }
  const FrameBox& box() const { return box_; }
  double spacing() const { return spacing_; }
  // The scan's own largest voxel edge: how much detail the resampling above cannot add back.
  double scan_voxel_mm() const { return scan_voxel_mm_; }

 private:
  Volume volume_;  // HU, identity direction, origin at box.lo
  std::vector<uint8_t> scanned_;
  Eigen::Isometry3d frame_to_lps_;
  FrameBox box_;
  double spacing_;
  double scan_voxel_mm_;
};

}  // namespace maxillo::landmarking
