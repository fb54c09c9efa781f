#include "ceph/sagittal_projection.h"

#include <Eigen/Geometry>
#include <array>
#include <cassert>
#include <cmath>

#include "core/error.h"
#include "geometry/plane_fit.h"

namespace maxillo {
namespace {

constexpr std::array kMidlineLabels = {"S", "N", "A", "B", "ANS", "PNS", "Pog", "Gn", "Me", "Si"};

// Midline labels as they are; bilateral pairs as the mean of the sides present.
std::map<std::string, Eigen::Vector3d> merge_bilateral(const LandmarkSet& landmarks) {
  std::map<std::string, Eigen::Vector3d> merged;
  std::map<std::string, std::pair<Eigen::Vector3d, int>> sides;
  for (const auto& lm : landmarks) {
    if (auto base = bilateral_base(lm.label)) {
      auto& [sum, count] = sides.try_emplace(*base, Eigen::Vector3d::Zero(), 0).first->second;
      sum += lm.position;
      ++count;
    } else {
      merged[lm.label] = lm.position;
    }
  }
  for (const auto& [base, sum_count] : sides) merged.try_emplace(base, sum_count.first / sum_count.second);
  return merged;
}

bool is_mid_sagittal(const std::string& label) {
  for (const char* m : kMidlineLabels)
    if (label == m) return true;
  return is_bilateral_base(label);
}

}  // namespace

std::optional<Eigen::Vector2d> SagittalLandmarks::find(const std::string& label) const {
  auto it = points.find(label);
  if (it == points.end()) return std::nullopt;
  return it->second;
}

SagittalLandmarks cephalogram_to_sagittal(const LandmarkSet& landmarks, const CephalogramAxes& axes) {
  assert(axes.pixel_spacing_mm > 0 && "pixel spacing must be positive");
  const double anterior_sign = axes.facing == FacingDirection::kPlusX ? 1 : -1;
  const double superior_sign = axes.vertical == ImageVerticalAxis::kUp ? 1 : -1;
  SagittalLandmarks out;
  for (const auto& [label, p] : merge_bilateral(landmarks))
    out.points[label] = Eigen::Vector2d(anterior_sign * p.x(), superior_sign * p.y()) * axes.pixel_spacing_mm;
  out.frame = "cephalogram image plane";
  return out;
}

SagittalProjection project_to_mid_sagittal(const LandmarkSet& landmarks) {
  SagittalProjection result;
  auto merged = merge_bilateral(landmarks);
  std::vector<Eigen::Vector3d> fit;
  for (const auto& [label, p] : merged)
    if (is_mid_sagittal(label)) fit.push_back(p);
  result.fitted_points = static_cast<int>(fit.size());
  if (fit.size() < 3) {
    result.status = ProjectionStatus::kTooFewMidlinePoints;
    return result;
  }
  // Points (nearly) on one line leave the plane's orientation undetermined.
  const std::optional<FittedPlane> plane = fit_plane(fit);
  if (!plane) {
    result.status = ProjectionStatus::kDegenerate;
    return result;
  }
  const Eigen::Vector3d& centroid = plane->centroid;
  Eigen::Vector3d normal = plane->normal;
  if (normal.x() < 0) normal = -normal;  // towards the patient's left
  // LPS anterior (-y) minus its component along the normal.
  Eigen::Vector3d anterior = Eigen::Vector3d(0, -1, 0) - Eigen::Vector3d(0, -1, 0).dot(normal) * normal;
  if (anterior.norm() < 1e-6) {  // plane perpendicular to the anterior axis: not a sagittal plane
    result.status = ProjectionStatus::kDegenerate;
    return result;
  }
  anterior.normalize();
  Eigen::Vector3d superior = anterior.cross(normal);
  double squared = 0;
  for (const auto& p : fit) squared += std::pow((p - centroid).dot(normal), 2);
  result.rms_distance_mm = std::sqrt(squared / double(fit.size()));
  result.normal = normal;
  for (const auto& [label, p] : merged)
    result.landmarks.points[label] = Eigen::Vector2d((p - centroid).dot(anterior), (p - centroid).dot(superior));
  result.landmarks.frame = "mid-sagittal plane fitted to " + std::to_string(fit.size()) + " midline points";
  return result;
}

SagittalLandmarks to_sagittal(const LandmarkSet& landmarks, LandmarkGeometry geometry, const CephalogramAxes& axes,
                              const std::string& source) {
  if (geometry == LandmarkGeometry::kAuto) {
    bool planar = !landmarks.empty();
    for (const auto& lm : landmarks) planar = planar && lm.position.z() == 0;
    geometry = planar ? LandmarkGeometry::kCephalogram : LandmarkGeometry::kVolumeLps;
  }
  if (geometry == LandmarkGeometry::kCephalogram) return cephalogram_to_sagittal(landmarks, axes);
  auto projection = project_to_mid_sagittal(landmarks);
  if (projection.status == ProjectionStatus::kTooFewMidlinePoints)
    throw Error(ErrorCode::kBadValue, source,
                "fewer than 3 midline landmarks (S, N, A, B, ANS, PNS, Pog, Gn, Me, Si or bilateral pairs): "
                "cannot fit the mid-sagittal plane");
  if (projection.status == ProjectionStatus::kDegenerate)
    throw Error(ErrorCode::kBadValue, source, "the midline landmarks lie on one line: no mid-sagittal plane");
  return projection.landmarks;
}

}  // namespace maxillo
