#pragma once
// The patient's anatomical frame (Frankfort horizontal), from four landmark positions.
//
//   left      = unit(PoL - PoR), averaged with unit(OrL - OrR) when both orbitales exist
//               (the two transverse axes of the Frankfort horizontal agree to a few degrees,
//               and averaging halves the effect of one misplaced point);
//   superior  = unit(forward x left), forward = mean(Or) - mean(Po): the normal of the
//               Frankfort horizontal (the plane through the porions and orbitales);
//   anterior  = left x superior (in the FH plane, perpendicular to the transverse axis);
//   origin    = midpoint of the porions.
// Why not the mid-sagittal plane through N and S: they lie 60-70 mm apart on nearly the same
// line as the FH's anterior axis, so that plane's tilt is poorly conditioned; the porion-porion
// distance (~120 mm) fixes the transverse axis far better.
//
// Without both porions and an orbitale, or with degenerate ones (porions < 20 mm apart,
// orbitales not anterior to them), the frame is the patient axes: anterior = -y,
// superior = +z, left = +x (LPS), origin 0, which is right for a head scanned supine.
// ceph/landmark_frame.h picks the four points out of a landmark set.
#include <Eigen/Core>
#include <optional>

namespace maxillo {

enum class FrameSource { Frankfort, PatientAxes };

struct AnatomicalFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();      // LPS mm
  Eigen::Vector3d anterior = -Eigen::Vector3d::UnitY();  // unit vectors, right-handed:
  Eigen::Vector3d superior = Eigen::Vector3d::UnitZ();   // anterior x left = superior
  Eigen::Vector3d left = Eigen::Vector3d::UnitX();
  FrameSource source = FrameSource::PatientAxes;
};

// The porions and orbitales that define the Frankfort horizontal (LPS mm), each optional.
struct FrankfortPoints {
  std::optional<Eigen::Vector3d> porion_right{}, porion_left{};
  std::optional<Eigen::Vector3d> orbitale_right{}, orbitale_left{};
};

// The Frankfort frame when the points allow it, else the patient-axes frame (see above).
AnatomicalFrame frankfort_frame(const FrankfortPoints& points);

}  // namespace maxillo
