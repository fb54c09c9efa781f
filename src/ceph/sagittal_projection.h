#pragma once
// Landmarks in the mid-sagittal plane: the 2D frame every cephalometric measurement works in.
//
// Sagittal frame: 2D, millimetres, u = anterior, v = superior (the face looks to +u, the head
// is upright to +v). Its origin is arbitrary (measurements are translation invariant).
//
// Two inputs reach it:
//  * a 2D cephalogram: x, y in the image plane (z = 0). CephalogramAxes says which way the
//    image axes point and the pixel spacing: image pixel coordinates (ISBI, most viewers) have
//    y pointing DOWN and, for a standard lateral cephalogram, the face looking to +x.
//  * 3D landmarks (CT, LPS mm): the mid-sagittal plane is the least-squares plane through the
//    midline landmarks present (S, N, A, B, ANS, PNS, Pog, Gn, Me, Si) and the midpoints of the
//    bilateral pairs present (OrR/OrL, PoR/PoL, GoR/GoL, ArR/ArL, U6R/U6L, L6R/L6L). The fit
//    uses every such point so that the one-sided error of a single landmark averages out; the
//    plane's normal is oriented to the patient's left (+x LPS), u is LPS anterior (-y)
//    projected into the plane, v = u x normal (superior). Points are projected orthogonally.
//
// Bilateral pairs become one sagittal point named without the suffix (GoR/GoL -> Go, U6R/U6L
// -> U6, the mean of both sides; one side alone is used as it is), as a cephalogram superimposes
// the two sides. A midline label already present wins over a bilateral mean.
#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>

#include "ceph/landmark.h"

namespace maxillo {

struct SagittalLandmarks {
  std::map<std::string, Eigen::Vector2d> points;  // label -> (anterior, superior) mm
  std::string frame;  // how the plane was obtained, for reports ("cephalogram image plane", ...)
  std::optional<Eigen::Vector2d> find(const std::string& label) const;
};

enum class ImageVerticalAxis { kDown, kUp };     // image y grows downwards (pixels) or upwards
enum class FacingDirection { kPlusX, kMinusX };  // the face looks to +x (standard) or -x

struct CephalogramAxes {
  double pixel_spacing_mm = 1.0;  // 1 when x, y are already millimetres
  ImageVerticalAxis vertical = ImageVerticalAxis::kUp;
  FacingDirection facing = FacingDirection::kPlusX;
};

// How to read a landmark set: kAuto = cephalogram when every z is exactly 0, else 3D LPS.
enum class LandmarkGeometry { kAuto, kCephalogram, kVolumeLps };

// 2D: x, y of each landmark mapped with the axes; z is ignored.
SagittalLandmarks cephalogram_to_sagittal(const LandmarkSet& landmarks, const CephalogramAxes& axes);

enum class ProjectionStatus { kOk, kTooFewMidlinePoints, kDegenerate };
struct SagittalProjection {
  ProjectionStatus status = ProjectionStatus::kOk;
  SagittalLandmarks landmarks;      // empty unless kOk
  Eigen::Vector3d normal{1, 0, 0};  // LPS unit normal of the mid-sagittal plane (to the left)
  double rms_distance_mm = 0;       // RMS distance of the fitted points from the plane
  int fitted_points = 0;
};
// 3D LPS: fits the mid-sagittal plane (needs >= 3 midline points not on one line).
SagittalProjection project_to_mid_sagittal(const LandmarkSet& landmarks);

// Either of the above per `geometry`; Error(kBadValue, source) when the 3D plane cannot be fitted.
SagittalLandmarks to_sagittal(const LandmarkSet& landmarks, LandmarkGeometry geometry, const CephalogramAxes& axes,
                              const std::string& source);

}  // namespace maxillo
