#pragma once
// The least-squares plane through a point set.
#include <Eigen/Core>
#include <optional>
#include <span>

namespace maxillo {

struct FittedPlane {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // a point of the plane: the points' mean
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // unit; its sign is arbitrary (orient it yourself)
};

// Total least squares: the plane through the centroid whose normal is the direction of least
// spread (the last right singular vector of the centred points), minimising the sum of squared
// perpendicular distances. None for fewer than three points, or for points so nearly on one
// line (second singular value < 1e-3 of the first, or of 1 mm) that the plane's tilt about
// that line is undetermined.
std::optional<FittedPlane> fit_plane(std::span<const Eigen::Vector3d> points);

}  // namespace maxillo
