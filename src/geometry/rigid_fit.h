#pragma once
// Rigid fits: the rotation and translation that best map one point set onto another, and the
// rotation nearest to a matrix that has drifted from one.
#include <Eigen/Geometry>
#include <span>

namespace maxillo {

// The rigid transform T minimising sum |T from[i] - to[i]|^2 (Kabsch 1976; Umeyama 1991
// without scale): R = U diag(1, 1, det(U V^T)) V^T from the SVD of the cross-covariance, so a
// reflection is never returned. `from` and `to` pair up by index; at least three pairs, not
// all on one line, for a unique answer (otherwise one of the minimisers).
Eigen::Isometry3d best_rigid_transform(std::span<const Eigen::Vector3d> from, std::span<const Eigen::Vector3d> to);

// The proper rotation nearest to `m` in the Frobenius norm (the polar factor, by SVD).
Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& m);

}  // namespace maxillo
