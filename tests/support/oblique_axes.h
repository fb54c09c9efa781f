#pragma once
// A rotation far from every axis-aligned one, for geometry tests: a row taken for a column, or a
// direction matrix for its transpose, goes unnoticed with the identity and not with this.
#include <Eigen/Geometry>

namespace maxillo::testing {

inline Eigen::Matrix3d oblique_axes() {
  return (Eigen::AngleAxisd(0.35, Eigen::Vector3d(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(-0.6, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace maxillo::testing
