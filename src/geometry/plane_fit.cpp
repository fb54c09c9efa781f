#include "geometry/plane_fit.h"

#include <Eigen/SVD>
#include <algorithm>

namespace maxillo {

std::optional<FittedPlane> fit_plane(std::span<const Eigen::Vector3d> points) {
  if (points.size() < 3) return std::nullopt;
  FittedPlane plane;
  for (const Eigen::Vector3d& p : points) plane.centroid += p;
  plane.centroid /= double(points.size());
  Eigen::MatrixXd centred(Eigen::Index(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) centred.row(Eigen::Index(i)) = (points[i] - plane.centroid).transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinV);
  const Eigen::Vector3d singular = svd.singularValues();
  if (singular(1) < 1e-3 * std::max(singular(0), 1.0)) return std::nullopt;
  plane.normal = svd.matrixV().col(2).normalized();
  return plane;
}

}  // namespace maxillo
