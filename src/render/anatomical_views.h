#pragma once
// Where to put the camera for the standard clinical views. Pure Eigen, no VTK.
//
// Anatomical frame. Built from landmarks when they allow it, otherwise from the patient axes:
//   * Landmarks (FrameSource::Frankfort): needs PoR, PoL (porions) and OrR and/or OrL (orbitales).
//       left      = unit(PoL - PoR), averaged with unit(OrL - OrR) when both orbitales exist
//                   (the two transverse axes of the Frankfort horizontal agree to a few degrees,
//                   and averaging halves the effect of one misplaced point);
//       superior  = unit(forward x left), forward = mean(Or) - mean(Po): the normal of the
//                   Frankfort horizontal (the plane through the porions and orbitales);
//       anterior  = left x superior (in the FH plane, perpendicular to the transverse axis).
//       origin    = midpoint of the porions.
//     Why not the mid-sagittal plane through N, S: N and S lie 60-70 mm apart on nearly the
//     same line as the FH's anterior axis, so the plane's tilt is poorly conditioned; the
//     porion-porion distance (~120 mm) fixes the transverse axis far better.
//     Degenerate input (porions < 20 mm apart, orbitales not anterior to them) falls back.
//   * Patient axes (FrameSource::PatientAxes): anterior = -y, superior = +z, left = +x (LPS),
//     origin = 0. Correct for a head scanned in the usual supine position.
//
// Views (each looks at the scene centre, superior axis up in the image):
//   Frontal : camera in front of the face; the patient's left is on the image's right.
//   Lateral : right profile, the orthodontic standard: camera on the patient's right, the face
//             pointing to the image's right.
//   Oblique : 45 degrees between frontal and right lateral (right-front).
#include <Eigen/Core>
#include <optional>
#include <string_view>

#include "ceph/landmark.h"
#include "render/scene.h"

namespace maxillo::render {

enum class FrameSource { Frankfort, PatientAxes };

struct AnatomicalFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();     // LPS mm
  Eigen::Vector3d anterior = -Eigen::Vector3d::UnitY();  // unit vectors, right-handed:
  Eigen::Vector3d superior = Eigen::Vector3d::UnitZ();   // anterior x left = superior
  Eigen::Vector3d left = Eigen::Vector3d::UnitX();
  FrameSource source = FrameSource::PatientAxes;
};

// The Frankfort frame when the landmarks allow it, else the patient-axes frame (see above).
AnatomicalFrame anatomical_frame(const LandmarkSet& landmarks);

enum class StandardView { Frontal, Lateral, Oblique };

std::string_view name_of(StandardView view);                    // "frontal", "lateral", "oblique"
std::optional<StandardView> parse_standard_view(std::string_view name);  // inverse of name_of

// Fraction of the image left free around the scene's projection on each side.
inline constexpr double kViewMargin = 0.06;

// A camera for `view` that looks at bounds.centre() with frame.superior up and fits the
// projection of the bounds' 8 corners into an image of aspect = width / height, with
// kViewMargin to spare. Perspective uses a 15 degree view angle. bounds must not be empty.
Camera standard_camera(StandardView view, const AnatomicalFrame& frame, const Bounds& bounds,
                       double aspect, Projection projection = Projection::Parallel);

}  // namespace maxillo::render
