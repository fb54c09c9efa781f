#include "geometry/rigid_fit.h"

#include <Eigen/SVD>
#include <cassert>

namespace maxillo {
namespace {

// U diag(1, 1, +-1) V^T: the sign keeps the determinant at +1.
Eigen::Matrix3d proper_rotation(const Eigen::JacobiSVD<Eigen::Matrix3d>& svd) {
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

Eigen::Vector3d centroid(std::span<const Eigen::Vector3d> points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) sum += p;
  return sum / double(points.size());
}

}  // namespace

Eigen::Isometry3d best_rigid_transform(std::span<const Eigen::Vector3d> from, std::span<const Eigen::Vector3d> to) {
  assert(from.size() == to.size() && from.size() >= 3 && "best_rigid_transform needs three pairs or more");
  const Eigen::Vector3d from_centre = centroid(from), to_centre = centroid(to);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) covariance += (to[i] - to_centre) * (from[i] - from_centre).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = proper_rotation(svd);
  transform.translation() = to_centre - transform.linear() * from_centre;
  return transform;
}

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& m) {
  return proper_rotation(Eigen::JacobiSVD<Eigen::Matrix3d>(m, Eigen::ComputeFullU | Eigen::ComputeFullV));
}

}  // namespace maxillo
